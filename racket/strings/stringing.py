"""A string bed as a stringer describes it: the string (material and gauge) of the mains and
of the crosses, the pattern, the reference tension and whether the strings are fresh or
played; and the numbers of the :class:`racket.StringBed` that follow from it (stiffness,
stretch, loss, mass).

The stiffness is the membrane model's (:func:`racket.strings.tension.string_bed_stiffness`,
calibrated to the paper's 3e4 N/m at 55 lb on 100 in^2), the stretch a string's lengthening
as it deflects, the loss calibrated to Kawazoe's steel ball on strings with TWU's energy
return by material (:mod:`racket.strings.material`).
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from common.checks import (
    KG_AS_N,
    LB_AS_N,
    finite,
    in_range,
    positive,
    shown,
)
from common.typechecks import choice, instance
from common.units import LB
from racket.strings.bed import BED_STIFFNESS_RANGE, StringBed, bed_stiffness
from racket.strings.ert import dt_reading
from racket.strings.head import HEAD_ASPECT
from racket.strings.material import MATERIALS, Material, material_key
from racket.strings.sizes import REFERENCE_PATTERN, diameter, parse_pattern
from racket.strings.tension import TENSION_RANGE_LB, string_bed_stiffness

STATES = ("fresh", "played")
"""A string bed's states: as strung, or "played": after the tension loss of TWU's impact
test (**an assumption**: what a bed loses in play is taken to be what TWU's test takes)."""

STEEL_BALL_COR = 0.97
"""COR [-] of a steel ball on a string bed, "regardless of type or tension" (Kawazoe,
kawazoe-lab.com, post 813; ``data/measurements.md`` sec. 5): the ball does not deform, so
1 - 0.97**2 = 5.9 % of the energy is lost in the strings: their hysteresis and the friction
between mains and crosses, both inside this one number."""

LOSS_PER_RETURN = 0.3
"""How much of the difference of a material's single-string energy return from nylon's
reaches the bed's loss [-]: **an assumption**, bounded by Kawazoe's "regardless of type",
which keeps every material's steel-ball COR within 0.97 +/- 0.01 (0 to 0.4 would: polyester
at 0.4 loses 7.9 %, the band's edge).  Over the whole band of loss (3.96-7.84 %) the default
racket's e_A at the string centre (16.5 m/s) moves by about 0.01, its serve by about 0.01
times the head speed."""

LOSS_BAND = (1.0 - (STEEL_BALL_COR + 0.01) ** 2, 1.0 - (STEEL_BALL_COR - 0.01) ** 2)
"""The bed losses [-] a steel-ball COR of 0.97 +/- 0.01 allows: 3.96-7.84 %."""

MODAL_MASS_RATIO = 0.2695
"""Modal mass of a circular membrane's first mode over its mass [-], for the deflection at
its centre: J1(j01)**2 = 0.2695 (j01 = 2.405, the first zero of J0; P. M. Morse & K. U.
Ingard, Theoretical Acoustics, 1968, Sec. 5.2, the circular membrane).  The part of the bed
that moves with the ball (:meth:`Stringing.moving_mass`)."""


@dataclass(frozen=True)
class String:
    """One string: a material and a gauge.

    Parameters
    ----------
    material : Material or str
        A :class:`racket.strings.material.Material`, or its name or alias ("poly", "gut").
    gauge : float or str
        Its diameter [m], or a gauge name ("16L"; :data:`racket.strings.sizes.GAUGES`).
    """

    material: Material
    gauge: float

    def __post_init__(self):
        if not isinstance(self.material, Material):
            key = material_key(self.material, "material")
            object.__setattr__(self, "material", MATERIALS[key])
        object.__setattr__(self, "gauge", diameter(self.gauge))

    def axial_stiffness(self, tension: float) -> float:
        """EA [N] at ``tension`` [N] in a bed
        (:meth:`racket.strings.material.Material.axial_stiffness`).

        Parameters
        ----------
        tension : float
            The string's tension [N].
        """
        return self.material.axial_stiffness(self.gauge, tension)

    @property
    def linear_density(self) -> float:
        """Mass per length [kg/m]: density x pi d**2 / 4."""
        return self.material.density * np.pi * self.gauge**2 / 4.0

    def describe(self, gauge_too: bool = True) -> str:
        """The string as the conditions say it, "polyester 1.25 mm" (the material alone if
        not ``gauge_too``).

        Parameters
        ----------
        gauge_too : bool, optional
            Say the gauge.
        """
        mm = f"{1e3 * self.gauge:.2f}"
        mm = mm if abs(float(mm) - 1e3 * self.gauge) < 1e-9 else f"{1e3 * self.gauge:.4g}"
        return f"{self.material.name} {mm} mm" if gauge_too else self.material.name


STRINGS = {
    "polyester": String("polyester", 1.25e-3),
    "nylon": String("nylon", 1.30e-3),
    "multifilament": String("multifilament", 1.30e-3),
    "natural-gut": String("natural-gut", 1.30e-3),
}
"""String presets by name, at their material's usual gauge (polyester 16L, 1.25 mm; the
others 16, 1.30 mm; an assumption).  A hybrid is named "MAINS/CROSSES"
(``"natural-gut/polyester"``; :func:`stringing`)."""

HYBRID = "natural-gut/polyester"
"""The hybrid offered beside the presets (``racket-impact strings``, the page): natural-gut
mains, polyester crosses, the classic hybrid (**an assumption**: no survey of hybrids was
found)."""

LINEAR = "linear"
"""The ``string`` that asks for the paper's bed by name: a linear, lossless, massless spring
(R. Cross, Am. J. Phys. 68, 2000, Sec. VIII) of the bed's stiffness, with no string, gauge,
pattern or state (:func:`restrung`, :func:`racket.specs.from_specs`)."""

STRING_CHOICES = (*STRINGS, HYBRID)
"""The strings offered to compare: every preset of :data:`STRINGS` and :data:`HYBRID`."""


def string(name, gauge=None, argument: str = "string") -> String:
    """The preset string ``name`` (:data:`STRINGS`, or a material's alias: "poly", "gut"),
    at ``gauge`` [m or a name] if given.

    Parameters
    ----------
    name : str
        The preset.
    gauge : float or str, optional
        Its gauge [m], or a name ("17"); default the preset's.
    argument : str, optional
        The argument or option ``name`` came from, as a message quotes it.
    """
    preset = STRINGS[material_key(name, argument)]
    return preset if gauge is None else String(preset.material, gauge)


@dataclass(frozen=True)
class Stringing:
    """What a racket is strung with: mains and crosses, pattern, tension and state.

    Parameters
    ----------
    mains : String or str
        The mains' string (a :class:`String`, or a preset name of :data:`STRINGS`).
    crosses : String or str or None
        The crosses' string; None (default) for the mains' (a hybrid has two).
    pattern : (int, int) or str
        Mains x crosses [-]: (16, 19) (default) or "16x19"
        (:data:`racket.strings.sizes.PATTERN_RANGE`).
    tension : float or None
        Reference (stringing) tension [N], 20-80 lb; None when the bed's stiffness is
        measured instead (:meth:`bed`'s ``stiffness``).
    state : str
        ``"fresh"`` (default) or ``"played"`` (:data:`STATES`).
    """

    mains: String
    crosses: String | None = None
    pattern: tuple = REFERENCE_PATTERN
    tension: float | None = None
    state: str = "fresh"

    def __post_init__(self):
        mains = self.mains if isinstance(self.mains, String) else string(self.mains, None, "mains")
        crosses = self.crosses if self.crosses is not None else mains
        crosses = crosses if isinstance(crosses, String) else string(crosses, None, "crosses")
        object.__setattr__(self, "mains", mains)
        object.__setattr__(self, "crosses", crosses)
        object.__setattr__(self, "pattern", parse_pattern(self.pattern))
        if self.tension is not None:
            low, high = (t * LB for t in TENSION_RANGE_LB)
            tension = in_range("tension", self.tension, low, high, "N", slips=(LB_AS_N, KG_AS_N))
            object.__setattr__(self, "tension", tension)
        choice("state", self.state, STATES)

    @property
    def hybrid(self) -> bool:
        """True when the mains and crosses differ."""
        return self.mains != self.crosses

    @property
    def bed_tension(self) -> float:
        """The strings' tension in the bed [N]: the reference tension, times 1 - the
        material's tension loss (mains and crosses averaged) when played.
        """
        if self.tension is None:
            raise ValueError("this stringing has no tension: give one, or the bed's stiffness")
        if self.state == "fresh":
            return self.tension
        kept = 1.0 - 0.5 * (self.mains.material.tension_loss + self.crosses.material.tension_loss)
        return self.tension * kept

    @property
    def pattern_factor(self) -> float:
        """Strings per width relative to 16x19 [-]: (mains + crosses) / 35 (**an
        assumption**: the membrane's tension per width grows with the string count).
        """
        return sum(self.pattern) / sum(REFERENCE_PATTERN)

    def stiffness(self, area: float) -> float:
        """The bed's stiffness at its centre [N/m]: the membrane model at the bed's
        (played) tension, times :attr:`pattern_factor`:
        k = string_bed_stiffness(T_bed, A) (m + c) / 35.

        Parameters
        ----------
        area : float
            The bed's area [m^2].
        """
        return string_bed_stiffness(self.bed_tension, area) * self.pattern_factor

    def dt(self, area: float) -> float:
        """The ERT's dynamic tension [kp/cm]: the force that deflects the bed 1 cm, per cm,
        :meth:`stiffness` (1 + :meth:`stretch` (1 cm)**2) / 980.665 N/m
        (:func:`racket.strings.ert.dt_reading`).

        Parameters
        ----------
        area : float
            The bed's area [m^2].
        """
        return dt_reading(self.stiffness(area), self.stretch(area))

    def axial_stiffness(self, tension: float) -> float:
        """EA [N] at ``tension`` [N], the mean of the mains' and the crosses'.

        Parameters
        ----------
        tension : float
            The strings' tension in the bed [N].
        """
        return 0.5 * (self.mains.axial_stiffness(tension) + self.crosses.axial_stiffness(tension))

    def stretch(self, area: float, stiffness: float | None = None) -> float:
        """How fast the bed stiffens as it deflects [1/m^2]: F = k w (1 + stretch w**2).

        A string of length L at tension T pinned at both ends and pushed at its middle by w
        lengthens by 2 w**2 / L (strain 2 w**2 / L**2), so its tension rises by EA times
        that, and F = 2 T' w / l with l its half length: F = (4 T / L) w +
        (8 (EA - T) / L**3) w**3 to third order, so stretch = 2 (EA - T) / (T L**2).  T is
        the bed's tension, L the diameter of the circle of the bed's area and EA the mean
        of the mains' and crosses' at that tension, TWU's secant over an impact's strain
        step (:mod:`racket.strings.twu_test`) (**assumptions**: the bed stiffens as its
        middle string does).

        Parameters
        ----------
        area : float
            The bed's area [m^2].
        stiffness : float, optional
            The bed's measured stiffness [N/m]: T is then the tension that gives it in the
            membrane model; default: T = :attr:`bed_tension`.
        """
        if stiffness is None:
            tension = self.bed_tension
        else:
            stiffness = positive("stiffness", stiffness, "N/m")  # (a search's too: no range)
            per_newton = string_bed_stiffness(1.0, area) * self.pattern_factor  # k is linear in T
            tension = stiffness / per_newton
        length = 2.0 * np.sqrt(area / np.pi)
        return 2.0 * (self.axial_stiffness(tension) - tension) / (tension * length**2)

    @property
    def loss(self) -> float:
        """Fraction [-] of the energy stored in the bed that a load and unload dissipates:
        1 - 0.97**2 (Kawazoe's steel ball) + 0.3 (ER_nylon - ER), ER the single-string
        energy return of the mains and crosses averaged (:data:`LOSS_PER_RETURN`).  The
        friction between mains and crosses is inside Kawazoe's number.
        """
        reference = MATERIALS["nylon"].energy_return
        returned = 0.5 * (self.mains.material.energy_return + self.crosses.material.energy_return)
        return 1.0 - STEEL_BALL_COR**2 + LOSS_PER_RETURN * (reference - returned)

    def mass(self, area: float, aspect: float = HEAD_ASPECT) -> float:
        """Mass of the strings inside the head [kg]: on an ellipse of length / width
        ``aspect``, a main's mean chord is pi/4 of the length and a cross's pi/4 of the
        width, so mass = pi/4 (m lambda_m length + c lambda_c width), lambda the mass per
        length (:attr:`String.linear_density`).

        Parameters
        ----------
        area : float
            The bed's area [m^2].
        aspect : float, optional
            Its length / width [-] (:data:`racket.strings.head.HEAD_ASPECT`).
        """
        length = np.sqrt(4.0 * area * aspect / np.pi)
        mains, crosses = self.pattern
        chords = (mains * self.mains.linear_density * length
                  + crosses * self.crosses.linear_density * length / aspect)  # fmt: skip
        return float(0.25 * np.pi * chords)

    def moving_mass(self, area: float, aspect: float = HEAD_ASPECT) -> float:
        """The part of :meth:`mass` that moves with the ball [kg]: the first mode's modal
        mass of a circular membrane for its centre's deflection, :data:`MODAL_MASS_RATIO`
        (0.27) of the mass: the bed's :attr:`racket.StringBed.moving_mass`.

        **An assumption**: the frame, whose mass is the strung racket's as measured, keeps
        it as well, so that it is counted twice (3.6 g of a 300 g racket for polyester 16L
        16x19 in 100 in^2); taking it out of the frame would need the strings' mass apart
        from the frame's, which no spec sheet gives.

        Parameters
        ----------
        area : float
            The bed's area [m^2].
        aspect : float, optional
            Its length / width [-].
        """
        return MODAL_MASS_RATIO * self.mass(area, aspect)

    def bed(self, extent, width=None, profile="membrane", stiffness=None) -> StringBed:
        """The :class:`racket.StringBed` of this stringing over ``extent``: its stiffness,
        stretch, loss and moving mass, and ``stringing`` = self.

        Parameters
        ----------
        extent : (float, float)
            Where the strings are [m from the tip].
        width : float, optional
            The bed's width [m]; None for length / :data:`racket.strings.head.HEAD_ASPECT`.
        profile : str, optional
            ``"membrane"`` (default) or ``"uniform"``.
        stiffness : float, optional
            A measured stiffness [N/m] at the centre (from an ERT's DT:
            :func:`racket.strings.ert.stiffness_from_dt`) instead of the tension's; the
            stretch then follows from it.
        """
        shape = StringBed(BED_STIFFNESS_RANGE[0], extent, width, profile)  # its shape alone
        if stiffness is not None:  # as typed, before the stretch that follows from it
            stiffness = bed_stiffness("stiffness", stiffness)
        k = self.stiffness(shape.area) if stiffness is None else stiffness
        return StringBed(
            k,
            extent,
            width,
            profile,
            self.stretch(shape.area, stiffness),
            self.loss,
            self,
            moving_mass=self.moving_mass(shape.area, shape.aspect),
        )

    def describe(self, tension: str | None = None) -> str:
        """Short text for the conditions: "polyester 1.25 mm 16x19 at 55 lb, fresh".

        Parameters
        ----------
        tension : str, optional
            The tension as the user typed it ("25 kg"), said instead of :attr:`tension`.
        """
        if not self.hybrid:
            strings = self.mains.describe()
        elif self.mains.gauge == self.crosses.gauge:
            strings = f"{self.mains.describe(False)}/{self.crosses.describe()}"
        else:
            strings = f"{self.mains.describe()}/{self.crosses.describe()}"
        if tension is None and self.tension is not None:
            tension = f"{shown(round(self.tension / LB, 2))} lb"
        tension = f" at {tension}" if tension else ""
        return f"{strings} {self.pattern[0]}x{self.pattern[1]}{tension}, {self.state}"


def stringing(
    name, gauge=None, pattern=REFERENCE_PATTERN, tension_n=None, state="fresh", argument="name"
):
    """A :class:`Stringing` from a preset name (:data:`STRINGS`, or an alias) or a hybrid
    "MAINS/CROSSES" ("natural-gut/polyester").

    Parameters
    ----------
    name : str
        The preset, or two joined by "/" (a word; anything else is refused, saying what it
        takes).
    gauge : float or str, optional
        The gauge of every string [m or a name]; default each preset's.
    pattern : (int, int) or str, optional
        Mains x crosses [-]; default 16x19.
    tension_n : float, optional
        Reference tension [N].
    state : str, optional
        ``"fresh"`` or ``"played"``.
    argument : str, optional
        The argument or option ``name`` came from, as a message quotes it ("--string").
    """
    takes = f"a preset or MAINS/CROSSES ({', '.join(STRINGS)}; e.g. {HYBRID!r})"
    instance(argument, name, str, takes)
    parts = name.split("/")
    if len(parts) > 2:
        raise ValueError(f"{argument} must be {takes}, got {name!r}")
    if len(parts) == 2 and not all(part.strip() for part in parts):
        raise ValueError(f"{argument} must give the mains and the crosses either side of '/' "
                         f"(e.g. {HYBRID!r}), got {name!r}")  # fmt: skip
    if tension_n is not None:
        tension_n = finite("tension_n", tension_n, "N")
    mains, crosses = (string(part, gauge, argument) for part in (parts * 2)[:2])
    return Stringing(mains, crosses, REFERENCE_PATTERN if pattern is None else pattern,
                     tension_n, state)  # fmt: skip


def restrung(bed: StringBed, string=None, gauge=None, pattern=None, state=None, stiffness=None):
    """``bed`` strung again: what is given replaces the bed's, the rest is kept (a new
    ``string`` comes at its own gauge unless ``gauge`` is given).  A bed with no stringing
    (the paper's spring) gains one only with ``string``, keeping its stiffness; a
    ``stiffness`` (measured; from an ERT's DT: :func:`racket.strings.ert.stiffness_from_dt`)
    replaces the tension's.  The tension itself is :func:`racket.specs.restring.with_tension`'s.

    Parameters
    ----------
    bed : StringBed
        The bed to restring.
    string : str, optional
        A preset (:data:`STRINGS`) or "MAINS/CROSSES"; :data:`LINEAR` for the paper's plain
        spring of the bed's stiffness.
    gauge : float or str, optional
        The gauge [m], or a name ("16L").
    pattern : str or (int, int), optional
        Mains x crosses [-].
    state : str, optional
        ``"fresh"`` or ``"played"``.
    stiffness : float, optional
        The bed's measured stiffness [N/m].
    """
    old = bed.stringing
    if string == LINEAR:
        for name, value in (("gauge", gauge), ("pattern", pattern), ("state", state)):
            if value is not None:
                raise ValueError(
                    f"{name} describes a string, and {LINEAR!r} is the paper's plain spring "
                    "with none: drop it, or name a string (e.g. polyester)"
                )
        k = bed.stiffness if stiffness is None else stiffness
        return StringBed(k, bed.extent, bed.width, bed.profile)
    if old is None and string is None:
        for name, value in (("gauge", gauge), ("pattern", pattern), ("state", state)):
            if value is not None:
                raise ValueError(
                    f"{name} describes a string, and this string bed has none (the paper's "
                    "spring): give the string too, e.g. polyester"
                )
        return bed if stiffness is None else replace(bed, stiffness=stiffness)
    if string is not None:
        mains = stringing(string, gauge)
        mains, crosses = mains.mains, mains.crosses
    else:
        mains, crosses = (old.mains, old.crosses) if gauge is None else (
            String(old.mains.material, gauge), String(old.crosses.material, gauge))  # fmt: skip
    kept = old or Stringing(mains)
    tension = None if stiffness is not None else kept.tension
    strung = Stringing(mains, crosses, pattern or kept.pattern, tension, state or kept.state)
    if stiffness is None and tension is None:  # a measured or a plain bed: its stiffness kept
        stiffness = bed.stiffness
    return strung.bed(bed.extent, bed.width, bed.profile, stiffness)
