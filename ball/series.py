"""Monotone force laws in series: the force that gives a total compression.

Springs in series carry one force F and their compressions add (Eqs. 10-11 with two
monotone laws): ``z = sum_i compression_i(F, max(F, f_max))``.  The right-hand side rises
with F on every branch and is continuous where loading meets unloading (at F = f_max), so
for any z there is exactly one F >= 0; it is found by Newton's method inside a shrinking
bracket (bisection whenever a Newton step would leave it).  Works on arrays, so a sweep
solves all its contacts at once; one contact's ODE asks for one force at a time, which
:func:`series_solver` finds in Python floats (with arrays of one, the stiffening ball's
solve took 70 times as long).
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np

from ball.laws import MonotoneLaw, _PowerBranches
from common.checks import ArgumentTypeError, finite, finite_array, non_negative, shown

_DOUBLINGS = 2100
"""Doublings of the force at most while bracketing the root (2**2100 spans every float)."""

_ITERATIONS = 2300
"""Newton-bisection steps at most once the root is bracketed: enough to bisect down to one
float, where a very steep unloading curve puts the force (e.g. 1e-310 N on a ball whose COR
is near zero)."""


def series_compression(laws: Sequence[MonotoneLaw], f, f_max):
    """Total compression [m] of ``laws`` in series at force ``f`` [N], largest force ``f_max`` [N].

    ``f`` above ``f_max`` is on the loading curve; below it, on the unloading curves.

    Parameters
    ----------
    laws : sequence of MonotoneLaw
        The force laws in series.
    f : float or array_like
        Force they carry [N], >= 0.
    f_max : float or array_like
        Largest force reached so far [N]; broadcasts with ``f``.
    """
    f = np.asarray(f, dtype=float)
    branch_max = np.maximum(f, f_max)
    return sum(law.compression(f, branch_max) for law in laws)


def series_compliance(laws: Sequence[MonotoneLaw], f, f_max):
    """d(total compression)/d(force) [m/N] of ``laws`` in series at ``f``, ``f_max``.

    Parameters
    ----------
    laws, f, f_max
        As in :func:`series_compression`.
    """
    f = np.asarray(f, dtype=float)
    branch_max = np.maximum(f, f_max)
    return sum(law.compliance(f, branch_max) for law in laws)


def _checked(laws) -> Sequence[MonotoneLaw]:
    """``laws`` if it is a non-empty list or tuple of MonotoneLaw; ArgumentTypeError if not."""
    laws_ok = isinstance(laws, tuple | list) and all(isinstance(w, MonotoneLaw) for w in laws)
    if not (laws_ok and laws):
        raise ArgumentTypeError(
            "laws must be a non-empty list of MonotoneLaw (LinearSpring, LinearHysteresis, "
            f"...), got {shown(laws)}"
        )
    return laws


def series_force(laws: Sequence[MonotoneLaw], z, f_max, rtol: float = 1e-14, guess=None):
    """Force [N] in ``laws`` in series compressed by a total ``z`` [m] after a largest ``f_max``.

    Returns 0 where ``z`` is at or below the compression left at zero force (the contact
    is open).  ``z`` and ``f_max`` broadcast.

    Parameters
    ----------
    laws : sequence of MonotoneLaw
        The force laws in series.
    z : float or array_like
        Total compression [m].
    f_max : float or array_like
        Largest force reached so far [N].
    rtol : float, optional
        Relative tolerance [-] on the force at which Newton's method stops.
    guess : float, optional
        A force near the answer [N] for a scalar ``z`` (an ODE's right-hand side passes the
        last one): Newton's method starts there, a few steps instead of about twenty.  The
        answer is the same to ``rtol``.
    """
    laws = _checked(laws)
    if np.ndim(z) == 0 and np.ndim(f_max) == 0:
        z = finite("z", z, "m")
        return series_solver(laws, f_max, rtol)(z, guess)
    z = finite_array("z", z, "m")
    f_max = finite_array("f_max", f_max, "N")
    if (f_max < 0.0).any():  # a force, never negative (a power law's branch would be NaN)
        raise ValueError(f"f_max must be >= 0 N, got {shown(f_max[f_max < 0.0].flat[0])}")
    z, f_max = np.broadcast_arrays(z, f_max)
    with np.errstate(over="ignore"):
        return _array_force(laws, z, f_max, rtol)


def series_solver(laws: Sequence[MonotoneLaw], f_max: float, rtol: float = 1e-14):
    """:func:`series_force` for many scalar compressions after one largest force, as an
    ODE's right-hand side asks for it: what depends on ``f_max`` alone (each law's unloading
    curve) is worked out once, and each solve runs in Python floats.

    Parameters
    ----------
    laws : sequence of MonotoneLaw
        The force laws in series.
    f_max : float
        Largest force reached so far [N].
    rtol : float, optional
        Relative tolerance [-] on the force, as in :func:`series_force`.

    Returns
    -------
    callable
        ``force(z, guess=None)``: the force [N] at the total compression ``z`` [m] (a float),
        Newton's method starting from ``guess`` [N] as in :func:`series_force`.
    """
    laws = _checked(laws)
    f_max = non_negative("f_max", f_max, "N")
    with np.errstate(over="ignore"):  # a huge f_max's loading compression overflows to inf
        branches = [_branch(law, f_max) for law in laws]
        unit = float(series_compression(laws, 1.0, 1.0))

    def force(z: float, guess=None) -> float:
        z = finite("z", z, "m")
        with np.errstate(over="ignore"):  # doubling towards a huge force may overflow
            return _scalar_force(branches, unit, z, f_max, rtol, guess)

    return force


def _array_force(laws, z: np.ndarray, f_max: np.ndarray, rtol: float) -> np.ndarray:
    """:func:`series_force` for arrays ``z``, ``f_max`` of one shape, all contacts at once."""
    z = z.astype(float, copy=True)
    force = np.zeros(z.shape)
    active = z > series_compression(laws, np.zeros(z.shape), f_max)
    if not np.any(active):
        return force[()] if force.ndim == 0 else force
    z_a, fm_a = z[active], f_max[active]
    lo = np.zeros(z_a.shape)
    # Start at the force a linear spring with the laws' compliance at 1 N would need.
    hi = np.maximum(fm_a, z_a / series_compression(laws, 1.0, 1.0))
    for _ in range(_DOUBLINGS):  # grow the bracket until it holds the root
        short = series_compression(laws, hi, fm_a) < z_a
        if not np.any(short):
            break
        lo = np.where(short, hi, lo)
        hi = np.where(short, 2.0 * hi, hi)
    else:
        raise RuntimeError("no finite force compresses the laws by z")
    f = hi
    for _ in range(_ITERATIONS):
        resid = series_compression(laws, f, fm_a) - z_a
        lo = np.where(resid < 0, f, lo)
        hi = np.where(resid >= 0, f, hi)
        slope = series_compliance(laws, f, fm_a)
        with np.errstate(divide="ignore", invalid="ignore"):
            # No Newton step on a vertical or undefined branch.
            newton = np.where((slope > 0) & np.isfinite(slope), f - resid / slope, np.nan)
        # Newton converged: a small step that stays in the bracket and on its branch (the
        # slope changes at f_max).
        crosses = ((newton < fm_a) & (fm_a <= f)) | ((f < fm_a) & (fm_a < newton))
        kept = (newton >= lo) & (newton <= hi) & ~crosses
        stepped = kept & (np.abs(newton - f) <= rtol * np.abs(newton))
        # Bracketed to rtol, or to one float (z's rounding, in force): f stays.
        stays = (resid == 0) | (~stepped & ((hi - lo <= rtol * hi) | (np.nextafter(lo, hi) == hi)))
        inside = (newton > lo) & (newton < hi)
        f = np.where(stays, f, np.where(inside | stepped, newton, 0.5 * (lo + hi)))
        if np.all(stays | stepped):
            break
    else:
        raise RuntimeError("Newton's method did not converge on the series force")
    force[active] = f
    return force[()] if force.ndim == 0 else force


def _branch(law: MonotoneLaw, f_max: float):
    """``law`` after a largest force ``f_max`` [N], one force at a time: a function of a
    force f >= 0 [N] (a float) giving the compression [m] and the compliance [m/N] there, as
    ``law.compression`` and ``law.compliance`` at f and max(f, f_max).  For a power-unloading
    law (the stiffening ball, the power laws) its unloading curve is worked out once, and the
    rest in floats (its loading curve by its array methods, for which an overflow is inf).
    """
    if not isinstance(law, _PowerBranches):  # the linear laws: by their array methods

        def at(f):
            top = max(f, f_max)
            return float(law.compression(f, top)), float(law.compliance(f, top))

        return at
    top, b = float(law._x_max(f_max)), float(law.unloading_exponent(f_max))

    def at_power(f):
        if f >= f_max:  # the loading curve
            if f <= 0.0:
                return 0.0, math.inf
            return float(law._x_max(f)), float(law._loading_compliance(f))
        x = top * (f / f_max) ** (1.0 / b)
        return x, x / (b * f) if f > 0.0 else math.inf

    return at_power


def _series_at(branches, f: float) -> tuple[float, float]:
    """Total compression [m] and compliance [m/N] of the laws' ``branches`` at force ``f``."""
    x = slope = 0.0
    for at in branches:
        x_i, slope_i = at(f)
        x += x_i
        slope += slope_i
    return x, slope


def _scalar_force(branches, unit: float, z: float, f_max: float, rtol: float, guess) -> float:
    """:func:`series_force` for one ``z`` and ``f_max`` in Python floats, on the laws'
    ``branches`` (:func:`_branch`), whose loading compression at 1 N is ``unit`` [m]:
    Newton's method from ``guess`` (or the force of the linear spring of that compliance),
    doubling the force until the root is bracketed and bisecting whenever a step would leave
    the bracket.
    """
    if _series_at(branches, 0.0)[0] - z >= 0.0:
        return 0.0
    lo, hi = 0.0, math.inf
    if guess is not None and guess > 0.0 and math.isfinite(guess):
        f = float(guess)
    else:
        f = max(f_max, z / unit)
    for _ in range(_DOUBLINGS + _ITERATIONS):  # doublings (hi still infinite), then Newton
        x, slope = _series_at(branches, f)
        r = x - z
        if r == 0.0:
            return f
        lo, hi = (f, hi) if r < 0.0 else (lo, f)
        f_new = math.nan  # no Newton step on a vertical or undefined branch
        if slope > 0.0 and math.isfinite(slope):
            f_new = f - r / slope
            # A small step is converged unless it left the bracket or crossed f_max, where
            # the branch (and the slope it was taken with) changes.
            crosses = f_new < f_max <= f or f < f_max < f_new
            kept = lo <= f_new <= hi and not crosses
            if kept and abs(f_new - f) <= rtol * abs(f_new):
                return f_new
        if hi < math.inf and (hi - lo <= rtol * hi or math.nextafter(lo, hi) == hi):
            return f  # bracketed to rtol, or to one float (z's rounding, in force)
        if lo < f_new < hi:
            f = f_new
        elif math.isinf(hi):
            f = 2.0 * f
        else:
            f = 0.5 * (lo + hi)
    raise RuntimeError(f"no force compresses the laws by z = {z!r} m")
