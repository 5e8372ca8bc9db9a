"""How the string bed's stiffness varies over the face: the membrane model.

A membrane of tension N per unit length spanning a circle of radius R, pushed by a load
spread over a small radius a centred at a distance r from the middle, deflects under the
load by w = F / (2 pi N) ln((R**2 - r**2) / (R a)): the Green's function of the Laplacian in
a disk evaluated at the load's own position, G(r, r) = ln((R**2 - r**2) / R) / (2 pi),
smoothed over the patch (e.g. P. M. Morse & H. Feshbach, Methods of Theoretical Physics,
1953, Sec. 7.2, method of images).  The stiffness F / w is therefore

    k(r) = 2 pi N / ln(R (1 - rho**2) / a),   rho = r / R,

equal to the centre's 2 pi N / ln(R / a) at rho = 0 and rising towards the frame.  An
elliptical bed uses the elliptical radius rho**2 = (dx / a_s)**2 + (y / b_s)**2 and the
circle of the same area (R = sqrt(a_s b_s)), as the centre's value does
(:func:`racket.strings.tension.string_bed_stiffness`).  Where the load patch would reach the frame
(R (1 - rho**2) < 2 a) the membrane solution no longer applies; the stiffness is held at
its value there (at most about 2.5 times the centre's on a 100 in^2 head).  The ratio to the
centre depends on the head's size only: the tension cancels.  Cross measured the rise of
the string-plane stiffness towards the frame (R. Cross, "Flexible beam analysis of the
effects of string tension and frame stiffness on racket performance", Sports Eng. 3, 2000,
and "The dead spot of a tennis racket", Am. J. Phys. 65, 1997); the numbers here are the
model's, not fitted to those measurements.
"""

from __future__ import annotations

import numpy as np

CONTACT_RADIUS = 0.025
"""Radius [m] over which the ball loads the strings in the membrane model (the contact
patch of a tennis ball on strings is about 5 cm across at 20-30 m/s)."""


MIN_RADIUS = 2.0 * CONTACT_RADIUS
"""Smallest bed radius [m] the membrane model describes: below it the load patch never fits
inside the bed, and the held stiffness would fall (below ``CONTACT_RADIUS``, turn negative)."""


def bed_radius(area: float) -> float:
    """Radius [m] of the circle of a string bed's ``area`` [m^2], refused at or below
    :data:`MIN_RADIUS`.

    Parameters
    ----------
    area : float
        The bed's area [m^2].
    """
    radius = float(np.sqrt(area / np.pi))
    if not radius > MIN_RADIUS:
        raise ValueError(
            f"a membrane string bed must be larger than {np.pi * MIN_RADIUS**2:.4g} m^2 "
            f"(a circle of radius {MIN_RADIUS:g} m), got {area:.4g} m^2"
        )
    return radius


def stiffness_ratio(rho2, radius: float) -> np.ndarray:
    """K / k_centre of a membrane of ``radius`` [m] (a circle of the bed's area) at the
    squared elliptical radius ``rho2`` (0 at the centre, 1 at the frame); see the module
    docstring.

    Parameters
    ----------
    rho2 : float or array_like
        Squared elliptical radius [-], 0 at the centre and 1 at the frame (clipped to [0, 1]).
    radius : float
        Radius of the circle of the bed's area [m].
    """
    rho2 = np.minimum(np.maximum(rho2, 0.0), 1.0)  # (np.clip costs a few points more)
    centre = np.log(radius / CONTACT_RADIUS)
    near = np.log(np.maximum(radius * (1.0 - rho2), 2.0 * CONTACT_RADIUS) / CONTACT_RADIUS)
    return centre / near
