"""A tennis ball that stiffens without bound as it is squashed towards its limit.

Loading F = k X / (1 - X / X_lim): linear (stiffness k) at small compression, stiffening as
the compression X nears X_lim, which it never reaches.  With X_lim the ball's radius this is
the geometric limit of a ball on a flat surface (its centre cannot pass the surface), so no
impact however fast squashes the ball beyond its radius.  Written in the force domain,

    X(F) = X_lim F / (F + F_c),    F_c = k X_lim,

and the energy stored on loading to F is X_lim F_c (ln(1 + r) - r / (1 + r)), r = F / F_c:
closed forms, so the law works in series with the strings in :func:`ball.collide` and in
the racket solver's exact per-step force solve, for every impact point at once.  Unloading
is a power of the largest force, F = F_max (X / X_max)**b, with b set so that the ball
returns e(X_max)**2 of the energy stored, e(X_max) = max(e0 - slope X_max, COR_FLOOR) as in
:class:`~ball.GrowingHysteresis`.

Why a new law, not :class:`~ball.GrowingHysteresis` (F = k X**a): a power law that keeps a
fast ball's compression below its radius at 70 m/s must have a >= 1.8, and then it is stiff
at low speed too (a 4 ms contact at 7 m/s needs a nearly linear start).  The hyperbola is
linear at low speed and bounded at high speed with one stiffness; its dynamic (secant)
stiffness F_max / X_max rises with speed, as measured (Haake, Carre & Goodwill, J. Sports
Sci. 21, 2003), and its contact time falls.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ball.bodies import ball_radius
from ball.falling_cor import falling_cor, falling_cor_parameters
from ball.laws import STIFFENING, _PowerBranches
from common.checks import positive

_SERIES_BELOW = 1e-3
"""Below this r = F / F_c the stored energy is summed as a series (the closed form
ln(1 + r) - r / (1 + r) loses digits to cancellation there)."""


def _stored_over_r2(r):
    """(ln(1 + r) - r / (1 + r)) / r**2, by its series where r is small (-> 1/2 at 0)."""
    r = np.asarray(r, dtype=float)
    small = r < _SERIES_BELOW
    if not small.any():  # (an impact's forces: the closed form alone, the same numbers)
        with np.errstate(over="ignore", invalid="ignore"):
            return np.asarray((np.log1p(r) - r / (1.0 + r)) / r**2)
    rs = np.where(small, r, 0.0)
    series = 0.5 - rs * (2.0 / 3.0 - rs * (0.75 - rs * (0.8 - rs * 5.0 / 6.0)))
    rl = np.where(small, 1.0, r)
    with np.errstate(over="ignore", invalid="ignore"):  # -> 0 beyond any physical force
        return np.where(small, series, (np.log1p(rl) - rl / (1.0 + rl)) / rl**2)


def stored_fraction(r):
    """ln(1 + r) - r / (1 + r), the energy stored up to r = F / F_c in units of X_lim F_c.

    Parameters
    ----------
    r : float or array
        Force over F_c = k X_lim [-], >= 0.
    """
    return np.asarray(r, dtype=float) ** 2 * _stored_over_r2(r)


@dataclass(frozen=True)
class StiffeningHysteresis(_PowerBranches):
    """A ball whose loading stiffens without bound towards a largest compression (see the
    module docstring): F = k X / (1 - X / X_lim) on loading, F = F_max (X / X_max)**b on
    unloading, the rigid-surface COR e(X_max) = max(e0 - slope X_max, COR_FLOOR).

    Parameters
    ----------
    k : float
        Stiffness at small compression [N/m], > 0.
    x_lim : float
        Compression the loading approaches and never reaches [m] (the ball's radius), in
        :data:`ball.bodies.BALL_RADIUS_RANGE`.
    e0 : float
        COR of a vanishingly slow bounce on a rigid surface [-], in (COR_FLOOR, 1].
    slope : float
        Fall of the rigid-surface COR per metre of peak compression [1/m], >= 0.
    """

    k: float
    x_lim: float
    e0: float
    slope: float

    def __post_init__(self):
        object.__setattr__(self, "k", positive("k", self.k, "N/m"))
        object.__setattr__(self, "x_lim", ball_radius("x_lim", self.x_lim))
        e0, slope = falling_cor_parameters(self.e0, self.slope)
        object.__setattr__(self, "e0", e0)
        object.__setattr__(self, "slope", slope)

    @property
    def _f_c(self) -> float:
        return self.k * self.x_lim

    def _x_max(self, f_max):
        # a float or an array: no np.asarray, which would cost the scalar solves of
        # ball.series (an ODE's right-hand side) most of their time
        return self.x_lim * f_max / (f_max + self._f_c)

    def _force_at(self, x):
        return self.k * x / (1.0 - x / self.x_lim)

    def secant_stiffness(self, mass: float, speed: float) -> float:
        """F_max / X_max = (F_max + F_c) / x_lim [N/m] of a ball of ``mass`` [kg] hitting a
        rigid surface at ``speed`` [m/s] (inf where the force overflows: never NaN).
        """
        with np.errstate(over="ignore"):  # an overflowing force: an infinite stiffness
            return float((self.peak_force(mass, speed) + self._f_c) / self.x_lim)

    def _loading_compliance(self, f):
        # a float or an array, as _x_max; squared by hand, so that a float's overflow is inf
        return self.x_lim * self._f_c / ((f + self._f_c) * (f + self._f_c))

    def stored(self, f_max):
        """Energy [J] stored by loading to ``f_max`` [N]: X_lim F_c (ln(1 + r) - r/(1 + r))."""
        return self.x_lim * self._f_c * stored_fraction(np.asarray(f_max) / self._f_c)

    @property
    def storable(self) -> float:
        """The energy [J] stored at 1 - X/x_lim = 1e-9: beyond it no float is left between
        the compressions a collision would step through (refused as too energetic).
        """
        return float(self.stored(1e9 * self._f_c))

    def cor_at_compression(self, x_max):
        """Rigid-surface COR e(X_max) of a bounce compressing the ball by ``x_max`` [m]."""
        return falling_cor(self.e0, self.slope, x_max)

    def unloading_exponent(self, f_max):
        """Exponent b of the unloading curve from the largest force ``f_max`` [N]: it returns
        e(X_max)**2 of the energy stored, F_max X_max / (b + 1) = e**2 W(F_max).
        """
        f_max = np.asarray(f_max, dtype=float)
        r = f_max / self._f_c
        e = self.cor_at_compression(self._x_max(f_max))
        # F_max X_max / W = r**2 / ((1 + r) stored_fraction(r)): 2 as r -> 0 (linear), and
        # infinite (a vertical unloading) where a force beyond any physical one overflows it
        with np.errstate(divide="ignore", over="ignore"):
            return 1.0 / ((1.0 + r) * _stored_over_r2(r) * e**2) - 1.0

    def peak_force(self, mass: float, speed):
        """Largest force [N] of a ball of ``mass`` [kg] hitting a rigid surface at ``speed``
        [m/s]: where the loading has stored mass speed**2 / 2.

        With s = ln(1 + r) the stored energy is X_lim F_c (s - 1 + exp(-s)), convex in s;
        Newton's method from s = eps + 1 (above the root) converges from above.
        """
        eps = 0.5 * mass * np.asarray(speed, dtype=float) ** 2 / (self.x_lim * self._f_c)
        s = eps + 1.0
        for _ in range(100):
            step = (s + np.expm1(-s) - eps) / -np.expm1(-s)
            s = s - step
            if np.all(np.abs(step) <= 1e-15 * s):
                break
        return self._f_c * np.expm1(s)

    def peak_compression(self, mass: float, speed):
        """Largest compression [m] of a ball of ``mass`` [kg] hitting a rigid surface at
        ``speed`` [m/s] (< x_lim at every speed).
        """
        return self._x_max(self.peak_force(mass, speed))

    def cor_at_speed(self, mass: float, speed):
        """COR [-] of a ball of ``mass`` [kg] bouncing off a rigid surface at ``speed`` [m/s]."""
        return self.cor_at_compression(self.peak_compression(mass, speed))

    @property
    def rigid_cor(self) -> float:
        """e0, the COR of a vanishingly slow bounce (it falls with speed:
        :meth:`cor_at_speed`).
        """
        return self.e0

    @property
    def kernel_law(self) -> tuple:
        """(STIFFENING, (k, x_lim, e0, slope)): the law in the racket solver's kernel."""
        return STIFFENING, (self.k, self.x_lim, self.e0, self.slope)
