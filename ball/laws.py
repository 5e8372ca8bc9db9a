"""Ball force laws (paper Sec. III and Eq. 7).

Two kinds of law live here.

*Monotone laws* (:class:`LinearSpring`, :class:`LinearHysteresis`,
:class:`PowerLawHysteresis`) give a force that rises with compression on every branch.
They are written in the force domain, as the compression reached at force ``f`` given the
largest force ``f_max`` seen so far in the collision:

* loading (``f >= f_max``): the loading curve, ``compression(f, f)``;
* unloading or reloading (``f < f_max``): the unloading curve from ``f_max``, which the
  ball follows in both directions until it again reaches ``f_max``.

Springs in series carry the same force and their compressions add, so writing the laws
this way makes any series combination (ball on ball, ball on strings) a single monotone
equation for the force; see :mod:`ball.series`.

The *sine law* of the unhappy ball (:class:`SineLaw`, Eq. 7) is not monotone: its force
falls back to zero at the largest compression ``Xo``, and during a collision its
compression never decreases.  It is handled by :mod:`ball.unhappy`.

All functions accept NumPy arrays and broadcast.
"""

from __future__ import annotations

import math
from abc import ABC, abstractmethod
from dataclasses import dataclass

import numpy as np

from common.checks import finite, in_range, positive, shown

LINEAR, POWER, SINE = 0, 1, 2
"""Codes of the law families in the racket solver's compiled kernel
(:mod:`racket.kernel`), each law's ``kernel_law`` giving its code and numbers."""

MAX_UNLOADING_EXPONENT = 1000.0
"""Largest unloading exponent b of :class:`PowerLawHysteresis` (see there)."""


class MonotoneLaw(ABC):
    """A force law whose force rises with compression on each branch."""

    @abstractmethod
    def compression(self, f, f_max):
        """Compression [m] at force ``f`` [N] after a largest force ``f_max`` [N] (f <= f_max)."""

    @abstractmethod
    def compliance(self, f, f_max):
        """d(compression)/d(force) [m/N] on the branch the ball is on at ``f``, ``f_max``."""

    @abstractmethod
    def dissipated(self, f_max):
        """Energy [J] lost in one loading to ``f_max`` [N] and unloading to zero force."""

    @property
    @abstractmethod
    def rigid_cor(self) -> float:
        """COR of a bounce on a rigid, immovable surface (the ball's own e)."""

    @abstractmethod
    def secant_stiffness(self, mass: float, speed: float) -> float:
        """F_max / X_max [N/m] of a ball of ``mass`` [kg] hitting a rigid surface at
        ``speed`` [m/s]: the linear spring that the ball is, at that speed."""

    @property
    @abstractmethod
    def kernel_law(self) -> tuple:
        """(code, (p0, p1, p2)): the law in the racket solver's compiled kernel."""


@dataclass(frozen=True)
class LinearSpring(MonotoneLaw):
    """Elastic linear spring F = k X, no loss: a perfectly happy ball, or a string bed.

    Parameters
    ----------
    k : float
        Stiffness [N/m], > 0.
    """

    k: float

    def __post_init__(self):
        object.__setattr__(self, "k", positive("k", self.k, "N/m"))

    def compression(self, f, f_max):
        return np.asarray(f, dtype=float) / self.k

    def compliance(self, f, f_max):
        return np.full(np.broadcast(f, f_max).shape, 1.0 / self.k)

    def dissipated(self, f_max):
        return np.zeros(np.shape(f_max))

    @property
    def rigid_cor(self) -> float:
        return 1.0

    def secant_stiffness(self, mass: float, speed: float) -> float:
        return self.k

    @property
    def kernel_law(self) -> tuple:
        return LINEAR, (self.k, 1.0, 0.0)


@dataclass(frozen=True)
class LinearHysteresis(MonotoneLaw):
    """Linear loading F = k X, linear unloading with stiffness k / e**2.

    The unloading line starts at the largest force and is steeper than the loading line by
    1/e**2, so the energy given back is e**2 times the energy stored: a bounce on a rigid
    surface has COR exactly ``e``.  ``e = 0`` unloads vertically (the ball never pushes back).

    Parameters
    ----------
    k : float
        Loading stiffness [N/m], > 0.  Paper Sec. III: about 4e4 N/m for a tennis ball.
    e : float
        COR of the ball on a rigid surface, 0 <= e <= 1 (0.75 for a tennis ball on concrete).
    """

    k: float
    e: float

    def __post_init__(self):
        object.__setattr__(self, "k", positive("k", self.k, "N/m"))
        object.__setattr__(self, "e", in_range("e", self.e, 0.0, 1.0))

    def compression(self, f, f_max):
        f = np.asarray(f, dtype=float)
        e2 = self.e**2
        return (np.asarray(f_max, dtype=float) * (1.0 - e2) + e2 * f) / self.k

    def compliance(self, f, f_max):
        unloading = np.asarray(f) < np.asarray(f_max)
        return np.where(unloading, self.e**2 / self.k, 1.0 / self.k)

    def dissipated(self, f_max):
        return (1.0 - self.e**2) * np.asarray(f_max, dtype=float) ** 2 / (2.0 * self.k)

    @property
    def rigid_cor(self) -> float:
        return self.e

    def secant_stiffness(self, mass: float, speed: float) -> float:
        return self.k

    @property
    def kernel_law(self) -> tuple:
        return LINEAR, (self.k, self.e, 0.0)


@dataclass(frozen=True)
class PowerLawHysteresis(MonotoneLaw):
    """Nonlinear hysteretic ball: load F = k X**a, unload F = F_max (X / X_max)**b.

    The loading stores F_max X_max / (a + 1), the unloading returns F_max X_max / (b + 1),
    so a bounce on a rigid surface has e**2 = (a + 1) / (b + 1).  With a > 1 the ball
    stiffens as it is squashed, so the contact gets shorter at higher speed (paper Sec. III).

    Parameters
    ----------
    k : float
        Stiffness coefficient [N/m**a], > 0.
    a : float
        Loading exponent, in [0.5, 5] (1 is linear, 1.5 is Hertzian).
    b : float
        Unloading exponent, in [a, 1000] (b = a is elastic; b = 1000 leaves a COR of about
        0.05 at a = 1.5, and the contact time grows without bound as b does).
    """

    k: float
    a: float
    b: float

    def __post_init__(self):
        object.__setattr__(self, "k", positive("k", self.k, "N/m**a"))
        a = in_range("a", self.a, 0.5, 5.0)
        b = finite("b", self.b)
        if not a <= b <= MAX_UNLOADING_EXPONENT:
            raise ValueError(
                f"b must be in [a, {MAX_UNLOADING_EXPONENT:g}] = [{a:g}, "
                f"{MAX_UNLOADING_EXPONENT:g}] (b < a would give the ball energy), got {shown(b)}"
            )
        object.__setattr__(self, "a", a)
        object.__setattr__(self, "b", b)

    @classmethod
    def with_cor(cls, k: float, a: float, e: float) -> PowerLawHysteresis:
        """The law with loading k X**a whose rigid-surface COR is ``e`` (0 < e <= 1)."""
        a = in_range("a", a, 0.5, 5.0)
        e_min = math.ceil(1e3 * math.sqrt((a + 1.0) / (MAX_UNLOADING_EXPONENT + 1.0))) / 1e3
        e = in_range("e", e, e_min, 1.0, hint=f" (a power-law ball with a = {a:g})")
        return cls(k=k, a=a, b=max(a, (a + 1.0) / e**2 - 1.0))

    def _x_max(self, f_max):
        return (np.asarray(f_max, dtype=float) / self.k) ** (1.0 / self.a)

    def compression(self, f, f_max):
        f = np.asarray(f, dtype=float)
        f_max = np.asarray(f_max, dtype=float)
        ratio = np.divide(f, f_max, out=np.zeros(np.broadcast(f, f_max).shape), where=f_max > 0)
        return self._x_max(f_max) * np.clip(ratio, 0.0, 1.0) ** (1.0 / self.b)

    def compliance(self, f, f_max):
        f = np.asarray(f, dtype=float)
        exponent = np.where(f < np.asarray(f_max), self.b, self.a)
        with np.errstate(divide="ignore", invalid="ignore"):
            c = self.compression(f, f_max) / (exponent * f)
        return np.where(f > 0, c, np.inf)

    def dissipated(self, f_max):
        f_max = np.asarray(f_max, dtype=float)
        return f_max * self._x_max(f_max) * (1.0 / (self.a + 1.0) - 1.0 / (self.b + 1.0))

    @property
    def rigid_cor(self) -> float:
        return math.sqrt((self.a + 1.0) / (self.b + 1.0))

    def secant_stiffness(self, mass: float, speed: float) -> float:
        # The loading stores k X**(a + 1) / (a + 1) = mass speed**2 / 2 at X_max.
        x_max = ((self.a + 1.0) * mass * speed**2 / (2.0 * self.k)) ** (1.0 / (self.a + 1.0))
        return self.k * x_max ** (self.a - 1.0)

    @property
    def kernel_law(self) -> tuple:
        return POWER, (self.k, self.a, self.b)


@dataclass(frozen=True)
class SineLaw:
    """The unhappy ball (Eq. 7): F = Fo sin(pi X / Xo), with Fo = k0 Xo.

    ``Xo`` is not a parameter of the ball: it is the largest compression reached in the
    collision at hand, and it grows with the impact speed while ``k0 = Fo / Xo`` stays
    constant (paper Sec. IV).  During a collision the compression X never decreases (the
    ball recovers over about 0.2 s, far longer than an impact), so all the work done on the
    ball, 2 Fo Xo / pi over a full cycle, is lost.  Collisions with this law are solved
    self-consistently for ``Xo`` in :mod:`ball.unhappy`.

    Parameters
    ----------
    k0 : float
        Fo / Xo [N/m], > 0.  Paper: 2e4 N/m for the 10.3 g unhappy ball.
    """

    k0: float

    def __post_init__(self):
        object.__setattr__(self, "k0", positive("k0", self.k0, "N/m"))

    def force(self, x, x_o):
        """Force [N] at compression ``x`` [m], in a collision of largest compression ``x_o`` [m]."""
        theta = np.clip(np.pi * np.asarray(x, dtype=float) / x_o, 0.0, np.pi)
        return self.k0 * x_o * np.sin(theta)

    def dissipated(self, x_o, x_end=None):
        """Work [J] done on the ball from X = 0 to ``x_end`` (default ``x_o``), all of it lost."""
        x_end = x_o if x_end is None else x_end
        return self.k0 * x_o**2 / np.pi * (1.0 - np.cos(np.pi * np.asarray(x_end) / x_o))

    @property
    def rigid_cor(self) -> float:
        return 0.0

    def secant_stiffness(self, mass: float, speed: float) -> float:
        """k0 = Fo / Xo [N/m] at every speed (paper Sec. IV)."""
        return self.k0

    @property
    def kernel_law(self) -> tuple:
        """(code, (k0, 0, 0)): the law in the racket solver's compiled kernel."""
        return SINE, (self.k0, 0.0, 0.0)
