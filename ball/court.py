"""A ball bouncing on a court: slide, grip, spin and the ITF Court Pace Rating (issue 36).

The normal problem comes first, and is the head-on bounce of :func:`ball.collide` of the
ball's own law on the :data:`~ball.WALL` (issue 44: its own pulse, not a linear stand-in,
whose contacts were 15-20 % shorter); its force history drives the tangential contact of
:func:`ball.grip.slide` (a one-way coupling, see :mod:`ball.grip`).  **Assumption** (the
court's yield): the pulse keeps the ball's own shape and contact time, and its impulse is
scaled to m (1 + e) v with the court's COR e, so that the bounce's COR is the court's exactly
(the court's yield and the ball's loss together, as the ITF measures it; the court's own
compliance, which would lengthen the contact a little, is left out).

Face-frame axes are (along, across, normal), the normal up out of the court; the ball moves
+along, and topspin (its top moving forward) is +across.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ball.bodies import WALL, Ball
from ball.catalog import BALL_PRESETS, DEFAULT_BALL
from ball.collision import collide
from ball.grip import FRICTION_RANGE, slide
from ball.spin import BallSpin, ask_spin
from common.checks import (
    FASTEST_STROKE,
    RPM_AS_RAD_S,
    SPEED_RANGE,
    finite,
    in_range,
    shown,
    slip_hints,
    too_fast,
    whole,
)
from common.typechecks import ask, instance

COR_RANGE = (0.05, 1.0)
"""Normal COR [-] of a bounce a :class:`Court` accepts."""

FASTEST_BOUNCE = 80.0
"""Fastest ball [m/s] :func:`bounce` accepts (faster than any serve reaches the court)."""

"""A spin in rpm where rad/s are asked for."""


@dataclass(frozen=True)
class Court:
    """A surface a ball bounces on.

    Parameters
    ----------
    name : str
        Its name.
    friction : float
        Ball-court coefficient of sliding friction [-], in [0, 2].
    cor : float
        Normal (vertical) COR of a bounce on it [-], in [0.05, 1].
    """

    name: str
    friction: float
    cor: float

    def __post_init__(self):
        instance("name", self.name, str, "a word")
        object.__setattr__(self, "friction", in_range("friction", self.friction, *FRICTION_RANGE))
        object.__setattr__(self, "cor", in_range("cor", self.cor, *COR_RANGE))


def _by_name(*courts: Court) -> dict:
    return {court.name: court for court in courts}


COURTS = _by_name(Court("grass", 0.53, 0.75), Court("clay", 0.80, 0.90), Court("hard", 0.60, 0.80))
"""The court presets by name (sources: :data:`COURT_SOURCES`)."""

LAB_SURFACES = _by_name(
    Court("wood", 0.21, 0.765), Court("emery paper", 0.67, 0.815), Court("Rebound Ace", 0.67, 0.765)
)
"""The surfaces of Cross's oblique bounces at 3.4-3.8 m/s, each **calibrated on Cross 2002
Table II** (``data/measurements.md`` sec. 6) with the ball's
:data:`ball.spin.STIFFNESS_RATIO` and :data:`ball.spin.OFFSET_RATIO` (found with them).
The COR is the mean of the surface's two rows' e_y.  The friction is found on a grid of 0.01
(with :func:`bounce`'s default ball and steps) by :mod:`studies.validation.grip_calibration`:
the one that minimises the largest of the misfits of rebound angle, spin and vx2/vx1 over
the surface's two rows, each over its target (3 degrees, 15 %, 0.07; ``tests/test_court.py``
holds the rows).  (Issue 44 moved them, with the ball's pulse and tangential stiffness: wood
0.20 -> 0.21, emery paper 0.56 -> 0.67, Rebound Ace 0.59 -> 0.67.)"""

_CROSS_COURTS = (
    "Cross, Sports Eng. 6 (2003) and 'Measurement of the speed and bounce of tennis courts' "
    "(2010), quoted in data/measurements.md sec. 7"
)
_TABLE_II = (
    "calibrated on Cross, Am. J. Phys. 70 (2002) 482, Table II (data/measurements.md sec. 6)"
)

COURT_SOURCES = {
    "grass": f"friction 0.53 (30 m/s, 17 degrees), COR about 0.75: {_CROSS_COURTS}",
    "clay": f"friction about 0.8, COR about 0.9 (0.91 measured in 2010): {_CROSS_COURTS}",
    "hard": (
        "ASSUMPTION: friction 0.6 and COR 0.8, between grass and clay (no sourced number "
        "for an acrylic hard court was found; Rebound Ace, a hard court, is 0.61 and 0.765 "
        "at 3.6 m/s in LAB_SURFACES)"
    ),
    **dict.fromkeys(LAB_SURFACES, _TABLE_II),
}
"""Where each court's and lab surface's numbers come from."""

CPR_SPEED, CPR_ANGLE = 30.0, math.radians(16.0)
"""The ITF Court Pace Rating test's ball [m/s] and angle above the court [rad]: 30 +/- 2
m/s, 16 +/- 2 degrees, spin at most 3 rev/s (ITF CS 01/02, itftennis.com, own text)."""

CPR_ANGLE_DEG = round(math.degrees(CPR_ANGLE), 9)
"""The ITF pace test's angle above the court [deg] (:data:`ball.court.CPR_ANGLE`)."""

CPR_CATEGORIES = ((1, "slow", 30.0), (2, "medium-slow", 35.0), (3, "medium", 40.0),
                  (4, "medium-fast", 45.0), (5, "fast", math.inf))  # fmt: skip
"""The ITF court pace categories: (number, name, the CPR [-] it stays below): 1 up to 29,
2 30-34, 3 35-39, 4 40-44, 5 45 and above (ITF Technical Booklet 2015 p. 3 names the five;
the bands as quoted by laykold.com, "Court Pace Ratings or Court Pace Index", and
tennisyard.com's guide to court surfaces; the bands are read as below 30, 35, 40 and 45: a
CPR of 29.5 is category 1)."""


@dataclass(frozen=True)
class Bounce:
    """Outcome of :func:`bounce`; the ball moves forward (+along) and topspin is positive.

    Attributes
    ----------
    speed_after : float
        Ball speed after [m/s].
    angle_after : float
        Angle of the rebound above the court [rad] (above pi/2: the ball comes back).
    spin_after : float
        Spin after [rad/s], topspin positive.
    vx_ratio : float
        Horizontal velocity after over before, vx2 / vx1 [-].
    e_y : float
        Vertical COR, vy2 / vy1 [-].
    apparent_friction : float
        |vx2 - vx1| / (vy1 + vy2) [-], as the ITF measures it (the sliding friction only if
        the ball slid throughout).
    contact_time : float
        Duration of the contact [s].
    slid_throughout : bool
        True if the ball never gripped.
    translational_before, rotational_before : float
        The ball's kinetic energy of translation and of rotation before [J].
    translational_after, rotational_after : float
        The same after [J].
    normal_loss : float
        Energy lost in the normal bounce [J], m vy1^2 (1 - e_y^2) / 2.
    slip_loss : float
        Energy lost to the ball sliding on the court [J].
    offset_work : float
        Energy the normal force's offset took from the spin [J] (negative: gave it; taken
        from the normal motion, which the one-way coupling does not debit).
    stiffness_work : float
        Energy the contact's tangential spring gained as its stiffness followed the normal
        force [J] (from the normal motion, likewise).
    """

    speed_after: float
    angle_after: float
    spin_after: float
    vx_ratio: float
    e_y: float
    apparent_friction: float
    contact_time: float
    slid_throughout: bool
    translational_before: float
    rotational_before: float
    translational_after: float
    rotational_after: float
    normal_loss: float
    slip_loss: float
    offset_work: float
    stiffness_work: float

    @property
    def energy_in(self) -> float:
        """The ball's kinetic energy before [J]."""
        return self.translational_before + self.rotational_before

    @property
    def residual(self) -> float:
        """Energy [J] the budget leaves unaccounted: in + stiffness work - out - losses -
        offset work (the stepping's round-off: :mod:`ball.grip` books the slip loss as the
        discrete power).
        """
        out = self.translational_after + self.rotational_after
        losses = self.normal_loss + self.slip_loss + self.offset_work
        return self.energy_in + self.stiffness_work - out - losses


def _angle(angle) -> float:
    """The angle above the court [rad], in (0, pi/2), with a hint if it is in degrees."""
    x = finite("angle", angle, "rad")
    if not 0.0 < x < math.pi / 2:
        hint = slip_hints(x, 1e-9, math.pi / 2 - 1e-9, "rad", ((math.pi / 180, "degrees typed "
                          "as radians?", "degrees"),))  # fmt: skip
        raise ValueError(
            f"angle must be in (0, 1.571) rad (0-90 degrees above the court), got "
            f"{shown(angle)}{f' ({hint})' if hint else ''}"
        )
    return x


def normal_force(ball: Ball, cor: float, speed: float, steps: int):
    """The normal force history of a ball hitting a court, on a uniform grid.

    Parameters
    ----------
    ball : Ball
        The ball; its own law gives the pulse's shape and duration.
    cor : float
        The court's normal COR [-]: the impulse is m (1 + cor) v.
    speed : float
        Normal speed [m/s].
    steps : int
        Steps of the grid over the contact.

    Returns
    -------
    tuple
        (force [N] at the ``steps + 1`` times, the grid's step [s], the head-on
        :class:`~ball.Collision` of the ball's own law on the wall).  The history is scaled
        so that its impulse (linear between samples) is m (1 + cor) v exactly.
    """
    hit = collide(ball, WALL, speed, samples=steps)
    t = np.linspace(0.0, hit.history.t[-1], steps + 1)
    force = np.interp(t, hit.history.t, hit.history.force)
    force[-1] = 0.0
    dt = t[1] - t[0]
    impulse = ball.mass * (1.0 + cor) * speed
    return force * impulse / (dt * (force.sum() - 0.5 * force[0])), dt, hit


def bounce(
    court: Court,
    speed: float,
    angle: float,
    spin: float = 0.0,
    ball: Ball | None = None,
    ball_spin: BallSpin | None = None,
    steps: int = 2000,
) -> Bounce:
    """A ball's bounce on ``court``: slides, grips, springs back, and leaves spinning.

    Parameters
    ----------
    court : Court
        The surface (:data:`COURTS`, :data:`LAB_SURFACES` or one's own).
    speed : float
        Ball speed before [m/s], in (0, 80]; one faster than the serve record
        (:data:`common.checks.FASTEST_STROKE`) is asked about in a warning (mph typed as m/s?).
    angle : float
        Angle of its path below the horizontal as it falls, i.e. above the court [rad],
        in (0, pi/2).
    spin : float
        Spin before [rad/s], topspin (the ball's top moving forward) positive, in [-1000,
        1000]; one above :data:`ball.spin.MOST_SPIN` is asked about (rpm typed as rad/s?).
    ball : Ball, optional
        The ball (its mass, and its law's secant stiffness); None: the default preset's.
    ball_spin : BallSpin, optional
        Its radius, inertia, tangential stiffness and offset; None: :class:`BallSpin`'s
        defaults at the ball's radius.
    steps : int
        Steps of the force history over the contact, in [100, 100000].

    Returns
    -------
    Bounce
    """
    instance("court", court, Court, "a ball.court.Court", " (e.g. COURTS['clay'])")
    speed = finite("speed", speed, "m/s")
    if not 0.0 < speed <= FASTEST_BOUNCE:
        raise ValueError(f"speed must be in (0, {FASTEST_BOUNCE:g}] m/s, got {shown(speed)}")
    ask(too_fast, "speed", speed, "m/s", FASTEST_STROKE, "the serve record")
    angle = _angle(angle)
    if speed * math.sin(angle) < SPEED_RANGE[0]:
        raise ValueError(
            f"the ball must come down at {SPEED_RANGE[0]:g} m/s at least, got speed "
            f"{shown(speed)} m/s at {math.degrees(angle):.4g} deg: "
            f"{speed * math.sin(angle):.3g} m/s"
        )
    spin = in_range("spin", spin, -1000.0, 1000.0, "rad/s", slips=(RPM_AS_RAD_S,))
    ask_spin("spin", spin)
    steps = whole("steps", steps, 100, 100_000)
    if ball is None:
        ball = BALL_PRESETS[DEFAULT_BALL].ball()
    instance("ball", ball, Ball, "a ball.Ball or None")
    if ball_spin is None:
        ball_spin = BallSpin() if ball.radius is None else BallSpin(radius=ball.radius)
    instance("ball_spin", ball_spin, BallSpin, "a ball.spin.BallSpin or None")

    m, v_x, v_y = ball.mass, speed * math.cos(angle), speed * math.sin(angle)
    force, dt, hit = normal_force(ball, court.cor, v_y, steps)
    grip = slide(force, dt, m, ball_spin, court.friction, [v_x, 0.0], [0.0, spin, 0.0],
                 law=ball.law)  # fmt: skip
    vx2, spin2, vy2 = float(grip.velocity[0, 0]), float(grip.spin[0, 1]), court.cor * v_y
    inertia = ball_spin.inertia(m)
    return Bounce(
        speed_after=math.hypot(vx2, vy2),
        angle_after=math.atan2(vy2, vx2),
        spin_after=spin2,
        vx_ratio=vx2 / v_x,
        e_y=vy2 / v_y,
        apparent_friction=abs(vx2 - v_x) / (v_y + vy2),
        contact_time=hit.contact_time,
        slid_throughout=bool(grip.slid_throughout[0]),
        translational_before=0.5 * m * speed**2,
        rotational_before=0.5 * inertia * spin**2,
        translational_after=0.5 * m * (vx2**2 + vy2**2),
        rotational_after=0.5 * inertia * spin2**2,
        normal_loss=0.5 * m * (v_y**2 - vy2**2),
        slip_loss=float(grip.slip_loss[0]),
        offset_work=float(grip.offset_work[0]),
        stiffness_work=float(grip.stiffness_work[0]),
    )


def category(cpr: float) -> int:
    """The ITF court pace category (1 slow to 5 fast) of a Court Pace Rating.

    Parameters
    ----------
    cpr : float
        The Court Pace Rating [-].
    """
    cpr = finite("cpr", cpr)
    return next(number for number, _, below in CPR_CATEGORIES if cpr < below)


def court_pace_rating(court: Court, ball: Ball | None = None) -> tuple[float, int]:
    """The ITF Court Pace Rating of ``court``, from a simulated test bounce.

    The ITF test: a ball without spin at 30 m/s, 16 degrees above the court; CPR = 100 (1 -
    mu) + 150 (0.81 - e), mu the apparent friction and e the vertical COR of the bounce
    (ITF Technical Booklet 2015 p. 43).  No temperature correction: the simulated ball is
    taken to be at the ITF's 23 C.

    Parameters
    ----------
    court : Court
        The surface.
    ball : Ball, optional
        The test ball; None: the default preset's.

    Returns
    -------
    tuple
        (the CPR [-], its category, 1 slow to 5 fast: :func:`category`).
    """
    test = bounce(court, CPR_SPEED, CPR_ANGLE, ball=ball)
    cpr = 100.0 * (1.0 - test.apparent_friction) + 150.0 * (0.81 - test.e_y)
    return cpr, category(cpr)
