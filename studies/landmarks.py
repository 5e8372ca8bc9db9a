"""Landmarks on a racket that players and coaches ask about: where the hand is, and the
centre of percussion."""

from __future__ import annotations

from racket import Racket

HAND_FROM_BUTT = 0.07
"""Where the hand holds the racket, for the centre of percussion [m from the butt]."""


def center_of_percussion(racket: Racket, pivot: float) -> float:
    """Centre of percussion [m from the tip] for a pivot at ``pivot`` [m from the tip]: an
    impact there leaves the pivot at rest (no jar to the hand)."""
    beam = racket.beam
    d = pivot - beam.center_of_mass
    return pivot - (beam.inertia_cm + beam.mass * d**2) / (beam.mass * d)
