"""Ball force laws and head-on two-body collisions (R. Cross, Am. J. Phys. 2000, Secs. II-VI).

Public API: the force laws :class:`LinearSpring`, :class:`LinearHysteresis`,
:class:`PowerLawHysteresis`, :class:`GrowingHysteresis` (COR and stiffness that change with
speed), :class:`StiffeningHysteresis` (the real tennis ball's law, bounded by its radius) and
:class:`SineLaw`; :class:`Ball` and :data:`WALL`; the real-ball presets
:data:`BALL_PRESETS` (:mod:`ball.catalog`); baseballs and softballs of A. M. Nathan's law,
:data:`BASEBALL_PRESETS` and :func:`baseball` (:mod:`ball.baseball`);
:func:`collide` and its :class:`Collision` result; the closed forms in
:mod:`ball.closed_forms`.

Each name but the baseball's loads on first use (:mod:`common.lazy`).
"""

from typing import TYPE_CHECKING

# at once: the function baseball has its module's name, which importing ball.baseball (as
# the command line does) would set on this package over a name loaded on first use
from ball.baseball import BASEBALL_PRESETS, DEFAULT_BASEBALL, baseball
from common.lazy import lazy_names
from common.version import __version__

if TYPE_CHECKING:  # the public names, loaded on first use (common.lazy): by module below
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

__getattr__, __dir__ = lazy_names(
    __name__,
    {
        "ball.bodies": ("WALL", "Ball", "Wall", "warn_if_squashed"),
        "ball.catalog": ("BALL_PRESETS", "DEFAULT_BALL"),
        "ball.closed_forms": (
            "energy_loss_fraction",
            "energy_loss_fraction_lab",
            "series_cor",
            "serve_speed",
            "unhappy_cor",
            "unhappy_solution",
        ),
        "ball.collision": ("Collision", "CollisionHistory", "collide"),
        "ball.laws": (
            "GrowingHysteresis",
            "LinearHysteresis",
            "LinearSpring",
            "MonotoneLaw",
            "PowerLawHysteresis",
            "SineLaw",
        ),
        "ball.series": ("series_force",),
        "ball.stiffening": ("StiffeningHysteresis",),
    },
)
