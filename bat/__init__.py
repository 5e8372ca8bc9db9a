"""Baseball and softball bats struck by a ball (issue 37), beside the tennis racket.

A bat is a free-free beam (thick, :class:`beam.ThickBeam`, or thin) struck on its own
surface, with no strings between, held free, pivoted as in the certification rig or in the
hands: a :class:`Bat`, swung by a :class:`BatSwing`.  It is one of the two kinds of
implement (:class:`racket.implement.Implement`) that the one impact solver strikes:
``racket.impact(bat, ball, position, speed)`` (the solver's public face; its room is
:mod:`racket.solver`, and it knows a bat only through that face).

Public API: :class:`Bat`, :class:`BatSwing`, the :data:`BATS` presets (A. M. Nathan's
wooden R161, the default :data:`DEFAULT_BAT`, and a hollow alloy what-if) and
:data:`BAT_SUPPORTS`; the certification numbers from a ball's speeds (:func:`bbcor`,
:func:`collision_efficiency`, :func:`besr`, :func:`bpf`, :func:`batted_ball_speed`,
:data:`BBCOR_LIMIT`).  Positions are metres from the tip (the barrel's end), as everywhere.
The balls (baseballs, softballs) are in :mod:`ball`; the bat studies and the command line
``racket-impact bat`` in :mod:`studies.bat`.
"""

from bat.bat import BAT_SUPPORTS, Bat
from bat.certification import (
    BBCOR_LIMIT,
    batted_ball_speed,
    bbcor,
    besr,
    bpf,
    collision_efficiency,
)
from bat.presets import BATS, DEFAULT_BAT
from bat.swing import BatSwing
from common.version import __version__

__all__ = [
    "BATS",
    "BAT_SUPPORTS",
    "BBCOR_LIMIT",
    "DEFAULT_BAT",
    "Bat",
    "BatSwing",
    "__version__",
    "batted_ball_speed",
    "bbcor",
    "besr",
    "bpf",
    "collision_efficiency",
]
