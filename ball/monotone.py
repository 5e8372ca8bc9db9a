"""Time integration of a head-on contact between monotone force laws (Eqs. 8-11).

With a monotone law on each side (or a ball on the wall) the two bodies obey, in the
relative coordinate z = x - y - D = X + Y,

    mu d2z/dt2 = -F(z),      F from the laws in series (:func:`ball.series.series_force`),

with mu the reduced mass (the ball's mass against the wall).  Both bodies start to decelerate
together, so z rises to a single maximum: the laws load until dz/dt = 0 and unload after.
The two phases are integrated separately with an 8th-order Runge-Kutta method (DOP853) at
tight tolerance; each ends on an event located to machine precision (dz/dt = 0, then the
force returning to zero), so the switch between the smooth branches is exact.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from ball.contact import RelativeContact
from ball.laws import MonotoneLaw
from ball.series import series_compression, series_force, series_solver

_RTOL = 1e-12
_STEEP = 1e-6
"""Unloading travels below this fraction of the largest compression are not time-stepped."""


def monotone_contact(
    law_a: MonotoneLaw,
    law_b: MonotoneLaw | None,
    mu: float,
    closing_speed: float,
    samples: int = 400,
) -> RelativeContact:
    """Integrate one contact from first touch until the force returns to zero.

    Parameters
    ----------
    law_a, law_b : MonotoneLaw
        The two force laws; ``law_b`` is None for the rigid wall.
    mu : float
        Reduced mass [kg].
    closing_speed : float
        Approach speed at first touch [m/s], > 0.
    samples : int
        History points per phase.
    """
    from scipy.integrate import solve_ivp  # scipy loads on first use (import time)

    laws: Sequence[MonotoneLaw] = [law_a] if law_b is None else [law_a, law_b]
    energy = 0.5 * mu * closing_speed**2
    if energy > sum(law.storable for law in laws):
        raise ValueError(
            f"the collision's energy ({energy:g} J) is more than the balls' force laws can "
            "store short of their limits (a stiffening ball squashed flat): slower, please"
        )
    # Time and length scales for the tolerances: the secant stiffness of the loading curve
    # at a force of 1 N sets the contact period.
    f_ref = 1.0
    k_ref = f_ref / float(series_compression(laws, f_ref, f_ref))
    t_ref = np.pi * np.sqrt(mu / k_ref)
    atol = [1e-14 * closing_speed * t_ref, 1e-14 * closing_speed]

    last = [0.0]  # the last force: the next evaluation's starting guess
    loaded = series_solver(laws, 0.0)

    def loading(_t, s):
        last[0] = loaded(s[0], last[0])
        return [s[1], -last[0] / mu]

    def turning(_t, s):
        return s[1]

    turning.terminal, turning.direction = True, -1
    # The integration span is an upper bound only; the events end each phase.
    t_max = 1e4 * t_ref

    def phase(rhs, start: float, state: list, event, what: str):
        """One phase, DOP853 from ``start`` [s] and ``state`` (z [m], z' [m/s]) until
        ``event``; RuntimeError saying ``what`` did not happen if it never comes.
        """
        sol = solve_ivp(rhs, (start, start + t_max), state, method="DOP853", rtol=_RTOL,
                        atol=atol, events=event, dense_output=True)  # fmt: skip
        if sol.status != 1:
            raise RuntimeError(f"contact did not {what}: {sol.message}")
        return sol

    ph1 = phase(loading, 0.0, [0.0, closing_speed], turning, "reach maximum compression")
    t1, (z_max, _) = ph1.t_events[0][0], ph1.y_events[0][0]
    f_max = float(series_force(laws, z_max, 0.0))
    z_open = float(series_compression(laws, 0.0, f_max))

    phases = [(ph1, 0.0, t1, loaded)]
    t_end, speed_end = t1, 0.0
    travel = z_max - z_open
    if travel > _STEEP * z_max:
        last[0] = f_max
        unloaded = series_solver(laws, f_max)

        def unloading(_t, s):
            last[0] = unloaded(s[0], last[0])
            return [s[1], -last[0] / mu]

        def opened(_t, s):
            return s[0] - z_open

        opened.terminal, opened.direction = True, -1
        ph2 = phase(unloading, t1, [z_max, 0.0], opened, "open")
        t_end, speed_end = ph2.t_events[0][0], ph2.y_events[0][0][1]
        phases.append((ph2, t1, t_end, unloaded))
    # Each phase's history; its forces by its own solver, each from the force before.
    t, v, force = [], [], []
    for sol, ta, tb, solve in phases:
        t.append(np.linspace(ta, tb, samples))
        z_p, v_p = sol.sol(t[-1])
        v.append(v_p)
        force.append(_in_turn(solve, z_p))
    t, v, force = np.concatenate(t), np.concatenate(v), np.concatenate(force)
    if 64 * np.finfo(float).eps * z_max < travel <= _STEEP * z_max:
        # A nearly vertical unloading (tiny e): the contact opens within a sliver of z that
        # time-stepping cannot resolve in floating point.  The unloading branch is elastic,
        # so the separation speed follows from the energy it returns, int F dz (Gauss-Legendre,
        # exact for linear laws); its duration is the quarter period of that sliver.
        nodes, weights = np.polynomial.legendre.leggauss(32)
        returned = (
            0.5
            * travel
            * weights
            @ series_force(laws, z_open + 0.5 * travel * (nodes + 1.0), f_max)
        )
        speed_end = -np.sqrt(2.0 * returned / mu)
        t_end = t1 + 0.5 * np.pi * np.sqrt(mu * travel / f_max)
        t, v = np.append(t, t_end), np.append(v, speed_end)
        force = np.append(force, 0.0)  # z = z_open: the contact is open
    v[-1] = speed_end
    history_fmax = np.where(np.arange(t.size) >= samples, f_max, 0.0)
    branch = np.maximum(force, history_fmax)
    comp_a = law_a.compression(force, branch)
    comp_b = np.zeros_like(force) if law_b is None else law_b.compression(force, branch)
    return RelativeContact(
        t=t,
        force=force,
        compression_a=comp_a,
        compression_b=comp_b,
        closing_speed=v,
        dissipated_a=float(law_a.dissipated(f_max)),
        dissipated_b=0.0 if law_b is None else float(law_b.dissipated(f_max)),
    )


def _in_turn(solve, z: np.ndarray) -> np.ndarray:
    """The force [N] at each total compression of ``z`` [m] by ``solve`` (a
    :func:`~ball.series.series_solver`), in turn, each solve starting from the force before.
    """
    force = np.empty(z.size)
    last = 0.0
    for i, z_i in enumerate(z.tolist()):
        force[i] = last = solve(z_i, last)
    return force
