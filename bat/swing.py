"""A bat swung as a batter swings it: its centre of mass moving and the bat turning, or
turning about a point (A. M. Nathan, Am. J. Phys. 68, 979 (2000), Sec. III C: the centre
of mass at 24 m/s and 51 rad/s about it, a turn about a point 9 cm from the knob; Sec. III D:
56 rad/s about a point 15 cm from the knob).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from common.checks import in_range, shown
from racket.swing import ARM_REACH

ANGULAR_VELOCITY_RANGE = (0.0, 200.0)
"""A bat's angular velocity [rad/s] racket-impact accepts (> 0 for a :class:`BatSwing`: a
bat at rest has no swing): **an assumption**, generous around a swing's (N2000: 51 and
56 rad/s; a fast swing turns at 40-60)."""

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
        The bat's angular velocity [rad/s], in [0, 200]; the barrel's end moves fastest.
    cm_speed : float or None
        Speed of the centre of mass towards the ball [m/s], in [0, 60]: the bat turns about
        the point ``cm_speed / angular_velocity`` beyond its centre of mass towards the knob.
    pivot_from_knob : float or None
        Or the point it turns about [m from the knob] (of a pivoted bat: its pivot).  Give
        one of the two.
    """

    angular_velocity: float
    cm_speed: float | None = None
    pivot_from_knob: float | None = None

    def __post_init__(self):
        w = in_range("angular_velocity", self.angular_velocity, *ANGULAR_VELOCITY_RANGE, "rad/s")
        if w == 0.0:
            raise ValueError("angular_velocity must be > 0 rad/s: a bat at rest has no swing "
                             "(None where a swing is asked for)")  # fmt: skip
        object.__setattr__(self, "angular_velocity", w)
        if (self.cm_speed is None) == (self.pivot_from_knob is None):
            raise ValueError("give one of cm_speed [m/s] and pivot_from_knob [m], not both")
        if self.cm_speed is not None:
            v = in_range("cm_speed", self.cm_speed, *CM_SPEED_RANGE, "m/s")
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
