"""The hand holding a racket: springs and dashpots spread over the grip, joining the handle
to the mass of the hand and forearm, and the grip presets.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from common.checks import (
    CM_AS_M,
    GRAMS_AS_KG,
    KN_AS_N,
    in_range,
    non_negative,
    positive,
    shown,
    slip_hints,
)

GRIP_RADIUS = 0.0177
"""Radius [m] at which the hand grips the handle: a 4 3/8 grip (grip sizes are the
handle's perimeter in inches), 111 mm round, as a circle.  The hand's springs act there,
so it resists the racket's twist by k r**2 per unit length (assumption: the same spring
across the handle as along it)."""


HAND_MASS_RANGE = (0.05, 5.0)
"""The effective mass of the hand and forearm a grip moves [kg] that :class:`Hand` accepts
(or ``inf``, the grip held still).  From the body's segments as fractions of its mass
(Dempster's, as tabulated by D. A. Winter, *Biomechanics and Motor Control of Human
Movement*, 4th ed., 2009, Table 4.1: hand 0.006, forearm 0.016, upper arm 0.028): the
whole arm of a 100 kg player is 5 kg, the hand of a 20 kg child 0.12 kg; **an
assumption** below that (a light grip engages part of a small hand), down to 0.05 kg.  The
grip presets' masses (:data:`GRIP_MASSES`, 0.13-1 kg) lie inside.  A mass in grams typed as
kg (190 for 0.19) is refused with the hint; a far lighter hand gave NaN in e."""

HAND_STIFFNESS_RANGE = (1e3, 1e8)
"""The grip's stiffness [N/m] that :class:`Hand` accepts: **an assumption**, generous
around the grips of this project (1e4 N/m held still, :data:`GRIP_STIFFNESS` 2.5e5 N/m, a
pin of 1e6 N/m in ``studies.validation``).  Below 1e3 N/m a 0.3 kg racket would sag 3 mm
in the hand under its own weight; above 1e8 N/m the grip is stiffer than the handle it
holds.  A stiffness in kN/m typed as N/m (250 for 2.5e5) is refused with the hint."""

HAND_DAMPING_MAX = 1e3
"""The largest damping coefficient [N s/m] :class:`Hand` accepts: **an assumption**, over
twice the critical damping 2 sqrt(k m) of the medium grip (436 N s/m).  A grip of 1e4 N s/m
over 1 cm held the racket so long that its impact did not end within the solver's budget."""

GRIP_LENGTH_RANGE = (0.01, 0.5)
"""The length of handle a hand covers [m] that :class:`Hand` accepts: **an assumption**,
from a 1 cm pin to more than two hands (a palm is about 10 cm wide); the racket refuses a
grip that reaches its strings.  A length in cm typed as m (10 for 0.1) is refused with
the hint."""


@dataclass(frozen=True)
class Hand:
    """A hand holding the handle: a spring and a dashpot spread evenly over the grip.

    Parameters
    ----------
    stiffness : float
        Total transverse stiffness of the hand on the handle [N/m], in
        :data:`HAND_STIFFNESS_RANGE`.
    damping : float
        Total damping coefficient of the hand [N s/m], 0 to :data:`HAND_DAMPING_MAX`.
    grip_length : float
        Length of handle the hand covers, from the butt [m], in :data:`GRIP_LENGTH_RANGE`.
    mass : float
        Effective mass of the hand and forearm that the grip moves [kg], in
        :data:`HAND_MASS_RANGE`; the grip's
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
        stiffness = positive("hand stiffness", self.stiffness, "N/m")  # a sign slip said so
        stiffness = in_range(
            "hand stiffness", stiffness, *HAND_STIFFNESS_RANGE, "N/m", slips=(KN_AS_N,)
        )
        object.__setattr__(self, "stiffness", stiffness)
        damping = non_negative("hand damping", self.damping, "N s/m")
        damping = in_range("hand damping", damping, 0.0, HAND_DAMPING_MAX, "N s/m")
        object.__setattr__(self, "damping", damping)
        length = positive("grip_length", self.grip_length, "m")
        length = in_range("grip_length", length, *GRIP_LENGTH_RANGE, "m", slips=(CM_AS_M,))
        object.__setattr__(self, "grip_length", length)
        if not (isinstance(self.mass, float) and math.isinf(self.mass) and self.mass > 0):
            mass, (low, high) = positive("hand mass", self.mass, "kg"), HAND_MASS_RANGE
            if not low <= mass <= high:
                slipped = slip_hints(mass, low, high, "kg", (GRAMS_AS_KG,))
                raise ValueError(
                    f"hand mass must be in [{low:g}, {high:g}] kg, or inf (the grip held "
                    f"still), got {shown(self.mass)}" + (f" ({slipped})" if slipped else "")
                )
            object.__setattr__(self, "mass", mass)
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
