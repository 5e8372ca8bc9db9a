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

from ball.falling_cor import falling_cor, falling_cor_parameters
from common.checks import finite, in_range, positive, shown

LINEAR, POWER, SINE, GROWING, STIFFENING = 0, 1, 2, 3, 4
"""Codes of the law families in the racket solver's compiled kernel (:mod:`racket.solver.kernel`),
each law's ``kernel_law`` giving its code and (up to four) numbers."""

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

    def loading_compliance(self, f):
        """d(compression)/d(force) [m/N] on the loading curve at ``f`` [N] (as
        :meth:`compliance` with ``f_max = f``).
        """
        return self.compliance(f, f)

    @abstractmethod
    def dissipated(self, f_max):
        """Energy [J] lost in one loading to ``f_max`` [N] and unloading to zero force."""

    def at_peak(self, f_max):
        """(:meth:`dissipated` [J], ``compression(f_max, f_max)`` [m]) at ``f_max`` [N]."""
        return self.dissipated(f_max), self.compression(f_max, f_max)

    @property
    @abstractmethod
    def rigid_cor(self) -> float:
        """COR of a bounce on a rigid, immovable surface (the ball's own e)."""

    @abstractmethod
    def secant_stiffness(self, mass: float, speed: float) -> float:
        """F_max / X_max [N/m] of a ball of ``mass`` [kg] hitting a rigid surface at
        ``speed`` [m/s]: the linear spring that the ball is, at that speed.
        """

    @property
    @abstractmethod
    def kernel_law(self) -> tuple:
        """(code, (p0, p1, p2, p3)): the law in the racket solver's compiled kernel."""

    @property
    def storable(self) -> float:
        """The most energy [J] a collision can store in the ball (inf: no limit)."""
        return np.inf


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
        return LINEAR, (self.k, 1.0, 0.0, 0.0)


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
        COR of the ball on a rigid surface [-], 0 <= e <= 1 (0.75 for a tennis ball on concrete).
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

    def at_peak(self, f_max):
        # (both at once, and one force, an impact's, in Python's numbers: the same bits)
        f_max = np.asarray(f_max, dtype=float)
        one, e2 = f_max.shape == (1,), self.e**2
        f = f_max.item() if one else f_max
        loss, squashed = (1.0 - e2) * (f * f) / (2.0 * self.k), (f * (1.0 - e2) + e2 * f) / self.k
        return (np.array([loss]), np.array([squashed])) if one else (loss, squashed)

    @property
    def rigid_cor(self) -> float:
        return self.e

    def secant_stiffness(self, mass: float, speed: float) -> float:
        return self.k

    @property
    def kernel_law(self) -> tuple:
        return LINEAR, (self.k, self.e, 0.0, 0.0)


class _PowerBranches(MonotoneLaw):
    """A loading curve X_load(F) and a power unloading F = F_max (X / X_max)**b from the
    largest force: the branches shared by the power-law balls (:class:`_PowerLoading`) and
    :class:`~ball.stiffening.StiffeningHysteresis`.  The subclass gives the loading curve
    (:meth:`_x_max`, :meth:`_force_at`, :meth:`_loading_compliance`, :meth:`stored`,
    :meth:`peak_compression`) and :meth:`unloading_exponent`; the unloading returns
    F_max X_max / (b + 1).
    """

    @abstractmethod
    def unloading_exponent(self, f_max):
        """Exponent b of the unloading curve from the largest force ``f_max`` [N]."""

    @abstractmethod
    def _x_max(self, f_max):
        """Compression [m] on the loading curve at force ``f_max`` [N]."""

    @abstractmethod
    def _loading_compliance(self, f):
        """d(compression)/d(force) [m/N] on the loading curve at force ``f`` > 0 [N]."""

    @abstractmethod
    def stored(self, f_max):
        """Energy [J] stored by loading the ball to force ``f_max`` [N]."""

    @abstractmethod
    def peak_compression(self, mass: float, speed: float):
        """Largest compression [m] of a ball of ``mass`` [kg] hitting a rigid surface at
        ``speed`` [m/s]: where the loading has stored mass speed**2 / 2.
        """

    def compression(self, f, f_max):
        f_max = np.asarray(f_max, dtype=float)
        return self._unloaded(np.asarray(f, dtype=float), f_max, self.unloading_exponent(f_max))

    def _unloaded(self, f, f_max, b):
        """Compression [m] at ``f`` [N] unloading from ``f_max`` [N] with exponent ``b`` [-]."""
        ratio = np.divide(f, f_max, out=np.zeros(np.broadcast(f, f_max).shape), where=f_max > 0)
        return self._x_max(f_max) * np.clip(ratio, 0.0, 1.0) ** (1.0 / b)

    def compliance(self, f, f_max):
        f = np.asarray(f, dtype=float)
        unloading = f < np.asarray(f_max)
        with np.errstate(divide="ignore", invalid="ignore"):
            c = np.where(
                unloading,
                self.compression(f, f_max) / (self.unloading_exponent(f_max) * f),
                self._loading_compliance(np.where(f > 0, f, 1.0)),
            )
        return np.where(f > 0, c, np.inf)

    def loading_compliance(self, f):
        # the loading branch of compliance() alone: no unloading exponent to compute
        f = np.asarray(f, dtype=float)
        return np.where(f > 0, self._loading_compliance(np.where(f > 0, f, 1.0)), np.inf)

    def dissipated(self, f_max):
        f_max = np.asarray(f_max, dtype=float)
        return self._dissipated(f_max, self.unloading_exponent(f_max))

    def _dissipated(self, f_max, b):
        """:meth:`dissipated` [J] at ``f_max`` [N] (an array) of unloading exponent ``b`` [-]."""
        return self.stored(f_max) - f_max * self._x_max(f_max) / (b + 1.0)

    def at_peak(self, f_max):
        f_max = np.asarray(f_max, dtype=float)
        b = self.unloading_exponent(f_max)  # once for both
        return self._dissipated(f_max, b), self._unloaded(f_max, f_max, b)

    def secant_stiffness(self, mass: float, speed: float) -> float:
        x = self.peak_compression(mass, speed)
        return self._force_at(x) / x

    @abstractmethod
    def _force_at(self, x):
        """Force [N] on the loading curve at compression ``x`` [m]."""


class _PowerLoading(_PowerBranches):
    """Loading F = k X**a (the subclass gives ``k``, ``a`` and :meth:`unloading_exponent`)."""

    k: float
    a: float

    def _x_max(self, f_max):
        return (np.asarray(f_max, dtype=float) / self.k) ** (1.0 / self.a)

    def _loading_compliance(self, f):
        return self._x_max(f) / (self.a * np.asarray(f, dtype=float))

    def _force_at(self, x):
        return self.k * x**self.a

    def stored(self, f_max):
        """Energy [J] stored by loading to ``f_max`` [N]: F_max X_max / (a + 1)."""
        f_max = np.asarray(f_max, dtype=float)
        return f_max * self._x_max(f_max) / (self.a + 1.0)

    def peak_compression(self, mass: float, speed: float) -> float:
        """Largest compression [m] of a ball of ``mass`` [kg] hitting a rigid surface at
        ``speed`` [m/s]: the loading stores k X**(a + 1) / (a + 1) = mass speed**2 / 2.
        """
        return ((self.a + 1.0) * mass * speed**2 / (2.0 * self.k)) ** (1.0 / (self.a + 1.0))


@dataclass(frozen=True)
class PowerLawHysteresis(_PowerLoading):
    """Nonlinear hysteretic ball: load F = k X**a, unload F = F_max (X / X_max)**b.

    The loading stores F_max X_max / (a + 1), the unloading returns F_max X_max / (b + 1),
    so a bounce on a rigid surface has e**2 = (a + 1) / (b + 1).  With a > 1 the ball
    stiffens as it is squashed, so the contact gets shorter at higher speed (paper Sec. III).

    Parameters
    ----------
    k : float
        Stiffness coefficient [N/m**a], > 0.
    a : float
        Loading exponent [-], in [0.5, 5] (1 is linear, 1.5 is Hertzian).
    b : float
        Unloading exponent [-], in [a, 1000] (b = a is elastic; b = 1000 leaves a COR of about
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

    def unloading_exponent(self, f_max):
        """Exponent b of the unloading curve from the largest force ``f_max`` [N]."""
        return np.full(np.shape(f_max), self.b) if np.ndim(f_max) else self.b

    @property
    def rigid_cor(self) -> float:
        return math.sqrt((self.a + 1.0) / (self.b + 1.0))

    @property
    def kernel_law(self) -> tuple:
        return POWER, (self.k, self.a, self.b, 0.0)


@dataclass(frozen=True)
class GrowingHysteresis(_PowerLoading):
    """A ball whose stiffness and hysteresis loss grow with its deformation, so that its COR
    falls and its contact shortens as the impact speed rises (paper Sec. III: "a slight
    decrease in both e1 and the impact duration as the ball speed increases ... due to a
    nonlinear increase in the ball stiffness ... [and] in the hysteresis loss").

    Loading F = k X**a (a >= 1: stiffening); unloading F = F_max (X / X_max)**b from the
    largest compression X_max, with b = (a + 1) / e**2 - 1 so that the unloading returns
    e**2 of the energy stored, and

        e(X_max) = max(e0 - slope X_max, COR_FLOOR),

    the COR of a bounce on a rigid surface that compresses the ball by X_max.  On a rigid
    surface X_max grows as speed**(2 / (a + 1)), so e falls nearly linearly with speed, as
    measured (see :mod:`ball.catalog`).  On strings the ball is compressed less, so it
    loses less: the strings' benefit grows with speed.  This is the hysteretic form of the
    paper's force-domain laws (every branch monotone in the force, so the ball works in
    series with the strings in :func:`ball.collide` and in the racket solver's exact force
    solve); a velocity-dependent damper (Hunt-Crossley, F = k X**a (1 + c X')) gives the
    same trend but makes the force depend on the rate of compression, which a spring in
    series (the strings) turns into a differential-algebraic problem.

    Parameters
    ----------
    k : float
        Stiffness coefficient [N/m**a], > 0.
    a : float
        Loading exponent [-], in [1, 3].
    e0 : float
        COR of a vanishingly slow bounce on a rigid surface [-], in (COR_FLOOR, 1]
        (:data:`ball.falling_cor.COR_FLOOR`).
    slope : float
        Fall of the rigid-surface COR per metre of peak compression [1/m], >= 0.
    calibrated_to : float, optional
        Largest compression [m] of the measurements the law was fitted to: a result beyond
        it warns (:func:`ball.warn_if_squashed`).  None: not checked.
    """

    k: float
    a: float
    e0: float
    slope: float
    calibrated_to: float | None = None

    def __post_init__(self):
        object.__setattr__(self, "k", positive("k", self.k, "N/m**a"))
        object.__setattr__(self, "a", in_range("a", self.a, 1.0, 3.0))
        e0, slope = falling_cor_parameters(self.e0, self.slope)
        object.__setattr__(self, "e0", e0)
        object.__setattr__(self, "slope", slope)
        if self.calibrated_to is not None:
            object.__setattr__(
                self, "calibrated_to", positive("calibrated_to", self.calibrated_to, "m")
            )

    def cor_at_compression(self, x_max):
        """Rigid-surface COR e(X_max) of a bounce compressing the ball by ``x_max`` [m]."""
        return falling_cor(self.e0, self.slope, x_max)

    def unloading_exponent(self, f_max):
        """Exponent b of the unloading curve from the largest force ``f_max`` [N]: it returns
        e(X_max)**2 of the F_max X_max / (a + 1) stored.
        """
        e = self.cor_at_compression(self._x_max(f_max))
        return (self.a + 1.0) / e**2 - 1.0

    @property
    def rigid_cor(self) -> float:
        """e0, the COR of a vanishingly slow bounce (it falls with speed: the rigid-surface
        COR at speed v is e(X_max(v)), :meth:`peak_compression`).
        """
        return self.e0

    @property
    def kernel_law(self) -> tuple:
        return GROWING, (self.k, self.a, self.e0, self.slope)


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
    def storable(self) -> float:
        """The most energy [J] a collision can store in the ball: no limit (its Xo grows)."""
        return np.inf

    @property
    def kernel_law(self) -> tuple:
        """(code, (k0, 0, 0, 0)): the law in the racket solver's compiled kernel."""
        return SINE, (self.k0, 0.0, 0.0, 0.0)
