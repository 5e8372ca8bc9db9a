"""The model under each measurement's conditions: the balls, rackets, supports, speeds and
hands the sources describe (each number with its source, or said to be an assumption),
and the model's runs under them (each run once).
"""

from __future__ import annotations

import math
from dataclasses import replace
from functools import cache

import numpy as np
import pandas as pd

from ball import BALL_PRESETS, WALL, Ball, LinearSpring, collide
from ball.catalog import ITF_DROP_SPEED, TWU_SPEED
from common.units import GRAVITY, LB
from racket import CATALOG, GRIPS, Hand, from_specs, impact
from racket.specs.ra import f1_from_ra
from racket.strings.stringing import stringing
from racket.system import held_mode, held_system

BALL = "itf-type-2"
"""The ball of every racket comparison: the ITF type 2 (medium) ball, the pressurised ball
of ordinary play (assumption: the sources name no ball type)."""

STRUNG = "{0.name} at {0.specs[tension_lb]:g} lb".format(CATALOG["pure-drive-2021"])
"""The racket of the comparisons whose source names none, as each row says it: its name and
string tension, "Babolat Pure Drive (2021) at 55 lb" (:data:`racket.CATALOG`)."""

DROP_1M_SPEED = math.sqrt(2.0 * GRAVITY * 1.0)
"""Speed [m/s] of a ball dropped from 1 m (4.43 m/s; air drag neglected): Cross's drop onto
clamped strings, and the low-speed drop assumed for the seed paper's clamped-string e and
contact time (Cross 2000, Sec. III gives no speed; "low speed")."""

CLAMPED_STRING = "nylon"
"""The string of the clamped-string drops, whose sources name none: nylon (synthetic gut) at
its usual gauge, 16x19, **an assumption** (the commonest string before polyester spread in
the 2000s).  The bed's stiffness is the row's; its stretch and loss follow from the string
(:meth:`racket.strings.stringing.Stringing.bed`)."""

STEEL_BALL = Ball(mass=0.0571, law=LinearSpring(k=5e7))
"""Kawazoe's steel ball, "a non-deforming ball": 5e7 N/m, about 1700 times the bed, at the
tennis ball's mass (**an assumption**: he gives neither; on a head-clamped, massless bed
the COR depends on neither)."""


def steel_ball_racket(racket):
    """``racket`` with its bed's moving mass left out, for :data:`STEEL_BALL`: **an
    assumption**.  The bed's mass is its first mode's (:meth:`racket.strings.stringing.Stringing.
    moving_mass`), the mass that moves with a contact longer than the bed's period (a tennis
    ball's 4-6 ms against the bed's 2 ms).  A steel ball's contact is far shorter: it moves
    the strings under it as a wave spreads, which one mass cannot stand for (a rigid ball
    on the first mode's 3-4 g would lose a quarter of its energy to the bed's vibration, a
    COR of 0.83-0.87, where Kawazoe measures 0.97 "regardless of type or tension").  So the
    steel ball meets the bed's loss alone, which is what its COR calibrates.

    Parameters
    ----------
    racket : racket.Racket
        A racket with a strung bed.
    """
    return replace(racket, strings=replace(racket.strings, moving_mass=0.0))


STEEL_SPEED = 10.0
"""Speed [m/s] of the steel ball on the strings (**an assumption**: Kawazoe gives none; on
a clamped bed the COR hardly depends on it, e**2 = 1 - loss)."""

SEED_BED = 4e4
"""String-plane stiffness [N/m] for the seed paper's clamped-string numbers: its "typically
about 4e4 N/m" (Cross 2000, Sec. III)."""

CROSS_BED = 3e4
"""String-plane stiffness [N/m] for Cross's 1 m drop onto clamped strings (tennis.html gives
no racket): the seed paper's "about 3e4 N/m at 55 lb" (Sec. VIII), a typical stringing."""

TWU_PIVOT_SPEED = 17.9
"""Ball speed [m/s] of TWU "Racquet Control" part 2."""

TWU_OFFSET = 0.08
"""Offset [m] from the long axis of TWU part 1's impacts at 3 and 9 o'clock: the largest it
measured (its lateral offsets run from -80 to +60 mm; ``measurements.md`` section 4)."""

GRABINER_SPEED = math.sqrt(2.0 * GRAVITY * 5.75)
"""Ball speed [m/s] of Grabiner, Groppel and Campbell's drops, from 5.75 m: 10.62 m/s
(``measurements.md`` section 3)."""

TWU_SHEET = CATALOG["pure-drive-2021"].specs | dict(mass_kg=0.291, swingweight_kgcm2=315.0)
"""TWU part 1's racket as a spec sheet: the Pure Drive (2021) sheet at TWU's 291 g and a
swingweight of 315 kg cm^2 (assumption: TWU gives the mass and a 100 in^2 class head, not
the swingweight)."""

TWU_LEAD = 0.0134
"""Lead tape per side [kg] in TWU part 1: 26.8 g in all, at 3 and at 9 o'clock."""

EDGE_INSET = 0.04
"""Where the "tip" and "throat" impacts are [m inside the string bed's ends along the long
axis]: the ball's centre 4 cm inside, its edge (radius 3.35 cm) just clear of the frame.
**An assumption**: the sources do not give the distance."""

PIN = Hand(stiffness=1e6, damping=0.0, grip_length=0.02, resists_twist=False)
"""A pin at the handle end (TWU part 2, "free to twist and rotate about the handle end"):
a stiff (1e6 N/m), undamped, short (2 cm) grip held still that lets the racket roll freely.
**An approximation** of a hinge: the grip stops the butt translating, and over 2 cm resists
the racket's rotation about it only weakly."""

STROKE_SPEEDS = {"forehand": 30.0, "volley": 20.0, "serve": 45.0}
"""Closing speeds [m/s] of ball and racket assumed for Hamori's strokes (recreational
players, rally speeds; his article gives none): **assumptions**.  The model hits a
hand-held racket at rest at this speed at the string centre; the contact time depends on
the closing speed, barely on how it is split between ball and racket."""

HAMORI_BAND = 0.5e-3
"""Half-width [s] of the band around each of Hamori's dwell times: **an assumption**
(his article states no uncertainty; 10,000 frames per second resolve 0.1 ms, and the stroke
speed and impact point are not known)."""

HAMORI = "Hamori, 'Contact at 10,000 frames per second', tennisplayer.net (own text)"

HAMORI_RACKETS = {
    name: (row, dict(zip(("head_size_in2", "mass_kg", "balance_cm", "swingweight_kgcm2",
                          "f1_hz"), sheet, strict=True)))
    for name, row, sheet in (
        ("Babolat AeroPro Drive", "AeroPro Drive Cortex", (100.0, 0.31468, 33.02, 328.0, 152.3)),
        ("Wilson Pro Staff 85", "Pro Staff 90 (no 85 in the table)",
         (90.0, 0.346, 32.0, 315.0, 146.2)),
        ("Wilson Pro Staff 95", "BLX Pro Staff Six.One 95", (95.0, 0.326, 32.1, 303.0, 144.5)),
        ("Wilson Pro Staff 97", "Pro Staff 97", (97.0, 0.325, 32.0, 312.0, 144.5)),
    )
}  # fmt: skip
"""Hamori's rackets as spec sheets: the closest row of the TWU table
(``tests/data/twu_racquets_half.csv``: head size, strung mass, balance, swingweight, free
frequency; 27 in long; all 16x19), named beside each.  Each row's string is strung fresh at
its usual gauge (:data:`racket.strings.stringing.STRINGS`; **an assumption**: Hamori names the
material and the tension only): polyester and gut at one tension give the same stiffness
(the membrane model, from the tension) but not the same stretch and loss."""

HAMORI_PATTERN = (16, 19)
"""String pattern of Hamori's rackets: the TWU table's rows named in
:data:`HAMORI_RACKETS` are all 16x19."""


@cache
def _ball(name: str = BALL):
    return BALL_PRESETS[name].ball()


def _wall_cor(name: str) -> float:
    return float(collide(_ball(name), WALL, ITF_DROP_SPEED).e)


def _wall_contact_ms() -> float:
    return 1e3 * float(collide(_ball(), WALL, ITF_DROP_SPEED).contact_time)


def _wall_compression_mm() -> float:
    ball = _ball()
    return 1e3 * float(ball.law.peak_compression(ball.mass, ITF_DROP_SPEED))


def clamped_racket(stiffness: float, string: str = CLAMPED_STRING, tension_n=None):
    """The Pure Drive (2021) with its head clamped and a uniform bed of ``string`` (a preset
    of :data:`racket.strings.stringing.STRINGS`) of ``stiffness`` [N/m], or at ``tension_n`` [N]
    when ``stiffness`` is None: the frame does not take part, so any strung racket gives
    the same numbers.

    Parameters
    ----------
    stiffness : float or None
        The bed's stiffness [N/m] (its stretch follows from it), or None for the tension's.
    string : str
        A preset string (default :data:`CLAMPED_STRING`).
    tension_n : float or None
        The string tension [N], with ``stiffness`` None.
    """
    racket = CATALOG["pure-drive-2021"].racket(support="clamped-head")
    strung = stringing(string, tension_n=tension_n)
    start, end = racket.strings.extent
    bed = strung.bed((start, end), racket.strings.width, "uniform", stiffness=stiffness)
    return replace(racket, strings=bed)


@cache
def _clamped(stiffness: float):
    """The tennis ball dropped 1 m onto :func:`clamped_racket` of ``stiffness``."""
    racket = clamped_racket(stiffness)
    return impact(racket, _ball(), racket.strings.center, DROP_1M_SPEED)


@cache
def _steel_cor(string: str, tension_lb: float) -> float:
    """COR of :data:`STEEL_BALL` on :func:`clamped_racket` strung with ``string`` at
    ``tension_lb``.
    """
    racket = steel_ball_racket(clamped_racket(None, string, tension_lb * LB))
    return float(impact(racket, STEEL_BALL, racket.strings.center, STEEL_SPEED).e)


def _dt(string: str, tension_lb: float) -> float:
    """The ERT's dynamic tension [kp/cm] of the Pure Drive (2021)'s bed strung with
    ``string`` at ``tension_lb``.
    """
    area = CATALOG["pure-drive-2021"].racket().strings.area
    return stringing(string, tension_n=tension_lb * LB).dt(area)


@cache
def _savage_drops() -> dict:
    """Drop [%] of the first bending mode, held vs free, per (racket, grip): the Pure Drive's
    sheet tuned to each of Savage's free frequencies (as :data:`racket.GRIPS` was fitted).
    """
    sheet = {k: v for k, v in CATALOG["pure-drive-2021"].specs.items() if k != "ra"}
    drops = {}
    for label, free_hz in (("A", 183.75), ("B", 162.5)):
        modes = from_specs(**sheet, f1_hz=free_hz).beam.modes
        for grip, hand in GRIPS.items():
            held = held_mode(held_system(modes, hand), 2)[0]
            drops[label, grip] = 100.0 * (1.0 - held / free_hz)
    return drops


@cache
def _grabiner_ratio() -> float:
    racket = CATALOG["pure-drive-2021"].racket()
    centre = racket.strings.center
    free = impact(racket, _ball(), centre, GRABINER_SPEED)
    held = impact(replace(racket, support="hand-held"), _ball(), centre, GRABINER_SPEED)
    return float(held.ball_rebound / free.ball_rebound)


@cache
def hamori_racket(racket: str, string: str, tension_lb: float):
    """Hamori's ``racket`` (:data:`HAMORI_RACKETS`) strung fresh with ``string`` at
    ``tension_lb``, hand-held (the medium grip).
    """
    return from_specs(
        support="hand-held", length_m=0.6858, tension_lb=tension_lb, string=string,
        pattern=HAMORI_PATTERN, **HAMORI_RACKETS[racket][1],
    )  # fmt: skip


@cache
def _hamori_ms(racket: str, string: str, tension_lb: float, stroke: str) -> float:
    r = hamori_racket(racket, string, tension_lb)
    return 1e3 * float(impact(r, _ball(), r.strings.center, STROKE_SPEEDS[stroke]).contact_time)


@cache
def _twu_part_1() -> dict:
    """e_A of TWU's hand-held 291 g racket (:data:`TWU_SHEET`, the medium grip) at the
    centre and at 3 o'clock (:data:`TWU_OFFSET` off the axis), with and without the lead;
    the tip resting on the floor is left out.
    """
    plain = from_specs(support="hand-held", **TWU_SHEET)
    out = {}
    for name, racket in (("plain", plain), ("lead", plain.with_lead_tape(TWU_LEAD, "3 and 9"))):
        r = impact(racket, _ball(), racket.strings.center, TWU_SPEED, offset=[0.0, TWU_OFFSET])
        out[name] = r.e_A
    return out


def _along(racket) -> np.ndarray:
    """Tip, centre and throat impact points [m from the tip] (:data:`EDGE_INSET`)."""
    start, end = racket.strings.extent
    return np.array([start + EDGE_INSET, racket.strings.center, end - EDGE_INSET])


@cache
def _twu_part_2() -> np.ndarray:
    """e_A at the tip, centre and throat of the Pure Drive (2021) pinned at its butt
    (:data:`PIN`), 17.9 m/s, and at 3 o'clock beside the centre with the ball's edge at the
    frame (the periphery).
    """
    racket = CATALOG["pure-drive-2021"].racket(support="hand-held")
    racket = replace(racket, hand=PIN)
    ball, x = _ball(), _along(racket)
    side = 0.5 * racket.strings.full_width - ball.radius
    x, y = np.r_[x, racket.strings.center], np.r_[0.0, 0.0, 0.0, side]
    return impact(racket, ball, x, TWU_PIVOT_SPEED, offset=y).e_A


@cache
def _typical() -> np.ndarray:
    """e_A at the tip, centre and throat of the Pure Drive (2021), hand-held (medium grip),
    at 16.5 m/s (assumption: racquettech gives neither racket, support nor speed).
    """
    racket = CATALOG["pure-drive-2021"].racket(support="hand-held")
    return impact(racket, _ball(), _along(racket), TWU_SPEED).e_A


@cache
def _ra_groups() -> pd.DataFrame:
    from studies.twu import TWU_TABLE

    table = pd.read_csv(TWU_TABLE)
    return table.groupby("RA Stiffness")["Vibration Frequency (Hz)"].agg(["mean", "std", "size"])


def _ra_frequency(ra: float) -> float:
    return float(f1_from_ra(ra))
