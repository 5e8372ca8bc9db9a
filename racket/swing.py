"""A swing: the racket rotating about a fixed pivot, so that every point has its own speed."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from common.checks import in_range
from common.checks import speed as check_speed

WRIST_BEYOND_BUTT = 0.05
"""Default swing pivot: the wrist, this far beyond the butt [m] (a hand on the grip holds
the butt against the heel of the palm; an assumption, not a measurement)."""

PIVOT_RANGE = (-1.0, 0.3)
"""Where a pivot may be [m from the butt, + towards the tip, - beyond the butt]: from a
straight arm swung from the shoulder (an arm is about 0.7 m long) to the top of the grip
and throat (0.3 m; both bounds are assumptions, generous on purpose)."""


def check_swung_support(support: str) -> None:
    """Refuse to swing a racket whose ``support`` is not ``"free"``: a hand or clamp is at
    rest in this model.

    Parameters
    ----------
    support : str
        The racket's support.
    """
    if support != "free":
        raise ValueError(
            f"swing_speed must be 0 for a {support} racket (the hand or clamp is at rest); "
            "swing a free racket, as the paper does"
        )


@dataclass(frozen=True)
class Swing:
    """The racket rotating about a fixed pivot at the moment of impact.

    Parameters
    ----------
    head_speed : float
        Racket-head speed [m/s]: the speed of the string bed's centre towards the ball, in
        [0.001, 300].  Every other point moves in proportion to its distance from the pivot.
    pivot_from_butt : float
        The pivot [m from the butt, + towards the tip, - beyond it], in [-1, 0.3]; default
        -0.05, the wrist (:data:`WRIST_BEYOND_BUTT`).

    Notes
    -----
    The racket's speed at an impact point x [m from the tip] is omega (x_p - x), with
    x_p = L - pivot_from_butt the pivot and omega = head_speed / (x_p - x_centre) (small
    rotations during the contact; the rigid-body motion superposes on the collision,
    :mod:`studies.serve`).

    Examples
    --------
    >>> from racket import CATALOG
    >>> racket = CATALOG["pure-drive-2021"].racket()
    >>> swing = Swing(30.0)  # head speed 30 m/s about the wrist
    >>> round(float(swing.point_speeds(racket, racket.strings.center - 0.05)), 2)
    32.67
    """

    head_speed: float
    pivot_from_butt: float = -WRIST_BEYOND_BUTT

    def __post_init__(self):
        object.__setattr__(self, "head_speed", check_speed("head_speed", self.head_speed))
        object.__setattr__(
            self,
            "pivot_from_butt",
            in_range("pivot_from_butt", self.pivot_from_butt, *PIVOT_RANGE, "m from the butt"),
        )

    def pivot(self, racket) -> float:
        """The pivot [m from the tip] on ``racket``."""
        return racket.beam.length - self.pivot_from_butt

    def angular_velocity(self, racket) -> float:
        """The racket's angular velocity [rad/s]."""
        return self.head_speed / (self.pivot(racket) - racket.strings.center)

    def point_speeds(self, racket, position) -> np.ndarray:
        """Speed [m/s] towards the ball of each point ``position`` [m from the tip]."""
        return self.angular_velocity(racket) * (self.pivot(racket) - np.asarray(position, float))

    def impact_kwargs(self, racket, position) -> dict:
        """The ``swing_speed`` and ``pivot`` of :func:`racket.impact` for this swing."""
        return {"swing_speed": self.point_speeds(racket, position), "pivot": self.pivot(racket)}
