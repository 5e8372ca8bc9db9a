"""Baseballs and softballs: A. M. Nathan's ball law, and presets of it.

Nathan's law (A. M. Nathan, "Dynamics of the baseball-bat collision", Am. J. Phys. 68, 979
(2000), eqs. 7-8; "N2000" below) compresses the ball along F = k1 u**alpha and lets it
expand along F = k2 u**beta, with

    beta = (1 + alpha) / e0**2 - 1,

where u [m] is the compression of the ball's radius, F [N] the force, k1 [N/m**alpha] the
stiffness coefficient, alpha [-] the loading exponent and e0 [-] the ball's COR on a
perfectly rigid object.  k2 [N/m**beta] makes the two branches meet at the largest
compression u_max: k2 = k1 u_max**(alpha - beta).  The expansion returns
(1 + alpha) / (1 + beta) = e0**2 of the energy stored, so a bounce on a rigid wall has COR
e0 at every speed.  This is :meth:`ball.PowerLawHysteresis.with_cor` ``(k1, alpha, e0)``
exactly: its unloading F = F_max (u / u_max)**b, b = beta, is the same curve.

Every number below has its source beside it or the word ASSUMPTION.  "bats.md" is the
project's collected inputs for bats (``data/bats.md``, sections 2 and 4.4);
"[quoted]" marks a number read where someone else reports its source.

**Baseballs** (:data:`BASEBALL_PRESETS` ``baseball``, ``baseball-low-speed``,
``baseball-fig2``, ``mlb-low``, ``mlb-high``): k1 = 6.53e7 N/m**1.84 and alpha = 1.84
(N2000, Fig. 2 caption; the caption prints no unit, N and m reproduce the figure's axes).
N2000 chose them as "intelligent guesses based on static hysteresis measurements and dynamic
measurements done at low speed" (p. 981) and restates them for no collision: the same k1 and
alpha in every case is an ASSUMPTION.  The presets differ in e0 only: N2000's high-speed case
(0.50, p. 986), its low-speed case (0.66, pp. 984-985), its Fig. 2 curve (0.53, a 58 m/s
impact on a rigid surface), and the ends of the Major League rule, 0.514-0.578 for a 26 m/s
impact on a massive object (N2000, footnote 13).  N2000 keeps e0 constant within each case
(footnote 17 adds that a real ball's e0 "decreases slowly with increasing impact speed"); so
does this law.  Mass and radius are not stated in N2000: 0.145 kg and 36.6 mm are
ASSUMPTIONS inside the rules' 141.7-148.8 g and 36.38-37.39 mm (5-5 1/4 oz and a
9-9 1/4 in circumference, Official Baseball Rules 3.01, [quoted] in bats.md section 2).  The
radius does not enter the law: it only bounds the compression (:func:`ball.warn_if_squashed`).

**Softballs** (``softball-44-375`` ... ``softball-50-525``: COR grade, then compression in
lb): the 12-inch ball's COR grades 0.44, 0.47 and 0.50 and its compressions of 375 or 525 lb
to squeeze it by 1/4 in (Softball News, [quoted] in bats.md section 4.4).  Its mass and
radius are the middle of the 12-inch ball's bands, 6 1/4-7 oz and 11 7/8-12 1/8 in of
circumference (Amateur Softball Association, Official Rules of Softball 2001, pp. 60-61,
[quoted] by The Physics Factbook, hypertextbook.com/facts/2001/WilliamPoon.shtml, which
quotes Encarta 98's 11.88-12.13 in and 6.25-7 oz alike).  No dynamic measurement of a
softball's force law was found, so its law is an ASSUMPTION: Nathan's alpha = 1.84, and the
k1 whose loading curve passes through the compression spec (:func:`softball_stiffness`).

What the softball's assumption implies.  The compression test is ASTM F1888's, "a slow rate
force-displacement measurement" (Sec. 1.2) of "the reduction in ball diameter under a
specified compressive load between two flat plates" (Sec. 2.1.2; the standard's text as
copied at mydoc123.com, p-535951).  Each plate's contact takes half of the 1/4 in, so the
force of a ball on a wall at compression u is taken as the test's at 2 u (the two contacts
are springs in series, and N2000's u is the compression of one radius: an ASSUMPTION that
holds for a deformation local to each contact).  375 lb at 1/8 in then gives k1 within 1 % of
Nathan's baseball's; read as 375 lb at the full 1/4 in, the spec would make k1
2**1.84 = 3.6 times smaller.  A ball is viscoelastic, and the test is slow: "the large
difference in strain rate between the test and play conditions sometimes caused
discrepancies" (L. V. Smith, on ASTM F2845, ASTM Standardization News).  A static number used
for a dynamic law makes the ball softer than in play, so the softball's contact is longer,
and its compression and its share of the energy in a collision with a flexible bat larger,
than a real softball's.  The COR grade is measured at 60 mph on a rigid wall (ASTM F1887,
bats.md section 4.4); the law gives it at every speed.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ball.bodies import Ball
from ball.laws import MAX_UNLOADING_EXPONENT, PowerLawHysteresis
from common.checks import GRAMS_AS_KG, OZ_AS_KG, finite, in_range, shown
from common.units import INCH, LB, OUNCE

NATHAN_K1 = 6.53e7
"""Nathan's k1 [N/m**1.84]: N2000, Fig. 2 caption (the unit derived: N and m reproduce the
figure's axes, bats.md section 2)."""

NATHAN_ALPHA = 1.84
"""Nathan's alpha [-], the loading exponent: N2000, Fig. 2 caption."""

E0_HIGH_SPEED = 0.50
"""e0 [-] of N2000's high-speed case (a 40 m/s ball onto a bat swung at 24 m/s): "We
assume e0 = 0.50" (N2000, p. 986).  The default baseball's."""

E0_LOW_SPEED = 0.66
"""e0 [-] of N2000's low-speed case (a 1 m/s ball onto a bat at rest; Cross's ball measured
0.64 at 1 m/s on a hard floor): N2000, pp. 984-985."""

E0_FIG2 = 0.53
"""e0 [-] of N2000's Fig. 2 curve, "for an impact of a 58-m/s (130-mph) ball with a rigid
surface" (Fig. 2 caption)."""

FIG2_SPEED = 58.0
"""Speed [m/s] of the impact on a rigid surface that N2000's Fig. 2 draws (caption)."""

MLB_COR_RANGE = (0.514, 0.578)
"""The COR [-] the rules of Major League Baseball allow a baseball, "for a 26 m/s [impact
on] a massive stationary object" (N2000, footnote 13)."""

MLB_COR_SPEED = 26.0
"""Speed [m/s] of the Major League rule's COR test (N2000, footnote 13)."""

BASEBALL_MASS = 0.145
"""Mass [kg] of the baseball presets: **an ASSUMPTION** (N2000 does not state it; the
repository of bats.md section 2 uses it), inside the rules' :data:`BASEBALL_MASS_RULE`."""

BASEBALL_MASS_RULE = (5.0 * OUNCE, 5.25 * OUNCE)
"""A baseball's mass [kg] by the rules, 5 to 5 1/4 oz, 141.7-148.8 g (Official Baseball
Rules 3.01, [quoted] in bats.md section 2)."""

BASEBALL_RADIUS = 0.0366
"""Radius [m] of the baseball presets: **an ASSUMPTION** (N2000 does not state it; the
repository of bats.md section 2 uses it), inside the rules' :data:`BASEBALL_RADIUS_RULE`.  It
does not enter Nathan's law."""

BASEBALL_RADIUS_RULE = (9.0 * INCH / (2.0 * math.pi), 9.25 * INCH / (2.0 * math.pi))
"""A baseball's radius [m] by the rules: a circumference of 9 to 9 1/4 in, 36.38-37.39 mm
(Official Baseball Rules 3.01, [quoted] in bats.md section 2)."""

MASS_RANGE = (0.1, 0.25)
"""The mass [kg] :func:`baseball` accepts: **an ASSUMPTION**, generous around a baseball's
and a 12-inch softball's (141.7-198.4 g), so that one typed in g or oz is refused with the
hint."""

LOWEST_E0 = math.ceil(1e3 * math.sqrt((NATHAN_ALPHA + 1.0) / (MAX_UNLOADING_EXPONENT + 1.0))) / 1e3
"""Lowest e0 [-] of Nathan's law here: below it the expansion exponent beta passes
:data:`ball.laws.MAX_UNLOADING_EXPONENT` (as :meth:`ball.PowerLawHysteresis.with_cor`)."""

SOFTBALL_MASS_RULE = (6.25 * OUNCE, 7.0 * OUNCE)
"""A 12-inch softball's mass [kg] by the rules, 6 1/4 to 7 oz (ASA, Official Rules of
Softball 2001, pp. 60-61, [quoted] by The Physics Factbook, hypertextbook.com)."""

SOFTBALL_MASS = 0.5 * (SOFTBALL_MASS_RULE[0] + SOFTBALL_MASS_RULE[1])
"""Mass [kg] of the softball presets: the middle of :data:`SOFTBALL_MASS_RULE`, 6.625 oz."""

SOFTBALL_RADIUS_RULE = (11.875 * INCH / (2.0 * math.pi), 12.125 * INCH / (2.0 * math.pi))
"""A 12-inch softball's radius [m] by the rules: a circumference of 11 7/8 to 12 1/8 in (ASA,
Official Rules of Softball 2001, pp. 60-61, [quoted] by The Physics Factbook)."""

SOFTBALL_RADIUS = 12.0 * INCH / (2.0 * math.pi)
"""Radius [m] of the softball presets: a 12 in circumference, the middle of the rule's."""

SOFTBALL_CORS = (0.44, 0.47, 0.50)
"""A softball's COR grades [-] (Softball News, [quoted] in bats.md section 4.4), measured on a
rigid wall at 60 mph (ASTM F1887)."""

SOFTBALL_COMPRESSIONS_LB = (375.0, 525.0)
"""A softball's compression grades [lbf]: the force to squeeze it by 1/4 in (Softball News,
[quoted] in bats.md section 4.4)."""

COMPRESSION_SQUEEZE = 0.25 * INCH
"""How far [m] the compression test squeezes the ball, 1/4 in (Softball News, [quoted] in
bats.md section 4.4): a reduction of its diameter between two flat plates (ASTM F1888,
Sec. 2.1.2)."""

TEST_CONTACTS = 2
"""Contacts [-] of the compression test: the ball between two flat plates (ASTM F1888,
Sec. 3.1).  Each takes half of :data:`COMPRESSION_SQUEEZE` at the test's force (**an
ASSUMPTION** of how the static test maps on to the compression of one radius in Nathan's law:
the contacts as springs in series)."""

SOFTBALL_ALPHA = NATHAN_ALPHA
"""The softball's loading exponent [-]: **an ASSUMPTION**, Nathan's baseball's (no dynamic
measurement of a softball's force law was found)."""

_N2000 = (
    "N2000 = A. M. Nathan, Am. J. Phys. 68, 979 (2000): law eqs. 7-8; k1 = 6.53e7 N/m^1.84, "
    "alpha = 1.84 (Fig. 2 caption)"
)
_SAME_K1 = "ASSUMPTION: Fig. 2's k1 and alpha in every case (N2000 restates them for none)"
_BASEBALL = (
    "ASSUMPTION: mass 0.145 kg and radius 36.6 mm (not in N2000; the rules allow 141.7-148.8 g "
    "and 36.38-37.39 mm, Official Baseball Rules 3.01, quoted)"
)
_CONSTANT = "ASSUMPTION: e0 the same at every speed (as N2000; its footnote 17: it falls slowly)"
_ASA = (
    "mass and radius: the middle of 6 1/4-7 oz and 11 7/8-12 1/8 in of circumference (ASA, "
    "Official Rules of Softball 2001, pp. 60-61, quoted by The Physics Factbook, "
    "hypertextbook.com/facts/2001/WilliamPoon.shtml)"
)
_GRADES = "COR and compression grades: Softball News, quoted in the project's data-hunt notes"
_SOFT_LAW = (
    "ASSUMPTION: alpha = 1.84 (Nathan's baseball), k1 through the compression spec at 1/8 in "
    "per plate (1/4 in of diameter between two plates, ASTM F1888): a static number in a "
    "dynamic law, softer than in play"
)


def nathan_law(e0: float, k1: float = NATHAN_K1, alpha: float = NATHAN_ALPHA):
    """Nathan's law (N2000 eqs. 7-8) as :class:`~ball.PowerLawHysteresis`: loading
    k1 u**alpha, expansion exponent beta = (1 + alpha) / e0**2 - 1.

    Parameters
    ----------
    e0 : float
        COR of the ball on a rigid object [-], in [:data:`LOWEST_E0`, 1].
    k1 : float
        Stiffness coefficient [N/m**alpha] (default Nathan's, :data:`NATHAN_K1`).
    alpha : float
        Loading exponent [-] (default Nathan's, :data:`NATHAN_ALPHA`).
    """
    return PowerLawHysteresis.with_cor(k1, alpha, e0)


def softball_stiffness(compression_lb: float, alpha: float = SOFTBALL_ALPHA) -> float:
    """The k1 [N/m**alpha] whose loading curve k1 u**alpha passes through a compression
    grade: ``compression_lb`` at u = :data:`COMPRESSION_SQUEEZE` / :data:`TEST_CONTACTS`
    (an ASSUMPTION, see the module docstring).

    Parameters
    ----------
    compression_lb : float
        Force [lbf] that squeezes the ball by 1/4 in between two plates, > 0.
    alpha : float
        Loading exponent [-] (default :data:`SOFTBALL_ALPHA`).
    """
    force = finite("compression_lb", compression_lb, "lbf") * LB
    if force <= 0.0:
        raise ValueError(f"compression_lb must be > 0 lbf, got {shown(compression_lb)}")
    return force / (COMPRESSION_SQUEEZE / TEST_CONTACTS) ** alpha


@dataclass(frozen=True)
class BaseballPreset:
    """A named baseball or softball: Nathan's law with its numbers, and their sources.

    Attributes
    ----------
    name, description, radius, sources
        As in :class:`ball.catalog.BallPreset`.
    mass : float
        Mass [kg].
    k1 : float
        Stiffness coefficient of the loading [N/m**alpha].
    alpha : float
        Loading exponent [-].
    e0 : float
        COR on a rigid object [-].
    """

    name: str
    description: str
    mass: float
    radius: float
    k1: float
    alpha: float
    e0: float
    sources: tuple = ()

    def build(self) -> PowerLawHysteresis:
        """The preset's law, :func:`nathan_law` ``(e0, k1, alpha)``."""
        return nathan_law(self.e0, self.k1, self.alpha)

    def ball(self) -> Ball:
        """The preset as a :class:`~ball.Ball`."""
        return Ball(self.mass, self.build(), self.radius)


def _baseball_preset(name: str, e0: float, what: str, source: str) -> BaseballPreset:
    return BaseballPreset(
        name, f"baseball, e0 {e0:g}: {what}", BASEBALL_MASS, BASEBALL_RADIUS, NATHAN_K1,
        NATHAN_ALPHA, e0, (_N2000, f"e0 = {e0:g}: {source}", _SAME_K1, _BASEBALL, _CONSTANT),
    )  # fmt: skip


def _softball_preset(cor: float, compression_lb: float) -> BaseballPreset:
    grade = f"{round(100 * cor)}-{compression_lb:g}"
    return BaseballPreset(
        f"softball-{grade}",
        f"12-inch softball, COR {cor:.2f}, compression {compression_lb:g} lb",
        SOFTBALL_MASS, SOFTBALL_RADIUS, softball_stiffness(compression_lb), SOFTBALL_ALPHA, cor,
        (_GRADES, _ASA, _SOFT_LAW, _N2000, _CONSTANT),
    )  # fmt: skip


BASEBALL_PRESETS = {
    preset.name: preset
    for preset in (
        _baseball_preset("baseball", E0_HIGH_SPEED, "Nathan's high-speed case, the default",
                         "N2000 p. 986 (high-speed case)"),
        _baseball_preset("baseball-low-speed", E0_LOW_SPEED, "Nathan's low-speed case",
                         "N2000 pp. 984-985 (low-speed case)"),
        _baseball_preset("baseball-fig2", E0_FIG2, "Nathan's Fig. 2 curve (58 m/s)",
                         "N2000 Fig. 2 caption"),
        _baseball_preset("mlb-low", MLB_COR_RANGE[0], "the Major League rule's lowest COR",
                         "N2000 footnote 13 (the rule's 0.514-0.578 at 26 m/s)"),
        _baseball_preset("mlb-high", MLB_COR_RANGE[1], "the Major League rule's highest COR",
                         "N2000 footnote 13 (the rule's 0.514-0.578 at 26 m/s)"),
        *(_softball_preset(cor, lb) for lb in SOFTBALL_COMPRESSIONS_LB for cor in SOFTBALL_CORS),
    )
}  # fmt: skip
"""The baseball and softball presets by name (see the module docstring)."""

DEFAULT_BASEBALL = "baseball"
"""The default baseball: Nathan's law with his high-speed case's e0 = 0.50."""


def baseball(e0: float = E0_HIGH_SPEED, mass: float = BASEBALL_MASS) -> Ball:
    """A baseball of Nathan's law (N2000 eqs. 7-8, k1 = 6.53e7 N/m**1.84, alpha = 1.84) at
    any e0, with the radius of the presets (:data:`BASEBALL_RADIUS`, an ASSUMPTION).

    Parameters
    ----------
    e0 : float
        COR of the ball on a rigid object [-], in (0, 1] (from :data:`LOWEST_E0`, where the
        expansion exponent reaches its limit); default N2000's high-speed case, 0.50.
    mass : float
        Ball mass [kg], in :data:`MASS_RANGE` (a mass in g or oz typed as kg is refused with
        the hint); default 0.145 kg (an ASSUMPTION, inside the rules' 141.7-148.8 g).

    Returns
    -------
    Ball

    Examples
    --------
    >>> from ball import WALL, baseball, collide
    >>> round(collide(baseball(0.55), WALL, 40.0).e, 6)
    0.55
    """
    e0 = finite("e0", e0)
    if not 0.0 < e0 <= 1.0:
        raise ValueError(f"e0 must be in (0, 1], got {shown(e0)}")
    e0 = in_range(
        "e0", e0, LOWEST_E0, 1.0,
        hint=" (below it Nathan's expansion exponent beta = (1 + alpha) / e0**2 - 1 passes "
        f"{MAX_UNLOADING_EXPONENT:g})",
    )  # fmt: skip
    mass = in_range("mass", mass, *MASS_RANGE, "kg", slips=(GRAMS_AS_KG, OZ_AS_KG))
    return Ball(mass, nathan_law(e0), BASEBALL_RADIUS)
