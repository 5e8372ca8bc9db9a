"""Ball impacts on a flexible tennis racket (paper Sec. VII).

A racket is a free-free beam (:mod:`beam`), a string bed on it (:mod:`racket.strings`) and
how it is held (free, head-clamped or in a :class:`Hand`); rackets from spec sheets are in
:mod:`racket.specs`, and the impact solver that strikes them has its own room,
:mod:`racket.solver`, reached through :func:`impact` (bats, :mod:`bat`, are struck by the
same solver through the same face).

Public API: :class:`Racket`, :class:`StringBed`, :class:`Hand`, :func:`impact` and its
:class:`Impact` result, a :class:`Swing` about a pivot, the default racket and ball
(:func:`default_racket`, the catalogue's Pure Drive 2021, and :func:`default_ball`, the ITF
type 2 ball), the paper's (:func:`paper_racket`, :func:`paper_ball`), rackets from spec
sheets (:func:`from_specs`, :func:`string_bed_stiffness`, the :data:`CATALOG` of well-known
rackets) and the modelled flex test (:func:`flex_test_stiffness`); what a racket is strung
with (:class:`Stringing` of a :class:`String` of a material of :data:`MATERIALS`, the
:data:`STRINGS` presets, :func:`stringing` by name); spin (issue 36): a :class:`Stroke`
(the :data:`STROKES` presets) and :func:`hit`, the ball's flight after it; a spinning ball
meeting the strings obliquely, :func:`oblique_impact`.

``import racket`` loads none of them (nor numpy): each name loads on first use
(:mod:`common.lazy`).
"""

from typing import TYPE_CHECKING

from common.lazy import lazy_names
from common.version import __version__

if TYPE_CHECKING:  # the public names, loaded on first use (common.lazy): by module below
    from racket.hand import GRIPS, Hand
    from racket.presets import (
        DEFAULT_RACKET,
        TENNIS_BALL_MASS,
        TENNIS_BALL_RADIUS,
        default_ball,
        default_racket,
        paper_ball,
        paper_racket,
    )
    from racket.racket import SUPPORTS, Racket
    from racket.solver import Impact, ObliqueImpact, StrokeImpact, hit, impact, oblique_impact
    from racket.specs import from_specs
    from racket.specs.catalog import CATALOG
    from racket.specs.stiffness import flex_test_stiffness
    from racket.strings import (
        MATERIALS,
        STRINGS,
        String,
        StringBed,
        Stringing,
        string_bed_stiffness,
        stringing,
    )
    from racket.stroke import STROKES, Stroke
    from racket.swing import Swing

__all__ = [
    "CATALOG",
    "DEFAULT_RACKET",
    "GRIPS",
    "MATERIALS",
    "STRINGS",
    "STROKES",
    "SUPPORTS",
    "TENNIS_BALL_MASS",
    "TENNIS_BALL_RADIUS",
    "Hand",
    "Impact",
    "ObliqueImpact",
    "Racket",
    "String",
    "StringBed",
    "Stringing",
    "Stroke",
    "StrokeImpact",
    "Swing",
    "__version__",
    "default_ball",
    "default_racket",
    "flex_test_stiffness",
    "from_specs",
    "hit",
    "impact",
    "oblique_impact",
    "paper_ball",
    "paper_racket",
    "string_bed_stiffness",
    "stringing",
]

__getattr__, __dir__ = lazy_names(
    __name__,
    {
        "racket.hand": ("GRIPS", "Hand"),
        "racket.presets": (
            "DEFAULT_RACKET",
            "TENNIS_BALL_MASS",
            "TENNIS_BALL_RADIUS",
            "default_ball",
            "default_racket",
            "paper_ball",
            "paper_racket",
        ),
        "racket.racket": ("SUPPORTS", "Racket"),
        "racket.solver": (
            "Impact",
            "ObliqueImpact",
            "StrokeImpact",
            "hit",
            "impact",
            "oblique_impact",
        ),
        "racket.specs": ("from_specs",),
        "racket.specs.catalog": ("CATALOG",),
        "racket.specs.stiffness": ("flex_test_stiffness",),
        "racket.strings": (
            "MATERIALS",
            "STRINGS",
            "String",
            "StringBed",
            "Stringing",
            "string_bed_stiffness",
            "stringing",
        ),
        "racket.stroke": ("STROKES", "Stroke"),
        "racket.swing": ("Swing",),
    },
)
