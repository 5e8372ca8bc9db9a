"""The string bed as the user types it, on the command line and in TOML: the tension in kg
and the ERT's dynamic tension (their ranges and slips of unit), and a ``[racket.strings]``
table applied to a racket's bed (:func:`strings_from_table`).
"""

from __future__ import annotations

from dataclasses import replace

from common.checks import (
    CM_AS_M,
    finite_array,
    in_range,
    loose_tension,
    non_negative,
    shown,
    suspect,
)
from common.typechecks import choice
from common.units import GRAVITY, KP_PER_CM, LB
from racket import StringBed
from racket.strings.bed import BED_END_MAX
from racket.strings.sizes import diameter, parse_pattern
from racket.strings.stringing import LINEAR, STATES, restrung, stringing
from racket.strings.tension import TENSION_RANGE_LB
from studies.sweeps import STRING_STIFFNESS_RANGE

TENSION_KG_RANGE = tuple(t * LB / GRAVITY for t in TENSION_RANGE_LB)
"""The string tensions [kg] a racket may be strung at: 20-80 lb in kg (9.07-36.3 kg)."""

DT_RANGE = tuple(k / KP_PER_CM for k in STRING_STIFFNESS_RANGE)
"""The ERT dynamic tensions [kp/cm] a bed may have: a sweep's string stiffnesses."""

LB_AS_KG = (LB / GRAVITY, "lb typed as kg?", "lb")
"""A slip of unit: a tension in lb where kg are asked for."""

N_M_AS_KP_CM = (1.0 / KP_PER_CM, "N/m typed as kp/cm?", "N/m")
"""A slip of unit: a string bed's stiffness in N/m where the ERT's kp/cm are asked for."""

N_CM_AS_KP_CM = (1.0 / GRAVITY, "N/cm typed as kp/cm?", "N/cm")
"""A slip of unit: the ERT's dynamic tension in N/cm where kp/cm are asked for (1 kp/cm =
9.80665 N/cm; a bed typed ten times too stiff)."""

PLAYED_DT = (28.0, 46.0)
"""What players' string beds read on the ERT [kp/cm]: "most players' DT values fall between
28-46" (ert300.com, ``data/measurements.md`` sec. 5).  A DT above it that is one in N/cm is
asked about (:func:`stiff_dt`)."""

STRING_KEYS = {"stiffness", "extent", "profile", "string", "gauge", "pattern", "state",
               "tension_lb", "tension_kg", "dt_kp_cm"}  # fmt: skip
"""The keys of a ``[racket.strings]`` table."""

BED_KEYS = ("tension_lb", "tension_kg", "stiffness", "dt_kp_cm")
"""The ``[racket.strings]`` keys that each set the bed's stiffness: one at most."""


def stiff_dt(name: str, dt_kp_cm: float) -> None:
    """Warn (``UserWarning``, :func:`common.checks.suspect`) when a DT [kp/cm] lies above
    :data:`PLAYED_DT` and is one in N/cm typed as kp/cm ("--string-bed-dt 300 kp/cm is
    stiffer than players' beds read (most 28-46 kp/cm): N/cm typed as kp/cm? 300 N/cm would
    be 30.59 kp/cm").

    Parameters
    ----------
    name : str
        The input, as the message quotes it (a flag or a TOML key).
    dt_kp_cm : float
        The DT typed [kp/cm].
    """
    low, high = PLAYED_DT
    why = f"stiffer than players' beds read (most {low:g}-{high:g} kp/cm)"
    suspect(name, dt_kp_cm, PLAYED_DT, "kp/cm", (N_CM_AS_KP_CM,), why)


def _extent(name: str, value) -> tuple[float, float]:
    """A string bed's extent as typed (``name``): two numbers [m from the tip], each within
    :data:`racket.strings.bed.BED_END_MAX` (one in cm refused with the hint); their order and
    the frame are the bed's and the racket's to check.
    """
    extent = finite_array(name, value, "m from the tip")
    if extent.shape != (2,):
        raise ValueError(f"{name} must be [start, end] [m from the tip], got {shown(value)}")
    for x in extent:
        non_negative(name, x, "m from the tip")
        in_range(name, x, 0.0, BED_END_MAX, "m from the tip", slips=(CM_AS_M,))
    return float(extent[0]), float(extent[1])


def strings_from_table(bed: StringBed, table: dict) -> tuple[StringBed, float | None]:
    """``bed`` as a ``[racket.strings]`` table changes it, each key given replacing the
    bed's (:func:`racket.strings.stringing.restrung`), and the tension it gives [N] or None (for
    :func:`racket.specs.restring.with_tension`).  The keys and their ranges are
    :mod:`studies.config`'s to check first.

    Parameters
    ----------
    bed : StringBed
        The racket's bed.
    table : dict
        The ``[racket.strings]`` table (``string``, ``gauge`` [mm or a name], ``pattern``,
        ``state``, ``tension_lb`` [lb], ``tension_kg`` [kg], ``stiffness`` [N/m],
        ``dt_kp_cm`` [kp/cm], ``extent`` [m from the tip], ``profile``).
    """
    where = "[racket.strings]"
    typed = [key for key in BED_KEYS if key in table]
    if len(typed) > 1:
        raise ValueError(f"{where} takes one of {', '.join(BED_KEYS)}; got {' and '.join(typed)}")
    if "tension_lb" in table:  # asked about as --tension-lb is (kg typed as lb?)
        loose_tension(f"{where} tension_lb", table["tension_lb"])
    if "dt_kp_cm" in table:  # asked about as --string-bed-dt is (N/cm typed as kp/cm?)
        stiff_dt(f"{where} dt_kp_cm", table["dt_kp_cm"])
    gauge = table.get("gauge")
    gauge = None if gauge is None else diameter(gauge, f"{where} gauge", "mm")
    pattern = table.get("pattern")
    pattern = None if pattern is None else parse_pattern(pattern, f"{where} pattern")
    state = table.get("state") and choice(f"{where} state", table["state"], STATES)
    measured = [key for key in typed if key in ("stiffness", "dt_kp_cm")]
    if state == "played" and measured:
        raise ValueError(
            f"{where} state = 'played' lowers the strings' tension, and {measured[0]} sets the "
            "bed as measured (played or not): give one"
        )
    stiffness = table.get("stiffness")
    if table.get("string", LINEAR) != LINEAR:
        stringing(table["string"], gauge, argument=f"{where} string")  # refused as typed
    elif (bed.stringing is None or "string" in table) and (gauge or pattern or state):
        plain = f"string = {LINEAR!r} is" if "string" in table else "this bed is"
        raise ValueError(
            f"{where} gauge, pattern and state describe a string, and {plain} a plain "
            "spring with none: name a string, e.g. string = 'polyester'"
        )
    extent = bed.extent if "extent" not in table else _extent(f"{where} extent", table["extent"])
    bed = replace(bed, extent=extent, profile=table.get("profile", bed.profile))
    if bed.stringing is not None or "string" in table or stiffness is not None:
        bed = restrung(bed, table.get("string"), gauge, pattern, state, stiffness)
    if "dt_kp_cm" in table:  # read on the strings as strung, as an ERT reads them
        from racket.strings.ert import stiffness_from_dt

        k = stiffness_from_dt(bed, table["dt_kp_cm"], f"{where} dt_kp_cm")
        bed = restrung(bed, stiffness=k)
    tension = table.get("tension_lb", 0.0) * LB or table.get("tension_kg", 0.0) * GRAVITY
    return bed, tension or None
