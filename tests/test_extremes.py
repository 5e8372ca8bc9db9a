"""Every physical input checked in every path (issue 34): extremes computed or refused in one
line naming the input as given, with its range and a likely slip of unit; never NaN."""

from dataclasses import replace
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from ball import WALL, Ball, LinearHysteresis, StiffeningHysteresis, collide
from common.checks import shown
from racket import Hand, Swing, default_ball, default_racket, from_specs, impact, paper_racket
from racket.hand import HAND_MASS_RANGE
from racket.specs.catalog import CATALOG
from racket.specs.sheet import SPEC_RANGES, spec_sheet
from racket.swing import equal_effort
from studies.cli import main
from studies.config import load_racket, racket_from_table
from studies.face.maps import compare_summary

TWU = Path(__file__).parent / "data" / "twu_racquets_half.csv"
SHEET = dict(CATALOG["pure-drive-2021"].specs)


def _one_line(err) -> str:
    message = str(err.value)
    assert "\n" not in message
    return message


# ----- the hand ------------------------------------------------------------------------
@pytest.mark.parametrize("mass", [1e-9, 1e-300, 1e-3, 6.0, 1e9])
def test_a_hand_outside_its_range_is_refused_not_nan(mass):
    with pytest.raises(ValueError, match=r"^hand mass must be in \[0.05, 5\] kg") as err:
        Hand(2.5e5, 10.0, 0.10, mass)
    assert _one_line(err).endswith(f"got {shown(mass)}")


def test_a_hand_in_grams_is_refused_with_the_slip():
    with pytest.raises(ValueError, match=r"grams typed as kg\? 190 would be 0.19 kg") as err:
        Hand(mass=190)
    _one_line(err)


def test_a_grip_stiffness_in_kn_per_m_is_refused_with_the_slip():
    with pytest.raises(ValueError, match=r"^hand stiffness .*kN/m typed as N/m\? 250 would be"):
        Hand(stiffness=250.0)
    with pytest.raises(ValueError, match=r"^grip_length .*cm typed as m\? 10 would be 0.1 m"):
        Hand(grip_length=10)


@pytest.mark.parametrize("mass", [*HAND_MASS_RANGE, float("inf")])
def test_the_hand_range_ends_are_computed(mass):
    racket = replace(default_racket(), support="hand-held", hand=Hand(2.5e5, 10.0, 0.10, mass))
    x = np.linspace(*racket.strings.extent, 5)[1:-1]
    r = impact(racket, default_ball(), x, 16.5)
    assert np.all(np.isfinite(r.e)) and np.all((r.e > 0) & (r.e < 1))


def test_a_toml_hand_says_the_slip():
    table = {"support": "hand-held", "hand": {"stiffness": 2.5e5, "mass": 190}}
    with pytest.raises(ValueError, match=r"^hand mass .*grams typed as kg\? 190 would be"):
        racket_from_table(table)


# ----- spec sheets: slips said by the API, so the TOML and the page say them too ---------
def test_a_swingweight_in_kg_m2_is_refused_with_the_slip_by_the_api():
    with pytest.raises(ValueError, match=r"kg m\^2 typed as kg cm\^2\? 0.0325 kg m\^2 would"):
        from_specs(**{**SHEET, "swingweight_kgcm2": 0.0325})
    with pytest.raises(ValueError, match=r"cm\^2 typed as in\^2\? 645 cm\^2 would be"):
        spec_sheet(**{**SHEET, "head_size_in2": 645})


def test_the_twistweight_range_holds_every_measured_racket_with_a_margin():
    measured = pd.read_csv(TWU)["Twistweight (kg cm^2)"]
    low, high, _ = SPEC_RANGES["twistweight_kgcm2"]
    assert low < measured.min() - 1 and high > measured.max() + 5  # 9.6-23.2
    assert low > 5 and high < 40  # what no racket has is refused


@pytest.mark.parametrize("twistweight", [5.0, 40.0])
def test_a_twistweight_no_racket_has_is_refused(twistweight):
    with pytest.raises(ValueError, match=r"^twistweight_kgcm2 must be in \[8, 30\] kg cm\^2"):
        spec_sheet(**SHEET, twistweight_kgcm2=twistweight)


# ----- lead tape ------------------------------------------------------------------------
def test_lead_tape_of_a_ton_is_refused_and_grams_as_kg_said():
    racket = default_racket()
    with pytest.raises(ValueError, match=r"^mass_kg must be in \[0, 0.2\] kg, got 1000000$"):
        racket.with_lead_tape(1e6, "3 and 9")
    with pytest.raises(ValueError, match=r"grams typed as kg\? 5 would be 0.005 kg"):
        racket.with_mass(5, 0.1)


# ----- the ball -------------------------------------------------------------------------
@pytest.mark.parametrize(
    ("x_lim", "slip"),
    [(3.35, "cm typed as m\\? 3.35 would be 0.0335 m"),
     (33.5, "mm typed as m\\? 33.5 mm would be 0.0335 m"), (1e-6, "got 1e-06$")],
)  # fmt: skip
def test_a_ball_limit_in_cm_mm_or_a_micron_is_refused(x_lim, slip):
    with pytest.raises(ValueError, match=rf"^x_lim must be in \[0.005, 0.15\] m.*{slip}"):
        StiffeningHysteresis(3.8e4, x_lim, 0.8, 7.0)
    with pytest.raises(ValueError, match=r"^radius must be in \[0.005, 0.15\] m"):
        Ball(0.057, LinearHysteresis(4e4, 0.75), x_lim)


def test_a_speed_beyond_the_ball_law_names_the_speed_and_the_fastest():
    ball = default_ball()
    with pytest.raises(ValueError, match=r"^v_a must be in \[0.001, 170.7\] m/s .* got 300$"):
        collide(ball, WALL, 300.0)
    assert collide(ball, WALL, 100.0).e > 0.5  # below it: computed


def test_the_command_line_names_the_speed_as_typed(capsys):
    assert main(["ball", "itf-type-2", "--speeds-mph", "10", "500"]) == 2
    err = capsys.readouterr().err
    assert "--speeds-mph must be in [0.002237, 381.9] mph for these balls" in err
    assert err.rstrip().endswith("got 500") and "J)" not in err
    assert main(["collide", "--a", "itf-type-2", "--b", "wall", "--va-kmh", "700"]) == 2
    assert "--va-kmh must be in [0.0036, 614.6] km/h" in capsys.readouterr().err


@pytest.mark.parametrize("mass", [1e4, 1e9])  # (1e3 kg is refused as 1 kg in grams)
def test_a_heavy_stiffening_ball_is_refused_by_name_never_nan(mass):
    ball = Ball(mass, default_ball().law, 0.0335)
    assert not np.isnan(ball.law.secant_stiffness(mass, 20.0))
    with pytest.raises(ValueError, match="the ball and strings are too soft"):
        impact(default_racket(), ball, 0.17, 20.0)


# ----- names, paths and swingweights -----------------------------------------------------
def test_a_nul_byte_in_a_file_name_is_said():
    with pytest.raises(ValueError, match=r"^cannot read 'a\\x00.toml': .* NUL byte$"):
        load_racket("a\x00.toml")


def test_a_swingweight_in_kg_cm2_is_named_not_turned_into_a_head_speed():
    message = r"^reference_swingweight .*kg cm\^2 typed as kg m\^2\? 325 kg cm\^2 would be"
    with pytest.raises(ValueError, match=message):
        equal_effort(Swing(30.0), 325.0, 0.033)
    with pytest.raises(ValueError, match=r"^swingweight 0.0001 kg m\^2 against"):
        equal_effort(Swing(30.0), 2.0, 1e-4)


# ----- compare's summary: computed where it can be, said where it cannot ----------------
def test_compare_summary_says_every_nan():
    from studies.sweeps import compare

    rackets = {"paper": paper_racket(), "pd": replace(default_racket(), support="clamped-head")}
    ball = default_ball()
    table = compare(rackets, ball, 16.5, 5)
    summary = compare_summary(rackets, table, ball, 16.5).set_index("racket")
    assert np.all(np.isfinite(summary["e_A_centre"]))
    notes = summary.attrs["notes"]
    assert any(n.startswith("paper: e_A at 3 o'clock and sweet area '-'") for n in notes)
    assert any(n.startswith("pd: centre of percussion '-' (clamped-head)") for n in notes)
    nan = summary.isna()
    said = {("paper", "e_A_3_oclock"), ("paper", "sweet_area_cm2")}
    said |= {("pd", "centre_of_percussion_from_tip_cm")}
    assert {(r, c) for r in nan.index for c in nan.columns if nan.loc[r, c]} == said
