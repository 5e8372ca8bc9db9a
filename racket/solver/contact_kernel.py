"""The ball and the string bed in series, as the compiled time-steppers solve them.

Each step's force solves g_ball(F) + h_bed(F) + a F = z_pred (:mod:`racket.solver.kernel`):
the ball's compression on its branch (:mod:`racket.solver.ball_kernel`), what the bed adds
to its linear deflection while it stiffens or loses energy (:mod:`racket.solver.bed_kernel`),
and the compliance a of the bed's linear part, the modes left out and the step.  The sum
rises with F on every branch, so the force is unique, found by a safeguarded Newton
iteration in the bed's deflection.  For the paper's bed (no stretch, no loss) these
functions hand over to the ball's own (closed forms for a linear ball), so that bed runs
exactly as before.
"""

from __future__ import annotations

import math

from numba import njit

from racket.solver.ball_kernel import (
    NEWTON_SETTLED,
    NEWTON_STEPS,
    _branch,
    ball_compression,
    monotone_force,
    unloading_exponent,
)
from racket.solver.bed_kernel import bed_active, bed_extra, deflection, stored
from racket.solver.layout import LINEAR


@njit(cache=True)
def contact_compression(law, params, bed, inv_ks, f, f_max):
    """The ball's compression at force ``f`` after the largest ``f_max``, plus what the bed
    adds to its linear deflection f inv_ks [m] (:func:`racket.solver.bed_kernel.bed_extra`).
    """
    x = ball_compression(law, params, f, f_max)
    if bed_active(bed):
        x += bed_extra(bed, inv_ks, f, f_max)[0]
    return x


MEMO_ROWS = 5
"""Rows of a contact's memo (:func:`contact_force`): the largest force they were made for
[N], the bed's loading deflection [m] and the ball's compression [m] there, the bed's
unloading set-back [m] (NaN until the contact first unloads from that force) and the ball's
unloading exponent [-].  A new memo holds -1 in its first row."""


@njit(cache=True)
def contact_force(law, params, coef, bed, inv_ks, a, z_pred, f_max, guess, memo, i):
    """Force solving g_ball(F) + h_bed(F) + a F = z_pred, 0 if the contact is open; the
    ball's own solve (:func:`racket.solver.ball_kernel.monotone_force`) for the paper's bed.

    The unknown is the bed's deflection on its loading curve, u, in which the force
    F = k u (1 + s u**2) and the bed's whole deflection, u + delta (1 - F / F_max) while
    unloading, are explicit: the equation g_ball(F(u)) + u + delta (1 - F / F_max) +
    (a - 1/k) F(u) = z_pred then needs no inner solve of the bed's cubic.  What depends
    only on F_max is kept in the contact's memo (column ``i`` of ``memo``, rows
    :data:`MEMO_ROWS`): while loading it is the last step's solution, while unloading it
    stays.

    Parameters
    ----------
    law, params, coef : int, ndarray, tuple
        The ball's law, its numbers and its force coefficients.
    bed : ndarray (2,)
        The bed's stretch [1/m^2] and loss [-].
    inv_ks : float
        1 / the bed's stiffness at the impact point [m/N].
    a : float
        Compliance in series with the ball [m/N]: the bed's linear part, the modes left out
        and the step's.
    z_pred : float
        The contact's compression the step would give without force [m].
    f_max, guess : float
        The largest force so far, and a first guess (the force extrapolated) [N].
    memo : ndarray (MEMO_ROWS, n)
        The contacts' memos; column ``i`` is this one's.
    """
    if not bed_active(bed):
        return monotone_force(law, params, coef, a, z_pred, f_max, guess)
    k, s = 1.0 / inv_ks, bed[0]
    rest_of = a - inv_ks  # the compliance beside the bed's: the modes left out, the step
    if memo[0, i] != f_max:
        memo[0, i] = f_max
        memo[1, i] = deflection(k, s, f_max)[0] if f_max > 0.0 else 0.0
        memo[2, i] = _ball(law, params, f_max, f_max, 1.0)[0] if f_max > 0.0 else 0.0
        memo[3, i] = math.nan
    u_max = memo[1, i]
    guess_u = guess * u_max / f_max if f_max > 0.0 else guess * inv_ks
    if z_pred >= memo[2, i] + u_max + rest_of * f_max:  # loading: g, u and F all rise
        f, u = _root(law, params, k, s, rest_of, 0.0, z_pred, u_max, z_pred, f_max, 1.0, guess_u)
        memo[0, i], memo[1, i], memo[3, i] = f, u, math.nan  # the next step's largest force
        memo[2, i] = _ball(law, params, f, f, 1.0)[0]
        return f
    if math.isnan(memo[3, i]):
        memo[3, i] = 2.0 * bed[1] * stored(k, s, u_max) / f_max
        memo[4, i] = 1.0 if law == LINEAR else unloading_exponent(law, params, f_max)
    delta, b = memo[3, i], memo[4, i]
    if z_pred <= _ball(law, params, 0.0, f_max, b)[0] + delta:
        return 0.0
    return _root(law, params, k, s, rest_of, delta, z_pred, 0.0, u_max, f_max, b, guess_u)[0]


@njit(cache=True)
def _ball(law, params, f, f_max, b):
    """The ball's compression at ``f`` on its branch after ``f_max``, and d/dF: the linear
    law's lines (loading, or unloading with e**2 / k), or the power laws' branches.
    """
    if law == LINEAR:
        k, e2 = params[0], params[1] * params[1]
        if f >= f_max:
            return f / k, 1.0 / k
        return (f_max * (1.0 - e2) + e2 * f) / k, e2 / k
    return _branch(law, params, f, f_max, b)


@njit(cache=True)
def _root(law, params, k, s, rest_of, delta, target, u_lo, u_hi, f_max, b, guess):
    """The bed's loading-curve deflection u in [u_lo, u_hi] where g_ball(F) + u +
    delta (1 - F / f_max) + rest_of F = target, F = k u (1 + s u**2), by safeguarded Newton
    from ``guess`` (the bracket's middle if outside it), to
    :data:`racket.solver.ball_kernel.NEWTON_SETTLED`; returns F and u there.
    """
    u = guess if u_lo < guess < u_hi else 0.5 * (u_lo + u_hi)
    set_back = delta / f_max if delta > 0.0 else 0.0
    for _ in range(NEWTON_STEPS):
        f = k * u * (1.0 + s * u * u)
        g, dg = _ball(law, params, f, f_max, b)
        resid = g + u + delta - set_back * f + rest_of * f - target
        if resid == 0.0:
            return f, u
        if resid < 0.0:
            u_lo = u
        else:
            u_hi = u
        slope = (dg + rest_of - set_back) * k * (1.0 + 3.0 * s * u * u) + 1.0
        u_new = u - resid / slope
        newton = u_lo < u_new < u_hi
        if not newton:
            u_new = 0.5 * (u_lo + u_hi)
        step = abs(u_new - u)
        u = u_new
        if step <= 1e-15 * u_new or (newton and step <= NEWTON_SETTLED * u_new):
            break
    return k * u * (1.0 + s * u * u), u
