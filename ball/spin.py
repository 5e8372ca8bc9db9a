"""What a ball needs to slide, grip and spin on a surface (issue 36): its moment of inertia,
the tangential compliance of its contact and the offset of the normal force.

The normal force keeps the ball's own law (:mod:`ball.laws`); the tangential force of the
contact is the ball's tangential spring, limited by Coulomb friction, :mod:`ball.grip`.
"""

from __future__ import annotations

from dataclasses import dataclass

from common.checks import in_range, positive

INERTIA_FACTOR = 0.55
"""A tennis ball's moment of inertia over m R^2 [-]: 0.55, a hollow ball with a 6 mm wall
(Cross, "Grip-slip behavior of a bouncing ball", Am. J. Phys. 70 (2002) 1093, Table I;
``data/measurements.md`` sec. 6).  2/5 for a solid ball, 2/3 for a thin shell."""

OFFSET_RATIO = 0.06
"""Offset of the normal force from the ball's centre over its radius [-]: 2 mm on the ball's
33.5 mm, the low end of the source's "about R/10 (2-3 mm for tennis balls)" (Cross 2002,
quoted in ``data/measurements.md`` sec. 6; a calibration row).  **Calibrated** with
:data:`TANGENTIAL_STIFFNESS`: at R/10 (3.35 mm) no friction meets both of Cross's wood rows
(the 45 degree spin is 16-21 % high at any tangential stiffness); at 2 mm all six Table II
rows are met.
While the ball slides it acts behind the centre, so that its torque adds to friction's:
Cross 2002's abstract, "The spin of the ball was found to be larger than that due to the
friction force alone, a result that can be explained if the normal reaction force acts
vertically through a point behind the center of the ball" (and the same section's "R times
the friction impulse was 30-40 % less than the measured change of angular momentum"; its
words "ahead ..., opposing the spin" describe the other sense, which would make the spin
smaller than friction's alone: the measured numbers are followed)."""

TANGENTIAL_STIFFNESS = 8.7e4
"""Tangential stiffness of a tennis ball's contact [N/m]: the spring between the ball's
centre and the patch that grips the surface, which lets a gripping ball spring back and spin
faster than rolling (Cross 2002: R omega / v_x = 1.41 on emery paper).  **Calibrated** on
Cross's oblique bounces without spin (Am. J. Phys. 70 (2002) 482, Table II, six rows on wood,
emery paper and Rebound Ace at 3.4-3.8 m/s, 20 and 45 degrees; ``data/measurements.md``
sec. 6), together with each surface's friction (:data:`ball.court.LAB_SURFACES`) and the
offset (:data:`OFFSET_RATIO`): a scan over 1e4-1e7 N/m, each surface's friction on a grid of
0.01, the largest misfit over its target (3 degrees, 15 %, 0.07) minimised.  The result moves
fast with it (the tangential period, 2 pi sqrt(m_eff / k_t) = 3 ms with m_eff = m I / (I + m
R^2), is about the contact time, so the grip's spring-back changes phase): with the offset at
R/10, emery paper and Rebound Ace stay within the targets only for 6.5e4-9e4 N/m.  The ball's
tangential COR, e_x = -(contact point's speed after) / (before), is then about 0.2 at 20
degrees and 0 at 45 degrees (measured, from the same rows: 0.19, 0.19, 0.00, -0.02; Cross
2002's Table III quotes 0.10-0.17 for gripping bounces).  The court's normal pulse is a
linear law at the ball's secant stiffness (:mod:`ball.court`), 3.3-3.4 ms there against 4.0
ms with the ball's own law: under another pulse the same k_t springs back in another phase.
See ``tests/test_court.py``."""

TANGENTIAL_STIFFNESS_RANGE = (1e3, 1e8)
"""Tangential stiffnesses [N/m] :class:`BallSpin` accepts."""


@dataclass(frozen=True)
class BallSpin:
    """A ball's properties sideways and in rotation.

    Parameters
    ----------
    radius : float
        Ball radius [m] (0.0335, the ITF ball's middle).
    inertia_factor : float
        Moment of inertia over m R^2 [-], in (0, 2/3] (:data:`INERTIA_FACTOR`).
    tangential_stiffness : float
        Stiffness [N/m] of the contact's tangential spring (:data:`TANGENTIAL_STIFFNESS`).
    offset_ratio : float
        The normal force's offset over the radius [-], in [0, 0.5]
        (:data:`OFFSET_RATIO`).
    """

    radius: float = 0.0335
    inertia_factor: float = INERTIA_FACTOR
    tangential_stiffness: float = TANGENTIAL_STIFFNESS
    offset_ratio: float = OFFSET_RATIO

    def __post_init__(self):
        object.__setattr__(self, "radius", in_range("radius", self.radius, 0.005, 0.1, "m"))
        factor = positive("inertia_factor", self.inertia_factor)
        object.__setattr__(self, "inertia_factor", in_range("inertia_factor", factor, 0, 2 / 3))
        k = in_range(
            "tangential_stiffness", self.tangential_stiffness, *TANGENTIAL_STIFFNESS_RANGE, "N/m"
        )
        object.__setattr__(self, "tangential_stiffness", k)
        offset = in_range("offset_ratio", self.offset_ratio, 0.0, 0.5)
        object.__setattr__(self, "offset_ratio", offset)

    def inertia(self, mass: float) -> float:
        """Moment of inertia [kg m^2] of a ball of ``mass`` [kg] about its centre."""
        return self.inertia_factor * positive("mass", mass, "kg") * self.radius**2

    @property
    def offset(self) -> float:
        """The normal force's offset from the centre [m]."""
        return self.offset_ratio * self.radius
