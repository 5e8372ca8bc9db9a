"""A string's gauge and a string bed's pattern, as a stringer gives them: gauge names
(15 to 19) or diameters, patterns such as "16x19", each checked against its range.
"""

from __future__ import annotations

import re

from common.checks import INCH_AS_M, MM_AS_M, in_range, shown, whole
from common.units import INCH

GAUGES = {
    "15": 1.45e-3, "15L": 1.37e-3, "16": 1.30e-3, "16L": 1.25e-3,
    "17": 1.20e-3, "17L": 1.15e-3, "18": 1.10e-3, "19": 1.05e-3,
}  # fmt: skip
"""Diameter [m] of each gauge name.  The gauges are ranges (Ashaway, S. Crandall, "String
gauge: the basic choice", ashawayusa.com: 15 1.41-1.49 mm, 15L 1.33-1.41, 16 1.26-1.34,
17 1.16-1.26, 18 1.06-1.16; Tennis Express, "String Theory, Part II": 19 1.00-1.10 mm);
each name takes about its range's middle, rounded to the 0.05 mm strings are sold in.  16L
(1.25 mm) and 17L (1.15 mm) lie between their neighbours: **an assumption** (no chart found
gives them), as strings labelled 16L are 1.25 mm."""

GAUGE_RANGE = (1.00e-3, 1.50e-3)
"""The gauges [m] a string may have: 19 to 15 gauge (:data:`GAUGES`)."""

PATTERN_RANGE = ((12, 22), (14, 24))
"""The mains and crosses [-] a pattern may have: generous around the 16x16 to 18x20 of
tennis rackets (an assumption)."""

REFERENCE_PATTERN = (16, 19)
"""The pattern [-] of the membrane model's calibration (the paper's racket: the commonest)."""

_GAUGE_SLIPS = {
    "m": (MM_AS_M, INCH_AS_M),
    "mm": ((1e3, "m typed as mm?", "m"), (1e3 * INCH, "inches typed as mm?", "in")),
}


def diameter(value, name: str = "gauge", unit: str = "m") -> float:
    """A string's gauge [m] from a name of :data:`GAUGES` ("16L") or a diameter in ``unit``
    in :data:`GAUGE_RANGE`; ValueError naming ``name`` and the value, with the range and a
    likely slip of unit (mm or inches typed as m; m or inches as mm), or the names.

    Parameters
    ----------
    value : str or float
        A gauge name, or the diameter [``unit``] (a number, or a word that is one).
    name : str, optional
        The input's name as the user typed it ("gauge", "--gauge").
    unit : str, optional
        ``"m"`` (default) or ``"mm"``.
    """
    scale = 1e-3 if unit == "mm" else 1.0
    if isinstance(value, str):
        said = value.strip().upper()
        if said in GAUGES:
            return GAUGES[said]
        try:
            value = float(said)
        except ValueError:
            raise ValueError(
                f"{name} must be a gauge name ({', '.join(GAUGES)}) or a diameter [{unit}], "
                f"got {value!r}"
            ) from None
    named = isinstance(value, int | float) and str(value).removesuffix(".0") in GAUGES
    hint = f" (a gauge name is a word: '{shown(value)}')" if named and unit == "m" else ""
    low, high = (end / scale for end in GAUGE_RANGE)
    return scale * in_range(name, value, low, high, unit, hint, slips=_GAUGE_SLIPS[unit])


def parse_pattern(value, name: str = "pattern") -> tuple[int, int]:
    """A string pattern (mains, crosses) from "16x19" or a pair; ValueError naming ``name``
    and the value, with :data:`PATTERN_RANGE`, otherwise.

    Parameters
    ----------
    value : str or (int, int)
        "MAINSxCROSSES" (``"16x19"``) or (mains, crosses) [-].
    name : str, optional
        The input's name as the user typed it ("pattern", "--pattern").
    """
    pair = value
    if isinstance(value, str):
        match = re.fullmatch(r"\s*(\d+)\s*[xX*]\s*(\d+)\s*", value)
        pair = (int(match[1]), int(match[2])) if match else None
    if not isinstance(pair, tuple | list) or len(pair) != 2:
        raise ValueError(f"{name} must be MAINSxCROSSES such as '16x19', got {shown(value)}")
    (low_m, high_m), (low_c, high_c) = PATTERN_RANGE
    return whole(f"{name} mains", pair[0], low_m, high_m), whole(
        f"{name} crosses", pair[1], low_c, high_c
    )
