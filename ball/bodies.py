"""Colliding bodies: a ball (mass plus force law) and the rigid, immovable wall."""

from __future__ import annotations

import math
from dataclasses import dataclass

from ball.laws import MonotoneLaw, SineLaw
from common.checks import positive


@dataclass(frozen=True)
class Ball:
    """A ball: a point mass with a spring (its force law) on its front face (paper Fig. 1).

    Parameters
    ----------
    mass : float
        Ball mass [kg], > 0.
    law : MonotoneLaw or SineLaw
        Its force law (:class:`~ball.LinearSpring`, :class:`~ball.LinearHysteresis`,
        :class:`~ball.PowerLawHysteresis` or :class:`~ball.SineLaw`).
    """

    mass: float
    law: MonotoneLaw | SineLaw

    def __post_init__(self):
        object.__setattr__(self, "mass", positive("mass", self.mass, "kg"))
        if not isinstance(self.law, (MonotoneLaw, SineLaw)):
            raise ValueError(
                "law must be LinearSpring, LinearHysteresis, PowerLawHysteresis or SineLaw, "
                f"got {self.law!r}"
            )


@dataclass(frozen=True)
class Wall:
    """A rigid surface of infinite mass: it neither moves nor deforms."""

    @property
    def mass(self) -> float:
        return math.inf


WALL = Wall()
"""The rigid, infinitely massive wall (the paper's "massive, rigid surface")."""
