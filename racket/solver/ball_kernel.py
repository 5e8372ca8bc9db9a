"""The ball's force laws as the compiled time-steppers solve them, one step at a time.

Each step reduces to one scalar equation for the force at the step's end (see
:mod:`racket.solver.kernel`), g_ball(F) + a F = z_pred, a the compliance in series with the ball:
closed form for a linear law, a safeguarded Newton iteration for power laws
(:func:`monotone_force`), and for the unhappy ball (sine law) a return mapping in its
compression X, which never decreases (:func:`sine_step`, the fold and snap described in
:mod:`racket.solver.kernel`).

Law codes (:data:`ball.laws.LINEAR` ...): 0 linear hysteresis (k, e), 1 power law (k, a, b),
2 sine law (k0), 3 growing hysteresis (k, a, e0, slope), 4 stiffening hysteresis (k, X_lim,
e0, slope), each from the law's ``kernel_law``.  Shared by the scalar kernel
(:mod:`racket.solver.kernel`) and the lockstep kernel (:mod:`racket.solver.lockstep`).
"""

from __future__ import annotations

import math

from numba import njit

from ball.falling_cor import COR_FLOOR
from racket.solver.layout import LINEAR, POWER, STIFFENING

NEWTON_SETTLED = 1e-8
"""A Newton step at most this fraction of its unknown ends the force solves' iterations: the
iteration converges quadratically, so the error it leaves is of the order of the step's
square, round-off (the laws' second derivatives are of the order of their first over the
force).  Waiting instead for a step of round-off size costs one more evaluation of the laws
per solve, a third of the solve's time."""

NEWTON_STEPS = 100
"""Most iterations of a safeguarded Newton solve of a contact force (the ball's, the bed's,
the two's in series): a bisection a step at worst halves the bracket, so 100 reach the last
bit of any force."""


@njit(cache=True)
def _loading(law, params, f):
    """Compression on a monotone ball law's loading curve at force f > 0, and its
    d(compression)/d(force): k X**a (POWER, GROWING: params k, a) or the hyperbola
    X = X_lim F / (F + k X_lim) (STIFFENING: params k, X_lim).
    """
    if law == STIFFENING:
        f_c = params[0] * params[1]
        return params[1] * f / (f + f_c), params[1] * f_c / ((f + f_c) * (f + f_c))
    x = (f / params[0]) ** (1.0 / params[1])
    return x, x / (params[1] * f)


@njit(cache=True)
def _branch(law, params, f, f_max, b):
    """Compression of a power-unloading ball at force f after largest force f_max, and its
    d(compression)/d(force) on the branch it is on (unloading X_max (f / f_max)**(1 / b)).
    """
    if f <= 0.0:
        return 0.0, math.inf
    if f >= f_max:
        return _loading(law, params, f)
    x = _loading(law, params, f_max)[0] * (f / f_max) ** (1.0 / b)
    return x, x / (b * f)


@njit(cache=True)
def _stored_over_r2(r):
    """(ln(1 + r) - r / (1 + r)) / r**2, as in :mod:`ball.stiffening` (its series below 1e-3)."""
    if r < 1e-3:
        return 0.5 - r * (2.0 / 3.0 - r * (0.75 - r * (0.8 - r * 5.0 / 6.0)))
    return (math.log1p(r) - r / (1.0 + r)) / (r * r)


@njit(cache=True)
def unloading_exponent(law, params, f_max):
    """Exponent b of a ball's unloading curve from the largest force f_max: fixed (POWER:
    params k, a, b), or set by the largest compression so that the unloading returns
    e**2 of the energy stored, e = max(e0 - slope X_max, COR_FLOOR) (GROWING: params k, a,
    e0, slope, b = (a + 1) / e**2 - 1; STIFFENING: params k, X_lim, e0, slope,
    b = F_max X_max / (e**2 W) - 1 with W the stored energy).
    """
    if law == POWER:
        return params[2]
    x_max = _loading(law, params, f_max)[0] if f_max > 0.0 else 0.0
    e = max(params[2] - params[3] * x_max, COR_FLOOR)
    if law == STIFFENING:
        r = f_max / (params[0] * params[1])
        return 1.0 / ((1.0 + r) * _stored_over_r2(r) * e * e) - 1.0
    return (params[1] + 1.0) / (e * e) - 1.0


@njit(cache=True)
def ball_compression(law, params, f, f_max):
    """Compression of a monotone ball law (code ``law``, numbers ``params``) at force f
    after largest force f_max.
    """
    if law == LINEAR:
        k, e = params[0], params[1]
        if f >= f_max:
            return f / k
        return (f_max * (1.0 - e * e) + e * e * f) / k
    if f <= 0.0:  # no compression left (:func:`_branch`): the exponent is not needed
        return 0.0
    return _branch(law, params, f, f_max, unloading_exponent(law, params, f_max))[0]


@njit(cache=True, inline="always")
def bracketed_newton(f, resid, slope, lo, hi):
    """One safeguarded Newton step from the force ``f`` [N] whose residual ``resid`` (not
    zero) rises with the force at ``slope``: the bracket [lo, hi] narrowed to the side of
    the root, the step (or the bracket's middle where the step leaves it), the bracket, and
    whether the iteration has settled (a Newton step within :data:`NEWTON_SETTLED` of the
    force, or any within 1e-15).  Inlined where it is called, so that the lockstep kernel's
    loop over a tile vectorises with it (:mod:`racket.solver.lockstep_ball`).
    """
    if resid < 0.0:
        lo = f
    else:
        hi = f
    f_new = f - resid / slope
    newton = lo < f_new < hi
    if not newton:
        f_new = 0.5 * (lo + hi)
    step = abs(f_new - f)
    return f_new, lo, hi, step <= 1e-15 * f_new or (newton and step <= NEWTON_SETTLED * f_new)


@njit(cache=True)
def _branch_force(target, c, f_lo, f_hi, f_max, law, params, b, guess):
    """Solve g(F) + c F = target for F in [f_lo, f_hi] (g the ball's branch, :func:`_branch`),
    by safeguarded Newton from ``guess`` (the bracket's middle if outside it): g + c F rises
    with F, and the bracket holds the root; a Newton step within :data:`NEWTON_SETTLED` of the
    force ends it.
    """
    f = guess if f_lo < guess < f_hi else 0.5 * (f_lo + f_hi)
    for _ in range(NEWTON_STEPS):
        g, dg = _branch(law, params, f, f_max, b)
        resid = g + c * f - target
        if resid == 0.0:  # (the bracket would close on f, and Newton's step leave it)
            return f
        f_new, f_lo, f_hi, settled = bracketed_newton(f, resid, dg + c, f_lo, f_hi)
        if settled:
            return f_new
        f = f_new
    return f


@njit(cache=True)
def force_coefficients(law, params, a):
    """Numbers of the force solve that stay the same over an impact (``a`` = the series
    compliance plus the step's): for a linear law, 1 / (1/k + a) and 1 / (e**2/k + a),
    the slopes of force against z_pred on loading and unloading, and (1 - e**2) / k, the
    residual compression per unit of the largest force.
    """
    if law == LINEAR:
        k, e2 = params[0], params[1] * params[1]
        return 1.0 / (1.0 / k + a), 1.0 / (e2 / k + a), (1.0 - e2) / k
    return 0.0, 0.0, 0.0


@njit(cache=True)
def monotone_force(law, params, coef, a, z_pred, f_max, guess):
    """Force solving g_ball(F) + a F = z_pred (a = 1/k_s + c), 0 if the contact is open;
    ``coef`` from :func:`force_coefficients`; a non-linear law's Newton iteration starts from
    ``guess`` (the force extrapolated from the last two steps).
    """
    if law == LINEAR:
        f = z_pred * coef[0]  # loading line
        if f >= f_max:
            return f
        return max((z_pred - f_max * coef[2]) * coef[1], 0.0)  # unloading line
    top = _loading(law, params, f_max)[0] if f_max > 0.0 else 0.0
    return branch_force(law, params, a, z_pred, f_max, guess, top, math.nan)


@njit(cache=True)
def branch_force(law, params, a, z_pred, f_max, guess, top, b):
    """:func:`monotone_force` for a power law, given its compression ``top`` [m] at the
    largest force ``f_max`` and its unloading exponent ``b`` there (NaN: worked out here),
    which a caller may keep from step to step.
    """
    if z_pred >= top + a * f_max:  # loading: b plays no part
        return _branch_force(z_pred, a, f_max, z_pred / a, f_max, law, params, 1.0, guess)
    if z_pred <= 0.0:
        return 0.0
    if math.isnan(b):
        b = unloading_exponent(law, params, f_max)
    return _branch_force(z_pred, a, 0.0, f_max, f_max, law, params, b, guess)


@njit(cache=True)
def _sine_root(target, c, k0, x_o, lo, hi):
    """X in [lo, hi] with X + c k0 Xo sin(pi X / Xo) = target, the left side monotone there."""
    x = 0.5 * (lo + hi)
    rising = (lo + c * k0 * x_o * math.sin(math.pi * lo / x_o)) < target
    for _ in range(200):
        s = math.sin(math.pi * x / x_o)
        resid = x + c * k0 * x_o * s - target
        below = resid < 0.0
        if below == rising:
            lo = x
        else:
            hi = x
        slope = 1.0 + c * k0 * math.pi * math.cos(math.pi * x / x_o)
        x_new = x - resid / slope if slope != 0.0 else 0.5 * (lo + hi)
        if not (min(lo, hi) < x_new < max(lo, hi)):
            x_new = 0.5 * (lo + hi)
        if abs(x_new - x) <= 1e-15 * x_o:
            return x_new
        x = x_new
    return x


@njit(cache=True)
def sine_step(k0, x_o, a, z_pred, x_n, cross_tol):
    """One return-mapping step of the unhappy ball.

    Returns (force, new X, residual): ``residual`` > 0 is a snap (the overshoot past the
    fold's maximum, or the push on a spent ball, over Xo), otherwise minus the gap left to
    the fold's maximum over Xo while the ball flows along the rising branch (-inf
    elsewhere).  ``a`` = 1/k_s + c is the compliance in series with the ball, ``x_n`` its
    compression so far.
    """
    if x_n >= x_o:  # spent: the force came back to zero at X = Xo
        if z_pred > x_n:
            return 0.0, x_n, (z_pred - x_n) / x_o
        return 0.0, x_n, -math.inf

    ck = a * k0 * math.pi
    x_fold = x_o / math.pi * math.acos(-1.0 / ck) if ck > 1.0 else x_o
    h_n = x_n + a * k0 * x_o * math.sin(math.pi * x_n / x_o)  # X + a F_sine(X)
    h_fold = x_fold + a * k0 * x_o * math.sin(math.pi * x_fold / x_o)
    if x_n < x_fold:
        if z_pred >= h_n:
            if z_pred <= h_fold:
                x = _sine_root(z_pred, a, k0, x_o, x_n, x_fold)
                return k0 * x_o * math.sin(math.pi * x / x_o), x, (z_pred - h_fold) / x_o
            return 0.0, x_n, (z_pred - h_fold) / x_o  # past the fold's maximum: a snap
        if h_fold - h_n > cross_tol * x_o or x_fold >= x_o:
            return max((z_pred - x_n) / a, 0.0), x_n, -math.inf  # lock
        # At the fold and relaxing: cross onto the falling branch.
        if z_pred >= x_o:
            x = _sine_root(z_pred, a, k0, x_o, x_fold, x_o)
            return k0 * x_o * math.sin(math.pi * x / x_o), x, -math.inf
        return 0.0, x_o, -math.inf
    if z_pred > h_n:
        # Pushed again on the falling branch (the frame's vibration): the ball holds its
        # compression, like any loaded material reloaded below its previous peak.
        return (z_pred - x_n) / a, x_n, -math.inf
    if z_pred >= x_o:
        x = _sine_root(z_pred, a, k0, x_o, x_n, x_o)
        return k0 * x_o * math.sin(math.pi * x / x_o), x, -math.inf
    return 0.0, x_o, -math.inf  # force back to zero at X = Xo: the contact opens
