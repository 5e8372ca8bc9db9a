"""The string bed's moving mass, as the compiled time-steppers solve it: a third body between
the ball and the frame.

A bed with a mass m_s (:attr:`racket.StringBed.moving_mass`) is a point mass at the impact
point, at q (along the ball's path, as the ball's u), between two contacts: the ball pushes
it with F1 = F_ball(u - q), and it pushes the frame with F2, the bed's law at its deflection
w = q - y (y the frame's point, with the static correction of the modes left out).  The
ball is a free mass stepped exactly for forces varying linearly over the step, as the frame's
blocks are, and the bed mass, which oscillates 8-11 times as fast as the contact, a free mass
stepped with Newmark's beta 1/12 (:data:`BED_MASS_BETA`); at the step's end

    g_ball(F1) + a1 F1 = X0 + h F2          (the ball's compression)
    w_bed(F2) + (h + c_f) F2 = R0 + h F1    (the bed's deflection)

with X0 and R0 what the step would give without either force at its end, h = dt**2 /
(12 m_s), a1 the ball's and the bed mass's step compliance, and c_f the frame's step
compliance plus the modes left out.  Each equation alone rises with its force (the ball's
:func:`racket.solver.ball_kernel.monotone_force`, the bed's :func:`bed_force`); the two are
coupled only through h, some 1e-4 of either compliance at the default step.  One Newton
iteration in the two unknowns solves them together (:func:`massed_forces`), with one sweep of
the two safeguarded scalar solves (the ball's from the bed's force extrapolated, then the
bed's, third order in the step) where it does not settle.  Where the ball's force peaked
within the step, the step is solved again with the ball unloading from that peak
(:func:`peak_top`).

The bed's law is :mod:`racket.solver.bed_kernel`'s, written in u, its deflection on the
loading curve: F(u) = k u (1 + s u**2), and w = u + delta clip(1 - F / F_max, 0, 1), delta
the unloading curve's set-back after the largest force F_max.  Loading (u above its largest)
w = u; unloading, the set-back curve; beyond its set-back (u < 0) the bed pulls back,
losslessly, about the set it took (w = u + delta, F < 0), as a membrane does on either side.
A contact that never loads past F_max retraces its unloading curve, so it loses nothing more.

When the ball leaves within a step, the kernels step the frame's state back to that moment
(as on a massless bed) and keep the bed mass's at the step's end: the bed's force on the two
over the rest of the step cancels in their momentum as one body (the dc motion,
:func:`racket.solver.budget.split`), and a hand's force over it stays out of e, which is then
second order in the step whatever holds the frame.
"""

from __future__ import annotations

import math

from numba import njit

from racket.solver.ball_kernel import (
    NEWTON_SETTLED,
    NEWTON_STEPS,
    _loading,
    ball_compression,
    branch_force,
    monotone_force,
    unloading_exponent,
)
from racket.solver.bed_kernel import deflection, stored
from racket.solver.layout import LINEAR

BED_MEMO_ROWS = 12
"""Rows of a massed bed's memo: the bed's largest force F_max it was made for [N], its
loading deflection u there [m], its set-back delta [m] and its last solution's u [m]; the
ball's largest force it was made for [N], its compression there [m] and its unloading
exponent (NaN until needed); the bed's u a step and two steps before the last [m] (rows 7
and 11) and the ball's force at the last three steps [N] (rows 8-10, the last first), from
which :func:`massed_forces` extrapolates its guesses (and :func:`peak_top` fits the ball's
peak).  A new memo holds -1 in rows 0 and 4,
0 in rows 3 and 7-11."""

BED_MASS_BETA = 1.0 / 12.0
"""Newmark's beta for the bed mass's position (Fox & Goodwin's 1/12): it moves by
dt qd + dt**2 / m_s ((1/2 - beta) F0 + beta F1) over a step, F0 and F1 the net force on it at
the step's start and end, and its velocity by dt (F0 + F1) / (2 m_s).  Any beta is second
order in the step; 1/12 makes the period of an oscillation fourth order (1/6, the step
exact for a force varying linearly, lengthens it by (omega dt)**2 / 24), and the bed mass
oscillates 8-11 times as fast as the contact (module docstring).  Stable for omega dt < 6**0.5
(N. M. Newmark, J. Eng. Mech. Div. ASCE 85, 1959, 67-94; 12**0.5 for 1/6): with the ball's
secant stiffness, about 0.1 on the default racket at 300 steps, 0.4 at 80 m/s; a light bed
mass at few steps and high speed goes beyond it, and :func:`racket.solver.driver.impact` then
steps the impact again finer."""

EARLY_OVER_LATE = (0.5 - BED_MASS_BETA) / BED_MASS_BETA
"""(1/2 - beta) / beta: the step-start force's weight in the bed mass's move, over the
end's (h, :func:`bed_mass_coupling`)."""

_FUSED_STEPS = 8  # the two-unknown Newton iteration settles in two or three from its guesses


@njit(cache=True)
def bed_mass_coupling(dt, mass):
    """The bed mass's move per newton of net force at the step's end, h = beta dt**2 / m_s
    [m/N] (:data:`BED_MASS_BETA`), for the step ``dt`` [s] and the moving mass ``mass`` [kg].
    """
    return BED_MASS_BETA * dt * dt / mass


@njit(cache=True)
def _remember(k, s, loss, f_max, memo, i):
    """Column ``i`` of ``memo`` made for ``f_max``: the loading deflection there and the
    set-back (see :data:`BED_MEMO_ROWS`).
    """
    if memo[0, i] != f_max:
        memo[0, i] = f_max
        u_max = deflection(k, s, f_max)[0] if f_max > 0.0 else 0.0
        memo[1, i] = u_max
        memo[2, i] = 2.0 * loss * stored(k, s, u_max) / f_max if f_max > 0.0 else 0.0


@njit(cache=True)
def bed_force(k, s, loss, comp, z, f_max, guess, memo, i):
    """The bed's force F [N] and loading-curve deflection u [m] where w_bed(F) + comp F = z.

    Parameters
    ----------
    k, s, loss : float
        The bed's stiffness at the point [N/m], stretch [1/m^2] and loss [-].
    comp : float
        Compliance in series with the bed [m/N] (the step's and the frame's).
    z : float
        What the bed's deflection and the series compliance's take up [m].
    f_max : float
        The bed's largest force so far [N].
    guess : float
        The Newton iteration's first guess [m].
    memo : ndarray (BED_MEMO_ROWS, n)
        The beds' memos; column ``i`` is this one's.
    """
    _remember(k, s, loss, f_max, memo, i)
    u_max, delta = memo[1, i], memo[2, i]
    loading = z >= u_max + comp * f_max
    if loading:  # w = u
        lo, hi, set_back, shift = u_max, max(z, u_max), 0.0, 0.0
    elif z >= delta:  # unloading (or reloading) along the set-back curve
        lo, hi, set_back, shift = 0.0, u_max, delta / f_max, delta
    else:  # beyond the set-back: pulling back about it
        lo, hi, set_back, shift = z - delta, 0.0, 0.0, delta
    u = guess if lo < guess < hi else 0.5 * (lo + hi)
    for _ in range(NEWTON_STEPS):
        f = k * u * (1.0 + s * u * u)
        resid = u + shift - set_back * f + comp * f - z
        if resid == 0.0:
            break
        if resid < 0.0:
            lo = u
        else:
            hi = u
        u_new = u - resid / (1.0 + (comp - set_back) * k * (1.0 + 3.0 * s * u * u))
        newton = lo < u_new < hi
        if not newton:
            u_new = 0.5 * (lo + hi)
        # the scale is the bed's largest deflection, as u goes through 0 beyond its set-back
        step, scale = abs(u_new - u), abs(u_new) + u_max
        u = u_new
        if step <= 1e-15 * scale or (newton and step <= NEWTON_SETTLED * scale):
            break
    return k * u * (1.0 + s * u * u), u


@njit(cache=True, inline="always")
def bed_residual(k, s, u, delta, u_max, rate, comp, r0, h, f1):
    """The bed's equation at its loading-curve deflection ``u`` [m] (see the module
    docstring): its force F2 [N] and dF2/du [N/m], and w_bed(u) + comp F2 - r0 - h F1 [m]
    and its slope in u [-], on the loading curve, the set-back one (below ``u_max``, set back
    by ``delta`` - ``rate`` F2) or beyond the set-back (u < 0).  Inlined where it is called,
    so that the lockstep kernel's loop over a tile vectorises with it
    (:mod:`racket.solver.lockstep_massed`).
    """
    uu = u * u
    f2, df2 = k * u * (1.0 + s * uu), k * (1.0 + 3.0 * s * uu)
    w, dw = u, 1.0  # the bed's deflection: loading, set-back curve, beyond the set-back
    if u < 0.0:
        w += delta
    elif u < u_max:
        w += delta - rate * f2
        dw -= rate * df2
    return f2, df2, w + comp * f2 - r0 - h * f1, dw + comp * df2


@njit(cache=True)
def massed_forces(law, params, coef, a1, bed, k, comp, h, x0, r0, f1_max, f2_max, f_before,
                  force, f2_guess, memo, i):  # fmt: skip
    """The ball's force F1 and the bed's F2 [N] at the step's end, and the ball's largest
    force so far [N] (:func:`massed_solve` and :func:`peak_top`); the memo keeps the step's
    unknowns for the next step's guesses.  ``f_before`` and ``force`` are the ball's forces
    at the last two steps' ends [N]; the other parameters are :func:`massed_solve`'s.
    """
    f1, u = massed_solve(law, params, coef, a1, bed, k, comp, h, x0, r0, f1_max, f2_max,
                         2.0 * force - f_before, f2_guess, memo, i)  # fmt: skip
    top = peak_top(memo[10, i], f_before, force, f1, f1_max)
    if top > f1_max:  # the ball unloads from its peak within the step, not from the last end
        f1_max = top
        f1, u = massed_solve(law, params, coef, a1, bed, k, comp, h, x0, r0, f1_max, f2_max,
                             2.0 * force - f_before, f2_guess, memo, i)  # fmt: skip
    s = bed[0]
    memo[11, i], memo[7, i], memo[3, i] = memo[7, i], memo[3, i], u
    memo[10, i], memo[9, i], memo[8, i] = memo[9, i], memo[8, i], f1
    f2 = k * u * (1.0 + s * u * u)
    if f2 > f2_max:  # loading: the memo made for the largest force this sets
        memo[0, i], memo[1, i], memo[2, i] = f2, u, 2.0 * bed[1] * stored(k, s, u) / f2
    return f1, f2, f1_max


@njit(cache=True)
def peak_top(older, before, at, after, peak):
    """The ball's largest force [N] where it peaked within the step: if ``at``, its force
    at the last step's end [N], was the largest so far (``peak``) and the force fell to
    ``after`` at this step's end, the top within the step of the parabola through its
    loading forces ``older``, ``before`` and ``at`` at the three steps' ends before; else
    ``peak``.

    The steps' ends sample a peak low by up to (omega dt)**2 / 8 of the force's swing at
    omega, and a bed's moving mass ripples the ball's force 8-11 times as fast as the
    contact: unloading from the last end's force, the ball's loss (set by its peak) was off
    by up to 1e-4 of the peak, jittering e by 3e-5 from one impact point to the next at the
    default step.  The parabola is the loading curve's (unloading, the ball is stiffer, so
    a parabola through ``after`` overshoots); its top is third order in the step.
    """
    curve = older - 2.0 * before + at
    if not (at >= peak and before <= at and 0.0 < after < at and curve < 0.0):
        return peak
    slope = at - before + 0.5 * curve  # dF/d(step) at ``at``
    t = min(max(-slope / curve, -1.0), 1.0)  # within the last step or this one
    return at + t * (slope + 0.5 * curve * t)


@njit(cache=True)
def massed_solve(law, params, coef, a1, bed, k, comp, h, x0, r0, f1_max, f2_max, guess, f2_guess,
                 memo, i):  # fmt: skip
    """The ball's force F1 [N] and the bed's loading-curve deflection u [m] at the step's end
    (F2 = k u (1 + s u**2); see the module docstring): one Newton iteration in two unknowns.

    Each equation rises with its own unknown on every branch (the ball's compression with
    F1, the bed's deflection with u), and they are coupled through h alone, some 1e-4 of the
    compliances beside it: the Jacobian [[g' + a1, -h F2'], [-h, w' + c F2']] is all but
    diagonal, the iteration converges quadratically from the unknowns extrapolated
    (quadratically) from the last three steps, and each iteration evaluates each law once,
    the two evaluations independent of each other (the processor runs them side by side).
    It ends at a step within :data:`racket.solver.ball_kernel.NEWTON_SETTLED` of both
    unknowns.  Where it does not settle in ``_FUSED_STEPS``, or the ball's force reaches
    zero (the ball touching or leaving the bed), one sweep of the safeguarded scalar solves
    takes over: the ball's from the bed's force extrapolated, then the bed's from the ball's
    (off by h times the extrapolation's error in F2, about 1e-13 m at the default step).

    Parameters
    ----------
    law, params, coef : int, ndarray, tuple
        The ball's law, its numbers and its force coefficients for ``a1``.
    a1 : float
        The ball's and the bed mass's step compliance [m/N].
    bed : ndarray (3,)
        The bed's stretch [1/m^2], loss [-] and moving mass [kg].
    k, comp, h : float
        The bed's stiffness at the point [N/m], the compliance in series with it [m/N] (the
        step's h and the frame's), and h [m/N].
    x0, r0 : float
        The ball's compression and the bed's deflection with neither force at the end [m].
    f1_max, f2_max, guess, f2_guess : float
        The ball's and the bed's largest forces, and the ball's and the bed's forces
        extrapolated from the last two steps [N] (the scalar solves' guesses).
    memo : ndarray (BED_MEMO_ROWS, n)
        The beds' memos (column ``i``).
    """
    s = bed[0]
    _remember(k, s, bed[1], f2_max, memo, i)
    u_max, delta = memo[1, i], memo[2, i]
    rate = delta / f2_max if f2_max > 0.0 else 0.0  # the set-back curve's delta / F_max
    u_guess = 3.0 * (memo[3, i] - memo[7, i]) + memo[11, i]
    f1, u = 3.0 * (memo[8, i] - memo[9, i]) + memo[10, i], u_guess
    for _ in range(_FUSED_STEPS):
        if not f1 > 0.0:
            break
        f2, df2, r2, d2 = bed_residual(k, s, u, delta, u_max, rate, comp, r0, h, f1)
        g, dg = _ball_at(law, params, f1, f1_max, memo, i)
        r1, d1 = g + a1 * f1 - x0 - h * f2, dg + a1
        step1 = -(r1 * d2 + h * df2 * r2) / (d1 * d2 - h * h * df2)
        step2 = (h * step1 - r2) / d2
        f1 += step1
        u += step2
        if abs(step1) <= NEWTON_SETTLED * f1 and abs(step2) <= NEWTON_SETTLED * (abs(u) + u_max):
            break
    else:
        f1 = 0.0  # (not settled: the scalar solves)
    if not f1 > 0.0:
        f1 = _ball_force(law, params, coef, a1, x0 + h * f2_guess, f1_max, guess, memo, i)
        u = bed_force(k, s, bed[1], comp, r0 + h * f1, f2_max, u_guess, memo, i)[1]
    return f1, u


@njit(cache=True)
def _ball_at(law, params, f, f_max, memo, i):
    """The ball's compression [m] at force ``f`` > 0 [N] after the largest ``f_max`` [N], and
    its d/dF [m/N], on the branch it is on: the linear law's lines, a power law's loading
    curve, or its unloading curve from what rows 4-6 of ``memo`` keep for ``f_max``.
    """
    if law == LINEAR:
        k, e2 = params[0], params[1] * params[1]
        if f >= f_max:
            return f / k, 1.0 / k
        return (f_max * (1.0 - e2) + e2 * f) / k, e2 / k
    if f >= f_max:
        return _loading(law, params, f)
    unloading_memo(law, params, f_max, memo, i)
    b = memo[6, i]
    x = memo[5, i] * (f / f_max) ** (1.0 / b)
    return x, x / (b * f)


@njit(cache=True)
def unloading_memo(law, params, f_max, memo, i):
    """Rows 4-6 of column ``i`` of ``memo`` made for the ball's largest force ``f_max`` [N],
    its unloading exponent (row 6) with them (:data:`BED_MEMO_ROWS`); for both kernels.
    """
    _ball_memo(law, params, f_max, memo, i)
    if math.isnan(memo[6, i]):
        memo[6, i] = unloading_exponent(law, params, f_max)


@njit(cache=True)
def _ball_memo(law, params, f_max, memo, i):
    """Rows 4-6 of column ``i`` of ``memo`` made for the ball's largest force ``f_max`` [N]
    (:data:`BED_MEMO_ROWS`).
    """
    if memo[4, i] != f_max:
        memo[4, i] = f_max
        memo[5, i] = _loading(law, params, f_max)[0] if f_max > 0.0 else 0.0
        memo[6, i] = math.nan


@njit(cache=True)
def _ball_force(law, params, coef, a, z, f_max, guess, memo, i):
    """The ball's force solving g_ball(F) + a F = z, as
    :func:`racket.solver.ball_kernel.monotone_force`, keeping what depends on its largest
    force alone in rows 4-6 of column ``i`` of ``memo`` (:data:`BED_MEMO_ROWS`).
    """
    if law == LINEAR:
        return monotone_force(law, params, coef, a, z, f_max, guess)
    _ball_memo(law, params, f_max, memo, i)
    switch = memo[5, i] + a * f_max
    if math.isnan(memo[6, i]) and 0.0 < z < switch:  # unloading
        memo[6, i] = unloading_exponent(law, params, f_max)
    f = branch_force(law, params, a, z, f_max, guess, memo[5, i], memo[6, i])
    if z >= switch and f > 0.0:  # loading: the memo made for the largest force this sets
        memo[4, i], memo[5, i], memo[6, i] = f, z - a * f, math.nan
    return f


@njit(cache=True)
def bed_elastic(bed, k, memo, i, f2, f2_max):
    """Energy [J] the bed would give back from its last solution (force ``f2`` [N], largest
    ``f2_max`` [N]) to its set; its loss, loss W(u_max), is counted once loaded
    (:func:`racket.solver.bed_kernel.bed_dissipated`).
    """
    _remember(k, bed[0], bed[1], f2_max, memo, i)
    return elastic(k, bed[0], memo[3, i], memo[2, i], f2, f2_max)


@njit(cache=True, inline="always")
def elastic(k, s, u, delta, f2, f2_max):
    """:func:`bed_elastic` in numbers alone: the bed's stiffness ``k`` [N/m] and stretch ``s``
    [1/m^2], its last loading-curve deflection ``u`` [m] and the set-back ``delta`` [m] of
    its memo made for ``f2_max``.
    """
    if u <= 0.0 or f2_max <= 0.0:
        return stored(k, s, abs(u))
    return stored(k, s, u) - 0.5 * delta * f2 * f2 / f2_max


@njit(cache=True)
def bed_deflection(bed, k, memo, i, f2, f2_max):
    """The bed's deflection w [m] at its last solution (force ``f2`` [N], largest ``f2_max``
    [N]).
    """
    _remember(k, bed[0], bed[1], f2_max, memo, i)
    u, delta = memo[3, i], memo[2, i]
    if u < 0.0 or f2_max <= 0.0:
        return u + delta
    return u + delta * max(1.0 - f2 / f2_max, 0.0)


@njit(cache=True)
def bed_gap(law, params, bed, k, residual, memo, i, f1_max, f2, f2_max, relative_speed):
    """How far [m] the ball's compression is from closing the contact again beyond the
    frame's point, at the bed's nearest reach: the ball's residual compression and the
    bed's set, less the amplitude its energy (kinetic, at ``relative_speed`` [m/s] to the
    frame, and elastic, with the modes left out, ``residual`` [m/N] in series with it) can
    swing it towards the ball (the bed is at least as stiff as k either side of its set, so
    the spring behind it at least as stiff as 1 / (1/k + residual)).  The frame's vibration
    can feed the bed more; the kernels watch some steps longer for that.
    """
    _remember(k, bed[0], bed[1], f2_max, memo, i)
    rest = ball_compression(law, params, 0.0, f1_max)
    return gap_from(rest, bed[0], bed[2], k, residual, memo[3, i], memo[2, i], f2, f2_max,
               relative_speed)  # fmt: skip


@njit(cache=True, inline="always")
def gap_from(rest, s, mass, k, residual, u, delta, f2, f2_max, relative_speed):
    """:func:`bed_gap` in numbers alone (the lockstep kernel's pass over its tile,
    :func:`racket.solver.lockstep_watch.watch_tile`, passes no arrays): the ball's residual
    compression ``rest`` [m], the bed's stretch ``s`` [1/m^2] and moving ``mass`` [kg], and
    :func:`elastic`'s numbers.  Inlined where it is called (as :func:`elastic`): a call
    there kept the pass's arrays' reference counts.
    """
    energy = 0.5 * mass * relative_speed * relative_speed + 0.5 * residual * f2 * f2
    energy += elastic(k, s, u, delta, f2, f2_max)
    return rest + delta - math.sqrt(2.0 * max(energy, 0.0) * (1.0 / k + residual))


@njit(cache=True)
def opening_fraction(law, params, f1, f1_max, x_end):
    """Fraction of the step at which the ball left the bed: where its compression beyond
    its residual one went through zero, from the step's start (force ``f1``) to ``x_end``
    (the compression with no force at the end), linearly.
    """
    rest = ball_compression(law, params, 0.0, f1_max)
    d_start = ball_compression(law, params, f1, f1_max) - rest
    d_end = x_end - rest
    if d_start - d_end <= 0.0:
        return 1.0
    return min(max(d_start / (d_start - d_end), 0.0), 1.0)
