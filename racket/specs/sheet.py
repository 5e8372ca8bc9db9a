"""A racket's spec sheet: the numbers retailers and manufacturers publish, checked and in SI.

:func:`spec_sheet` takes them in the units of spec sheets (g or kg, cm, kg cm^2, in^2, lb,
mm), checks each against its range (:data:`SPEC_RANGES`) before any work, and returns a
:class:`SpecSheet` in SI for the fit (:mod:`racket.specs.fit`).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from beam import SWINGWEIGHT_AXIS
from common import checks as slip  # the slips of unit: slip.CM_AS_M, ...
from common.checks import finite, in_range, positive, shown
from common.units import IN2, LB, POINT
from racket.strings.tension import TENSION_RANGE_LB, string_bed_stiffness


@dataclass(frozen=True)
class SpecSheet:
    """A racket's published numbers, in SI (built by :func:`spec_sheet` from user units).

    Parameters
    ----------
    length : float
        Overall length [m].
    mass : float
        Strung mass [kg].
    balance : float
        Balance point [m from the butt].
    swingweight : float
        Moment of inertia about the axis 10 cm from the butt [kg m^2].
    f1 : float or None
        Frame stiffness as the first free-free bending frequency of the strung frame [Hz],
    ra : float or None
        or as its RA rating [-] (f1 from it by :func:`racket.specs.ra.f1_from_ra`),
    flex : (float, float) or None
        or as a flex test: tip deflection [m] under a tip load [N].  Exactly one of the three.
    head_area : float
        Head (string-bed) area [m^2].
    string_stiffness : float
        String-plane stiffness [N/m].
    tension : float or None
        String tension [N] if the stiffness came from it, else None.
    twistweight : float or None
        Moment of inertia about the long axis [kg m^2], if given.
    recoil_weight : float or None
        Moment of inertia about the centre of mass [kg m^2], if given (with a swingweight
        too, it is a check: the fit meets the swingweight and reports the difference).
    swingweight_from_recoil : bool
        True when the sheet gave the recoil weight and no swingweight (``swingweight`` was
        derived from it by the parallel-axis rule).
    beam_widths : (float, float, float) or None
        Frame depth across the string plane at the tip, the sides and the throat [m].
    torsion_hz : float or None
        Measured first torsion frequency of the free frame [Hz], if given.
    """

    length: float
    mass: float
    balance: float
    swingweight: float
    f1: float | None
    ra: float | None
    head_area: float
    string_stiffness: float
    tension: float | None = None
    flex: tuple | None = None
    twistweight: float | None = None
    recoil_weight: float | None = None
    beam_widths: tuple | None = None
    swingweight_from_recoil: bool = False
    torsion_hz: float | None = None

    def __post_init__(self):
        length = positive("length_m", self.length, "m")
        positive("mass_kg", self.mass, "kg")
        balance = positive("balance", self.balance, "m from the butt")
        if not balance < length:
            raise ValueError(
                f"balance must lie on the racket, in (0, {100 * length:g}) cm from the butt, "
                f"got {100 * balance:g} cm"
            )
        positive("swingweight", self.swingweight, "kg m^2")
        if sum(v is not None for v in (self.f1, self.ra, self.flex)) != 1:
            raise ValueError(
                "give exactly one frame stiffness: f1_hz, ra or flex_deflection_mm (with "
                "flex_load_n)"
            )
        positive("head size", self.head_area, "m^2")
        positive("string_stiffness_n_m", self.string_stiffness, "N/m")
        if self.torsion_hz is not None:  # also for a sheet built without spec_sheet
            object.__setattr__(self, "torsion_hz", _check_spec("torsion_hz", self.torsion_hz))


SPEC_RANGES = {
    "length_m": (0.52, 0.75, "m"),
    "mass_kg": (0.15, 0.5, "kg"),
    "balance_cm": (20.0, 50.0, "cm from the butt"),
    "balance_pts_hl": (-24.0, 24.0, "pts head-light"),
    "swingweight_kgcm2": (100.0, 500.0, "kg cm^2"),
    "recoil_weight_kgcm2": (50.0, 300.0, "kg cm^2"),
    "twistweight_kgcm2": (8.0, 30.0, "kg cm^2"),
    "f1_hz": (60.0, 400.0, "Hz"),
    "torsion_hz": (150.0, 1500.0, "Hz"),
    "ra": (40.0, 90.0, ""),
    "flex_deflection_mm": (0.1, 100.0, "mm"),
    "flex_load_n": (1.0, 2000.0, "N"),
    "head_size_in2": (60.0, 140.0, "in^2"),
    "head_size_cm2": (387.0, 903.0, "cm^2"),  # 60-140 in^2
    "beam_width_mm": (10.0, 40.0, "mm"),
    "tension_lb": (*TENSION_RANGE_LB, "lb"),
    "tension_n": (*(t * LB for t in TENSION_RANGE_LB), "N"),  # 88.96-355.9 N, the same range
    "string_stiffness_n_m": (5e3, 2e5, "N/m"),
}
"""The range of each spec-sheet input, in its own unit, checked before the fit.  Generous
around real rackets: the ITF allows at most 73.7 cm (29 in) of length and a strung surface
of 39.4 x 29.2 cm (an ellipse of 140 in^2) (ITF Rules of Tennis, Appendix II); junior
rackets start at 19 in (48 cm), but the mass model's 19 cm handle, 5 cm of throat and a
60 in^2 head need 51.5 cm, so lengths start at 52 cm here; strung adult rackets weigh
230-370 g, balance 30-36 cm, swing 280-360 kg cm^2 and have beam widths of 17.5-29 mm
(retailers' spec sheets, e.g. tests/data/racket_specs_sample.csv); frames ring at
100-200 Hz (Taraborrelli et al., Appl. Sci. 2019); strings are strung at 40-65 lb; RA
ratings are 44-76 over the 622 rackets of the TWU table (:mod:`racket.specs.ra`; 55-76 on
the sample), widened to 40-90 (the regression is extrapolated outside 44-76); their
twistweights are 9.6-23.2 kg cm^2 (``tests/data/twu_racquets_half.csv``), widened to
8-30.  The rest (recoil weight 50-300 kg cm^2, f1 60-400 Hz, torsion 150-1500 Hz, a flex
test of 0.1-100 mm under 1-2000 N, string-bed 5e3-2e5 N/m) is this project's
assumption."""

SPEC_SLIPS = {
    "length_m": (slip.CM_AS_M, slip.INCH_AS_M),
    "mass_kg": (slip.GRAMS_AS_KG, slip.OZ_AS_KG),
    "balance_cm": (slip.INCH_AS_CM, slip.M_AS_CM),
    "swingweight_kgcm2": (slip.KGM2_AS_KGCM2,),
    "recoil_weight_kgcm2": (slip.KGM2_AS_KGCM2,),
    "twistweight_kgcm2": (slip.KGM2_AS_KGCM2,),
    "head_size_in2": (slip.CM2_AS_IN2,),
    "head_size_cm2": (slip.IN2_AS_CM2,),
    "tension_lb": (slip.N_AS_LB,),
    "tension_n": (slip.LB_AS_N, slip.KG_AS_N),
    "string_stiffness_n_m": (slip.KN_AS_N,),
}
"""The likely slips of unit of the spec sheet's values (:data:`SPEC_RANGES`), quoted when a
value out of its range is refused: a head size in cm^2 typed as in^2, a balance in inches
typed as cm, a swingweight in kg m^2 typed as kg cm^2, a tension in N typed as lb, a mass
in oz typed as kg...  Checked by :func:`spec_sheet`, so the TOML files and the page, which
build their rackets with it, say them too."""


def _check_spec(name: str, value) -> float:
    """A spec-sheet value in its range (:data:`SPEC_RANGES`), with a hint at a likely slip
    of unit (:data:`SPEC_SLIPS`: grams typed as kg, kg m^2 as kg cm^2, ...).
    """
    low, high, unit = SPEC_RANGES[name]
    return in_range(name, value, low, high, unit, slips=SPEC_SLIPS.get(name, ()))


def _one(kind: str, **given):
    """The one given value among ``given`` (name -> value or None); ValueError otherwise."""
    named = {k: v for k, v in given.items() if v is not None}
    if len(named) != 1:
        raise ValueError(
            f"give exactly one {kind}: {' or '.join(given)}"
            + (f" (got {', '.join(named)})" if named else "")
        )
    return next(iter(named.items()))


def _beam_widths(value) -> tuple[float, float, float]:
    """``beam_width_mm`` as (tip, sides, throat) [m]: one number for all, or three."""
    widths = np.atleast_1d(np.asarray(value, dtype=object)).ravel()
    if widths.size not in (1, 3):
        raise ValueError(
            f"beam_width_mm must be one width or three (tip, sides, throat) [mm], got "
            f"{shown(value)}"
        )
    checked = [_check_spec("beam_width_mm", w) / 1e3 for w in widths]
    return tuple(checked * 3) if len(checked) == 1 else tuple(checked)


def spec_sheet(
    *,
    length_m: float = 0.6858,
    mass_kg: float | None = None,
    swingweight_kgcm2: float | None = None,
    recoil_weight_kgcm2: float | None = None,
    twistweight_kgcm2: float | None = None,
    balance_cm: float | None = None,
    balance_pts_hl: float | None = None,
    f1_hz: float | None = None,
    ra: float | None = None,
    flex_deflection_mm: float | None = None,
    flex_load_n: float | None = None,
    head_size_in2: float | None = None,
    head_size_cm2: float | None = None,
    beam_width_mm=None,
    tension_lb: float | None = None,
    tension_n: float | None = None,
    string_stiffness_n_m: float | None = None,
    torsion_hz: float | None = None,
) -> SpecSheet:
    """A :class:`SpecSheet` from the units of spec sheets (see :func:`racket.from_specs`);
    every value is first checked against its range (:data:`SPEC_RANGES`).

    The inputs are in the units of spec sheets, named in each keyword; the result is in SI.

    Parameters
    ----------
    length_m : float, optional
        Overall length [m]; default 0.6858 (27 in).
    mass_kg : float
        Strung mass [kg].  Required.
    swingweight_kgcm2 : float, optional
        Swingweight [kg cm^2 = 1e-4 kg m^2] about the axis 10 cm from the butt (strung).
    recoil_weight_kgcm2 : float, optional
        Recoil weight [kg cm^2], the moment of inertia about the centre of mass: instead of
        the swingweight, or beside it as a check.  One of the two is required.
    twistweight_kgcm2 : float, optional
        Moment of inertia about the long axis [kg cm^2].
    balance_cm : float, optional
        Balance point [cm from the butt].
    balance_pts_hl : float, optional
        Balance in points head-light [pt] (1 pt = 1/8 in = 3.175e-3 m from the middle; negative
        = head-heavy).  Give exactly one of ``balance_cm`` and ``balance_pts_hl``.
    f1_hz : float, optional
        First free-free bending frequency of the strung frame [Hz].
    ra : float, optional
        RA rating [-] (Babolat RDC): f1 from it by the regression on 622 rackets measured by
        Tennis Warehouse University (:mod:`racket.specs.ra`, uncertain by about 6 Hz).
    flex_deflection_mm : float, optional
        Tip deflection in a flex test [mm] under ``flex_load_n``.  Give exactly one of
        ``f1_hz``, ``ra`` and ``flex_deflection_mm``.
    flex_load_n : float, optional
        The flex test's tip load [N] (with ``flex_deflection_mm``, and only with it).
    head_size_in2 : float, optional
        Head (string-bed) area [in^2 = 6.4516e-4 m^2].
    head_size_cm2 : float, optional
        Head (string-bed) area [cm^2].  Give exactly one of the two head sizes.
    beam_width_mm : float or (float, float, float), optional
        Frame depth across the string plane [mm]: one value, or the tip, sides and throat.
    tension_lb : float, optional
        String tension [lb, a force of 4.448 N].
    tension_n : float, optional
        String tension [N].
    string_stiffness_n_m : float, optional
        String-plane stiffness [N/m].  Give exactly one of the tensions and the stiffness.
    torsion_hz : float, optional
        Measured first torsion frequency of the free frame [Hz].
    """
    given = {k: v for k, v in locals().items() if v is not None}
    if "mass_kg" not in given:
        raise ValueError("the spec sheet needs mass_kg")
    if "swingweight_kgcm2" not in given and "recoil_weight_kgcm2" not in given:
        raise ValueError("the spec sheet needs swingweight_kgcm2 (or recoil_weight_kgcm2)")
    if (flex_deflection_mm is None) != (flex_load_n is None):
        raise ValueError("flex_deflection_mm and flex_load_n go together: give both or neither")
    widths = _beam_widths(given.pop("beam_width_mm")) if beam_width_mm is not None else None
    for name, value in given.items():
        _check_spec(name, value)
    length = positive("length_m", length_m, "m")
    mass = positive("mass_kg", mass_kg, "kg")
    name, value = _one("balance", balance_cm=balance_cm, balance_pts_hl=balance_pts_hl)
    if name == "balance_cm":
        balance = positive("balance_cm", value, "cm from the butt") / 100.0
    else:  # points head-light: 1/8 in each, counted from the middle
        balance = length / 2.0 - finite("balance_pts_hl", value, "pts") * POINT
    recoil = None if recoil_weight_kgcm2 is None else recoil_weight_kgcm2 * 1e-4
    if swingweight_kgcm2 is not None:
        swingweight = swingweight_kgcm2 * 1e-4
    else:  # parallel axes: about the axis 10 cm from the butt = about the centre of mass + M d^2
        swingweight = recoil + mass * (balance - SWINGWEIGHT_AXIS) ** 2
    name, value = _one("head size", head_size_in2=head_size_in2, head_size_cm2=head_size_cm2)
    area = positive(name, value, name[-3:]) * (IN2 if name.endswith("in2") else 1e-4)
    name, value = _one(
        "string bed",
        tension_lb=tension_lb,
        tension_n=tension_n,
        string_stiffness_n_m=string_stiffness_n_m,
    )
    tension = None
    if name == "string_stiffness_n_m":
        k_strings = positive(name, value, "N/m")
    else:
        tension = positive(name, value, name[-2:]) * (LB if name == "tension_lb" else 1.0)
        k_strings = string_bed_stiffness(tension, area)
    name, value = _one("frame stiffness", f1_hz=f1_hz, ra=ra, flex_deflection_mm=flex_deflection_mm)
    return SpecSheet(
        length=length,
        mass=mass,
        balance=balance,
        swingweight=swingweight,
        f1=value if name == "f1_hz" else None,
        ra=value if name == "ra" else None,
        flex=(value / 1e3, flex_load_n) if name == "flex_deflection_mm" else None,
        head_area=area,
        string_stiffness=k_strings,
        tension=tension,
        twistweight=None if twistweight_kgcm2 is None else twistweight_kgcm2 * 1e-4,
        recoil_weight=recoil,
        beam_widths=widths,
        swingweight_from_recoil=swingweight_kgcm2 is None,
        torsion_hz=torsion_hz,
    )
