"""Colliding bodies: a ball (mass plus force law) and the rigid, immovable wall."""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass

from ball.laws import MonotoneLaw, SineLaw
from common.checks import (
    CM_AS_M,
    GRAMS_AS_KG,
    MM_AS_M,
    OZ_AS_KG,
    finite_array,
    in_range,
    positive,
    slip_hints,
)
from common.typechecks import instance

BALL_RADIUS_RANGE = (0.005, 0.15)
"""The radius of a ball [m] racket-impact accepts: **an assumption**, generous around the
balls of ball sports (table tennis 20 mm, a tennis ball 33.5 mm, a basketball about
120 mm).  It bounds a ball's :attr:`Ball.radius` and the limit ``x_lim`` of
:class:`~ball.StiffeningHysteresis` (the ball's radius), so that a radius in cm or mm typed
as m (3.35 or 33.5 for 0.0335) is refused with the hint."""

RADIUS_SLIPS = (CM_AS_M, MM_AS_M)
"""The likely slips of unit of a ball's radius: cm or mm typed as m."""


BALL_MASS_RANGE = (0.001, 1.0)
"""The mass of a ball [kg]: **an assumption**, generous around the balls of ball sports (a
table-tennis ball 2.7 g, a tennis ball 57 g, a baseball 145 g, a basketball about 0.6 kg; the
project's balls 10.3 g to 0.2 kg), the ``[ball]`` TOML's ``mass`` range
(``studies.config.TOML_RANGES``).  A :class:`Ball` outside it that a slip of unit would
bring into it (57 for 0.057: grams typed as kg) is refused with the hint; one heavier than
any slip explains (over 1000 kg: 1e12 in the collision tests) stands in for an immovable
partner, and is taken."""

MASS_SLIPS = (GRAMS_AS_KG, OZ_AS_KG)
"""The likely slips of unit of a ball's mass: grams or ounces typed as kg."""


def ball_mass(name: str, value) -> float:
    """A ball's mass [kg], > 0: ValueError naming ``name`` with :data:`BALL_MASS_RANGE` and
    the slip if it lies outside that range and grams or ounces typed as kg would bring it in
    (:data:`MASS_SLIPS`: 1-1000 kg); any other positive mass is taken (over 1000 kg, a body
    standing in for an immovable one).

    Parameters
    ----------
    name : str
        The argument's name, as the message quotes it.
    value : object
        The mass [kg].
    """
    mass = positive(name, value, "kg")
    low, high = BALL_MASS_RANGE
    if not low <= mass <= high and slip_hints(value, low, high, "kg", MASS_SLIPS):
        heaviest = high / min(factor for factor, *_ in MASS_SLIPS)  # the last a slip explains
        in_range(name, value, low, high, "kg", slips=MASS_SLIPS,
                 hint=f"; a body over {heaviest:g} kg is taken as a stand-in for an immovable "
                      "one")  # fmt: skip
    return mass


def ball_radius(name: str, value) -> float:
    """A ball's radius [m] (or a length as large, ``x_lim``), in :data:`BALL_RADIUS_RANGE`:
    ValueError naming ``name`` with the range and a likely slip of unit otherwise.

    Parameters
    ----------
    name : str
        The argument's name, as the message quotes it.
    value : object
        The radius [m].
    """
    positive(name, value, "m")  # a sign slip said as such
    return in_range(name, value, *BALL_RADIUS_RANGE, "m", slips=RADIUS_SLIPS)


@dataclass(frozen=True)
class Ball:
    """A ball: a point mass with a spring (its force law) on its front face (paper Fig. 1).

    Parameters
    ----------
    mass : float
        Ball mass [kg], > 0: a ball's is in :data:`BALL_MASS_RANGE`; one outside it that a
        slip of unit would bring into it (57: grams typed as kg?) is refused with the hint,
        any other is taken (a partner of 1e12 kg stands in for an immovable one).
    law : MonotoneLaw or SineLaw
        Its force law (:class:`~ball.LinearSpring`, :class:`~ball.LinearHysteresis`,
        :class:`~ball.PowerLawHysteresis`, :class:`~ball.GrowingHysteresis` or
        :class:`~ball.SineLaw`).
    radius : float, optional
        Ball radius [m], in :data:`BALL_RADIUS_RANGE`: a result that compresses the ball
        beyond it is out of the range where any force law of a ball means something, and
        warns (:func:`warn_if_squashed`).  None: not checked.
    """

    mass: float
    law: MonotoneLaw | SineLaw
    radius: float | None = None

    def __post_init__(self):
        object.__setattr__(self, "mass", ball_mass("mass", self.mass))
        if self.radius is not None:
            object.__setattr__(self, "radius", ball_radius("radius", self.radius))
        if not isinstance(self.law, (MonotoneLaw, SineLaw)):
            raise ValueError(
                "law must be LinearSpring, LinearHysteresis, PowerLawHysteresis, "
                "GrowingHysteresis or SineLaw, "
                f"got {self.law!r}"
            )


@dataclass(frozen=True)
class Wall:
    """A rigid surface of infinite mass: it neither moves nor deforms."""

    @property
    def mass(self) -> float:
        """Zero-size, infinite mass: the wall does not move [kg]."""
        return math.inf


WALL = Wall()
"""The rigid, infinitely massive wall (the paper's "massive, rigid surface")."""


def warn_if_squashed(ball: Ball, compression, stacklevel: int = 3) -> None:
    """Warn once (UserWarning) if any ``compression`` [m] of ``ball`` exceeds its radius (its
    force law is then used far beyond the deformations it describes), or the largest
    compression its law was calibrated to (``law.calibrated_to``, where it has one).

    Parameters
    ----------
    ball : Ball
        The ball whose radius and force law set the limits.
    compression : float or array_like
        Ball compression(s) to check [m]; only the largest matters.
    stacklevel : int, optional
        Passed to :func:`warnings.warn`, so the warning points at the caller's caller.
    """
    instance("ball", ball, Ball, "a ball.Ball")
    compression = finite_array("compression", compression, "m")
    if compression.size == 0:
        raise ValueError("compression must be one or more numbers [m], got none")
    largest = compression.item() if compression.size == 1 else float(compression.max())
    if ball.radius is not None and largest > ball.radius:
        warnings.warn(
            f"the ball is compressed by {1e3 * largest:.3g} mm, more than its radius "
            f"({1e3 * ball.radius:.3g} mm): its force law is used far outside its range",
            stacklevel=stacklevel,
        )
        return
    calibrated = getattr(ball.law, "calibrated_to", None)
    if calibrated is not None and largest > calibrated:
        warnings.warn(
            f"the ball is compressed by {1e3 * largest:.3g} mm, beyond the {1e3 * calibrated:.3g}"
            " mm its force law was calibrated to: the result is an extrapolation",
            stacklevel=stacklevel,
        )
