"""A racket restrung at another tension (:func:`with_tension`): the spec sheets', the
command line's ``--tension`` and the sweeps' tension axis.
"""

from __future__ import annotations

from dataclasses import replace

from common.checks import in_range
from common.typechecks import instance
from common.units import LB
from racket.racket import Racket
from racket.strings.tension import TENSION_RANGE_LB, string_bed_stiffness


def with_tension(racket, tension_n: float):
    """``racket`` strung at ``tension_n`` [N]: its string bed's (centre) stiffness from the
    membrane model (:func:`racket.strings.tension.string_bed_stiffness`) on its string bed's
    area; a bed strung with a :class:`racket.strings.stringing.Stringing` keeps its strings,
    pattern and state, and its stiffness, stretch and loss follow from them at the new tension.

    Parameters
    ----------
    racket : Racket
        The racket to restring.
    tension_n : float
        String (reference) tension [N], in the spec sheets' range
        (:data:`racket.strings.tension.TENSION_RANGE_LB`, 20-80 lb).
    """
    instance("racket", racket, Racket, "a racket.Racket")
    low, high = (tension * LB for tension in TENSION_RANGE_LB)
    tension_n = in_range("tension", tension_n, low, high, "N")
    bed = racket.strings
    if bed.stringing is not None:  # restrung by its own Stringing.bed()
        strung = replace(bed.stringing, tension=tension_n)
        return replace(racket, strings=strung.bed(bed.extent, bed.width, bed.profile))
    stiffness = string_bed_stiffness(tension_n, bed.area)
    return replace(racket, strings=replace(bed, stiffness=stiffness))
