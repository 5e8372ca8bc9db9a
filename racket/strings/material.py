"""What tennis strings are made of: polyester, nylon, multifilament and natural gut, each with
the numbers the string bed needs (axial stiffness, energy return, tension loss, friction,
density), each number with its source or marked as an assumption.

The single-string numbers are TWU's (Tennis Warehouse University's string database, as
scraped; medians over the strings of each material, ``data/measurements.md`` sec. 5; the
stiffness test reconstructed in sec. 8, :mod:`racket.strings.twu_test`).  TWU records the
polymer, not the construction, and puts multifilaments with nylon; their own numbers come
from the same scrapes with the strings labelled by name (``data/twu_multifilament``): about 5 %
less stiff than the other nylons, with a little more friction.
"""

from __future__ import annotations

from dataclasses import dataclass

from common.checks import in_range, positive
from common.typechecks import instance
from common.units import LB
from racket.strings.twu_test import LB_PER_IN, TwuTest


@dataclass(frozen=True)
class Material:
    """A string material and its single-string numbers.

    Parameters
    ----------
    name : str
        The name as printed ("polyester", "natural gut").
    aliases : tuple of str
        Other names a user may type for it ("poly", "gut"), lower case, hyphenated.
    twu : TwuTest
        TWU's single-string test at 51 lb: its secant stiffnesses and the tension at impact
        (:mod:`racket.strings.twu_test`).
    reference_gauge : float
        The gauge [m] ``twu`` is taken to belong to (the usual gauge of the
        material; **an assumption**: TWU's medians mix gauges).
    energy_return : float
        Fraction [-] of the energy of TWU's single-string impact the string returns.
    tension_loss : float
        Fraction [-] of its tension a string loses in TWU's impact test.
    friction : float
        String-string coefficient of friction [-] (TWU, median).
    density : float
        Density of the material [kg/m^3].
    ball_friction : float
        String-ball coefficient of friction [-] (TWU, median).
    """

    name: str
    aliases: tuple
    twu: TwuTest
    reference_gauge: float
    energy_return: float
    tension_loss: float
    friction: float
    density: float
    ball_friction: float

    def __post_init__(self):
        if not isinstance(self.twu, TwuTest):
            raise TypeError(f"{self.name} twu must be a TwuTest, got {self.twu!r}")
        in_range(f"{self.name} reference_gauge", self.reference_gauge, 1e-3, 1.5e-3, "m")
        for fraction in ("energy_return", "tension_loss", "friction", "ball_friction"):
            in_range(f"{self.name} {fraction}", getattr(self, fraction), 0.0, 1.0)
        positive(f"{self.name} density", self.density, "kg/m^3")

    def axial_stiffness(self, gauge: float, tension: float) -> float:
        """Axial stiffness EA [N] of a string of this material and ``gauge`` at ``tension``
        in a bed: TWU's secant EA at the same stress (:meth:`TwuTest.axial_stiffness` at
        tension (g0 / gauge)**2), times (gauge / g0)**2, g0 the reference gauge (the
        cross-section's area scales with the gauge squared).

        Parameters
        ----------
        gauge : float
            The string's diameter [m].
        tension : float
            Its tension in the bed [N].
        """
        scale = (positive("gauge", gauge, "m") / self.reference_gauge) ** 2
        return scale * self.twu.axial_stiffness(positive("tension", tension, "N") / scale)


_TWU = "TWU string database (scraped), median over the material, data/measurements.md sec. 5"
_PET = "PET 1370-1390 kg/m^3 (24kjx.com.cn, 'Common plastic density reference table', 2026)"
_PA66 = "nylon 66 (PA66) 1140 kg/m^3 (matmake.com, 'Density of common polymers and plastics')"

MATERIAL_SOURCES = {
    "twu": (
        "TWU string database (2019 scrape), medians over the material at 51 lb, reconstructed "
        "in data/measurements.md sec. 8: k at Slow / Medium / Fast 254 / 225 / 204 lb/in "
        "(polyester, 294 strings), 167 / 169 / 162 (nylon, 148), 100 / 102 / 97 (natural gut, "
        "12); tension at impact 28 / 40 / 43 lb"
    ),
    "energy_return": _TWU + ": 89.7 / 94.7 / 96.6 %",
    "tension_loss": _TWU + ": 44.8 / 21.7 / 15.3 % in TWU's impact test",
    "friction": _TWU + ": string-string COF 0.086 / 0.108 / 0.149",
    "ball_friction": _TWU + ": string-ball COF 0.444 / 0.425 / 0.417",
    "density": (
        f"polyester (co-poly): {_PET}, an assumption that co-poly is PET's; nylon and "
        f"multifilament: {_PA66}; natural gut: an assumption, 1300 kg/m^3 (1250-1350, "
        "collagen's), no source found"
    ),
    "reference_gauge": (
        "an assumption: polyester 1.25 mm (16L), the others 1.30 mm (16), each material's "
        "usual gauge"
    ),
    "multifilament": (
        "its own rows of the TWU string database, labelled by name from retailers' lists "
        "(data/twu_multifilament/README.md, 78 strings): k at 51 lb 162 / 166 / 155 lb/in, "
        "tension at impact 40.3 lb, energy return 94.9 %, tension loss 21.3 %, string-string "
        "COF 0.117, string-ball COF 0.435; density and gauge nylon's"
    ),
}
"""Where each number of :data:`MATERIALS` comes from."""


def _twu(slow: float, medium: float, fast: float, impact_lb: float) -> TwuTest:
    """A :class:`TwuTest` from TWU's units: k at Slow, Medium, Fast [lb/in], the tension at
    impact [lb].
    """
    return TwuTest(tuple(k * LB_PER_IN for k in (slow, medium, fast)), impact_lb * LB)


MATERIALS = {
    "polyester": Material(
        "polyester", ("poly", "co-poly", "copoly", "co-polyester"),
        _twu(254.0, 225.0, 204.0, 28.0),
        1.25e-3, 0.897, 0.448, 0.086, 1380.0, 0.444,
    ),
    "nylon": Material(
        "nylon", ("synthetic-gut", "syn-gut", "synthetic"),
        _twu(167.0, 169.0, 162.0, 40.0),
        1.30e-3, 0.947, 0.217, 0.108, 1140.0, 0.425,
    ),
    "multifilament": Material(
        "multifilament", ("multi",),
        _twu(162.0, 166.0, 155.0, 40.3),
        1.30e-3, 0.949, 0.213, 0.117, 1140.0, 0.435,
    ),
    "natural-gut": Material(
        "natural gut", ("gut",),
        _twu(100.0, 102.0, 97.0, 43.0),
        1.30e-3, 0.966, 0.153, 0.149, 1300.0, 0.417,
    ),
}  # fmt: skip
"""The string materials by name (sources: :data:`MATERIAL_SOURCES`)."""


def material_key(name, argument: str = "string") -> str:
    """The key of :data:`MATERIALS` that ``name`` (a key, a printed name or an alias, any
    case, spaces or hyphens) names; ValueError listing the materials otherwise.

    Parameters
    ----------
    name : str
        What the user typed: "polyester", "poly", "co-poly", "nylon", "synthetic gut",
        "multifilament", "natural gut", "gut", ...
    argument : str, optional
        The argument or option it came from, as the message quotes it.
    """
    instance(argument, name, str, f"a string material's name ({', '.join(MATERIALS)})")
    said = name.strip().lower().replace("_", "-").replace(" ", "-")
    for key, material in MATERIALS.items():
        if said in (key, material.name.replace(" ", "-"), *material.aliases):
            return key
    known = "; ".join(
        key + (f" ({', '.join(m.aliases)})" if m.aliases else "") for key, m in MATERIALS.items()
    )
    raise ValueError(f"{argument}: unknown string material {name!r}; materials: {known}")
