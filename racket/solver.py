"""Ball impacts on a flexible racket (paper Sec. VII).

:func:`impact` drives the racket's modes with the ball's force law in series with the
string bed, for one impact point or many at once, and splits the racket's motion at the
moment the ball finally leaves (after any re-contact) into its dc part (the rigid-body
modes) and its ac part (the bending modes):

* e_A = V1 / v1, the apparent COR, from the ball's speeds;
* e = (V1 + V2) / v1 with V2 = V_cm + b omega the dc speed of the impact point (Eq. 21),
  V_cm and omega the racket's momentum and angular momentum over its mass and moment of
  inertia (for a free racket, its rigid-body modes);
* e_van_zandt, the same with the whole impact-point speed at separation, vibration
  included (Van Zandt's error, Sec. VII);
* the energy budget: ball and racket kinetic energy, vibration energy per mode, the energy
  lost in the ball and to modal damping, and the residual that shows it closes.

Every outcome is the state at that moment.  The stepping goes on after it, to catch a
re-contact, until the gap exceeds the reach of the remaining vibration; for a hand-held
racket the hand keeps pushing meanwhile, so a later moment would give another momentum,
and another e.

The unhappy ball (sine law, Eq. 7) needs its Xo, the compression at which its force returns
to zero, which the collision itself decides: Xo is the smallest for which the contact never
pushes the ball past its fold (or a spent ball again), found per impact by a scan and a
refinement (:func:`_self_consistent_x_o`).  The impact is *self-consistent* when the ball
then leaves with its compression at Xo; on a vibrating frame near the tip the frame can
unload the ball before it reaches its fold, for every Xo that does not snap.  There is then
no self-consistent Xo; the smallest that does not snap is kept (it leaves the ball closest
to Xo: the compression at separation falls further below Xo as Xo grows), the impact is
flagged (``Impact.self_consistent``) and a warning says how many are.
"""

from __future__ import annotations

import contextlib
import os
import sys
import threading
import warnings
from concurrent.futures import ThreadPoolExecutor, wait
from contextlib import contextmanager
from dataclasses import dataclass

import numpy as np

from ball import Ball, SineLaw, warn_if_squashed
from common.checks import finite, finite_array, in_range, shown
from common.checks import speed as check_speed
from racket import layout
from racket.racket import Racket
from racket.swing import PIVOT_RANGE, check_swung_support

COMPILE_SECONDS = 15
"""About how long numba takes to compile the kernel on a 2-core machine (measured 12-15 s)."""

DEFAULT_STEPS_PER_CONTACT = 300
"""Time steps per estimated contact time for the monotone ball laws.  With the static
correction for the modes left out and the contact's opening placed within its step, e is
within 1.2e-5 of a 64-mode, 9600-step solution at every point of the paper racket (free and
hand-held; linear, elastic and power-law balls at 20 m/s), and the error falls as dt**2
(``benchmarks/accuracy.py`` measures the frontier of steps and modes)."""

SINE_STEPS_PER_CONTACT = 600
"""Time steps per estimated contact time for the unhappy ball (sine law), whose fold and
opening are not placed within their step: e within 1.6e-5 of a 2400-step solution on the
paper racket (10.3 g and 57 g balls at 10 m/s)."""

FORCE_TOL = 1e-9
"""An unhappy-ball contact that approaches a common speed asymptotically is over when its
force has fallen to this fraction of its peak and the relative speed to this fraction of the
closing speed (so e comes out within 1e-9 of its limit, 0, rather than slightly negative)."""

PIVOT_BEYOND_BUTT = -PIVOT_RANGE[0]
"""Farthest swing pivot beyond the butt [m] (:data:`racket.swing.PIVOT_RANGE`)."""

F1_MIN = 20.0
"""Lowest first bending frequency [Hz] of a frame that the impact solver accepts (at 10 Hz
the paper racket's contact no longer ends within its step budget)."""

CONTACT_TIME_MAX = 0.02
"""Longest contact [s] (ball and strings in series on an immovable frame) the solver
accepts; a tennis ball's lasts 4-5 ms (paper Sec. III).  Above about 40 ms (a ball softer
than about 300 N/m) the frame's vibration over such a long contact is no longer resolved
at the default step and an elastic ball can come out with e = 1.000004."""

CROSS_TOL = 1e-10
"""An unhappy ball crosses its fold when the contact relaxes within this fraction of Xo of
the fold's maximum (the Xo search drives the gap below half of it)."""

SELF_CONSISTENT_TOL = 1e-4
"""An unhappy-ball impact is self-consistent when its compression at separation equals
Xo to this relative tolerance (where the ball crosses its fold it ends within 1e-10 of Xo;
without a fold, strings stiffer than pi k0, it approaches Xo only asymptotically and the
stepped contact ends within 7e-5 of it)."""

SCAN_START, SCAN_RATIO, SCAN_MAX, SCAN_DOWN_MAX, REFINE_MAX = 0.7, 1.01, 400, 40, 60
"""The Xo search: start at this fraction of the rigid racket's Xo (halving it, at most
SCAN_DOWN_MAX times, until every impact snaps), step up by this ratio (so a gap in the
non-snapping Xo narrower than 1 % can be missed), at most this many scan and refinement
runs."""

ROUGH_STEPS_DIVISOR, ROUGH_MARGIN = 4, 0.97
"""The Xo search first scans with a quarter of the steps (Xo then differs by about 1e-4
from the full steps'), then scans and refines with the full steps from 3 % below where
that scan stopped: about 25 full runs instead of 55, the same Xo."""


CHUNK_POINTS = 4096
"""Impacts run together at most (without histories): bounds the memory of a call to about
10 MB however many positions it is given."""

IMPACTS_PER_THREAD = 8
"""Smallest share of a batch's impacts worth a thread of its own (one impact takes about
20 us; handing work to a thread about as long)."""


_HISTORY_ROWS = {
    "force": layout.H_FORCE,
    "ball_compression": layout.H_BALL_COMP,
    "string_deflection": layout.H_STRING,
    "ball_velocity": layout.H_BALL_VEL,
    "point_velocity": layout.H_POINT_VEL,
    "point_velocity_dc_history": layout.H_POINT_VEL_DC,
}
"""Impact attribute of each history row of the kernel."""


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
    k = ball.law.secant_stiffness(ball.mass, closing_speed)
    k_series = 1.0 / (1.0 / k + 1.0 / string_stiffness)
    return np.pi * np.sqrt(ball.mass / k_series)


@dataclass(frozen=True)
class Impact:
    """Outcome of :func:`impact`; every attribute is an array over the impact positions
    (a float, or 1-D history, when a single position was given).

    Attributes
    ----------
    position : float or ndarray
        Impact point [m from the tip].
    position_from_butt : float or ndarray
        The same [m from the butt], as spec sheets count.
    offset : float or ndarray or None
        Impact point's distance from the long axis [m, + towards 3 o'clock], or None for
        impacts on the axis without the roll and torsion modes (the paper's 1-D model).
    speed : float
        Ball speed towards the strings before impact [m/s].
    swing_speed : float or ndarray
        Racket (impact-point) speed towards the ball before impact [m/s].
    e : float or ndarray
        COR [-] from the dc (rigid-body) motion, Eq. 21 / Eq. 1.
    e_A : float or ndarray
        Apparent COR V1 / v1 [-] of a racket at rest; for a swung racket (impact point at v2
        towards the ball) the same in the frame of the swing, (V1 - v2) / (v1 + v2), which
        equals the racket at rest's at the closing speed v1 + v2 (the swing superposes).
    e_van_zandt : float or ndarray
        COR [-] with the vibration at separation wrongly included (Sec. VII).
    effective_mass : float or ndarray
        Racket effective mass at the impact point [kg] (Eq. 20, with y^2 / I_roll off the
        axis; for the free racket, also quoted for a hand-held one; inf clamped).
    ball_rebound : float or ndarray
        V1, the ball's speed after, away from the strings [m/s] (its exit speed).
    v_cm : float or ndarray
        Racket centre-of-mass velocity after [m/s] (along the ball's incoming path).
    omega : float or ndarray
        Racket angular velocity after [rad/s]; the point at x moves at v_cm + (x_cm - x)
        omega.
    roll_rate : float or ndarray
        Racket's angular velocity about its long axis after [rad/s] (the twist rate; the
        point at offset y moves at y roll_rate more; 0 without offsets).
    point_velocity_dc : float or ndarray
        V2 = v_cm + b omega (+ y roll_rate), dc velocity of the impact point after [m/s]
        (Eq. 21).
    contact_time : float or ndarray
        Duration of the contact [s].
    peak_force : float or ndarray
        Largest contact force [N].
    vibration_energy : float or ndarray
        The racket's mechanical energy beyond its rigid-body kinetic energy when the ball
        leaves [J]: the bending (and torsion) modes, and for a hand-held racket also the
        energy in the hand's spring.
    mode_energy : ndarray
        (..., n_bending) energy of each free-free bending mode when the ball leaves [J].
    energy_initial, ball_energy, racket_energy, ball_loss, damping_loss, energy_residual : \
float or ndarray
        Energy budget [J]: initial kinetic energy = ball_energy + racket_energy (rigid
        body) + vibration_energy + ball_loss + damping_loss + energy_residual; the residual
        is the integration error.
    closing_energy : float or ndarray
        The ball's kinetic energy in the frame of the racket's swing, m (v1 + v2)^2 / 2 [J]
        (energy_initial for a racket at rest): what the impact has to share out.
    x_o : float or ndarray
        The unhappy ball's Xo [m], the smallest that does not snap (NaN for other laws).
    self_consistent : bool or ndarray
        The unhappy ball's compression at separation equals Xo (to
        ``SELF_CONSISTENT_TOL``) [-]; always True for other laws.
    recontacts : int or ndarray
        Times the frame caught the ball again after it had left [-].
    t : ndarray or None
        (T,) time since first touch [s] of the histories (None unless ``histories``).
    force, ball_compression, string_deflection, ball_velocity, point_velocity, \
point_velocity_dc_history : ndarray or None
        (..., T) histories [N, m, m, m/s, m/s, m/s] (NaN after the ball has left; None
        unless ``histories``); the impact point's velocity is split into its dc part and
        the rest (ac = total - dc).
    """

    position: np.ndarray
    position_from_butt: np.ndarray
    offset: np.ndarray | None
    speed: float
    swing_speed: float
    e: np.ndarray
    e_A: np.ndarray
    e_van_zandt: np.ndarray
    effective_mass: np.ndarray
    ball_rebound: np.ndarray
    v_cm: np.ndarray
    omega: np.ndarray
    roll_rate: np.ndarray
    point_velocity_dc: np.ndarray
    contact_time: np.ndarray
    peak_force: np.ndarray
    vibration_energy: np.ndarray
    mode_energy: np.ndarray
    energy_initial: np.ndarray
    closing_energy: np.ndarray
    ball_energy: np.ndarray
    racket_energy: np.ndarray
    ball_loss: np.ndarray
    damping_loss: np.ndarray
    energy_residual: np.ndarray
    x_o: np.ndarray
    self_consistent: np.ndarray
    recontacts: np.ndarray
    t: np.ndarray
    force: np.ndarray
    ball_compression: np.ndarray
    string_deflection: np.ndarray
    ball_velocity: np.ndarray
    point_velocity: np.ndarray
    point_velocity_dc_history: np.ndarray

    @property
    def point_velocity_ac_history(self) -> np.ndarray:
        """Ac (vibration) part of the impact point's velocity against time [m/s] (None
        without histories).
        """
        if self.point_velocity is None:
            return None
        return self.point_velocity - self.point_velocity_dc_history


def _swing_velocities(modes, position, swing_speed, pivot):
    """Rigid-mode velocities (P, 2) of a racket whose impact point moves at -swing_speed
    (P,).
    """
    if not np.any(swing_speed):
        return np.zeros((position.size, 2))
    if pivot is None:  # pure translation
        v_cm = np.full(position.size, -swing_speed)
        spin = np.zeros(position.size)
    else:  # rotation about the pivot: v(x) = -swing (pivot - x) / (pivot - position)
        v_cm = -swing_speed * (pivot - modes.center_of_mass) / (pivot - position)
        spin = -swing_speed / (pivot - position)
    return np.column_stack([v_cm * np.sqrt(modes.mass), spin * np.sqrt(modes.inertia_cm)])


def impact(
    racket: Racket,
    ball: Ball,
    position,
    speed: float,
    *,
    offset=None,
    swing_speed=0.0,
    pivot: float | None = None,
    steps_per_contact: int | None = None,
    watch_after: float = 0.0,
    histories: bool = False,
) -> Impact:
    """A ball hits the racket head-on at ``position``, normal to the string plane.

    Parameters
    ----------
    racket : Racket
        The racket, initially still unless ``swing_speed`` > 0.
    ball : Ball
        The ball (any law of :mod:`ball`, the unhappy SineLaw included).
    position : float or array_like
        Impact point(s) [m from the tip], on the strings; an array runs all impacts together.
    speed : float
        Ball speed towards the strings [m/s], 0 or in [0.001, 300] (> 0 unless the racket
        is swung).
    offset : float or array_like, optional
        Distance of the impact point(s) from the racket's long axis [m, + towards 3
        o'clock], broadcast with ``position`` (to at most one dimension); the point must
        lie on the elliptical string bed.  Given (even 0), the racket's roll and torsion
        modes join the bending ones (the beam's roll inertia must be modelled, as on a
        spec-sheet racket); None (default): impacts on the long axis, bending only.
    swing_speed : float or array_like
        Speed [m/s] of the impact point towards the ball from the racket's rigid-body
        motion (a swing), 0 or in [0.001, 300]; 0 for a racket at rest.  An array gives each
        impact point its own (broadcast with the points), e.g. from one swing about a pivot
        (:meth:`racket.Swing.point_speeds`).
    pivot : float, optional
        The swing's instantaneous centre of rotation [m from the tip], beyond every impact
        point and at most 1 m beyond the butt (e.g. the wrist, 5 cm beyond it); None for
        pure translation.
    steps_per_contact : int, optional
        Time steps per estimated contact time, in [50, 100000]; default
        ``DEFAULT_STEPS_PER_CONTACT`` (300), ``SINE_STEPS_PER_CONTACT`` (600) for the
        unhappy ball.
    watch_after : float
        Extra time [s], in [0, 1], to keep stepping after the solver has decided that the
        ball has left for good, watching for another contact; the outcome does not depend
        on it unless that decision was wrong.
    histories : bool
        Also return the histories (force, compressions, velocities against time; the
        impacts then run twice, the second time recording); None otherwise.

    Returns
    -------
    Impact

    Raises
    ------
    ValueError
        For an input out of its range, a frame whose first bending (or, off the axis,
        torsion) mode is below ``F1_MIN`` (20 Hz), or a ball and strings so soft that the
        contact would last more than ``CONTACT_TIME_MAX`` (20 ms).

    References
    ----------
    .. [1] R. Cross, "The coefficient of restitution for collisions of happy balls, unhappy
       balls, and tennis balls", Am. J. Phys. 68, 1025-1031 (2000),
       doi:10.1119/1.1285945.

    Examples
    --------
    >>> from racket import paper_racket, tennis_ball
    >>> r = impact(paper_racket(), tennis_ball(), 0.16, 10.0)  # the string centre
    >>> round(r.e, 3), round(r.e_A, 3)
    (0.887, 0.442)
    """
    if not isinstance(racket, Racket):
        raise ValueError(f"racket must be a Racket, got {racket!r}")
    if not isinstance(ball, Ball):
        raise ValueError(f"ball must be a Ball, got {ball!r}")
    scalar = np.ndim(position) == 0 and np.ndim(offset) == 0
    x, y = racket.check_points(position, offset)
    speed = check_speed("speed", speed, allow_zero=True)
    scalar = scalar and np.ndim(swing_speed) == 0
    swing = _swing_speeds(swing_speed, x.size)
    closing = speed + swing
    if np.any(closing == 0.0):
        raise ValueError("speed must be > 0 m/s (or the racket swung, swing_speed > 0), got 0")
    if pivot is not None:
        pivot = finite("pivot", pivot, "m from the tip")
        reach = racket.beam.length + PIVOT_BEYOND_BUTT
        if not x.max() < pivot <= reach:
            raise ValueError(
                f"pivot must lie beyond the impact points and at most {PIVOT_BEYOND_BUTT:g} m "
                f"beyond the butt, in ({x.max():g}, {reach:g}] m from the tip, got {shown(pivot)}"
            )
    if steps_per_contact is None:
        sine = isinstance(ball.law, SineLaw)
        steps_per_contact = SINE_STEPS_PER_CONTACT if sine else DEFAULT_STEPS_PER_CONTACT
    steps_per_contact = int(in_range("steps_per_contact", steps_per_contact, 50, 100_000))
    watch_after = in_range("watch_after", watch_after, 0.0, 1.0, "s")
    if np.any(swing):
        check_swung_support(racket.support)
    f1 = racket.beam.modes.frequencies[0] if racket.beam.modes.count > 2 else np.inf
    if f1 < F1_MIN:
        raise ValueError(
            f"the frame's first bending frequency must be >= {F1_MIN:g} Hz for an impact, "
            f"got {f1:.4g} Hz"
        )
    roll = racket.beam.roll_modes if y is not None else None
    if roll is not None and roll.count > 1 and roll.frequencies[0] < F1_MIN:
        raise ValueError(
            f"the frame's first torsion frequency must be >= {F1_MIN:g} Hz for an impact off "
            f"the axis, got {roll.frequencies[0]:.4g} Hz"
        )
    # One time step per closing speed (it sets the contact time of a non-linear ball), so
    # that each impact's result depends on its own inputs only; a linear ball has one.
    speeds, group = np.unique(closing, return_inverse=True)
    scales = np.array([contact_time_scale(ball, racket.strings.stiffness, c) for c in speeds])
    if scales.max() > CONTACT_TIME_MAX:
        slow = speeds[np.argmax(scales)]
        raise ValueError(
            f"the ball and strings are too soft: their contact would last about "
            f"{1e3 * scales.max():.3g} ms, and racket-impact resolves contacts up to "
            f"{1e3 * CONTACT_TIME_MAX:g} ms (ball stiffness "
            f"{ball.law.secant_stiffness(ball.mass, slow):.3g} N/m, strings "
            f"{racket.strings.stiffness:.3g} N/m)"
        )
    _, step_group = np.unique(scales[group], return_inverse=True)
    batches = [np.flatnonzero(step_group == g) for g in range(step_group.max() + 1)]
    if histories and len(batches) > 1:
        raise ValueError(
            "histories need one time step for all impacts: give them one closing speed "
            "(ball speed + swing speed), or a ball whose contact time does not depend on it"
        )
    if not histories:  # in chunks: the kernel's inputs take about 1.6 kB per impact
        batches = [b[i : i + CHUNK_POINTS] for b in batches for i in range(0, b.size, CHUNK_POINTS)]
    run = (racket, ball, speed, pivot, steps_per_contact, watch_after, histories)
    with _one_blas_thread() if x.size > IMPACTS_PER_THREAD else contextlib.nullcontext():
        parts = [_solve(x[b], None if y is None else y[b], swing[b], *run) for b in batches]
    fields = parts[0][0]
    if len(parts) > 1:
        back = np.argsort(np.concatenate(batches))
        fields = {
            k: None if v is None else np.concatenate([p[0][k] for p in parts])[back]
            for k, v in fields.items()
        }
    squashed = fields.pop("compression")
    self_consistent = fields["self_consistent"]
    if not np.all(self_consistent):
        warnings.warn(
            f"{np.count_nonzero(~self_consistent)} of {x.size} unhappy-ball impacts "
            f"(first at {x[~self_consistent][0]:g} m from the tip) have no self-consistent "
            "Xo: the ball leaves before its compression reaches Xo (see Impact."
            "self_consistent)",
            stacklevel=2,
        )
    warn_if_squashed(ball, squashed)
    if scalar:
        fields = {
            k: (v if v is None else v[0] if v.ndim > 1 else v[0].item()) for k, v in fields.items()
        }
    return Impact(speed=speed, t=parts[0][1], **fields)


def _swing_speeds(swing_speed, count: int) -> np.ndarray:
    """``swing_speed`` as one value per impact point (P,), each 0 or a speed in range."""
    values = finite_array("swing_speed", swing_speed, "m/s")
    if values.ndim > 1:
        raise ValueError(
            f"swing_speed must be a number or one per impact point [m/s], got an array of "
            f"shape {values.shape}"
        )
    for v in np.unique(values):
        check_speed("swing_speed", v, allow_zero=True)
    try:
        return np.broadcast_to(values, (count,)).astype(float)
    except ValueError:
        raise ValueError(
            f"swing_speed must be one value or one per impact point ({count}), got {values.size}"
        ) from None


def _solve(
    x, y, swing_speed, racket, ball, speed, pivot, steps_per_contact, watch_after, histories
):
    """:func:`impact` at the points ``x`` (offsets ``y`` or None) once its inputs are
    checked: the Impact's fields (and the ball's largest compression, ``compression``) and
    the histories' times.
    """
    stepper = _Stepper(racket, ball, x, y, speed, swing_speed, pivot, steps_per_contact)
    code = stepper.code
    x_o = np.full(x.size, np.nan)
    if code == layout.SINE:
        # A rough search with a quarter of the steps, then the search itself from just
        # below where that one ended (a scan from the rigid racket's guess takes ~35 runs).
        rough_steps = max(50, steps_per_contact // ROUGH_STEPS_DIVISOR)
        rough = _Stepper(racket, ball, x, y, speed, swing_speed, pivot, rough_steps)
        guess = _x_o_guess(racket, ball, x, stepper.closing)
        start = _self_consistent_x_o(rough, SCAN_START * guess, refine=False)
        x_o = _self_consistent_x_o(stepper, ROUGH_MARGIN * start)
    extra_steps = round(watch_after / stepper.dt)
    out_ball, out_state, summary, _ = stepper.run(x_o, extra_steps=extra_steps)
    if not np.all(summary[:, layout.ENDED]):
        bad = x[summary[:, layout.ENDED] == 0][0]
        raise RuntimeError(
            f"the impact at {bad:g} m from the tip had not ended after "
            f"{stepper.max_steps * stepper.dt:.3g} s"
        )
    closing, dt, modes, system = stepper.closing, stepper.dt, stepper.modes, stepper.system
    n = system.count

    # dc part (rigid-body motion) and ac part (the rest) when the ball has left.
    ball_after = out_ball[:, 1]
    q, qd = system.modal_state(out_state)
    rigid_qd = qd[:, list(system.rigid)] if n else np.zeros((x.size, 2))
    v_cm = rigid_qd[:, 0] / np.sqrt(modes.mass)
    omega = rigid_qd[:, 1] / np.sqrt(modes.inertia_cm)
    v2_dc = v_cm + (modes.center_of_mass - x) * omega  # V = V_cm + b omega (Fig. 5)
    roll_rate = np.zeros(x.size)
    if stepper.face and n:  # the roll: y times its angular velocity
        roll_rate = rigid_qd[:, 2] / np.sqrt(racket.beam.roll_modes.roll_inertia)
        v2_dc = v2_dc + y * roll_rate
    v2_total = np.sum(stepper.phi * qd, axis=1)
    nb = min(n, modes.count)  # the bending coordinates come first
    mode_energy = 0.5 * (qd[:, 2:nb] ** 2 + (modes.omega[2:nb] * q[:, 2:nb]) ** 2)
    racket_energy = 0.5 * np.sum(rigid_qd**2, axis=1)
    mechanical = 0.5 * np.sum(qd**2 + (q @ system.stiffness) * q, axis=1)
    vibration = mechanical - racket_energy

    energy_initial = 0.5 * ball.mass * speed**2 + 0.5 * np.sum(stepper.swing_qd**2, axis=1)
    ball_energy = 0.5 * ball.mass * ball_after**2
    if code == layout.SINE:
        ball_loss = summary[:, layout.SINE_WORK]  # X never decreases: all work on it is lost
        self_consistent = np.abs(summary[:, layout.X_END] - x_o) <= SELF_CONSISTENT_TOL * x_o
    else:
        ball_loss = ball.law.dissipated(summary[:, layout.F_PEAK])
        self_consistent = np.ones(x.size, dtype=bool)
    peak = summary[:, layout.F_PEAK]
    damping_loss = summary[:, layout.DAMPING_LOSS]
    residual = energy_initial - (ball_energy + racket_energy + vibration + ball_loss + damping_loss)

    steps = np.rint(summary[:, layout.T_END] / dt).astype(int)
    used = int(steps.max()) + 1
    history = dict.fromkeys(_HISTORY_ROWS)
    if histories:
        hist = stepper.run(x_o, extra_steps=extra_steps, history_steps=used)[3]
        hist[:, np.arange(used)[None, :] > steps[:, None]] = np.nan  # after the ball left
        history = {name: hist[row] for name, row in _HISTORY_ROWS.items()}

    e_a = (-ball_after - (closing - speed)) / closing  # (V1 - v2) / (v1 + v2)
    m_eff = np.full(x.size, np.inf)
    if n:
        m_eff = racket.beam.effective_mass(x, y if stepper.face else None)
    fields = dict(
        position=x,
        position_from_butt=racket.beam.length - x,
        offset=y,
        swing_speed=np.array(stepper.closing - speed),
        e=(v2_dc - ball_after) / closing,
        e_A=e_a,
        e_van_zandt=(v2_total - ball_after) / closing,
        effective_mass=m_eff,
        ball_rebound=-ball_after,
        v_cm=v_cm,
        omega=omega,
        roll_rate=roll_rate,
        point_velocity_dc=v2_dc,
        contact_time=summary[:, layout.T_CONTACT],
        peak_force=summary[:, layout.F_PEAK],
        vibration_energy=vibration,
        mode_energy=mode_energy,
        energy_initial=energy_initial,
        closing_energy=0.5 * ball.mass * closing**2,
        ball_energy=ball_energy,
        racket_energy=racket_energy,
        ball_loss=np.asarray(ball_loss, dtype=float),
        damping_loss=damping_loss,
        energy_residual=residual,
        x_o=x_o,
        self_consistent=self_consistent,
        recontacts=summary[:, layout.RECONTACTS].astype(int),
        compression=x_o if code == layout.SINE else ball.law.compression(peak, peak),
        **history,
    )
    return fields, np.arange(used) * dt if histories else None


class _Stepper:
    """The kernel's inputs for one racket, ball and set of impact points, prepared once and
    run for any Xo (see :func:`racket.kernel.run_impacts`).
    """

    def __init__(self, racket, ball, x, y, speed, swing_speed, pivot, steps_per_contact):
        # The step follows from the bed's stiffest spot, whatever the points (the shortest
        # contact on it), and from the closing speed, the same for all (see impact).
        swing_speed = np.broadcast_to(np.asarray(swing_speed, dtype=float), x.shape)
        self.closing = speed + swing_speed
        self.dt = contact_time_scale(ball, racket.strings.stiffest, self.closing[0])
        self.dt /= steps_per_contact
        self.max_steps = 12 * steps_per_contact
        law = getattr(ball.law, "kernel_law", None)
        if law is None:
            raise ValueError(f"ball law {ball.law!r} is not supported on a racket")
        self.code = law[0]
        self.modes = modes = racket.beam.modes
        system, phi, self.face = racket.point_dynamics(x, y)
        self.system, self.phi = system, phi
        self.n = n = system.count
        trans, g0, g1 = system.step(self.dt)
        out_d, out_v, out_dc = system.outputs(phi)
        self.swing_qd = _swing_velocities(modes, x, swing_speed, pivot)
        z0 = np.zeros((x.size, 2 * n))
        if np.any(swing_speed):
            z0[:, n : n + 2] = self.swing_qd
        self.position = x
        inv_ks = 1.0 / racket.strings.stiffness_at(x, 0.0 if y is None else y)
        series = inv_ks.copy()
        if n:  # static correction: the bending modes left out respond quasi-statically
            count = modes.count  # the shapes phi already holds, spared computing again
            shapes = phi[:, :count].T if phi.shape[1] >= count else None
            series += racket.beam.residual_flexibility(x, shapes)
        if self.face and n:  # and the torsion modes left out
            series += racket.beam.roll_modes.residual_flexibility(x, y)
        self.points = layout.Points(
            unit=system.inputs(phi),
            out_d=out_d,
            out_v=out_v,
            out_dc=out_dc,
            reach_w=np.linalg.norm(out_d, axis=2) * ~system.dc,
            series=series,
            inv_ks=inv_ks,
            ball_velocity=np.full(x.size, speed),
            state0=system.state(z0),
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
        # The ball, a free mass: exact for a force going linearly from F0 to F1 over dt,
        # u += ud dt - (F0 / 3 + F1 / 6) dt**2 / m and ud -= (F0 + F1) dt / (2 m).
        dt = self.dt
        self.ball = layout.BallModel(
            trans=np.array([[1.0, dt], [0.0, 1.0]]),
            g0=np.array([dt * dt / 3.0, dt / 2.0]) / -ball.mass,
            g1=np.array([dt * dt / 6.0, dt / 2.0]) / -ball.mass,
            law=law[0],
            params=np.array(law[1], dtype=float),
        )

    def run(self, x_o, subset=None, stop_on_snap=False, extra_steps=0, history_steps=0):
        """Run the impacts (all, or those indexed by ``subset``) with Xo ``x_o`` [m] per
        impact run; returns the kernel's :class:`~racket.layout.Outputs` (ball, block
        states, summary, history), the history over the first ``history_steps`` steps
        (none if 0).
        """
        points = self.points
        if subset is not None:
            points = layout.Points(*(np.ascontiguousarray(v[subset]) for v in points))
        points = points._replace(x_o=np.ascontiguousarray(x_o, dtype=float))
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
                (layout.N_HISTORY, count, history_steps) if history_steps else (1, 1, 1)
            ),
        )
        from racket import kernel  # numba loads on first use (import time)

        args = (self.frame, points, self.ball, controls, out)
        with _compile_notice(kernel.run_impacts):
            _run_on_threads(kernel.run_impacts, args, count)
        return out


def load_kernel() -> None:
    """Load the compiled kernel now (numba compiles it on a machine's first run, 12-15 s,
    and caches it on disk), by running one impact of the paper's racket; a program that
    shows progress (the interactive page, the test suite) calls it before its first impact.
    """
    from racket.presets import paper_racket, tennis_ball

    impact(paper_racket(), tennis_ball(), 0.1, 10.0)


_BLAS = []  # the threadpoolctl controller, made on first use


@contextmanager
def _one_blas_thread():
    """Keep BLAS (numpy's small matrix products while preparing and reading the kernel's
    arrays) to one thread: its worker threads would compete with the kernel's for the
    cores.
    """
    if not _BLAS:
        from threadpoolctl import ThreadpoolController

        _BLAS.append(ThreadpoolController())
    with _BLAS[0].limit(limits=1, user_api="blas"):
        yield


def _run_on_threads(run, args, count: int):
    """Run ``run(*args, start, stop, step)`` (the kernel, which releases the GIL) over the
    ``count`` impacts: on this thread for fewer than two threads' worth
    (``IMPACTS_PER_THREAD`` each), else on T threads (this one and T - 1 of the kernel's
    pool), thread t taking impacts t, t + T, t + 2T, ...: neighbouring impacts take about
    as long, so the threads finish together, each with one call.
    """
    size = _pool_size()
    threads = min(size, count // IMPACTS_PER_THREAD)
    if threads < 2:
        run(*args, 0, count, 1)
        return
    pool = _POOL.get(size)
    if pool is None:
        pool = _POOL[size] = ThreadPoolExecutor(size - 1, "racket-impact-kernel")
    helpers = [pool.submit(run, *args, t, count, threads) for t in range(1, threads)]
    try:
        run(*args, 0, count, threads)  # this thread works too
    finally:
        wait(helpers)  # none still writes into the outputs when this returns or raises
    for done in helpers:
        done.result()  # re-raises an error of theirs


def _pool_size() -> int:
    """Threads of the kernel's pool: numba's ``NUMBA_NUM_THREADS`` (the cores available, or
    the environment variable).
    """
    from numba import config

    return max(1, config.NUMBA_NUM_THREADS)


_POOL = {}
"""The kernel's thread pool (by its size, should ``NUMBA_NUM_THREADS`` change), made on first
use and kept (starting threads for each call cost about 1 ms); a forked child makes its own
(its parent's threads do not exist in it)."""

os.register_at_fork(after_in_child=_POOL.clear)


@contextmanager
def _compile_notice(function, after: float = 1.0):
    """Say on stderr that ``function`` (a numba dispatcher) is being compiled (once per
    install: the compiled kernel is cached on disk) if its first call of this process takes
    more than ``after`` seconds; loading the cached kernel takes well under a second.
    """
    if id(function) in _READY or getattr(function, "signatures", True):  # compiled / no JIT
        _READY.add(id(function))
        yield
        return
    timer = threading.Timer(
        after,
        lambda: print(
            f"racket-impact: compiling the solver (once, about {COMPILE_SECONDS:g} s)...",
            file=sys.stderr,
            flush=True,
        ),
    )
    timer.start()
    try:
        yield
    finally:
        timer.cancel()


_READY = set()  # ids of the kernels known to be compiled in this process


def _x_o_guess(racket: Racket, ball: Ball, x: np.ndarray, closing: float) -> np.ndarray:
    """A first guess of the unhappy ball's Xo [m] per impact: the rigid racket's, the ball
    in series with the strings (Eqs. 12-16 where the strings are softer than pi k0, the
    rigid wall's energy balance otherwise); only a starting point for the scan.
    """
    k0, k_s = ball.law.k0, racket.strings.stiffness
    m2 = racket.beam.effective_mass(x) if racket.support != "clamped-head" else np.inf
    mu = ball.mass * m2 / (ball.mass + m2) if racket.support != "clamped-head" else ball.mass
    if k_s < np.pi * k0:
        return closing / (np.sqrt(k_s / mu) * (1.0 / np.pi + k0 / k_s)) * np.ones(x.size)
    return closing * np.sqrt(np.pi * mu / (4.0 * k0)) * np.ones(x.size)


def _self_consistent_x_o(stepper: _Stepper, start: np.ndarray, refine: bool = True):
    """Smallest Xo [m] per impact for which the unhappy ball never snaps.

    Too small an Xo lets the contact push the ball past the maximum of X + c F_sine(X),
    or push it again once spent, where it would snap: Xo was not its largest compression.
    On a vibrating frame the set of Xo that do not snap can have gaps, so a bisection on
    "snapped or not" can land on any of its edges.  Instead:

    1. scan Xo upwards from ``start`` (halved until every impact snaps there) in steps of
       ``SCAN_RATIO`` until an impact first runs without a snap (each run stops at its
       first snap); without ``refine``, that Xo is returned;
    2. refine between that Xo and the one before by the Illinois method on the kernel's
       snap residual (the overshoot past the fold, or minus the smallest gap left to it),
       which is continuous in Xo and zero at the smallest Xo that does not snap, until the
       gap is below ``CROSS_TOL`` Xo (the ball then reaches the fold and crosses it) or the
       bracket has shrunk to round-off (an edge where the residual jumps).
    """
    count = start.size
    every = np.arange(count)

    def snaps(x_o, subset):
        summary = stepper.run(x_o, subset, stop_on_snap=True)[2]
        return summary[:, layout.SNAPPED] > 0, summary[:, layout.SNAP_RESIDUAL]

    # 1. Scan: a start that snaps everywhere, then up until each impact first runs clean.
    lo = np.array(start, dtype=float)
    r_lo = np.empty(count)
    todo = every
    for _ in range(SCAN_DOWN_MAX):
        snapped, r_lo[todo] = snaps(lo[todo], todo)
        lo[todo[~snapped]] *= 0.5
        todo = todo[~snapped]
        if todo.size == 0:
            break
    if todo.size:
        raise RuntimeError(
            f"the unhappy ball does not snap even at Xo = {lo[todo[0]]:.3g} m (impact at "
            f"{stepper.position[todo[0]]:g} m from the tip): no smallest Xo to find"
        )
    hi, r_hi = lo * SCAN_RATIO, np.empty(count)
    todo = every
    for _ in range(SCAN_MAX):
        snapped, r_hi[todo] = snaps(hi[todo], todo)
        up = todo[snapped]
        lo[up], r_lo[up] = hi[up], r_hi[up]
        hi[up] *= SCAN_RATIO
        todo = up
        if todo.size == 0:
            break
    if todo.size:
        raise RuntimeError(
            f"no Xo keeps the unhappy ball from snapping through at {todo.size} impacts"
        )
    if not refine:
        return hi
    # 2. Illinois refinement of the residual's sign change in [lo, hi]; `gap` is the true
    # residual at hi (r_lo and r_hi get halved by the Illinois rule).
    gap = r_hi.copy()
    side = np.zeros(count, dtype=int)
    repeats = np.zeros(count, dtype=int)  # steps in a row that moved the same end
    todo = every[-gap > 0.5 * CROSS_TOL]
    for _ in range(REFINE_MAX):
        if todo.size == 0:
            break
        a, b, ra, rb = lo[todo], hi[todo], r_lo[todo], r_hi[todo]
        mid = b - rb * (b - a) / (rb - ra)
        # Bisect where the secant would leave the bracket or has moved the same end three
        # times running (the residual jumps at an edge: the secant then crawls).
        bad = ~((mid > a) & (mid < b)) | (repeats[todo] >= 3)
        mid[bad] = 0.5 * (a[bad] + b[bad])
        snapped, res = snaps(mid, todo)
        up, down = todo[snapped], todo[~snapped]
        lo[up], r_lo[up] = mid[snapped], res[snapped]
        hi[down], r_hi[down], gap[down] = mid[~snapped], res[~snapped], res[~snapped]
        # Illinois: halve the residual at the end that stays put twice running.
        r_hi[up[side[up] == 1]] *= 0.5
        r_lo[down[side[down] == -1]] *= 0.5
        repeats[up] = np.where(side[up] == 1, repeats[up] + 1, 1)
        repeats[down] = np.where(side[down] == -1, repeats[down] + 1, 1)
        repeats[todo[bad]] = 0
        side[up], side[down] = 1, -1
        done = -gap[todo] <= 0.5 * CROSS_TOL
        done |= hi[todo] - lo[todo] <= 4 * np.finfo(float).eps * hi[todo]
        todo = todo[~done]
    return hi
