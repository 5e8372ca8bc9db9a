"""A bat swung as a batter swings it: its centre of mass moving and the bat turning, or
turning about a point (A. M. Nathan, Am. J. Phys. 68, 979 (2000), Sec. III C: the centre
of mass at 24 m/s and 51 rad/s about it, a turn about a point 9 cm from the knob; Sec. III D:
56 rad/s about a point 15 cm from the knob).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from common.checks import RPM_AS_RAD_S, SPEED_SLIPS, in_range, shown, suspect
from common.typechecks import ask
from racket.swing import ARM_REACH

ANGULAR_VELOCITY_RANGE = (0.0, 200.0)
"""A bat's angular velocity [rad/s] racket-impact accepts (> 0 for a :class:`BatSwing`: a
bat at rest has no swing): **an assumption**, generous around a swing's (N2000: 51 and
56 rad/s; a fast swing turns at 40-60)."""

FASTEST_TURN = 1.5 * 51.0
"""The fastest a batter is taken to turn a bat [rad/s]: 76.5 rad/s.  **An ASSUMPTION**: no
record of bats' angular velocities is kept here; this is N2000's high-speed swing (51 rad/s,
``studies.bat.sweep.ANGULAR_VELOCITY``) half as fast again, as the command line bounds the
centre of mass's speed.  One typed faster is asked about (rpm or deg/s typed as rad/s?), not
refused (:data:`ANGULAR_VELOCITY_RANGE` refuses above 200 rad/s)."""

FASTEST_CM_SPEED = 1.5 * 24.0
"""The fastest a batter is taken to swing a bat's centre of mass [m/s]: 36 m/s (81 mph).
**An ASSUMPTION**, the command line's too: no record of bat speeds is kept here
(``data/bats.md`` gives none); this is N2000's high-speed swing (24 m/s,
``studies.bat.sweep.CM_SPEED``) half as fast again.  One typed faster is asked about (mph
or km/h typed as m/s?), not refused (:data:`CM_SPEED_RANGE` refuses above 60 m/s)."""

DEG_S_AS_RAD_S = (math.pi / 180.0, "deg/s typed as rad/s?", "deg/s")
"""A slip of unit: an angular velocity in deg/s where rad/s are asked for."""

CENTRE_BEYOND_KNOB = ARM_REACH
"""Farthest [m] beyond the knob the point a bat turns about may lie: the solver's reach for a
swing's centre (:data:`racket.swing.ARM_REACH`)."""

CENTRE_RANGE = (-CENTRE_BEYOND_KNOB, 1.2)
"""Where a :class:`BatSwing`'s ``pivot_from_knob`` may be [m from the knob]: from
:data:`CENTRE_BEYOND_KNOB` beyond the knob to the longest bat's end (1.2 m, the TOML's)."""

CM_SPEED_RANGE = (0.0, 60.0)
"""Speed of a bat's centre of mass [m/s] racket-impact accepts: **an assumption**, around
N2000's 24 m/s."""


@dataclass(frozen=True)
class BatSwing:
    """The bat's rigid motion at impact, towards the ball.

    Parameters
    ----------
    angular_velocity : float
        The bat's angular velocity [rad/s], in (0, 200]; the barrel's end moves fastest.  One
        above :data:`FASTEST_TURN` (76.5 rad/s) is asked about in a warning, with the slips of
        unit that would explain it (136 for 136 rpm).
    cm_speed : float or None
        Speed of the centre of mass towards the ball [m/s], in [0, 60]: the bat turns about
        the point ``cm_speed / angular_velocity`` beyond its centre of mass towards the knob.
        One above :data:`FASTEST_CM_SPEED` (36 m/s) is asked about (54 for 54 mph).
    pivot_from_knob : float or None
        Or the point it turns about [m from the knob] (of a pivoted bat: its pivot).  Give
        one of the two.
    """

    angular_velocity: float
    cm_speed: float | None = None
    pivot_from_knob: float | None = None

    def __post_init__(self):
        turns = (RPM_AS_RAD_S, DEG_S_AS_RAD_S)
        w = in_range("angular_velocity", self.angular_velocity, *ANGULAR_VELOCITY_RANGE, "rad/s",
                     slips=turns)  # fmt: skip
        if w == 0.0:
            raise ValueError("angular_velocity must be > 0 rad/s: a bat at rest has no swing "
                             "(None where a swing is asked for)")  # fmt: skip
        why = f"faster than batters turn a bat (about {FASTEST_TURN:.3g} rad/s, estimated)"
        ask(suspect, "angular_velocity", w, (0.0, FASTEST_TURN), "rad/s", turns, why, always=True)
        object.__setattr__(self, "angular_velocity", w)
        if (self.cm_speed is None) == (self.pivot_from_knob is None):
            raise ValueError("give one of cm_speed [m/s] and pivot_from_knob [m], not both")
        if self.cm_speed is not None:
            v = in_range("cm_speed", self.cm_speed, *CM_SPEED_RANGE, "m/s",
                         slips=SPEED_SLIPS["m/s"])  # fmt: skip
            why = (f"faster than batters swing a bat's centre of mass (about "
                   f"{FASTEST_CM_SPEED:.3g} m/s, estimated)")  # fmt: skip
            ask(suspect, "cm_speed", v, (0.0, FASTEST_CM_SPEED), "m/s", SPEED_SLIPS["m/s"], why,
                always=True)  # fmt: skip
            object.__setattr__(self, "cm_speed", v)
        else:
            pivot = in_range("pivot_from_knob", self.pivot_from_knob, *CENTRE_RANGE,
                             "m from the knob")  # fmt: skip
            object.__setattr__(self, "pivot_from_knob", pivot)

    def check(self, bat) -> None:
        """ValueError if ``bat`` would turn about a point more than
        :data:`CENTRE_BEYOND_KNOB` beyond its knob (a centre of mass fast for the turn).
        """
        beyond = self.pivot(bat) - bat.beam.length
        if beyond > CENTRE_BEYOND_KNOB:
            raise ValueError(
                f"cm_speed {shown(self.cm_speed)} m/s at angular_velocity "
                f"{shown(self.angular_velocity)} rad/s turns the bat about a point "
                f"{100 * beyond:.4g} cm beyond its knob, farther than "
                f"{100 * CENTRE_BEYOND_KNOB:g} cm: turn it faster or its centre of mass slower"
            )

    def pivot(self, bat) -> float:
        """The point the bat turns about [m from the tip]."""
        beam = bat.beam
        if self.pivot_from_knob is not None:
            return beam.length - self.pivot_from_knob
        return beam.center_of_mass + self.cm_speed / self.angular_velocity

    def point_speeds(self, bat, position) -> np.ndarray:
        """Speed [m/s] towards the ball of the points ``position`` [m from the tip]."""
        return self.angular_velocity * (self.pivot(bat) - np.asarray(position, dtype=float))

    def impact_kwargs(self, bat, position) -> dict:
        """``swing_speed`` and ``pivot`` of :func:`racket.impact` for this swing at the points
        ``position`` [m from the tip] (each must move towards the ball).
        """
        self.check(bat)
        speeds = self.point_speeds(bat, position)
        if np.any(speeds <= 0.0):
            raise ValueError(
                f"the swing turns about {bat.beam.length - self.pivot(bat):.4g} m from the knob: "
                "every impact point must lie beyond it, towards the barrel's end"
            )
        return {"swing_speed": speeds, "pivot": self.pivot(bat)}
