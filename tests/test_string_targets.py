"""Issue 35's targets for a real string bed, each a test on published numbers.

Met: the steel-ball calibration for every string, gauge and tension; the seed paper's
clamped-string e; the paper's claims (its bed stays the paper's spring). Not met, kept as
strict expected failures with the measured gap as their reason (nothing was tuned to move
them): Cross's 1 m drop, Hamori's count and his two pairs, the count of validation rows.
"""

import pytest

from common.units import LB
from racket import impact
from racket.strings.sizes import GAUGES
from racket.strings.stringing import STRINGS
from studies.validation import comparisons
from studies.validation.conditions import (
    STEEL_BALL,
    STEEL_SPEED,
    _hamori_ms,
    clamped_racket,
    steel_ball_racket,
)


@pytest.fixture(scope="module")
def table(validation_rows):
    return validation_rows.copy()


@pytest.mark.parametrize("string", [*STRINGS, "natural-gut/polyester"])
@pytest.mark.parametrize("tension_lb", [40.0, 55.0, 65.0])
@pytest.mark.parametrize("state", ["fresh", "played"])
def test_a_steel_ball_comes_back_at_0_97_from_every_string_and_tension(string, tension_lb, state):
    """Kawazoe: COR about 0.97 "regardless of type or tension" (the loss's calibration)."""
    from dataclasses import replace

    racket = clamped_racket(None, string, tension_lb * LB)
    bed = racket.strings
    strung = replace(bed.stringing, state=state)
    racket = replace(racket, strings=strung.bed(bed.extent, bed.width, "uniform"))
    racket = steel_ball_racket(racket)
    hit = impact(racket, STEEL_BALL, racket.strings.center, STEEL_SPEED)
    assert 0.96 <= hit.e <= 0.98


@pytest.mark.parametrize("gauge", sorted(GAUGES))
def test_the_steel_ball_calibration_holds_at_every_gauge(gauge):
    from dataclasses import replace

    racket = clamped_racket(None, "polyester", 55.0 * LB)
    strung, bed = racket.strings.stringing, racket.strings
    gauged = type(strung.mains)(strung.mains.material, GAUGES[gauge])
    strung = replace(strung, mains=gauged, crosses=gauged)
    racket = replace(racket, strings=strung.bed(bed.extent, bed.width, "uniform"))
    racket = steel_ball_racket(racket)
    assert 0.96 <= impact(racket, STEEL_BALL, racket.strings.center, STEEL_SPEED).e <= 0.98


def test_the_clamped_rows_at_the_seeds_conditions_agree(table):
    assert 0.85 <= table.loc["seed-clamped-e", "model"] <= 0.90


@pytest.mark.xfail(strict=True, reason="model 0.876 vs [0.80, 0.87]: the strings' loss and "
                   "the bed's mass took it from 0.917; see tests/test_validation.py "
                   "KNOWN_GAPS")  # fmt: skip
def test_the_1_m_drop_onto_clamped_strings_agrees(table):
    assert 0.80 <= table.loc["cross-1m-drop-e", "model"] <= 0.87


def _hamori_rows(table):
    return table[table.index.str.startswith("hamori-")]


@pytest.mark.xfail(strict=True, reason="6 of 12 in their bands (8 without the bed's mass, which "
                   "lengthens every contact by 0.2-0.5 ms): the three volleys (their 20 m/s "
                   "closing speed assumed), the Pro Staff 85's polyester, the AeroPro Drive's "
                   "67 lb forehand and the Pro Staff 97's serve")  # fmt: skip
def test_at_least_10_of_hamoris_12_dwell_times_agree(table):
    rows = _hamori_rows(table)
    assert len(rows) == 12
    assert rows["agrees"].sum() >= 10


def test_hamoris_pairs_come_out_in_order(table):
    """Polyester shorter than gut in the same racket, 37 lb longer than 67 lb: in order."""
    poly = _hamori_ms("Wilson Pro Staff 85", "polyester", 54.0, "forehand")
    gut = _hamori_ms("Wilson Pro Staff 85", "natural-gut", 54.0, "forehand")
    low = _hamori_ms("Babolat AeroPro Drive", "polyester", 37.0, "forehand")
    high = _hamori_ms("Babolat AeroPro Drive", "polyester", 67.0, "forehand")
    assert poly < gut and low > high


@pytest.mark.xfail(strict=True, reason="model 0.20 ms vs 0.9 +/- 0.4 ms: at one tension the "
                   "two beds differ in stretch (EA), loss and mass only")  # fmt: skip
def test_polyester_is_shorter_than_gut_by_hamoris_0_9_ms():
    poly = _hamori_ms("Wilson Pro Staff 85", "polyester", 54.0, "forehand")
    gut = _hamori_ms("Wilson Pro Staff 85", "natural-gut", 54.0, "forehand")
    assert gut - poly == pytest.approx(0.9, abs=0.4)


@pytest.mark.xfail(strict=True, reason="model 0.57 ms vs 1.1 +/- 0.4 ms: the stretch (from EA, "
                   "not the tension) makes the tension matter less at a forehand's deflection "
                   "(1.04 ms with a linear, massless bed; 0.36 ms without the bed's "
                   "mass)")  # fmt: skip
def test_37_lb_is_longer_than_67_lb_by_hamoris_1_1_ms():
    low = _hamori_ms("Babolat AeroPro Drive", "polyester", 37.0, "forehand")
    high = _hamori_ms("Babolat AeroPro Drive", "polyester", 67.0, "forehand")
    assert low - high == pytest.approx(1.1, abs=0.4)


SPIN_GROUPS = ("bounce", "spin", "stroke", "court")
"""The first words of issue 36's rows (oblique impacts, spin, courts), counted apart."""


def test_no_calibration_row_was_lost_and_validation_gained(table):
    """Before the real bed: validation 13 of 26, calibration 13 of 16 (the 16 still agree
    as they did, and the ball's compression on concrete since its band is the presets' one,
    issue 45; the new calibration rows are the string bed's)."""
    old_calibration = ("rebound", "concrete", "savage", "ra")
    first = table.index.str.split("-").str[0]
    kept = table[first.isin(old_calibration)]
    assert len(kept) == 16 and kept["agrees"].sum() == 14
    validation = table[(table["kind"] == "validation") & ~first.isin(SPIN_GROUPS)]
    assert len(validation) == 26 and validation["agrees"].sum() > 13


@pytest.mark.xfail(strict=True, reason="16 of 26 agree (13 before the real bed, 19 without "
                   "its mass): Cross's 1 m drop, six of Hamori's dwell times, two throats "
                   "and TWU's 3 o'clock with lead (strung by the one rule, issue 45)")  # fmt: skip
def test_at_least_22_of_26_validation_rows_agree(table):
    first = table.index.str.split("-").str[0]
    validation = table[(table["kind"] == "validation") & ~first.isin(SPIN_GROUPS)]
    assert validation["agrees"].sum() >= 22


def test_every_string_row_names_racket_string_and_tension():
    for c in comparisons():
        if c.name.startswith("hamori-"):
            assert " lb" in c.quantity and any(s in c.quantity for s in ("polyester", "gut"))
