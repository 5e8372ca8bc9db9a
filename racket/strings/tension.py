"""The string bed's stiffness from the string tension and the head size (a membrane model),
for a racket typed from its spec sheet; the tensions a racket may be strung at.
"""

from __future__ import annotations

import numpy as np

from common.checks import positive
from common.units import IN2
from racket.strings.membrane import CONTACT_RADIUS, MIN_RADIUS, bed_radius

MEMBRANE_REFERENCE = (245.0, 100.0 * IN2, 3e4)
"""Calibration of the membrane model: 245 N (55 lb) on a 100 in^2 head gives a string-plane
stiffness of 3e4 N/m (the paper, Sec. VIII)."""

TENSION_RANGE_LB = (20.0, 80.0)
"""The string tensions [lb] a racket may be strung at, generous around the 40-65 lb of real
rackets: the spec sheets' range (:data:`racket.specs.sheet.SPEC_RANGES`, which takes it)."""


def string_bed_stiffness(tension_n: float, head_area_m2: float) -> float:
    """String-plane stiffness [N/m] from the string tension and the head area.

    Membrane model: a circular membrane of radius R under a tension N per unit length,
    pushed by a load spread over a radius a at its centre, has the stiffness
    k = 2 pi N / ln(R / a) (the small-deflection solution of N lap(w) = -p, e.g. Timoshenko
    & Woinowsky-Krieger, Theory of Plates and Shells, membrane limit).  A string bed of
    spacing s has N = T / s, and an elliptical bed behaves like a circle of the same area
    (R. Cross & R. Bower, "Measurements of string tension in a tennis racket", Sports Eng. 4,
    2001: the string-plane frequency depends on the area, not the shape).  So
    k = C T / ln(R / a) with R = sqrt(A / pi), a = :data:`CONTACT_RADIUS`, and the constant C
    (the 2 pi / s and the effect of the frame and string stretch) fixed by
    :data:`MEMBRANE_REFERENCE`.  k rises in proportion to the tension and falls slowly with
    the head size.  This is the centre's value; :mod:`racket.strings.membrane` gives its rise
    towards the frame.

    Parameters
    ----------
    tension_n : float
        String (reference) tension [N].
    head_area_m2 : float
        Head (string-bed) area [m^2].
    """
    tension_n = positive("tension", tension_n, "N")
    head_area_m2 = positive("head size", head_area_m2, "m^2")
    if head_area_m2 <= np.pi * MIN_RADIUS**2:
        raise ValueError(
            f"head size must be > {np.pi * MIN_RADIUS**2 / IN2:.0f} in^2 for the "
            f"membrane model, got {head_area_m2 / IN2:.4g} in^2"
        )
    radius = bed_radius(head_area_m2)
    t_ref, a_ref, k_ref = MEMBRANE_REFERENCE
    c = k_ref * np.log(np.sqrt(a_ref / np.pi) / CONTACT_RADIUS) / t_ref
    return float(c * tension_n / np.log(radius / CONTACT_RADIUS))
