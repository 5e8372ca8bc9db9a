"""Ball force laws and head-on two-body collisions (R. Cross, Am. J. Phys. 2000, Secs. II-VI).

Public API: the force laws :class:`LinearSpring`, :class:`LinearHysteresis`,
:class:`PowerLawHysteresis`, :class:`GrowingHysteresis` (COR and stiffness that change with
speed), :class:`StiffeningHysteresis` (the real tennis ball's law, bounded by its radius) and
:class:`SineLaw`; :class:`Ball` and :data:`WALL`; the real-ball presets
:data:`BALL_PRESETS` (:mod:`ball.catalog`); baseballs and softballs of A. M. Nathan's law,
:data:`BASEBALL_PRESETS` and :func:`baseball` (:mod:`ball.baseball`);
:func:`collide` and its :class:`Collision` result; the closed forms in
:mod:`ball.closed_forms`.
"""

from ball.baseball import BASEBALL_PRESETS, DEFAULT_BASEBALL, baseball
from ball.bodies import WALL, Ball, Wall, warn_if_squashed
from ball.catalog import BALL_PRESETS, DEFAULT_BALL
from ball.closed_forms import (
    energy_loss_fraction,
    energy_loss_fraction_lab,
    series_cor,
    serve_speed,
    unhappy_cor,
    unhappy_solution,
)
from ball.collision import Collision, CollisionHistory, collide
from ball.laws import (
    GrowingHysteresis,
    LinearHysteresis,
    LinearSpring,
    MonotoneLaw,
    PowerLawHysteresis,
    SineLaw,
)
from ball.series import series_force
from ball.stiffening import StiffeningHysteresis
from common.version import __version__

__all__ = [
    "BALL_PRESETS",
    "BASEBALL_PRESETS",
    "DEFAULT_BALL",
    "DEFAULT_BASEBALL",
    "WALL",
    "Ball",
    "Collision",
    "CollisionHistory",
    "GrowingHysteresis",
    "LinearHysteresis",
    "LinearSpring",
    "MonotoneLaw",
    "PowerLawHysteresis",
    "SineLaw",
    "StiffeningHysteresis",
    "Wall",
    "__version__",
    "baseball",
    "collide",
    "energy_loss_fraction",
    "energy_loss_fraction_lab",
    "series_cor",
    "series_force",
    "serve_speed",
    "unhappy_cor",
    "unhappy_solution",
    "warn_if_squashed",
]
