"""The hand holding a racket: springs and dashpots spread over the grip, joining the handle
to the mass of the hand and forearm, and the grip presets.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from common.checks import non_negative, positive

GRIP_RADIUS = 0.0177
"""Radius [m] at which the hand grips the handle: a 4 3/8 grip (grip sizes are the
handle's perimeter in inches), 111 mm round, as a circle.  The hand's springs act there,
so it resists the racket's twist by k r**2 per unit length (assumption: the same spring
across the handle as along it)."""


@dataclass(frozen=True)
class Hand:
    """A hand holding the handle: a spring and a dashpot spread evenly over the grip.

    Parameters
    ----------
    stiffness : float
        Total transverse stiffness of the hand on the handle [N/m].
    damping : float
        Total damping coefficient of the hand [N s/m].
    grip_length : float
        Length of handle the hand covers, from the butt [m].
    mass : float
        Effective mass of the hand and forearm that the grip moves [kg], > 0; the grip's
        springs and dashpots join the handle to it, and it is otherwise free.  ``inf``
        (default): the grip is held still, the springs and dashpots join the handle to the
        ground (the model before the hand had a mass).  The grip presets
        :data:`GRIPS` have a finite mass.
    resists_twist : bool
        Whether the grip resists the racket's twist about its long axis (default True: a
        hand's springs act at the handle's surface, :data:`GRIP_RADIUS`).  False: the
        racket rolls freely in it, as about a pin at the butt.

    Notes
    -----
    A :class:`racket.Racket` is held by the medium grip of :data:`GRIPS` unless told otherwise: a
    hand of mass, calibrated to measured hand-held frequencies (see :data:`GRIP_MASSES`).
    ``Hand()`` itself (1e4 N/m, 10 N s/m over 0.10 m, a palm's width, infinite mass) is the
    grip held still, the model before the hand had a mass: order-of-magnitude values, not a
    measurement (the hand-arm system is usually described by lumped masses, springs and
    dashpots, ISO 10068; how a grip changes a racket's modes depends strongly on how hard it
    is squeezed, D. Chadefaux et al., J. Sports Sci. 35, 2017).  Held still, a racket's
    first bending mode rises (150 to 152.9 Hz for the Pure Drive), where measured hand-held
    frequencies fall; with the medium grip it falls to 137.5 Hz.  Either way the ball's
    rebound from the string centre hardly depends on the hand (the impulse reaches the hand
    after the ball has nearly left, paper Sec. VII).
    """

    stiffness: float = 1e4
    damping: float = 10.0
    grip_length: float = 0.10
    mass: float = math.inf
    resists_twist: bool = True

    def __post_init__(self):
        object.__setattr__(self, "stiffness", positive("hand stiffness", self.stiffness, "N/m"))
        object.__setattr__(self, "damping", non_negative("hand damping", self.damping, "N s/m"))
        object.__setattr__(self, "grip_length", positive("grip_length", self.grip_length, "m"))
        if not (isinstance(self.mass, float) and math.isinf(self.mass) and self.mass > 0):
            object.__setattr__(self, "mass", positive("hand mass", self.mass, "kg"))
        if not isinstance(self.resists_twist, bool):
            raise ValueError(f"resists_twist must be True or False, got {self.resists_twist!r}")


GRIP_STIFFNESS = 2.5e5
"""Stiffness [N/m] of every grip preset's springs between the handle and the hand's mass
(calibrated with :data:`GRIP_MASSES`, see there)."""

GRIP_MASSES = {"light": 0.13, "medium": 0.19, "tight": 1.0}
"""Effective mass [kg] of the hand and forearm that each grip moves.  Calibrated (with
:data:`GRIP_STIFFNESS`, one stiffness for all, by least squares, rounded) so that the first
bending mode of a held racket falls from the free one by the fractions Savage measured
(PhD thesis, RMIT 2006, appendix; ``data/measurements.md`` section 3): racket A,
183.75 Hz free, 170.25 / 165.0 / about 145 Hz held lightly / medium / tightly (7.3, 10.2 and
about 21 %); racket B, 162.5 Hz free, 149 / 146.25 / 142.5 Hz (8.3, 10.0 and 12.3 %).  The
model frames are the Pure Drive's sheet tuned to those free frequencies (his rackets' mass
and balance are not given).  The model gives 8.5 and 7.0 % (light), 10.9 and 9.3 %
(medium), 18 and 16 % (tight): within 2 % of his fractions, and inside the span of his
tight grips.  These numbers calibrate; they do not validate (a tighter grip engages more of
the forearm: an interpretation, not a measurement)."""

GRIP_DAMPING = 10.0
"""Damping coefficient [N s/m] of every grip preset (an assumption: the order-of-magnitude
default of the hand before it had a mass; Savage's damping is not in the data at hand)."""

GRIPS = {name: Hand(GRIP_STIFFNESS, GRIP_DAMPING, 0.10, mass) for name, mass in GRIP_MASSES.items()}
"""The grip presets, ``"light"``, ``"medium"`` (the default hand of a
:class:`racket.Racket`) and ``"tight"``: a hand of mass :data:`GRIP_MASSES` over a 10 cm grip."""
