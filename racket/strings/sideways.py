"""The string bed sideways (issue 36): the friction the ball meets on the strings, and the
mains that slide over the crosses and spring back ("snapback").

A ball that meets the strings obliquely pulls the strings under it sideways through
ball-string friction.  The mains under the ball are held on the crosses by string-string
friction, pressed together by the ball's own normal force, and pulled back to their places
by their tension.  While the ball's pull beats that friction they slide; as the ball's push
fades they spring back, and throw the ball's underside back: the spin it leaves with grows
(Lindsey, TWU "String movement and spin"; ``data/measurements.md`` sec. 6).  In
:mod:`ball.grip` this is the *layer*: a mass held by a spring and by Coulomb friction.

**The picture.**  Only the mains' segments under the ball move: outside the contact each
main is held where it crosses the crosses, so a moved segment is joined to its place by a
short straight ramp on each side, and its tension T pulls it back with 2 T / r (r the
ramp's length).  The mains under the ball are pressed onto the crosses by the ball's force,
which passes through the crossings under it, and slide when the ball's pull beats that
friction.

The numbers and what they rest on (``s_c`` the crosses' spacing, bed length / (crosses + 1),
``s_m`` the mains', bed width / (mains + 1); 16.5 and 14.6 mm in a 16x19, 100 in^2 head):

* ball-string friction: the material's TWU median (:attr:`Material.ball_friction`);
* main-cross friction: the material's string-string median (:attr:`Material.friction`), or
  :data:`LUBRICATED_FRICTION`;
* the pressing force: :data:`PRESS_RATIO` times the ball's normal force;
* the mains that move: :data:`CONTACT_WIDTH` / s_m of them (2.7);
* their stiffness: 2 T / r each, r = :data:`HOLD_SPACINGS` x s_c (28 kN/m a main at 52 lb,
  77 kN/m for the 2.7; T the bed's tension);
* their mass: each main's segment under the ball (:data:`CONTACT_WIDTH` long) and a third
  of each ramp (a straight ramp's modal mass for its end's motion), times its mass per
  length (0.24 g for polyester 1.25 mm): the snapback's own period, 2 pi sqrt(m / k), is
  0.35 ms, and does not depend on how many mains move.

What the picture leaves out (see :data:`HOLD_SPACINGS` and :data:`PRESS_RATIO`): the
weave's own pressure at the crossings (a few tens of N each), which a friction limit that is
a multiple of the ball's force cannot carry, and the crosses' share of the ball's grip.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ball.grip import Layer
from common.checks import in_range, non_negative, positive

CONTACT_WIDTH = 0.04
"""Width [m] of the ball's contact on the strings, across the mains and along them.
**An assumption**: a ball of radius R = 33.5 mm flattened by 6-10 mm on the strings at 20-30
m/s touches them over 2 sqrt(2 R delta) = 4-5 cm; range 3-5 cm.  The number of mains that
move is this over the mains' spacing; the stiffness and the mass both scale with it, so the
snapback's period does not."""

HOLD_SPACINGS = 1.0
"""Length of the ramp from the moved segment to where the crosses hold the main, in cross
spacings [-].  **An assumption**: the first crossing outside the contact is 0-1 spacing
from its edge, the second 1-2 (range 0.5-2).  The weave's friction alone holds far less:
a crossing is pressed by about 4 T d / (s_c + s_m) (the main and the cross each bent by
their diameter d over the spacing: 37 N at 52 lb), which at the polyester's 0.086 holds a
ramp of one spacing only up to about 0.2 mm of slide (T s / r = mu 4 T d / (s_c + s_m)); a
ramp held by friction alone grows with the slide (1.5-2.5 spacings at 1-3 mm, with its
force), so the picture counts on the crossings' notches and the neighbouring mains."""

PRESS_RATIO = 1.0
"""The force pressing the mains under the ball onto the crosses, over the ball's normal force
[-].  **An assumption**: the ball touches the strings at the crossings' upper strings and
presses them onto the lower ones, so its whole force passes through crossings (range 1-1.5:
the weave's own pressure, about 37 N a crossing at 52 lb over the 5 crossings under a 4 cm
contact, is 0.2-0.3 of the ball's peak force at 25 m/s; :mod:`ball.grip`'s limit, a multiple
of the ball's force, cannot carry a pressure that is there before the ball and after it)."""

LUBRICATED_FRICTION = 0.04
"""String-string coefficient of friction [-] of lubricated strings.  **An assumption**: no
measured value was found; silicone-lubricated polymer on polymer is about 0.03-0.06 (TWU's
dry medians are 0.086-0.149, ``data/measurements.md`` sec. 5)."""

STIFF_BALL_FRICTION = 0.43
"""Ball-string coefficient of friction [-] of a bed described without its strings (the
paper's, or a stiffness typed in): **an assumption**, the materials' TWU medians
(0.417-0.444, ``data/measurements.md`` sec. 5) in the middle."""


@dataclass(frozen=True)
class BedSideways:
    """What a ball meets sideways on a string bed.

    Parameters
    ----------
    ball_friction : float
        Ball-string coefficient of friction [-], in [0, 2].
    string_friction : float
        Main-cross coefficient of friction [-], in [0, 2] (times :data:`PRESS_RATIO` the
        ball's force, the limit of the mains' hold on the crosses).
    stiffness : float
        Spring [N/m] pulling the mains back, >= 0.
    mass : float
        The mains' moving mass sideways [kg]; 0 for a bed that does not slide (stiff
        sideways).
    """

    ball_friction: float
    string_friction: float = 0.0
    stiffness: float = 0.0
    mass: float = 0.0

    def __post_init__(self):
        friction = in_range("ball_friction", self.ball_friction, 0.0, 2.0)
        object.__setattr__(self, "ball_friction", friction)
        friction = in_range("string_friction", self.string_friction, 0.0, 2.0)
        object.__setattr__(self, "string_friction", friction)
        object.__setattr__(self, "stiffness", non_negative("stiffness", self.stiffness, "N/m"))
        object.__setattr__(self, "mass", in_range("mass", self.mass, 0.0, 0.05, "kg"))

    @property
    def slides(self) -> bool:
        """True when the mains can slide (a mass to move)."""
        return self.mass > 0.0

    def layer(self) -> Layer | None:
        """The :class:`ball.grip.Layer` of the sliding mains, or None for a stiff bed."""
        if not self.slides:
            return None
        return Layer(self.stiffness, self.mass, PRESS_RATIO * self.string_friction)


def _spacings(bed) -> tuple[float, float]:
    """The crosses' and the mains' spacings [m] of a strung bed: its length / (crosses + 1)
    and its width / (mains + 1).

    Parameters
    ----------
    bed : StringBed
        A bed described by its stringing (:attr:`StringBed.stringing`).
    """
    mains, crosses = bed.stringing.pattern
    length = positive("the bed's length", bed.extent[1] - bed.extent[0], "m")
    return length / (crosses + 1), bed.full_width / (mains + 1)


def sideways(bed, lubricated: bool = False, slide: bool = True) -> BedSideways:
    """The :class:`BedSideways` of a :class:`racket.StringBed`.

    Parameters
    ----------
    bed : StringBed
        The string bed; one described by its stringing (:attr:`StringBed.stringing`, with a
        tension) gets its material's friction and its mains' tension and mass; any other is
        stiff sideways, with :data:`STIFF_BALL_FRICTION`.
    lubricated : bool, optional
        Lubricated strings: the main-cross friction is :data:`LUBRICATED_FRICTION`.
    slide : bool, optional
        False: the mains never slide (a stiff-sideways bed, the limit).
    """
    stringing = bed.stringing
    if stringing is None or stringing.tension is None:
        return BedSideways(STIFF_BALL_FRICTION)
    mains = stringing.mains
    ball_friction = 0.5 * (mains.material.ball_friction + stringing.crosses.material.ball_friction)
    if not slide:
        return BedSideways(ball_friction)
    friction = LUBRICATED_FRICTION if lubricated else mains.material.friction
    cross_spacing, main_spacing = _spacings(bed)
    moving = CONTACT_WIDTH / main_spacing  # mains under the ball
    ramp = HOLD_SPACINGS * cross_spacing
    stiffness = moving * 2.0 * stringing.bed_tension / ramp
    mass = moving * mains.linear_density * (CONTACT_WIDTH + 2.0 * ramp / 3.0)
    return BedSideways(ball_friction, friction, stiffness, mass)


def snapback_period(side: BedSideways) -> float:
    """Period [s] of the mains springing back on their own, 2 pi sqrt(mass / stiffness)
    (inf for a stiff bed).

    Parameters
    ----------
    side : BedSideways
        The bed sideways.
    """
    if not side.slides or side.stiffness == 0.0:
        return math.inf
    return 2.0 * math.pi * math.sqrt(side.mass / side.stiffness)
