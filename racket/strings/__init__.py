"""The string bed in one room: what a racket is strung with and how the bed behaves.

* :mod:`~racket.strings.bed`: the :class:`StringBed` the solver sees (a spring between the
  ball and the frame: linear, stiffening, lossy, with a moving mass);
* :mod:`~racket.strings.material`, :mod:`~racket.strings.sizes` and
  :mod:`~racket.strings.stringing`: a stringer's description (material, gauge and pattern,
  tension and state, hybrids, the ERT's DT), which makes a :class:`StringBed`;
* :mod:`~racket.strings.head` and :mod:`~racket.strings.membrane`: the head's outline and
  the membrane model of the bed's stiffness over the face;
* :mod:`~racket.strings.tension`: a spec sheet's strings (the bed's stiffness from the
  tension and the head size);
* :mod:`~racket.strings.sideways`: the bed sideways, the mains' and crosses' layer that
  the ball's grip drives (:mod:`ball.grip`).

It builds on :mod:`common` and :mod:`ball` only: the racket (:mod:`racket.racket`) builds
on it, never the other way round.
"""

from racket.strings.bed import StringBed
from racket.strings.head import HEAD_ASPECT, Hoop
from racket.strings.material import MATERIALS, Material
from racket.strings.sideways import BedSideways, sideways
from racket.strings.stringing import STRINGS, String, Stringing, stringing
from racket.strings.tension import TENSION_RANGE_LB, string_bed_stiffness

__all__ = [
    "HEAD_ASPECT",
    "MATERIALS",
    "STRINGS",
    "TENSION_RANGE_LB",
    "BedSideways",
    "Hoop",
    "Material",
    "String",
    "StringBed",
    "Stringing",
    "sideways",
    "string_bed_stiffness",
    "stringing",
]
