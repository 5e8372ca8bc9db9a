"""The time-stepper's inputs for one racket, ball and set of impact points, prepared once
and run for any Xo (:class:`Stepper`), and the time step they share
(:func:`contact_time_scale`).
"""

from __future__ import annotations

import math
from functools import lru_cache

import numpy as np

from ball import Ball
from racket.solver import layout
from racket.solver.dispatch import run_kernel
from racket.solver.steps import system_steps

FORCE_TOL = 1e-9
"""An unhappy-ball contact that approaches a common speed asymptotically is over when its
force has fallen to this fraction of its peak and the relative speed to this fraction of the
closing speed (so e comes out within 1e-9 of its limit, 0, rather than slightly negative)."""

CROSS_TOL = 1e-10
"""An unhappy ball crosses its fold when the contact relaxes within this fraction of Xo of
the fold's maximum (the Xo search drives the gap below half of it)."""


def contact_time_scale(ball: Ball, string_stiffness: float, closing_speed: float) -> float:
    """Half-period [s] of the ball on immovable strings, treating the ball as linear with
    its secant stiffness at this speed: sets the time step.

    Parameters
    ----------
    ball : Ball
        The ball.
    string_stiffness : float
        String-plane stiffness [N/m].
    closing_speed : float
        Ball speed relative to the impact point [m/s].
    """
    k = _secant_stiffness(ball.law, ball.mass, closing_speed)
    k_series = 1.0 / (1.0 / k + 1.0 / string_stiffness)
    return math.pi * math.sqrt(ball.mass / k_series)  # (math's: numpy's costs more, same bits)


def _secant_stiffness(law, mass: float, closing_speed: float) -> float:
    """The ball law's secant stiffness [N/m] for ``mass`` [kg] at ``closing_speed`` [m/s]:
    kept (:func:`_kept_secant_stiffness`) for a frozen law, every law of :mod:`ball`;
    computed afresh for any other, which might change, or one that cannot be hashed.
    """
    params = getattr(law, "__dataclass_params__", None)
    if params is None or not params.frozen:
        return law.secant_stiffness(mass, closing_speed)
    try:
        return _kept_secant_stiffness(law, mass, closing_speed)
    except TypeError:  # a frozen law of the caller's with a field that cannot be hashed
        return law.secant_stiffness(mass, closing_speed)


@lru_cache(maxsize=1024)
def _kept_secant_stiffness(law, mass: float, closing_speed: float) -> float:
    """:func:`_secant_stiffness` kept: an impact asks for it twice (its time step and its
    check of the contact time), and one-position calls at one speed ask again and again (a
    stiffening ball's takes a Newton iteration).  The key is the frozen law (hashed by its
    numbers) and two numbers, so nothing invalidates an entry; beyond 1024 the least
    recently used go.
    """
    return law.secant_stiffness(mass, closing_speed)


def _swing_velocities(modes, position, swing_speed, pivot):
    """Rigid-mode velocities (P, 2) of a racket whose impact point moves at -swing_speed
    (P,), not all 0.
    """
    if pivot is None:  # pure translation
        v_cm = np.full(position.size, -swing_speed)
        spin = np.zeros(position.size)
    else:  # rotation about the pivot: v(x) = -swing (pivot - x) / (pivot - position)
        v_cm = -swing_speed * (pivot - modes.center_of_mass) / (pivot - position)
        spin = -swing_speed / (pivot - position)
    return np.column_stack([v_cm * np.sqrt(modes.mass), spin * np.sqrt(modes.inertia_cm)])


class Stepper:
    """The kernel's inputs for one racket, ball and set of impact points, prepared once and
    run for any Xo (see :func:`racket.solver.kernel.run_impacts`).

    Parameters
    ----------
    racket : Racket
        The racket.
    ball : Ball
        The ball.
    x : ndarray
        Impact points [m from the tip].
    y : ndarray or None
        Their offsets [m from the long axis], None for impacts on the axis (bending only).
    speed : float
        Ball speed [m/s] towards the strings before impact.
    swing_speed : float or ndarray
        Speed [m/s] of each impact point towards the ball from the racket's swing.
    pivot : float or None
        The swing's centre of rotation [m from the tip], None for pure translation.
    steps_per_contact : int
        Time steps [-] per estimated contact time.
    """

    def __init__(self, racket, ball, x, y, speed, swing_speed, pivot, steps_per_contact):
        # The step follows from the bed's stiffest spot, whatever the points (the shortest
        # contact on it), and from the closing speed, the same for all (see impact).
        swing_speed = np.asarray(swing_speed, dtype=float)
        if swing_speed.shape != x.shape:  # (impact's are one per point already)
            swing_speed = np.broadcast_to(swing_speed, x.shape)
        self.closing = speed + swing_speed
        scale = contact_time_scale(ball, racket.contact.stiffest, self.closing[0])
        self.dt = float(scale) / steps_per_contact  # (a float: numpy's scalars cost more)
        self.steps_per_contact = steps_per_contact
        self.max_steps = 12 * steps_per_contact
        law = getattr(ball.law, "kernel_law", None)
        if law is None:
            raise ValueError(f"ball law {ball.law!r} is not supported on a racket")
        self.code = law[0]
        self.modes = modes = racket.beam.modes
        system, phi, self.face = racket.point_dynamics(x, y)
        self.system, self.phi = system, phi
        self.n = n = system.count
        trans, g0, g1 = system_steps(system, self.dt)
        out_d, out_v, out_dc = system.outputs(phi)
        self.swing_qd = np.zeros((x.size, 2))
        state0 = np.zeros((x.size, system.blocks.shape[0], 2))  # at rest
        if np.count_nonzero(swing_speed):  # (ndarray.any's reduction costs 5x more)
            self.swing_qd = _swing_velocities(modes, x, swing_speed, pivot)
            z0 = np.zeros((x.size, 2 * n))
            z0[:, n : n + 2] = self.swing_qd
            state0 = system.state(z0)
        self.position = x
        inv_ks = 1.0 / racket.contact.stiffness_at(x, 0.0 if y is None else y)
        if n:  # static correction: the bending modes left out respond quasi-statically
            count = modes.count  # the shapes phi already holds, spared computing again
            shapes = phi[:, :count].T if phi.shape[1] >= count else None
            series = inv_ks + racket.beam.residual_flexibility(x, shapes)
            if self.face:  # and the torsion modes left out
                series += racket.beam.roll_modes.residual_flexibility(x, y)
        else:  # a clamped head: the strings alone
            series = inv_ks.copy()
        self.points = layout.Points(
            unit=system.inputs(phi),
            out_d=out_d,
            out_v=out_v,
            out_dc=out_dc,
            reach_w=_lengths(out_d) * system.vibrating,
            series=series,
            inv_ks=inv_ks,
            ball_velocity=np.full(x.size, speed),
            state0=state0,
            x_o=np.full(x.size, np.nan),
        )
        self.frame = layout.Frame(
            np.ascontiguousarray(system.blocks, dtype=float),
            trans,
            g0,
            g1,
            system.metric,
            *system.damping_rows,
        )
        bed = (0.0, 0.0, 0.0) if law[0] == layout.SINE else bed_law(racket.contact)
        self.ball = _ball_model(self.dt, ball.mass, law, bed)

    def run(self, x_o, subset=None, stop_on_snap=False, extra_steps=0, history_steps=0,
            force_only=False):  # fmt: skip
        """Run the impacts (all, or those indexed by ``subset``) with Xo ``x_o`` [m] per
        impact run; returns the kernel's :class:`~racket.solver.layout.Outputs` (ball, block
        states, summary, history), the history over the first ``history_steps`` steps
        (none if 0; the force's alone, one row, if ``force_only``).
        """
        points = self.points
        if subset is not None:
            points = layout.Points(*(np.ascontiguousarray(v[subset]) for v in points))
        x_o = np.ascontiguousarray(x_o, dtype=float)
        if x_o is not points.x_o:  # (the points' own, NaN, unless the unhappy ball's)
            points = points._replace(x_o=x_o)
        count = points.ball_velocity.size
        nb = self.frame.trans.shape[0]
        controls = layout.Controls(
            dt=self.dt,
            max_steps=self.max_steps + extra_steps,
            extra_steps=extra_steps,
            force_tol=FORCE_TOL,
            cross_tol=CROSS_TOL,
            stop_on_snap=stop_on_snap,
            record=history_steps > 0,
        )
        out = layout.Outputs(
            ball=np.zeros((count, 2)),
            state=np.zeros((count, nb, 2)),
            summary=np.zeros((count, layout.N_SUMMARY)),
            history=np.zeros(
                (1 if force_only else layout.N_HISTORY, count, history_steps)
                if history_steps
                else (1, 1, 1)
            ),
        )
        run_kernel((self.frame, points, self.ball, controls, out), count)
        return out


def _lengths(rows: np.ndarray) -> np.ndarray:
    """The length of each 2-vector (the last axis) of ``rows``: np.linalg.norm's bits (the
    sum of two squares rounds once whichever way it is added), in a fifth of its time.
    """
    squares = rows * rows
    return np.sqrt(squares[..., 0] + squares[..., 1])


def bed_law(strings) -> tuple:
    """The string bed's law for the kernels (:attr:`racket.solver.layout.BallModel.bed`):
    its stretch [1/m^2], loss [-] and moving mass [kg].  The unhappy ball's kernels take a
    linear, lossless, massless bed instead (all 0), whose return mapping takes the strings
    as a linear spring (:func:`racket.solver.driver.impact` says so when it drops a bed's
    stretch, loss or mass).

    Parameters
    ----------
    strings : racket.StringBed
        The racket's string bed.
    """
    return (strings.stretch, strings.loss, strings.moving_mass)


@lru_cache(maxsize=64)
def _ball_model(dt: float, mass: float, law: tuple, bed: tuple) -> layout.BallModel:
    """The ball for the kernels: a free mass [kg], exact for a force going linearly from F0
    to F1 over the step ``dt`` [s], u += ud dt - (F0 / 3 + F1 / 6) dt**2 / m and ud -= (F0
    + F1) dt / (2 m); its law (code, numbers) and the bed's (:func:`bed_law`).  Kept: the
    same for every impact at one closing speed.  Every Stepper at that step is given the same
    arrays, which the kernels only read; nothing may write to them (read-only arrays would
    have the kernels compiled again for that type).
    """
    return layout.BallModel(
        trans=np.array([[1.0, dt], [0.0, 1.0]]),
        g0=np.array([dt * dt / 3.0, dt / 2.0]) / -mass,
        g1=np.array([dt * dt / 6.0, dt / 2.0]) / -mass,
        law=law[0],
        params=np.array(law[1], dtype=float),
        bed=np.array(bed, dtype=float),
    )
