"""Bat presets: A. M. Nathan's wooden Louisville Slugger R161 built from his inputs, and a
hollow alloy bat of the same outline (a what-if).

The R161 (N2000 = A. M. Nathan, "Dynamics of the baseball-bat collision", Am. J. Phys. 68,
979-990 (2000), Table I and Sec. III A; ``data/bats.md`` section 1 holds every number with
how it was read):

* its profile: 84 slices 1 cm long, the diameter of each from the file ``r161.dat`` of
  GitHub ``navawolfish/bat-ball-collision-model`` (blob b408991d; column 1 z in cm from the
  knob, column 2 the diameter in mm, ``data/bats.md`` section 1.2).  Slice k spans
  z = k - 1 to k cm (**a choice**: the sources do not say where a slice lies; centred at
  z = k - 0.5 cm, its centre of mass is 0.561 m from the knob, Table I's 0.564);
* wood of one density, Young's and shear modulus: rho = 649 kg/m^3, Y = 1.814e10 Pa (tuned
  by Nathan to the fundamental's measured frequency, not given), S = 1.05e9 Pa (Van Zandt's,
  an assumption of both); Nathan's shear force is S A times the strain (kappa = 1);
* free ends, no damping (N2000 has none), and 18 bending modes (N2000 p. 984).

Built as stated, the profile weighs 0.869 kg at that density against Table I's 0.885 kg
(1.8 % lighter; ``data/bats.md`` section 1.2): the preset keeps the profile's mass, as
Nathan's own model (built from it) must have.
"""

from __future__ import annotations

import numpy as np

from bat.bat import Bat
from beam import ThickBeam

R161_LENGTH = 0.84
"""Length [m] of the R161 (N2000 Table I: 84 cm)."""

R161_DIAMETERS_MM = (
    50.500,
    50.500,
    35.436,
    33.427,
    32.084,
    30.563,
    29.560,
    28.368,
    27.407,
    27.002,
    26.526,
    26.087,
    26.102,
    26.155,
    26.129,
    26.115,
    26.220,
    26.493,
    26.808,
    26.966,
    26.982,
    26.996,
    27.001,
    26.970,
    27.163,
    27.712,
    27.991,
    28.181,
    28.564,
    28.906,
    29.014,
    29.309,
    29.778,
    29.974,
    30.305,
    30.735,
    30.967,
    31.071,
    31.532,
    32.043,
    32.617,
    33.198,
    34.133,
    34.858,
    35.943,
    36.882,
    37.971,
    39.266,
    40.424,
    41.972,
    43.484,
    44.976,
    46.742,
    48.706,
    50.386,
    51.978,
    53.391,
    54.719,
    56.077,
    57.262,
    58.274,
    59.225,
    60.092,
    60.841,
    61.444,
    61.898,
    62.229,
    62.475,
    62.662,
    62.815,
    62.950,
    63.079,
    63.214,
    63.364,
    63.539,
    63.730,
    63.918,
    64.086,
    64.218,
    64.290,
    64.302,
    64.300,
    64.300,
    64.300,
)
"""The R161's diameter [mm] of each 1-cm slice, from the knob (z = 1 ... 84 cm): ``r161.dat``
(see the module docstring), verbatim."""

WOOD_DENSITY = 649.0
"""Density of the R161's wood [kg/m^3] (N2000 Table I; printed "kg/m^2", a misprint)."""

WOOD_YOUNGS_MODULUS = 1.814e10
"""Young's modulus of the R161's wood [Pa] (N2000 Table I; tuned by Nathan to the measured
fundamental frequency, which N2000 does not give)."""

WOOD_SHEAR_MODULUS = 1.05e9
"""Shear modulus of the R161's wood [Pa] (N2000 Table I: Van Zandt's value, **an
assumption** of Nathan's, "the calculations are not very sensitive" to it)."""

NATHAN_MODES = 18
"""Bending modes Nathan keeps in every collision (N2000 p. 984)."""

ALLOY_DENSITY, ALLOY_YOUNGS_MODULUS, ALLOY_SHEAR_MODULUS = 2810.0, 7.17e10, 2.69e10
"""Density [kg/m^3], Young's and shear moduli [Pa] of the alloy bat: handbook values of
aluminium 7075-T6 (ASM Handbook, Vol. 2 (1990), Properties of wrought aluminum alloys):
**an assumption** that the bat is of it; no hollow bat's wall or laminate was found
(``data/bats.md`` section 4.4)."""

ALLOY_MASS = 0.850
"""Mass [kg] of the alloy what-if: 30 oz, a 33-in bat of the NCAA's -3 length-to-weight
rule (``data/bats.md`` section 4.1); its wall thickness is set to weigh this, the same
everywhere (**an assumption**)."""


def r161_stations() -> np.ndarray:
    """Segment boundaries [m from the tip] of the R161's 84 slices."""
    return np.linspace(0.0, R161_LENGTH, len(R161_DIAMETERS_MM) + 1)


def r161_beam(n_modes: int = NATHAN_MODES, elements: int = 250, stiffness_factor=1.0):
    """The R161 as a :class:`beam.ThickBeam` (see the module docstring).

    Parameters
    ----------
    n_modes : int
        Bending modes kept [-] (Nathan's 18 by default).
    elements : int
        About how many finite elements [-] (250 gives three per slice, 252).
    stiffness_factor : float
        Y and S times this [-] (1: Nathan's wood; a huge one, a bat that does not vibrate).
    """
    diameters = 1e-3 * np.asarray(R161_DIAMETERS_MM)[::-1]  # from the tip
    return ThickBeam.round(
        r161_stations(), diameters, WOOD_DENSITY, stiffness_factor * WOOD_YOUNGS_MODULUS,
        stiffness_factor * WOOD_SHEAR_MODULUS, damping=0.0, n_modes=n_modes, elements=elements,
    )  # fmt: skip


def r161(support: str = "free", **kwargs) -> Bat:
    """Nathan's wooden R161 (:func:`r161_beam`) held by ``support`` (:class:`bat.Bat`).

    Parameters
    ----------
    support : str
        ``"free"``, ``"pivoted"`` or ``"hand-held"``.
    **kwargs
        Passed to :class:`bat.Bat` (``pivot_from_knob``, ``clamp_offset``, ``hand``).
    """
    return Bat(r161_beam(), support, name="R161 (wood)", **kwargs)


def alloy_wall() -> float:
    """The alloy what-if's wall thickness [m]: what weighs :data:`ALLOY_MASS` on the R161's
    outline (a root of a quadratic in the thickness).
    """
    outer = 1e-3 * np.asarray(R161_DIAMETERS_MM)
    length = R161_LENGTH / outer.size
    # mass = rho l pi sum(t (D - t)) = rho l pi (t sum D - n t**2)
    a, b = outer.size, outer.sum()
    c = ALLOY_MASS / (ALLOY_DENSITY * length * np.pi)
    return float((b - np.sqrt(b * b - 4.0 * a * c)) / (2.0 * a))


def alloy(support: str = "free", **kwargs) -> Bat:
    """A hollow alloy bat of the R161's outline and :data:`ALLOY_MASS` (a what-if: see
    :data:`ALLOY_DENSITY`).  A beam model has no hoop modes: the thin wall's trampoline
    effect, what makes hollow bats livelier than wood, is not in it.

    Parameters
    ----------
    support : str
        ``"free"``, ``"pivoted"`` or ``"hand-held"``.
    **kwargs
        Passed to :class:`bat.Bat`.
    """
    outer = 1e-3 * np.asarray(R161_DIAMETERS_MM)[::-1]
    beam = ThickBeam.round(
        r161_stations(), outer, ALLOY_DENSITY, ALLOY_YOUNGS_MODULUS, ALLOY_SHEAR_MODULUS,
        bore=outer - 2.0 * alloy_wall(), damping=0.0, n_modes=NATHAN_MODES, elements=250,
    )  # fmt: skip
    return Bat(beam, support, name="alloy what-if (hollow)", **kwargs)


BATS = {"r161": r161, "alloy": alloy}
"""Bat presets by name: builders taking the support (and :class:`bat.Bat`'s options)."""

DEFAULT_BAT = "r161"
"""The bat of every bat answer: Nathan's R161."""
