"""Real tennis balls: presets of :class:`~ball.stiffening.StiffeningHysteresis` calibrated to
what is published, with the ITF's static bands of each type beside them.

What each preset is calibrated to (``data/measurements.md``, section 1):

* its rigid-surface COR at 7.06 m/s (the ITF's 254 cm drop): the middle of its type's ITF
  rebound band, e = sqrt(h / H) (ITF Rules of Tennis, Appendix I);
* the stiffness k, the same for every pressurised type: the middle of the interval
  [3.29e4, 4.35e4] N/m of k for which the 254 cm drop of the type 2 ball both compresses it
  by at most 8.5 mm (R. Cross, "about 6 mm", accepted 5-8.5) and lasts at least 3.5 ms
  (Cross 2000, Sec. III, "about 4 ms", accepted 3.5-4.5).  A loading curve that only
  stiffens cannot give both 6 mm and 4 ms: a real ball's wall buckles early in the contact
  and softens it (Cross, Sports Eng. 2, 1999), which no monotone law in the force domain
  follows; k = 3.8e4 N/m gives 7.9 mm and 3.7 ms.  Its secant stiffness at 7.06 m/s is
  about 5e4 N/m, near the seed paper's "about 4e4 N/m during compression";
* the fall of the COR with speed: **an assumption** (no table of a tennis ball's COR against
  speed could be reached; Cross 1999, Haake et al. 2003 and Goodwill et al. 2005 report the
  fall only in words, and Kawazoe 2002 finds the COR on a clamped racket nearly independent
  of speed).  The ITF type 2 ball's rigid-surface COR falls from the middle of its band at
  7.06 m/s to :data:`COR_AT_30` at 30 m/s (plausible range :data:`COR_AT_30_RANGE`); the
  other pressurised types fall by the same amount.  When a published table turns up, it
  replaces :data:`COR_AT_30` here, in one place.

Why the ITF deformation test is a separate check: it is quasi-static (the platen advancing
at about 3.3 mm/s, a 5 s hold before the reading), and a ball is viscoelastic, so its static
stiffness (80.07 N over 5.6-7.4 mm, 10.9-14.3 kN/m) is about a third of its stiffness in a
4 ms impact.  The dynamic law need not pass through the ITF point: each preset keeps its
type's static bands (:class:`ItfBands`) beside its dynamic law, and ``racket-impact ball``
reports the two apart.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from functools import cache, partial

from ball.bodies import Ball
from ball.stiffening import StiffeningHysteresis
from common.units import GRAVITY

ITF_DROP = 2.54
"""Drop height of the ITF rebound test [m] (100 in; ITF Rules of Tennis, Appendix I)."""

ITF_DROP_SPEED = math.sqrt(2.0 * GRAVITY * ITF_DROP)
"""Speed [m/s] of the ITF rebound test's ball on reaching the concrete, 7.06 m/s (air drag
neglected)."""

TWU_SPEED = 16.5
"""Ball speed [m/s] towards the strings of a racket at rest in TWU's tests, "Racquet
Control" part 1 (16.5 +/- 1 m/s)."""

ITF_FORCE = 8.165 * GRAVITY
"""Load [N] of the ITF deformation test, 8.165 kg, 80.07 N (ITF Rules of Tennis, App. I)."""

DROP_CONTACT_TIME = (4e-3, (3.5e-3, 4.5e-3))
"""Contact time [s] of a ball dropped onto concrete at low speed, "about 4 ms" (Cross 2000,
Sec. III, citing Cross 1999), and the band accepted at 7.06 m/s, +-0.5 ms (issue 24)."""

DROP_COMPRESSION = (6e-3, (5e-3, 8.5e-3))
"""Compression [m] of a ball dropped from 254 cm onto concrete, "about 6 mm" (R. Cross,
tennis.html), and the band accepted (issue 24; wider above: a loading curve that only
stiffens cannot reach 6 mm with a 4 ms contact, see the module docstring)."""

BALL_MASS = 0.0577
"""Mass [kg] of every ITF ball: the middle of 56.0-59.4 g (ITF Rules of Tennis, App. I)."""

RADIUS = 0.0335
"""Radius [m] of ITF type 1, type 2 and high-altitude balls: the middle of the 6.54-6.86 cm
diameter (ITF Rules of Tennis, Appendix I)."""

RADIUS_TYPE_3 = 0.035725
"""Radius [m] of the ITF type 3 (slow, larger) ball: the middle of its 6.99-7.30 cm diameter
(ITF Rules of Tennis, Appendix I)."""

STIFFNESS = 3.8e4
"""Small-compression stiffness k [N/m] of the pressurised presets (see the module
docstring: the middle of the interval that meets the sourced compression and contact time
of the 254 cm drop, rounded)."""

CALIBRATION_SPEED = 30.0
"""Speed [m/s] at which the assumed COR :data:`COR_AT_30` is set."""

COR_AT_30 = 0.62
"""Rigid-surface COR of the ITF type 2 ball at 30 m/s: **an assumption** (plausible range
:data:`COR_AT_30_RANGE`).  Qualitative sources: the COR falls with speed on a rigid surface
(Cross 2000, Sec. III; Haake, Carre & Goodwill, J. Sports Sci. 21, 2003)."""

COR_AT_30_RANGE = (0.55, 0.70)
"""Plausible range of :data:`COR_AT_30` (an assumption; the docs show how the headline
answers move over it)."""

PUNCTURED_COR_RATIO = 0.80
"""A punctured ball's COR over a pressurised one's: "about 20 % lower" (Haake, Carre &
Goodwill 2003, abstract); taken at every speed (an assumption)."""

PUNCTURED_STIFFNESS_RATIO = 0.65
"""A punctured ball's dynamic (secant) stiffness over a pressurised one's at 7.06 m/s:
"about 35 % lower" (Haake, Carre & Goodwill 2003, abstract)."""

PRESSURELESS_MEETS_PUNCTURED_AT = 70.0
"""Speed [m/s] at which the pressureless ball's COR reaches the punctured ball's: **an
assumption** (Haake et al. 2003: a pressureless ball's COR falls faster with speed and
approaches a punctured ball's at high speed; here it reaches it at the top of the speeds
studied, so that it approaches it without crossing)."""


@dataclass(frozen=True)
class ItfBands:
    """A ball type's ITF bands (ITF Rules of Tennis, Appendix I; the newer table, as
    reproduced by TWU "Tennis Ball Performance Testing", 2021).

    Attributes
    ----------
    rebound_cm : tuple
        Rebound height from a 254 cm drop onto concrete [cm].
    forward_deformation_cm : tuple
        Static compression under 80.07 N [cm].
    return_deformation_cm : tuple
        Static compression on the way back from a 25.4 mm compression, at 80.07 N [cm].
    diameter_cm : tuple
        Diameter [cm].
    """

    rebound_cm: tuple
    forward_deformation_cm: tuple
    return_deformation_cm: tuple
    diameter_cm: tuple

    @property
    def cor(self) -> tuple:
        """The rebound band as a COR at 7.06 m/s, sqrt(h / 254 cm) [-] (derived)."""
        return tuple(math.sqrt(0.01 * h / ITF_DROP) for h in self.rebound_cm)

    @property
    def static_stiffness(self) -> tuple:
        """80.07 N over the forward-deformation band [N/m] (derived)."""
        return tuple(ITF_FORCE / (0.01 * d) for d in reversed(self.forward_deformation_cm))


_SMALL, _LARGE = (6.54, 6.86), (6.99, 7.30)
TYPE_1_BANDS = ItfBands((138.0, 151.0), (0.56, 0.74), (0.74, 1.08), _SMALL)
TYPE_2_BANDS = ItfBands((135.0, 147.0), (0.56, 0.74), (0.80, 1.08), _SMALL)
TYPE_3_BANDS = ItfBands((135.0, 147.0), (0.56, 0.74), (0.80, 1.08), _LARGE)
HIGH_ALTITUDE_BANDS = ItfBands((122.0, 135.0), (0.56, 0.74), (0.80, 1.08), _SMALL)


def calibrated_law(
    mass: float, radius: float, k: float, cor_low: float, speed_high: float, cor_high: float
) -> StiffeningHysteresis:
    """The :class:`StiffeningHysteresis` of stiffness ``k`` and limit ``radius`` whose
    rigid-surface COR is ``cor_low`` at :data:`ITF_DROP_SPEED` and ``cor_high`` at
    ``speed_high``: the compressions at the two speeds depend on the loading only, and the
    COR is linear in the compression, so e0 and the slope follow exactly.

    Parameters
    ----------
    mass : float
        Ball mass [kg].
    radius : float
        Ball radius [m], the loading's limit.
    k : float
        Small-compression stiffness [N/m].
    cor_low : float
        Rigid-surface COR at 7.06 m/s [-].
    speed_high : float
        Second speed [m/s].
    cor_high : float
        Rigid-surface COR at ``speed_high`` [-].
    """
    loading = StiffeningHysteresis(k, radius, 1.0, 0.0)
    x_low = float(loading.peak_compression(mass, ITF_DROP_SPEED))
    x_high = float(loading.peak_compression(mass, speed_high))
    slope = (cor_low - cor_high) / (x_high - x_low)
    return StiffeningHysteresis(k, radius, cor_low + slope * x_low, slope)


def _middle(band) -> float:
    return 0.5 * (band[0] + band[1])


@dataclass(frozen=True)
class BallPreset:
    """A named real ball: how its law is calibrated, and its ITF bands.

    Attributes
    ----------
    name : str
        Preset name.
    description : str
        One line for a person.
    radius : float
        Radius [m].
    bands : ItfBands or None
        The ITF bands of its type (None: not an approved ball).
    build : callable
        Returns the calibrated :class:`StiffeningHysteresis`.
    sources : tuple of str
        Where each number comes from; assumptions say so.
    """

    name: str
    description: str
    radius: float
    bands: ItfBands | None
    build: object = field(repr=False)
    sources: tuple = ()

    def ball(self) -> Ball:
        """The preset as a :class:`~ball.Ball`."""
        return Ball(BALL_MASS, self.build(), self.radius)


def pressurised_law(
    bands: ItfBands, radius: float, cor_at_30: float = COR_AT_30
) -> StiffeningHysteresis:
    """A pressurised ball in ``bands``: the type 2 stiffness, its COR the middle of its band
    at 7.06 m/s, falling by as much as the type 2 ball's by 30 m/s (an assumption).

    Parameters
    ----------
    bands : ItfBands
        The ball's ITF type.
    radius : float
        Its radius [m].
    cor_at_30 : float
        The type 2 ball's rigid-surface COR at 30 m/s [-] (:data:`COR_AT_30`, an
        assumption; other values show how an answer depends on it).
    """
    type_2_fall = _middle(TYPE_2_BANDS.cor) - cor_at_30
    cor_low = _middle(bands.cor)
    return calibrated_law(
        BALL_MASS, radius, STIFFNESS, cor_low, CALIBRATION_SPEED, cor_low - type_2_fall
    )


@cache  # solved once (a root search), shared by the pressureless ball
def _punctured() -> StiffeningHysteresis:
    """A punctured ball: COR 20 % and secant stiffness at 7.06 m/s 35 % below type 2."""
    from scipy.optimize import brentq  # scipy loads on first use

    type_2 = pressurised_law(TYPE_2_BANDS, RADIUS)
    target = PUNCTURED_STIFFNESS_RATIO * type_2.secant_stiffness(BALL_MASS, ITF_DROP_SPEED)

    def secant(k):
        law = StiffeningHysteresis(k, RADIUS, 1.0, 0.0)
        return law.secant_stiffness(BALL_MASS, ITF_DROP_SPEED) - target

    k = brentq(secant, 0.1 * STIFFNESS, STIFFNESS, xtol=1e-9)
    cor_low = PUNCTURED_COR_RATIO * _middle(TYPE_2_BANDS.cor)
    cor_30 = PUNCTURED_COR_RATIO * COR_AT_30
    return calibrated_law(BALL_MASS, RADIUS, k, cor_low, CALIBRATION_SPEED, cor_30)


def _pressureless() -> StiffeningHysteresis:
    """A pressureless ball: type 2 at 7.06 m/s, reaching the punctured ball's COR at
    :data:`PRESSURELESS_MEETS_PUNCTURED_AT`.
    """
    speed = PRESSURELESS_MEETS_PUNCTURED_AT
    punctured = _punctured()
    cor_high = float(punctured.cor_at_speed(BALL_MASS, speed))
    return calibrated_law(BALL_MASS, RADIUS, STIFFNESS, _middle(TYPE_2_BANDS.cor), speed, cor_high)


_ITF = "ITF Rules of Tennis, Appendix I (rebound, deformation and size bands)"
_DROP = (
    "k: compression <= 8.5 mm (Cross, tennis.html: about 6 mm) and contact >= 3.5 ms (Cross "
    "2000, Sec. III: about 4 ms) for the 254 cm drop"
)
_FALL = (
    f"ASSUMPTION: the type 2 COR falls to {COR_AT_30:g} at 30 m/s (range "
    f"{COR_AT_30_RANGE[0]:g}-{COR_AT_30_RANGE[1]:g}); other types fall as much"
)
_HAAKE = "Haake, Carre & Goodwill, J. Sports Sci. 21 (2003) 839 (abstract)"

BALL_PRESETS = {
    preset.name: preset
    for preset in (
        BallPreset(
            "itf-type-2", "ITF type 2 (medium pace), the standard ball", RADIUS,
            TYPE_2_BANDS, partial(pressurised_law, TYPE_2_BANDS, RADIUS), (_ITF, _DROP, _FALL),
        ),
        BallPreset(
            "itf-type-1", "ITF type 1 (fast): livelier", RADIUS,
            TYPE_1_BANDS, partial(pressurised_law, TYPE_1_BANDS, RADIUS),
            (_ITF, _DROP, _FALL, "ASSUMPTION: the type 2 stiffness"),
        ),
        BallPreset(
            "itf-type-3", "ITF type 3 (slow): 6.99-7.30 cm across", RADIUS_TYPE_3,
            TYPE_3_BANDS, partial(pressurised_law, TYPE_3_BANDS, RADIUS_TYPE_3),
            (_ITF, _DROP, _FALL, "ASSUMPTION: the type 2 stiffness"),
        ),
        BallPreset(
            "high-altitude", "ITF high altitude: lower rebound", RADIUS,
            HIGH_ALTITUDE_BANDS, partial(pressurised_law, HIGH_ALTITUDE_BANDS, RADIUS),
            (_ITF, _DROP, _FALL, "ASSUMPTION: the type 2 stiffness"),
        ),
        BallPreset(
            "pressureless", "pressureless: type 2 when slow, its COR falls faster", RADIUS,
            TYPE_2_BANDS, _pressureless,
            (_ITF, _DROP, _HAAKE, "ASSUMPTION: the type 2 stiffness; its COR reaches the "
             f"punctured ball's at {PRESSURELESS_MEETS_PUNCTURED_AT:g} m/s"),
        ),
        BallPreset(
            "punctured", "punctured or worn out: COR 20 % and stiffness 35 % below type 2",
            RADIUS, None, _punctured,
            (_HAAKE, "ASSUMPTION: the 20 % holds at every speed"),
        ),
    )
}  # fmt: skip
"""The real-ball presets by name."""

DEFAULT_BALL = "itf-type-2"
"""The ball of every player-facing answer (the paper's racket keeps the paper's ball)."""
