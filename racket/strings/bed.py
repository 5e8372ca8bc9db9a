"""The string bed as the solver sees it: a spring between the ball and the frame, linear
and lossless (the paper's) or stiffening, lossy and with a mass of its own
(:class:`StringBed`); what a stringer strings it with is :mod:`racket.strings.stringing`.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np

from common.checks import (
    CM_AS_M,
    GRAMS_AS_KG,
    KN_AS_N,
    finite_array,
    in_range,
    non_negative,
    positive,
    shown,
)
from common.typechecks import choice
from racket.strings.head import HEAD_ASPECT
from racket.strings.membrane import bed_radius, stiffness_ratio

STRING_PROFILES = ("uniform", "membrane")

BED_STIFFNESS_RANGE = (1e3, 1e7)
"""String-bed stiffnesses [N/m] a :class:`StringBed` takes: **an assumption**, generous
around a strung racket's 2e4-5e4 (paper Secs. III and VIII); a sweep's range too
(``studies.sweeps.STRING_STIFFNESS_RANGE``).  A stiffness in kN/m typed as N/m (30 for 3e4)
is refused with the hint, before any number that follows from it (the bed's stretch)."""

BED_END_MAX = 1.5
"""The farthest from the tip a string bed may end [m]: the longest racket a TOML file
describes (``[racket] length``, 0.2-1.5 m; ``studies.config.TOML_RANGES``).  An extent
typed in cm (``(5, 37)`` for 0.05-0.37 m) is refused with the hint."""

STRETCH_MAX = 1e5
"""Largest :attr:`StringBed.stretch` [1/m^2]: the bed twice as stiff at a 3 mm deflection,
far beyond any string (a polyester bed at 20 lb, the stiffest case, has about 6e3)."""

BED_LOSS_MAX = 0.3
"""Largest :attr:`StringBed.loss` [-]: beyond a third, a stiffening bed's unloading curve
could turn back on itself; strings lose about 5 % (Kawazoe's steel ball, COR 0.97)."""

BED_MASS_MAX = 0.02
"""Largest :attr:`StringBed.moving_mass` [kg]: the whole of a 20 g string bed moving with
the ball, beyond any bed (a 16x19 bed weighs 12-20 g, of which about a quarter moves)."""


def bed_stiffness(name: str, value) -> float:
    """A string bed's stiffness [N/m] in :data:`BED_STIFFNESS_RANGE`: ValueError naming
    ``name`` with the range and the slip (kN/m typed as N/m?) otherwise.

    Parameters
    ----------
    name : str
        The argument's name, as the message quotes it.
    value : object
        The stiffness [N/m].
    """
    positive(name, value, "N/m")  # a sign slip said as such
    return in_range(name, value, *BED_STIFFNESS_RANGE, "N/m", slips=(KN_AS_N,))


@dataclass(frozen=True)
class StringBed:
    """The string plane: a spring between the ball and the frame, linear and lossless
    (the paper's) or stiffening as it deflects and losing a fraction of what it stores.

    Pushed by a force F the bed deflects by w with F = k w (1 + ``stretch`` w**2) while
    loading (k its stiffness at the point); unloading returns (1 - ``loss``) of the energy
    it stored, along a curve set back from the loading one by the deflection that leaves
    that loop's area (:mod:`racket.solver.bed_kernel`).

    Parameters
    ----------
    stiffness : float
        Stiffness of the string plane against a ball pushed into it [N/m] (about 3e4 to
        4e4 N/m for a racket strung at 55 lb; paper Secs. III and VIII), in
        :data:`BED_STIFFNESS_RANGE`.
    extent : (float, float)
        Where the strings are, as distances from the tip [m]: (start, end), start < end,
        each at most :data:`BED_END_MAX`.
    width : float or None
        Width of the string bed across the racket [m]; None (default) for an elliptical bed
        of length / width :data:`racket.strings.head.HEAD_ASPECT`.
    profile : str
        How the stiffness varies over the face: ``"uniform"`` (default; ``stiffness``
        everywhere, as in the paper) or ``"membrane"`` (``stiffness`` at the centre, rising
        towards the frame, :mod:`racket.strings.membrane`).
    stretch : float
        How fast the bed stiffens as it deflects [1/m^2]: F = k w (1 + stretch w**2); 0
        (default) for the paper's linear bed.  The strings lengthen as they deflect, so
        their tension rises with their axial stiffness EA (:mod:`racket.strings.stringing`).
    loss : float
        Fraction [-] of the energy stored in the bed that a load and unload dissipates (the
        strings' hysteresis and the friction between mains and crosses), in [0, 0.3]; 0
        (default) for the paper's lossless bed.
    stringing : object or None
        What the bed was strung with (:class:`racket.strings.stringing.Stringing`), for the
        outputs' conditions; None for a bed given by its numbers.
    moving_mass : float
        The bed's mass that moves with the ball [kg], in [0, 0.02]: a third body between
        the ball and the frame, pushed by the ball and pushing the frame through the bed's
        law (:mod:`racket.solver.bed_mass_kernel`), whose own vibration the ball does not
        get back; 0 (default) for the paper's massless bed.  The frame keeps the whole
        strung mass as well (**an assumption**: see
        :meth:`racket.strings.stringing.Stringing.moving_mass`).
    """

    stiffness: float
    extent: tuple
    width: float | None = None
    profile: str = "uniform"
    stretch: float = 0.0
    loss: float = 0.0
    stringing: object = None
    moving_mass: float = 0.0

    def __post_init__(self):
        object.__setattr__(self, "stiffness", bed_stiffness("stiffness", self.stiffness))
        extent = finite_array("extent", self.extent, "m from the tip")
        if extent.shape != (2,):
            raise ValueError(
                f"extent must be (start, end) [m from the tip], got {shown(self.extent)}"
            )
        start = non_negative("extent start", extent[0], "m from the tip")
        end = positive("extent end", extent[1], "m from the tip")
        for name, x in (("extent start", start), ("extent end", end)):
            in_range(name, x, 0.0, BED_END_MAX, "m from the tip", slips=(CM_AS_M,))
        if end <= start:
            raise ValueError(f"extent must have start < end [m from the tip], got {self.extent!r}")
        object.__setattr__(self, "extent", (start, end))
        if self.width is not None:
            object.__setattr__(self, "width", positive("strings width", self.width, "m"))
        choice("string bed profile", self.profile, STRING_PROFILES)
        stretch = non_negative("string bed stretch", self.stretch, "1/m^2")
        object.__setattr__(self, "stretch", in_range("string bed stretch", stretch, 0.0,
                                                     STRETCH_MAX, "1/m^2"))  # fmt: skip
        loss = non_negative("string bed loss", self.loss, "")
        object.__setattr__(self, "loss", in_range("string bed loss", loss, 0.0, BED_LOSS_MAX, ""))
        mass = non_negative("string bed moving mass", self.moving_mass, "kg")
        object.__setattr__(self, "moving_mass", in_range("string bed moving mass", mass, 0.0,
                                                         BED_MASS_MAX, "kg",
                                                         slips=(GRAMS_AS_KG,)))  # fmt: skip
        if self.profile == "membrane":
            bed_radius(self.area)  # refuses a bed too small for the membrane model

    @property
    def plain(self) -> bool:
        """True for the paper's bed: linear, lossless and massless."""
        return self.stretch == 0.0 and self.loss == 0.0 and self.moving_mass == 0.0

    @property
    def center(self) -> float:
        """Geometric centre of the string bed [m from the tip]."""
        return 0.5 * (self.extent[0] + self.extent[1])

    @property
    def full_width(self) -> float:
        """Width of the string bed [m] (:attr:`width`, or from :data:`HEAD_ASPECT`)."""
        if self.width is not None:
            return self.width
        return (self.extent[1] - self.extent[0]) / HEAD_ASPECT

    @property
    def aspect(self) -> float:
        """Length over width of the string bed [-]."""
        return (self.extent[1] - self.extent[0]) / self.full_width

    @property
    def area(self) -> float:
        """Area of the (elliptical) string bed [m^2]."""
        return 0.25 * np.pi * (self.extent[1] - self.extent[0]) * self.full_width

    def rho2(self, x, y=0.0) -> np.ndarray:
        """Squared elliptical radius of the points (``x`` [m from the tip], ``y`` [m from
        the long axis]): 0 at the bed's centre, 1 on its edge.
        """
        half_length = 0.5 * (self.extent[1] - self.extent[0])
        dx = (np.asarray(x, dtype=float) - self.center) / half_length
        return dx**2 + (np.asarray(y, dtype=float) / (0.5 * self.full_width)) ** 2

    @cached_property
    def stiffest(self) -> float:
        """The largest string-plane stiffness anywhere on the bed [N/m] (the solver's time
        step follows from it): :attr:`stiffness` for a uniform bed.  Computed once (the bed
        is frozen).
        """
        if self.profile == "uniform":
            return self.stiffness
        return self.stiffness * float(stiffness_ratio(1.0, self._radius))

    @cached_property
    def _radius(self) -> float:
        """Radius [m] of the circle of the bed's area (the membrane model's); computed once."""
        return bed_radius(self.area)

    def stiffness_at(self, x, y=0.0) -> np.ndarray:
        """String-plane stiffness [N/m] at (``x`` [m from the tip], ``y`` [m from the long
        axis]): :attr:`stiffness` for a uniform bed; the membrane's rise towards the frame
        (:func:`racket.strings.membrane.stiffness_ratio`) for a ``"membrane"`` one.
        """
        if self.profile == "uniform":
            x = np.asarray(x, float)  # (with y a number, the usual case: x's shape)
            shape = x.shape if isinstance(y, float) else np.broadcast(x, np.asarray(y, float)).shape
            return np.full(shape, self.stiffness)
        return self.stiffness * stiffness_ratio(self.rho2(x, y), self._radius)  # (broadcast)
