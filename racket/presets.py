"""Named rackets and balls: the one default racket and ball of every command, the page and
the Python API (:func:`default_racket`, :func:`default_ball`), and the paper's.

``"paper"`` is the racket of the paper's Sec. VII: a uniform beam 0.68 m long of mass
0.34 kg (a typical 1990s graphite racket, strung) whose first free-free bending mode is at
120 Hz (Cross's flexible-beam model, the source of the paper's Sec. VII numbers), with a
string bed over the 0.32 m of the head nearest the tip and of stiffness 4e4 N/m (Sec. III:
"the spring constant of the strings is typically about 4e4 N/m").  The tennis ball is the
paper's: 57 g, stiffness 4e4 N/m during compression, COR 0.75 on concrete (Sec. III).
The paper's string bed stays the paper's: a linear, lossless spring (no stringing).  The
default racket is a real one, the catalogue's Babolat Pure Drive (2021)
(:data:`racket.specs.catalog.CATALOG`), strung with fresh polyester 16L, 16x19, at 55 lb
(an assumption, :data:`racket.specs.strung.STRUNG`: a bed that stiffens as it deflects and
loses a little of what it stores, :mod:`racket.strings.stringing`), and the default ball the ITF
type 2 ball (:data:`ball.catalog.DEFAULT_BALL`).
"""

from __future__ import annotations

from ball import BALL_PRESETS, DEFAULT_BALL, Ball, LinearHysteresis
from beam import Beam
from racket.racket import Racket
from racket.specs.catalog import CATALOG
from racket.strings.bed import StringBed

DEFAULT_RACKET = "pure-drive-2021"
"""The racket of every command, the page and the Python API when none is named: a real,
measured racket of the catalogue (:data:`racket.specs.catalog.CATALOG`)."""

TENNIS_BALL_MASS = 0.057
"""Mass of a tennis ball [kg] (ITF rules: 56.0-59.4 g)."""

TENNIS_BALL_RADIUS = 0.0335
"""Radius of a tennis ball [m] (ITF Rules of Tennis, Appendix I: diameter 6.54-6.86 cm for
the type 2 ball; the middle of that range)."""


def paper_racket(support: str = "free") -> Racket:
    """The paper's racket (see the module docstring).

    Parameters
    ----------
    support : str, optional
        ``"free"``, ``"clamped-head"`` or ``"hand-held"`` (with the default
        :class:`~racket.Hand`), as for :class:`~racket.Racket`.
    """
    return Racket(
        Beam.uniform(length=0.68, mass=0.34, f1=120.0),
        StringBed(stiffness=4e4, extent=(0.0, 0.32)),
        support=support,
    )


def paper_ball() -> Ball:
    """The paper's tennis ball: 57 g, LinearHysteresis(k=4e4 N/m, e=0.75), radius 33.5 mm."""
    return Ball(TENNIS_BALL_MASS, LinearHysteresis(k=4e4, e=0.75), TENNIS_BALL_RADIUS)


def default_racket(support: str = "free") -> Racket:
    """The default racket, :data:`DEFAULT_RACKET` (the Babolat Pure Drive 2021 of the
    catalogue, fitted to its spec sheet).

    Parameters
    ----------
    support : str, optional
        ``"free"``, ``"clamped-head"`` or ``"hand-held"``, as for :class:`~racket.Racket`.
    """
    return CATALOG[DEFAULT_RACKET].racket(support)


def default_ball() -> Ball:
    """The default ball, :data:`ball.catalog.DEFAULT_BALL`: the ITF type 2 ball, a real ball
    whose COR falls with impact speed (:mod:`ball.catalog`).
    """
    return BALL_PRESETS[DEFAULT_BALL].ball()
