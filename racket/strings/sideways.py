"""The string bed sideways (issues 36, 44): the friction the ball meets on the strings, and
the strings that slide over each other and spring back ("snapback").

A ball that meets the strings obliquely pulls the strings under it sideways through
ball-string friction.  The strings cross: at half the crossings under the ball a main lies
on top, at the other half a cross (:data:`SHARE`), so the ball grips both families, each
through its own patch (:class:`ball.grip.Layer`).  A string moves only across its own
length: slip across the mains drives the mains, slip along them the crosses, oblique slip
both; along its length a string is held by its tension at the frame, so there the patch
meets the frame.  At the crossings the mains and crosses are pressed together by the
weave's own preload and by the ball's force, and stick (static friction) until the ball's
pull beats that hold, then slide (kinetic friction); their tension pulls them back, and as
the ball's push fades they spring back and throw the ball's underside back: the spin it
leaves with grows (Lindsey, TWU "String movement and spin"; ``data/measurements.md`` sec. 6).

The numbers and what they rest on (``s_c`` the crosses' spacing, bed length / (crosses + 1),
``s_m`` the mains', bed width / (mains + 1); 16.5 and 14.6 mm in a 16x19, 100 in^2 head;
T the bed's tension, d the strings' mean gauge):

* ball-string friction: the materials' TWU median (:attr:`Material.ball_friction`);
* the crossings' static friction: the mains' string-string median (TWU's "static
  friction", :attr:`Material.friction`), or :data:`LUBRICATED_FRICTION`; kinetic
  friction :data:`KINETIC_RATIO` of it;
* the pressing force: the weave's preload, 4 T d / (s_c + s_m) a crossing (37 N at 52 lb)
  over the pi (w / 2)^2 / (s_c s_m) crossings under the contact (5.2), and
  :data:`PRESS_RATIO` times the ball's normal force;
* the strings that move: :data:`CONTACT_WIDTH` / s_m mains (2.7) and / s_c crosses (2.4);
* their mass: each string's fundamental sideways mode, a string of length L held at the
  frame, rho L / 2 at its middle (0.74 g for the 2.7 mains of a polyester 16x19);
* their spring: set on the measured snapback, not on spin (:data:`SNAPBACK_TIME`): the
  mains, loaded by their share of a tennis ball's grip (:data:`BALL_TANGENTIAL_MASS`), go
  out and back in 2 ms, half a period: k = pi^2 (m + share m_t) / t^2 (27 kN/m); the
  crosses likewise with the rest of the grip (**an assumption**: their snapback was not
  measured).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ball.catalog import BALL_MASS
from ball.grip import Layer
from ball.spin import INERTIA_FACTOR
from common.checks import in_range, non_negative, positive
from common.typechecks import flag, instance
from racket.strings.bed import StringBed

CONTACT_WIDTH = 0.04
"""Width [m] of the ball's contact on the strings, across the mains and along them.
**An assumption**: a ball of radius R = 33.5 mm flattened by 6-10 mm on the strings at 20-30
m/s touches them over 2 sqrt(2 R delta) = 4-5 cm; range 3-5 cm.  The number of strings that
move is this over their spacing; their stiffness, mass and the preload all scale with it,
so the snapback's period does not."""

SHARE = 0.5
"""The share [-] of the ball's grip on the mains (the rest on the crosses).  **An
assumption** from the weave's geometry: a main lies on top at alternate crossings, so the
ball touches mains and crosses about equally; range 0.4-0.6
(``tests/test_spin_strings.py`` reports how the spin moves over it)."""

KINETIC_RATIO = 0.8
"""Kinetic over static string-string friction [-].  **An assumption**: TWU measures one
coefficient (its "static friction") and no measured kinetic one for strings was found; a
kinetic coefficient is below the static one, so the range is 0.6-1.0, the middle of it
taken (``tests/test_spin_strings.py`` reports the spin over it)."""

PRESS_RATIO = 1.0
"""The share of the ball's normal force that presses the crossings under it [-].  **An
assumption**: the ball touches the strings at the crossings' upper strings and presses them
onto the lower ones, so its whole force passes through crossings (range 1-1.5)."""

SNAPBACK_TIME = 2e-3
"""The measured snapback [s], which sets the strings' return spring (calibration): the mains
"slide sideways and spring back in about 2 ms, half or less of the time the ball is on the
strings" (Lindsey, quoted by Speckman, tennisplayer.net; ``data/measurements.md`` sec. 6).
Out and back is half a period of the mains loaded by the ball's grip (they move while the
ball is on them).  "About" **taken as** 1.5-2.5 ms (``tests/test_spin_strings.py`` reports
the spin over that range)."""

BALL_TANGENTIAL_MASS = BALL_MASS * INERTIA_FACTOR / (1.0 + INERTIA_FACTOR)
"""The tangential effective mass [kg] of the tennis ball whose grip loads the mains in the
snapback's measurement, m I / (I + m R^2) with the ITF ball's mass
(:data:`ball.catalog.BALL_MASS`) and I = 0.55 m R^2 (:data:`ball.spin.INERTIA_FACTOR`): the
calibration's conditions, so the spring is the bed's, whatever ball then meets it.  The
mains carry their share of it, s m_t (**an assumption**): between none (the ball sliding on
them) and all (the ball sliding on the crosses, its whole tangential inertia on the mains),
a spring 0.5 to 2 times as stiff, within what :data:`SNAPBACK_TIME`'s range spans (0.64 to
1.78 times)."""

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
        Static string-string coefficient of friction [-] at the crossings, in [0, 2].
    stiffness : (float, float)
        Springs [N/m] pulling the strings back, (along, across): the crosses' and the
        mains', each >= 0.
    mass : (float, float)
        Their moving mass sideways [kg], (along, across); (0, 0) for a bed that does not
        slide (stiff sideways).
    preload : float
        The weave's force [N] pressing the crossings under the ball, >= 0.
    share : float
        The share [-] of the ball's grip on the mains, in [0, 1].
    kinetic_ratio : float
        Kinetic over static string-string friction [-], in [0, 1].
    """

    ball_friction: float
    string_friction: float = 0.0
    stiffness: tuple = (0.0, 0.0)
    mass: tuple = (0.0, 0.0)
    preload: float = 0.0
    share: float = SHARE
    kinetic_ratio: float = KINETIC_RATIO

    def __post_init__(self):
        for name in ("stiffness", "mass"):
            value = getattr(self, name)
            if not isinstance(value, tuple | list) or len(value) != 2:
                raise ValueError(f"{name} must be an (along, across) pair, got {value!r}")
        for name in ("ball_friction", "string_friction"):
            object.__setattr__(self, name, in_range(name, getattr(self, name), 0.0, 2.0))
        pair = tuple(non_negative("stiffness", k, "N/m") for k in self.stiffness)
        object.__setattr__(self, "stiffness", pair)
        object.__setattr__(self, "mass", tuple(in_range("mass", m, 0.0, 0.05, "kg")
                                               for m in self.mass))  # fmt: skip
        if self.slides and min(self.mass) < 1e-6:
            raise ValueError(f"mass must be at least 1e-06 kg both ways when the strings "
                             f"slide, got {self.mass!r}")  # fmt: skip
        object.__setattr__(self, "preload", non_negative("preload", self.preload, "N"))
        object.__setattr__(self, "share", in_range("share", self.share, 0.0, 1.0))
        ratio = in_range("kinetic_ratio", self.kinetic_ratio, 0.0, 1.0)
        object.__setattr__(self, "kinetic_ratio", ratio)

    @property
    def slides(self) -> bool:
        """True when the strings can slide (a mass to move)."""
        return max(self.mass) > 0.0

    def layer(self) -> Layer | None:
        """The :class:`ball.grip.Layer` of the sliding strings, or None for a stiff bed."""
        if not self.slides:
            return None
        kinetic = self.kinetic_ratio * self.string_friction
        return Layer(self.stiffness, self.mass, self.string_friction, kinetic, self.preload,
                     PRESS_RATIO, self.share)  # fmt: skip


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


def _family(count: float, length: float, density: float, share: float) -> tuple[float, float]:
    """Spring [N/m] and mass [kg] of ``count`` strings of ``length`` [m] and ``density``
    [kg/m] moving sideways, which carry ``share`` [-] of the ball's grip: the mass of their
    fundamental mode at its middle, the spring that takes them, so loaded, out and back in
    :data:`SNAPBACK_TIME`.
    """
    mass = count * density * length / 2.0
    loaded = mass + share * BALL_TANGENTIAL_MASS
    return math.pi**2 * loaded / SNAPBACK_TIME**2, mass


def sideways(bed, lubricated: bool = False, slide: bool = True, share: float = SHARE,
             kinetic_ratio: float = KINETIC_RATIO) -> BedSideways:  # fmt: skip
    """The :class:`BedSideways` of a :class:`racket.StringBed`.

    Parameters
    ----------
    bed : StringBed
        The string bed; one described by its stringing (:attr:`StringBed.stringing`, with a
        tension) gets its materials' friction and its strings' tension and mass; any other
        is stiff sideways, with :data:`STIFF_BALL_FRICTION`.
    lubricated : bool, optional
        Lubricated strings: the crossings' friction is :data:`LUBRICATED_FRICTION`.  True or
        False (a word such as ``'no'`` is refused, not taken as True).
    slide : bool, optional
        False: the strings never slide (a stiff-sideways bed, the limit); True or False.
    share, kinetic_ratio : float, optional
        The grip's share on the mains [-] and kinetic over static string friction [-], as
        :class:`BedSideways` (:data:`SHARE`, :data:`KINETIC_RATIO`: assumptions).
    """
    instance("bed", bed, StringBed, "a racket.StringBed",
             " (a racket's is racket.strings)" if hasattr(bed, "strings") else "")  # fmt: skip
    lubricated, slide = flag("lubricated", lubricated), flag("slide", slide)
    stringing = bed.stringing
    if stringing is None or stringing.tension is None:
        return BedSideways(STIFF_BALL_FRICTION)
    mains, crosses = stringing.mains, stringing.crosses
    ball_friction = 0.5 * (mains.material.ball_friction + crosses.material.ball_friction)
    if not slide:
        return BedSideways(ball_friction)
    friction = LUBRICATED_FRICTION if lubricated else mains.material.friction
    cross_spacing, main_spacing = _spacings(bed)
    tension = stringing.bed_tension
    length = bed.extent[1] - bed.extent[0]
    k_m, m_m = _family(CONTACT_WIDTH / main_spacing, length, mains.linear_density, share)
    k_c, m_c = _family(CONTACT_WIDTH / cross_spacing, bed.full_width, crosses.linear_density,
                       1.0 - share)  # fmt: skip
    gauge = 0.5 * (mains.gauge + crosses.gauge)
    crossings = math.pi * (0.5 * CONTACT_WIDTH) ** 2 / (cross_spacing * main_spacing)
    preload = crossings * 4.0 * tension * gauge / (cross_spacing + main_spacing)
    return BedSideways(ball_friction, friction, (k_c, k_m), (m_c, m_m), preload, share,
                       kinetic_ratio)  # fmt: skip


def snapback_time(side: BedSideways) -> float:
    """Time [s] the mains take to go out and back, loaded by their share of a tennis ball's
    tangential mass: half a period, pi sqrt((m + share m_t) / k) (the quantity their spring
    is set on, :data:`SNAPBACK_TIME`); inf for a stiff bed.

    Parameters
    ----------
    side : BedSideways
        The bed sideways.
    """
    if not side.slides or side.stiffness[1] == 0.0:
        return math.inf
    loaded = side.mass[1] + side.share * BALL_TANGENTIAL_MASS
    return math.pi * math.sqrt(loaded / side.stiffness[1])
