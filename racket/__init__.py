"""Ball impacts on a flexible racket (paper Sec. VII).

Public API: :class:`Racket`, :class:`StringBed`, :class:`Hand`, :func:`impact` and its
:class:`Impact` result, a :class:`Swing` about a pivot, the default racket and ball
(:func:`default_racket`, the catalogue's Pure Drive 2021, and :func:`default_ball`, the ITF
type 2 ball), the paper's (:func:`paper_racket`, :func:`paper_ball`), rackets from spec
sheets (:func:`from_specs`, :func:`string_bed_stiffness`, the :data:`CATALOG` of well-known
rackets) and the modelled flex test (:func:`flex_test_stiffness`); what a racket is strung
with (:class:`Stringing` of a :class:`String` of a material of :data:`MATERIALS`, the
:data:`STRINGS` presets, :func:`stringing` by name); spin (issue 36): a :class:`Stroke`
(the :data:`STROKES` presets) and :func:`hit`, the ball's flight after it; a spinning ball
meeting the strings obliquely, :func:`oblique_impact`.  Bats (issue 37): a :class:`Bat`
(a beam struck on its own surface, free, pivoted or held; the :data:`BATS` presets, Nathan's
R161 by default) swung by a :class:`BatSwing`; :func:`impact` strikes either.
"""

from common.version import __version__
from racket.bat import BAT_SUPPORTS, Bat
from racket.bat_swing import BatSwing
from racket.bats import BATS, DEFAULT_BAT
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
from racket.racket import SUPPORTS, Racket, StringBed
from racket.solver import Impact, ObliqueImpact, StrokeImpact, hit, impact, oblique_impact
from racket.specs import from_specs, string_bed_stiffness
from racket.specs.catalog import CATALOG
from racket.specs.stiffness import flex_test_stiffness
from racket.string_material import MATERIALS
from racket.stringing import STRINGS, String, Stringing, stringing
from racket.stroke import STROKES, Stroke
from racket.swing import Swing

__all__ = [
    "BATS",
    "BAT_SUPPORTS",
    "CATALOG",
    "DEFAULT_BAT",
    "DEFAULT_RACKET",
    "GRIPS",
    "MATERIALS",
    "STRINGS",
    "STROKES",
    "SUPPORTS",
    "TENNIS_BALL_MASS",
    "TENNIS_BALL_RADIUS",
    "Bat",
    "BatSwing",
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
