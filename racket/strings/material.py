"""What tennis strings are made of: polyester, nylon, multifilament and natural gut, each with
the numbers the string bed needs (axial stiffness, energy return, tension loss, friction,
density), each number with its source or marked as an assumption.

The single-string numbers are TWU's (Tennis Warehouse University's string database, as
scraped; medians over the strings of each material, ``data/measurements.md`` sec. 5).  TWU
groups synthetic gut and multifilament with nylon, so multifilament takes the nylon group's
numbers: the database gives no separate row for it.
"""

from __future__ import annotations

from dataclasses import dataclass

from common.checks import in_range, positive
from common.units import INCH, LB

TWU_LENGTH = 0.30
"""Length [m] of the string sample in TWU's dynamic stiffness test, which turns its
single-string stiffness k [lb/in] into the axial stiffness EA = k L [N].  **An assumption**:
TWU's pages describe the test (a string at 51 lb hit by a quick impact, "how many pounds of
force it takes to stretch the string one inch"; TWU, "String Stiffness: the Alpha and Omega
of String Performance", Lindsey) but no sample length was found; 0.30 m is about a main
string's free length in a 100 in^2 head.  Plausible range 0.20-0.40 m: the bed's stretch
(:meth:`racket.strings.stringing.Stringing.stretch`) is proportional to EA, so it moves by -33 % to
+33 % over that range (a polyester 16L bed at 55 lb on 100 in^2: about 680 to 1360 1/m^2
instead of 1020); on the default racket at the string centre that moves e_A at 16.5 m/s
over 0.431-0.425, the dwell time at 30 m/s over 4.34-4.16 ms and the serve over 1.419-1.404
times the head speed.  At 0.30 m the moduli E = EA / A are 8.6 GPa (polyester, 1.25 mm),
6.2 GPa (nylon, 1.30 mm) and 3.7 GPa (gut, 1.30 mm): in the range of drawn polymer fibres
and collagen, stiffer than the bulk polymers' 2-4 GPa, as an impact's dynamic modulus is."""

TWU_TENSION = 51.0 * LB
"""Tension [N] of TWU's single-string tests: 51 lb (``data/measurements.md`` sec. 5)."""

LB_PER_IN = LB / INCH
"""One pound-force per inch [N/m] (TWU quotes string stiffness in lb/in): 175.1 N/m."""


@dataclass(frozen=True)
class Material:
    """A string material and its single-string numbers.

    Parameters
    ----------
    name : str
        The name as printed ("polyester", "natural gut").
    aliases : tuple of str
        Other names a user may type for it ("poly", "gut"), lower case, hyphenated.
    twu_stiffness : float
        Single-string dynamic stiffness in TWU's test at 51 lb [N/m] (:data:`TWU_LENGTH`).
    reference_gauge : float
        The gauge [m] ``twu_stiffness`` is taken to belong to (the usual gauge of the
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
    twu_stiffness: float
    reference_gauge: float
    energy_return: float
    tension_loss: float
    friction: float
    density: float
    ball_friction: float

    def __post_init__(self):
        positive(f"{self.name} twu_stiffness", self.twu_stiffness, "N/m")
        in_range(f"{self.name} reference_gauge", self.reference_gauge, 1e-3, 1.5e-3, "m")
        for fraction in ("energy_return", "tension_loss", "friction", "ball_friction"):
            in_range(f"{self.name} {fraction}", getattr(self, fraction), 0.0, 1.0)
        positive(f"{self.name} density", self.density, "kg/m^3")

    def axial_stiffness(self, gauge: float) -> float:
        """Axial stiffness EA [N] of a string of this material and ``gauge``:
        EA = k_TWU L_TWU (gauge / reference gauge)**2 (the cross-section's area scales with
        the gauge squared; :data:`TWU_LENGTH`).

        Parameters
        ----------
        gauge : float
            The string's diameter [m].
        """
        scale = (positive("gauge", gauge, "m") / self.reference_gauge) ** 2
        return self.twu_stiffness * TWU_LENGTH * scale


_TWU = "TWU string database (scraped), median over the material, data/measurements.md sec. 5"
_PET = "PET 1370-1390 kg/m^3 (24kjx.com.cn, 'Common plastic density reference table', 2026)"
_PA66 = "nylon 66 (PA66) 1140 kg/m^3 (matmake.com, 'Density of common polymers and plastics')"

MATERIAL_SOURCES = {
    "twu_stiffness": _TWU + ": polyester about 200, nylon 157, gut 94 lb/in at 51 lb",
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
    "multifilament": "TWU groups multifilament with nylon (synthetic gut): the nylon numbers",
}
"""Where each number of :data:`MATERIALS` comes from."""

MATERIALS = {
    "polyester": Material(
        "polyester", ("poly", "co-poly", "copoly", "co-polyester"), 200.0 * LB_PER_IN,
        1.25e-3, 0.897, 0.448, 0.086, 1380.0, 0.444,
    ),
    "nylon": Material(
        "nylon", ("synthetic-gut", "syn-gut", "synthetic"), 157.0 * LB_PER_IN,
        1.30e-3, 0.947, 0.217, 0.108, 1140.0, 0.425,
    ),
    "multifilament": Material(
        "multifilament", ("multi",), 157.0 * LB_PER_IN,
        1.30e-3, 0.947, 0.217, 0.108, 1140.0, 0.425,
    ),
    "natural-gut": Material(
        "natural gut", ("gut",), 94.0 * LB_PER_IN,
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
    if not isinstance(name, str):
        raise TypeError(f"{argument} must be a string material's name (text), got {name!r}")
    said = name.strip().lower().replace("_", "-").replace(" ", "-")
    for key, material in MATERIALS.items():
        if said in (key, material.name.replace(" ", "-"), *material.aliases):
            return key
    known = "; ".join(
        key + (f" ({', '.join(m.aliases)})" if m.aliases else "") for key, m in MATERIALS.items()
    )
    raise ValueError(f"{argument}: unknown string material {name!r}; materials: {known}")
