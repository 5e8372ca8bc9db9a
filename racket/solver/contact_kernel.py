"""The ball and the string bed in series, as the compiled time-steppers solve them.

Each step's force solves g_ball(F) + h_bed(F) + a F = z_pred (:mod:`racket.solver.kernel`):
the ball's compression on its branch (:mod:`racket.solver.ball_kernel`), what the bed adds
to its linear deflection while it stiffens or loses energy (:mod:`racket.solver.bed_kernel`),
and the compliance a of the bed's linear part, the modes left out and the step.  The sum
rises with F on every branch, so the force is unique, found by a safeguarded Newton
iteration.  For the paper's bed (no stretch, no loss) these functions hand over to the
ball's own (closed forms for a linear ball), so that bed runs exactly as before.
"""

from __future__ import annotations

from numba import njit

from racket.solver.ball_kernel import _branch, ball_compression, monotone_force, unloading_exponent
from racket.solver.bed_kernel import bed_active, bed_extra, set_back
from racket.solver.layout import LINEAR

_NEWTON_STEPS = 100
_BRACKET_DOUBLINGS = 200


@njit(cache=True)
def contact_compression(law, params, bed, inv_ks, f, f_max):
    """The ball's compression at force ``f`` after the largest ``f_max``, plus what the bed
    adds to its linear deflection f inv_ks [m] (:func:`racket.solver.bed_kernel.bed_extra`).
    """
    x = ball_compression(law, params, f, f_max)
    if bed_active(bed):
        x += bed_extra(bed, inv_ks, f, f_max)[0]
    return x


@njit(cache=True)
def contact_force(law, params, coef, bed, inv_ks, a, z_pred, f_max, guess):
    """Force solving g_ball(F) + h_bed(F) + a F = z_pred, 0 if the contact is open; the
    ball's own solve (:func:`racket.solver.ball_kernel.monotone_force`) for the paper's bed.

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
    """
    if not bed_active(bed):
        return monotone_force(law, params, coef, a, z_pred, f_max, guess)
    at_peak = _ball(law, params, f_max, f_max, 1.0)[0] if f_max > 0.0 else 0.0
    switch = at_peak + bed_extra(bed, inv_ks, f_max, f_max)[0] + a * f_max
    if z_pred >= switch:  # loading: the unloading exponent plays no part
        high = max(z_pred / a, 2.0 * f_max)
        for _ in range(_BRACKET_DOUBLINGS):
            if _excess(law, params, bed, inv_ks, a, z_pred, high, f_max, 1.0) >= 0.0:
                break
            high *= 2.0
        return _root(law, params, bed, inv_ks, a, z_pred, f_max, high, f_max, 1.0, guess)
    b = 1.0 if law == LINEAR else unloading_exponent(law, params, f_max)
    rest = _ball(law, params, 0.0, f_max, b)[0] + set_back(bed, inv_ks, f_max)
    if z_pred <= rest:
        return 0.0
    return _root(law, params, bed, inv_ks, a, z_pred, 0.0, f_max, f_max, b, guess)


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
def _excess(law, params, bed, inv_ks, a, target, f, f_max, b):
    """g_ball(f) + h_bed(f) + a f - target [m]."""
    return _ball(law, params, f, f_max, b)[0] + bed_extra(bed, inv_ks, f, f_max)[0] + a * f - target


@njit(cache=True)
def _root(law, params, bed, inv_ks, a, target, f_lo, f_hi, f_max, b, guess):
    """The force in [f_lo, f_hi] where g_ball + h_bed + a F = target, by safeguarded Newton
    from ``guess`` (the bracket's middle if outside it).
    """
    f = guess if f_lo < guess < f_hi else 0.5 * (f_lo + f_hi)
    for _ in range(_NEWTON_STEPS):
        g, dg = _ball(law, params, f, f_max, b)
        h, dh = bed_extra(bed, inv_ks, f, f_max)
        resid = g + h + a * f - target
        if resid == 0.0:
            return f
        if resid < 0.0:
            f_lo = f
        else:
            f_hi = f
        f_new = f - resid / (dg + dh + a)
        if not (f_lo < f_new < f_hi):
            f_new = 0.5 * (f_lo + f_hi)
        if abs(f_new - f) <= 1e-15 * f_new:
            return f_new
        f = f_new
    return f
