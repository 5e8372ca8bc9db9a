"""Ball impacts on a flexible racket (paper Sec. VII).

Public API: :class:`Racket`, :class:`StringBed`, :func:`impact` and its :class:`Impact`
result, the presets :func:`paper_racket` and :func:`tennis_ball`.
"""

from racket.presets import TENNIS_BALL_MASS, paper_racket, tennis_ball
from racket.racket import SUPPORTS, Racket, StringBed
from racket.solver import Impact, impact

__all__ = [
    "SUPPORTS",
    "TENNIS_BALL_MASS",
    "Impact",
    "Racket",
    "StringBed",
    "impact",
    "paper_racket",
    "tennis_ball",
]
