"""The model against published measurements: one :class:`Comparison` per measured number.

Every comparison runs the model under the measurement's own conditions (ball type and speed,
support, hand, racket, tension) and asks whether its value lies in the measured band.  The
numbers are those of ``../shared/data/measurements.md`` (sources and conditions there), each
with its source beside it; where a source states no uncertainty, the band used is **an
assumption** and says so (``band``).

Two kinds, kept apart (:attr:`Comparison.kind`):

* ``"calibration"``: the number was used to set a parameter of the model (the ITF rebound
  bands and the 254 cm drop's contact time and compression set the ball presets,
  :mod:`ball.catalog`; Savage's hand-held frequencies set the grips, :data:`racket.GRIPS`;
  the TWU table sets the RA regression, :mod:`racket.specs.ra`).  Agreement shows the
  calibration holds, not that the model is right.
* ``"validation"``: no parameter of the model was set from it.

:func:`validation_table` runs them all (a few seconds).  Where the model falls outside a
band the table says so; nothing is tuned to move it in (``tests/test_validation.py`` keeps
each disagreement as an expected failure with the measured gap).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field, replace
from functools import cache

import numpy as np
import pandas as pd

from ball import BALL_PRESETS, WALL, collide
from ball.catalog import DROP_COMPRESSION, DROP_CONTACT_TIME, ITF_DROP_SPEED
from common.units import GRAVITY
from racket import CATALOG, GRIPS, Hand, from_specs, impact
from racket.specs.ra import f1_from_ra
from racket.system import held_mode, held_system

KINDS = ("validation", "calibration")
"""The kinds of comparison: a number the model was not set from, or one it was."""

COLUMNS = ("quantity", "conditions", "measured", "low", "high", "model", "agrees", "kind", "source")
"""The columns of :func:`validation_table`."""

BALL = "itf-type-2"
"""The ball of every racket comparison: the ITF type 2 (medium) ball, the pressurised ball
of ordinary play (assumption: the sources name no ball type)."""

DROP_1M_SPEED = math.sqrt(2.0 * GRAVITY * 1.0)
"""Speed [m/s] of a ball dropped from 1 m (4.43 m/s; air drag neglected): Cross's drop onto
clamped strings, and the low-speed drop assumed for the seed paper's clamped-string e and
contact time (Cross 2000, Sec. III gives no speed; "low speed")."""

SEED_BED = 4e4
"""String-plane stiffness [N/m] for the seed paper's clamped-string numbers: its "typically
about 4e4 N/m" (Cross 2000, Sec. III)."""

CROSS_BED = 3e4
"""String-plane stiffness [N/m] for Cross's 1 m drop onto clamped strings (tennis.html gives
no racket): the seed paper's "about 3e4 N/m at 55 lb" (Sec. VIII), a typical stringing."""

TWU_SPEED = 16.5
"""Ball speed [m/s] of TWU "Racquet Control" part 1 (16.5 +/- 1 m/s)."""

TWU_PIVOT_SPEED = 17.9
"""Ball speed [m/s] of TWU "Racquet Control" part 2."""

TWU_OFFSET = 0.08
"""Offset [m] from the long axis of TWU part 1's impacts at 3 and 9 o'clock: the largest it
measured (its lateral offsets run from -80 to +60 mm; ``measurements.md`` section 4)."""

GRABINER_SPEED = math.sqrt(2.0 * GRAVITY * 5.75)
"""Ball speed [m/s] of Grabiner, Groppel and Campbell's drops, from 5.75 m: 10.62 m/s
(``measurements.md`` section 3)."""

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
    "Babolat AeroPro Drive": (
        "AeroPro Drive Cortex",
        dict(head_size_in2=100.0, mass_kg=0.31468, balance_cm=33.02,
             swingweight_kgcm2=328.0, f1_hz=152.3),
    ),
    "Wilson Pro Staff 85": (
        "Pro Staff 90 (no 85 in the table)",
        dict(head_size_in2=90.0, mass_kg=0.346, balance_cm=32.0,
             swingweight_kgcm2=315.0, f1_hz=146.2),
    ),
    "Wilson Pro Staff 95": (
        "BLX Pro Staff Six.One 95",
        dict(head_size_in2=95.0, mass_kg=0.326, balance_cm=32.1,
             swingweight_kgcm2=303.0, f1_hz=144.5),
    ),
    "Wilson Pro Staff 97": (
        "Pro Staff 97",
        dict(head_size_in2=97.0, mass_kg=0.325, balance_cm=32.0,
             swingweight_kgcm2=312.0, f1_hz=144.5),
    ),
}  # fmt: skip
"""Hamori's rackets as spec sheets: the closest row of the TWU table
(``tests/data/twu_racquets_half.csv``: head size, strung mass, balance, swingweight, free
frequency; 27 in long), named beside each.  The model has no string material: polyester and
gut at one tension give the same bed (:func:`racket.specs.strings.string_bed_stiffness`,
from the pull tension)."""


@dataclass(frozen=True)
class Comparison:
    """One measured number and the model's value under its conditions.

    Attributes
    ----------
    name : str
        Short identifier (the test's id).
    quantity : str
        What is compared, with its unit.
    conditions : str
        The measurement's conditions, as the model runs them.
    measured : float
        The published value [the unit of ``quantity``].
    low, high : float
        The band the model must fall in [the unit of ``quantity``].
    source : str
        Where the value was read.
    kind : str
        ``"validation"`` or ``"calibration"`` (:data:`KINDS`).
    band : str
        Where the band comes from: the source's own, or an assumption (said so).
    model : callable
        Returns the model's value (same unit as ``measured``).
    """

    name: str
    quantity: str
    conditions: str
    measured: float
    low: float
    high: float
    source: str
    kind: str
    band: str
    model: Callable[[], float] = field(repr=False, compare=False)

    def __post_init__(self):
        if self.kind not in KINDS:
            raise ValueError(f"kind must be one of {KINDS}, got {self.kind!r}")
        if not self.low <= self.high:
            raise ValueError(f"{self.name}: band must have low <= high, got {self.low, self.high}")

    def agrees(self, value: float) -> bool:
        """Whether ``value`` lies in the band, low to high.

        Parameters
        ----------
        value : float
            The model's value [the unit of ``quantity``].
        """
        return bool(self.low <= value <= self.high)


def _about(value: float, half: float) -> tuple[float, float, float]:
    return value, value - half, value + half


# ----- the model under each measurement's conditions --------------------------------------
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


@cache
def _clamped(stiffness: float):
    """The Pure Drive (2021) with its head clamped and a uniform bed of ``stiffness``: the
    frame does not take part, so any strung racket gives the same numbers.
    """
    racket = CATALOG["pure-drive-2021"].racket(support="clamped-head")
    bed = replace(racket.strings, stiffness=stiffness, profile="uniform")
    racket = replace(racket, strings=bed)
    return impact(racket, _ball(), racket.strings.center, DROP_1M_SPEED)


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
def _hamori_racket(racket: str, tension_lb: float):
    return from_specs(
        support="hand-held", length_m=0.6858, tension_lb=tension_lb, **HAMORI_RACKETS[racket][1]
    )


@cache  # (two of Hamori's rows differ only in the string, which the model has not)
def _hamori_ms(racket: str, tension_lb: float, stroke: str) -> float:
    r = _hamori_racket(racket, tension_lb)
    return 1e3 * float(impact(r, _ball(), r.strings.center, STROKE_SPEEDS[stroke]).contact_time)


@cache
def _twu_part_1() -> dict:
    """e_A of TWU's hand-held 291 g racket at the centre and at 3 o'clock
    (:data:`TWU_OFFSET` off the axis), with and without the lead.  The racket: the Pure
    Drive (2021) sheet at 291 g and swingweight 315 kg cm^2 (assumption: TWU gives the mass
    and a 100 in^2 class head, not the swingweight), the medium grip; the tip resting on the
    floor is left out.
    """
    specs = CATALOG["pure-drive-2021"].specs | dict(mass_kg=0.291, swingweight_kgcm2=315.0)
    plain = from_specs(support="hand-held", **specs)
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


# ----- the comparisons ---------------------------------------------------------------------
_ITF = "ITF Rules of Tennis, Appendix I (e = sqrt(h / 254 cm), derived)"
_CROSS_PAGE = "R. Cross, physics.usyd.edu.au/~cross/tennis.html (own text)"
_SEED = "R. Cross, Am. J. Phys. 68 (2000), Sec. III"
_TWU_1 = "TWU 'Racquet Control' part 1 (Cross & Lindsey; own text)"
_TWU_2 = "TWU 'Racquet Control' part 2 (own text)"
_RACQUETTECH = "racquettech.com, 'ball speeds' (own text)"
_SAVAGE = "Savage, PhD thesis, RMIT 2006, appendix (own text)"
_ABOUT_E = "assumption: 'about' read as +/-0.05"


def _itf(name: str, label: str) -> Comparison:
    low, high = BALL_PRESETS[name].bands.cor
    return Comparison(
        f"rebound-{name}", f"rebound e, {label} [-]", "254 cm drop onto concrete, 7.06 m/s",
        0.5 * (low + high), low, high, _ITF, "calibration", "the ITF band",
        lambda: _wall_cor(name),
    )  # fmt: skip


def _savage(label: str, free_hz: float, grip: str, held_hz: float, band) -> Comparison:
    drop = 100.0 * (1.0 - held_hz / free_hz)
    low, high, note = band if band else (drop - 2.0, drop + 2.0, "assumption: +/-2 points")
    return Comparison(
        f"savage-{label}-{grip}", "first-mode drop, held vs free [%]",
        f"racket {label} ({free_hz} Hz free), {grip} grip (racket.GRIPS)",
        drop, low, high, _SAVAGE, "calibration", note,
        lambda: _savage_drops()[label, grip],
    )  # fmt: skip


def _hamori(racket: str, strings: str, tension_lb: float, stroke: str, ms: float):
    model_name = HAMORI_RACKETS[racket][0]
    speed = STROKE_SPEEDS[stroke]
    return Comparison(
        f"hamori-{racket.split()[-1].lower()}-{strings}-{tension_lb:g}-{stroke}",
        f"dwell time, {stroke} [ms]",
        f"{racket} ({model_name}, TWU sheet), {strings} {tension_lb:g} lb, hand-held, "
        f"{speed:g} m/s closing (assumed), string centre",
        ms, ms - 1e3 * HAMORI_BAND, ms + 1e3 * HAMORI_BAND, HAMORI, "validation",
        "assumption: +/-0.5 ms", lambda: _hamori_ms(racket, tension_lb, stroke),
    )  # fmt: skip


def _ra(ra: int) -> Comparison:
    def measured():
        return _ra_groups().loc[ra]

    row = measured()
    return Comparison(
        f"ra-{ra}", f"free first frequency at RA {ra} [Hz]",
        f"the {int(row['size'])} TWU rackets of RA {ra} vs a spec-sheet racket of RA {ra}",
        float(row["mean"]), float(row["mean"] - row["std"]), float(row["mean"] + row["std"]),
        "TWU racquet table (tests/data/twu_racquets_half.csv), mean +/- standard deviation "
        "(derived)", "calibration", "the table's scatter", lambda: _ra_frequency(ra),
    )  # fmt: skip


def comparisons() -> list[Comparison]:
    """Every comparison, calibration and validation (the TWU table is read here)."""
    contact, contact_band = DROP_CONTACT_TIME
    compression = DROP_COMPRESSION[0]
    items = [
        _itf("itf-type-1", "ITF type 1"),
        _itf("itf-type-2", "ITF type 2"),
        _itf("itf-type-3", "ITF type 3"),
        _itf("high-altitude", "high altitude"),
        Comparison(
            "concrete-contact-time", "contact time on concrete [ms]",
            "ITF type 2, 7.06 m/s", 1e3 * contact, 1e3 * contact_band[0],
            1e3 * contact_band[1], _SEED + ", citing Cross 1999", "calibration",
            "assumption: 'about 4 ms' read as +/-0.5 ms", _wall_contact_ms,
        ),
        Comparison(
            "concrete-compression", "compression on concrete [mm]", "ITF type 2, 7.06 m/s",
            1e3 * compression, 1e3 * compression - 1.0, 1e3 * compression + 1.0, _CROSS_PAGE,
            "calibration", "assumption: 'about 6 mm' read as +/-1 mm (the presets accept "
            "5-8.5 mm)", _wall_compression_mm,
        ),
        Comparison(
            "concrete-energy-loss", "energy lost on concrete [%]",
            "ITF type 2, 254 cm drop, 7.06 m/s", *_about(45.0, 5.0), _CROSS_PAGE,
            "calibration", "assumption: 'about 45 %' read as +/-5 points; the COR at "
            "7.06 m/s is set by the ITF band", lambda: 100.0 * (1.0 - _wall_cor(BALL) ** 2),
        ),
        *(
            _savage(label, free_hz, grip, held_hz, band)
            for label, free_hz, grip, held_hz, band in (
                ("A", 183.75, "light", 170.25, None),
                ("A", 183.75, "medium", 165.0, None),
                ("A", 183.75, "tight", 144.5, (20.0, 22.7, "his 'about 142-147 Hz'")),
                ("B", 162.5, "light", 149.0, None),
                ("B", 162.5, "medium", 146.25, None),
                ("B", 162.5, "tight", 142.5, None),
            )
        ),
        *(_ra(ra) for ra in (60, 66, 72)),
        Comparison(
            "seed-clamped-e", "e on head-clamped strings [-]",
            f"ITF type 2, {DROP_1M_SPEED:.2f} m/s (low speed, assumed), uniform bed "
            f"{SEED_BED:.0e} N/m, string centre", *_about(0.88, 0.02), _SEED, "validation",
            "assumption: 'about 0.88' read as +/-0.02", lambda: float(_clamped(SEED_BED).e),
        ),
        Comparison(
            "cross-1m-drop-e", "e on head-clamped strings, 1 m drop [-]",
            f"ITF type 2, {DROP_1M_SPEED:.2f} m/s, uniform bed {CROSS_BED:.0e} N/m, "
            "string centre", math.sqrt(0.70), math.sqrt(0.65), math.sqrt(0.75), _CROSS_PAGE,
            "validation", "assumption: bounce 'about 0.70 m' read as 0.65-0.75 m "
            "(e = sqrt(h), derived)", lambda: float(_clamped(CROSS_BED).e),
        ),
        Comparison(
            "strings-contact-time", "contact time on strings [ms]",
            f"ITF type 2, {DROP_1M_SPEED:.2f} m/s (low speed, assumed), head-clamped, "
            f"uniform bed {SEED_BED:.0e} N/m", *_about(5.0, 0.5), _SEED + ", citing Cross 1999",
            "validation", "assumption: 'about 5 ms' read as +/-0.5 ms",
            lambda: 1e3 * float(_clamped(SEED_BED).contact_time),
        ),
        Comparison(
            "grabiner-gripped-vs-free", "rebound speed, gripped / free [-]",
            "Pure Drive (2021), medium grip vs free, ITF type 2 at 10.62 m/s, string centre",
            1.0, 0.98, 1.02, "Grabiner, Groppel & Campbell, Med. Sci. Sports Exerc. 15 (1983) "
            "542 (abstract)", "validation", "assumption: 'no significant difference' read as "
            "+/-2 %", _grabiner_ratio,
        ),
        *(
            _hamori(*row)
            for row in (
                ("Babolat AeroPro Drive", "polyester", 67.0, "forehand", 3.8),
                ("Babolat AeroPro Drive", "polyester", 67.0, "volley", 3.75),
                ("Babolat AeroPro Drive", "polyester", 67.0, "serve", 4.0),
                ("Babolat AeroPro Drive", "polyester", 37.0, "forehand", 4.9),
                ("Babolat AeroPro Drive", "polyester", 37.0, "volley", 4.1),
                ("Babolat AeroPro Drive", "polyester", 37.0, "serve", 4.0),
                ("Wilson Pro Staff 85", "polyester", 54.0, "forehand", 3.6),
                ("Wilson Pro Staff 85", "gut", 54.0, "forehand", 4.5),
                ("Wilson Pro Staff 95", "gut", 54.0, "forehand", 4.6),
                ("Wilson Pro Staff 97", "gut", 54.0, "forehand", 4.3),
                ("Wilson Pro Staff 97", "gut", 54.0, "volley", 4.1),
                ("Wilson Pro Staff 97", "gut", 54.0, "serve", 3.7),
            )
        ),
        Comparison(
            "twu-held-centre", "e_A at mid-face [-]",
            "hand-held 291 g racket (Pure Drive sheet, SW 315), medium grip, ITF type 2, "
            "16.5 m/s", *_about(0.4, 0.05), _TWU_1, "validation", _ABOUT_E,
            lambda: float(_twu_part_1()["plain"][0]),
        ),
        Comparison(
            "twu-held-3-oclock", "e_A near the frame at 3 / 9 o'clock [-]",
            "as mid-face, 8 cm off the axis (TWU's largest offset)", 0.15, 0.1, 0.2, _TWU_1,
            "validation",
            "the source's range 0.1-0.2", lambda: float(_twu_part_1()["plain"][1]),
        ),
        Comparison(
            "twu-held-3-oclock-lead", "e_A near the frame at 3 / 9 o'clock, 26.8 g lead [-]",
            "as above, 13.4 g at 3 and at 9 o'clock", *_about(0.3, 0.05), _TWU_1,
            "validation", _ABOUT_E, lambda: float(_twu_part_1()["lead"][1]),
        ),
        *(
            Comparison(
                f"twu-pivot-{where}", f"e_A at the {where}, pivoting about the handle end [-]",
                f"Pure Drive (2021) pinned at the butt, free to roll (approximation: a stiff "
                f"2 cm grip), ITF type 2, 17.9 m/s, {where}", value, low, high, _TWU_2,
                "validation",
                note, lambda i=i: float(_twu_part_2()[i]),
            )
            for i, where, value, low, high, note in (
                (0, "tip", 0.15, 0.1, 0.2, "the source's range 0.1-0.2"),
                (1, "centre", *_about(0.4, 0.05), _ABOUT_E),
                (2, "throat", *_about(0.5, 0.05), _ABOUT_E),
                (3, "periphery", 0.15, 0.1, 0.2, "the source's range 0.1-0.2 (3 o'clock)"),
            )
        ),
        *(
            Comparison(
                f"typical-{where}", f"e_A at the {where}, a typical racket [-]",
                f"Pure Drive (2021), hand-held, medium grip, ITF type 2, 16.5 m/s (assumed), "
                f"{where}", *_about(value, 0.05), _RACQUETTECH, "validation", _ABOUT_E,
                lambda i=i: float(_typical()[i]),
            )
            for i, where, value in ((0, "tip", 0.1), (1, "centre", 0.45), (2, "throat", 0.50))
        ),
    ]  # fmt: skip
    return items


def validation_table(items: list[Comparison] | None = None) -> pd.DataFrame:
    """Run the comparisons: one row each, with the model's value and whether it agrees.

    Parameters
    ----------
    items : list of Comparison, optional
        The comparisons to run; default :func:`comparisons`.

    Returns
    -------
    DataFrame
        Columns :data:`COLUMNS` (``measured``, ``low``, ``high`` and ``model`` in the unit of
        ``quantity``; ``agrees`` a bool), indexed by each comparison's name.
    """
    items = comparisons() if items is None else items
    rows = []
    for c in items:
        value = float(c.model())
        rows.append(
            dict(
                quantity=c.quantity, conditions=c.conditions, measured=c.measured, low=c.low,
                high=c.high, model=value, agrees=c.agrees(value), kind=c.kind, source=c.source,
            )
        )  # fmt: skip
    return pd.DataFrame(rows, index=pd.Index([c.name for c in items], name="name"))


GROUPS = {
    "the ball on a rigid surface": ("rebound", "concrete"),
    "the ball on clamped strings": ("seed", "cross", "clamped", "strings"),
    "the hand": ("savage", "grabiner"),
    "the frame's stiffness (RA)": ("ra",),
    "dwell times in real strokes (Hamori)": ("hamori",),
    "power over the face (e_A)": ("twu", "typical"),
}
"""The comparisons by what they test: group -> the first words of their names."""


def groups(table: pd.DataFrame):
    """The rows of a :func:`validation_table` by :data:`GROUPS`: (group, rows) pairs.

    Parameters
    ----------
    table : DataFrame
        The table of :func:`validation_table`.
    """
    first = table.index.str.split("-").str[0]
    for group, words in GROUPS.items():
        yield group, table[first.isin(words)]


def summary(table: pd.DataFrame) -> str:
    """One line: how many comparisons agree, by kind.

    Parameters
    ----------
    table : DataFrame
        The table of :func:`validation_table`.
    """
    parts = []
    for kind in KINDS:
        rows = table[table["kind"] == kind]
        parts.append(f"{kind}: {int(rows['agrees'].sum())} of {len(rows)} agree")
    return f"{len(table)} comparisons with published measurements; " + "; ".join(parts)
