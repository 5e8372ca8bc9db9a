"""The unhappy ball's Xo, which the collision itself decides (paper Eq. 7): the smallest Xo
per impact for which the contact never pushes the ball past its fold (or a spent ball
again), found by a scan and a refinement (:func:`self_consistent_x_o`) after a rough scan
with fewer steps (:func:`unhappy_x_o`).
"""

from __future__ import annotations

import numpy as np

from ball import Ball
from racket.racket import Racket
from racket.solver import layout
from racket.solver.stepper import CROSS_TOL, Stepper

SCAN_START, SCAN_RATIO, SCAN_MAX, SCAN_DOWN_MAX, REFINE_MAX = 0.7, 1.01, 400, 40, 60
"""The Xo search: start at this fraction of the rigid racket's Xo (halving it, at most
SCAN_DOWN_MAX times, until every impact snaps), step up by this ratio (so a gap in the
non-snapping Xo narrower than 1 % can be missed), at most this many scan and refinement
runs."""

ROUGH_STEPS_DIVISOR, ROUGH_MARGIN = 4, 0.97
"""The Xo search first scans with a quarter of the steps (Xo then differs by about 1e-4
from the full steps'), then scans and refines with the full steps from 3 % below where
that scan stopped: about 25 full runs instead of 55, the same Xo."""


def unhappy_x_o(racket, ball, x, y, speed, swing_speed, pivot, stepper: Stepper):
    """The unhappy ball's Xo [m] per impact of ``stepper``: a rough search with a quarter
    of the steps, then the search itself from just below where that one ended (a scan
    from the rigid racket's guess takes ~35 runs).

    Parameters
    ----------
    racket, x, y, speed, swing_speed, pivot
        As in :class:`~racket.solver.stepper.Stepper`.
    ball : Ball
        The unhappy ball (sine law).
    stepper : Stepper
        The impacts' kernel inputs with the full steps.
    """
    rough_steps = max(50, stepper.steps_per_contact // ROUGH_STEPS_DIVISOR)
    rough = Stepper(racket, ball, x, y, speed, swing_speed, pivot, rough_steps)
    guess = _x_o_guess(racket, ball, x, stepper.closing)
    start = self_consistent_x_o(rough, SCAN_START * guess, refine=False)
    return self_consistent_x_o(stepper, ROUGH_MARGIN * start)


def _x_o_guess(racket: Racket, ball: Ball, x: np.ndarray, closing: float) -> np.ndarray:
    """A first guess of the unhappy ball's Xo [m] per impact: the rigid racket's, the ball
    in series with the strings (Eqs. 12-16 where the strings are softer than pi k0, the
    rigid wall's energy balance otherwise); only a starting point for the scan.
    """
    k0, k_s = ball.law.k0, racket.contact.stiffness
    m2 = racket.effective_mass(x) if racket.support != "clamped-head" else np.inf
    mu = ball.mass * m2 / (ball.mass + m2) if racket.support != "clamped-head" else ball.mass
    if k_s < np.pi * k0:
        return closing / (np.sqrt(k_s / mu) * (1.0 / np.pi + k0 / k_s)) * np.ones(x.size)
    return closing * np.sqrt(np.pi * mu / (4.0 * k0)) * np.ones(x.size)


def self_consistent_x_o(stepper: Stepper, start: np.ndarray, refine: bool = True):
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

    Parameters
    ----------
    stepper : Stepper
        The impacts' kernel inputs.
    start : ndarray
        Xo [m] per impact to start the scan from.
    refine : bool, optional
        Refine after the scan (else the scan's first Xo without a snap is returned).
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
