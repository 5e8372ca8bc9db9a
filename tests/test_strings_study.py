"""``racket-impact strings`` and :func:`studies.strings.table.string_table` (issue 35): one racket
strung with each string in turn, what each bed is and what it does."""

import json

import numpy as np
import pytest

from common.units import KP_PER_CM
from racket import default_ball, default_racket, impact, paper_racket
from racket.strings.stringing import STRING_CHOICES, restrung
from studies.cli import main
from studies.strings.table import string_table


@pytest.fixture(scope="module")
def table():
    return string_table(default_racket(), default_ball(), 16.5, 40.0)


def test_one_row_per_string_each_the_racket_restrung(table):
    assert len(table) == len(STRING_CHOICES)
    racket = default_racket()
    for name, (_, row) in zip(STRING_CHOICES, table.iterrows(), strict=True):
        bed = restrung(racket.strings, string=name)
        assert bed.stringing.describe().startswith(row["string"] + " 16x19 at 55 lb")
        # the ERT's DT: the force at 1 cm, the bed's stretch included
        at_1_cm = bed.stiffness * 0.01 * (1.0 + bed.stretch * 0.01**2) / 0.01
        assert row["dt_kp_cm"] == pytest.approx(at_1_cm / KP_PER_CM, rel=1e-12)
        assert row["stretch_1_m2"] == pytest.approx(bed.stretch, rel=1e-12)
        assert row["loss_percent"] == pytest.approx(100 * bed.loss, rel=1e-12)
    # the same tension for all: the same small-deflection stiffness, not the same stretch,
    # so not the same DT: the stiffer strings read higher, as on an ERT
    assert np.allclose(table["stiffness_kN_m"], table["stiffness_kN_m"].iloc[0])
    assert table["stretch_1_m2"].nunique() > 1
    by = table.set_index("string")
    assert by["dt_kp_cm"].idxmax().startswith("polyester")
    assert by["dt_kp_cm"].idxmin().startswith("natural gut 1.30 mm")


def test_each_rows_numbers_are_its_racket_impacts(table):
    racket = default_racket()
    strung = racket.__class__(racket.beam, restrung(racket.strings, string="natural-gut"),
                              racket.support, racket.hand)  # fmt: skip
    hit = impact(strung, default_ball(), strung.strings.center, 16.5)
    row = table.set_index("string").loc["natural gut 1.30 mm"]
    assert row["e_A"] == pytest.approx(hit.e_A, rel=1e-10)
    assert row["dwell_ms"] == pytest.approx(1e3 * hit.contact_time, rel=1e-10)
    assert 1.0 < row["serve_ratio"] < 2.0


def test_polyester_stiffens_most_and_gut_loses_least(table):
    by = table.set_index("string")
    poly = next(s for s in by.index if s.startswith("polyester"))
    gut = next(s for s in by.index if s.startswith("natural gut "))
    assert by.loc[poly, "stretch_1_m2"] > by.loc[gut, "stretch_1_m2"]
    assert by.loc[poly, "loss_percent"] > by.loc[gut, "loss_percent"]
    assert by.loc[poly, "dwell_ms"] < by.loc[gut, "dwell_ms"]  # stiffer as it deflects


def test_each_row_s_spin_and_feel_are_the_stroke_s_and_the_hand_s(table):
    from dataclasses import replace

    from racket import STROKES
    from racket.feel import hand_feel
    from studies.feel import FEEL_SUPPORT, feel_numbers
    from studies.strings.table import SPIN_STROKE
    from studies.strokes.stroke import VALIDATED, stroke_table

    assert SPIN_STROKE in VALIDATED  # the spin column is the stroke validate checks
    racket, ball = default_racket(), default_ball()
    gut = replace(racket, strings=restrung(racket.strings, string="natural-gut"))
    row = table.set_index("string").loc["natural gut 1.30 mm"]
    spin = stroke_table([(SPIN_STROKE, STROKES[SPIN_STROKE])], gut, ball)["spin_rpm"].iloc[0]
    assert row["forehand_spin_rpm"] == pytest.approx(spin, rel=1e-8)
    held = replace(gut, support=FEEL_SUPPORT)
    feel = feel_numbers(hand_feel(held, ball, gut.strings.center, 16.5), held)
    assert row["feel_vibration_g"] == pytest.approx(feel["feel_vibration_g"], rel=1e-8)
    assert table["forehand_spin_rpm"].nunique() > 1  # the strings' grip differs


def test_a_gauge_reaches_every_row_and_the_command_says_control_is_not_modelled(capsys):
    thick = string_table(default_racket(), default_ball(), 16.5, 40.0, ["nylon", "polyester"],
                         gauge=1.40e-3)  # fmt: skip
    assert list(thick["string"]) == ["nylon 1.40 mm", "polyester 1.40 mm"]
    assert main(["strings", "--gauge", "1.40", "--strings", "polyester"]) == 0
    printed = " ".join(capsys.readouterr().out.split())
    assert "polyester 1.40 mm" in printed and "not modelled: control" in printed


def test_the_papers_spring_has_no_string_to_compare():
    with pytest.raises(ValueError, match="has no string"):
        string_table(paper_racket(), default_ball(), 16.5, 40.0)


def test_the_command_prints_its_conditions_and_writes_a_table_with_its_sidecar(tmp_path, capsys):
    out = tmp_path / "strings.csv"
    assert main(["strings", "--strings", "polyester", "natural-gut", "--out", str(out)]) == 0
    printed = capsys.readouterr().out
    assert printed.startswith("racket pure-drive-2021") and "[kp/cm]" in printed
    assert "natural gut 1.30 mm" in printed
    assert out.exists()
    sidecar = json.loads((tmp_path / "strings.csv.meta.json").read_text())
    assert "pure-drive-2021" in sidecar["conditions"]


def test_a_bad_string_is_refused_in_one_line_before_any_work(tmp_path, capsys):
    out = tmp_path / "s.csv"
    assert main(["strings", "--strings", "kevlar", "--out", str(out)]) == 2
    err = capsys.readouterr().err.strip()
    assert err.count("\n") == 0 and "kevlar" in err
    assert not out.exists()


@pytest.mark.parametrize("gauge", ["1.40", "1.15"])
def test_strings_at_another_gauge_differ_in_moving_mass_and_e(gauge, tmp_path, capsys):
    # issue 45's acceptance: --gauge reached no row before (the 1.25 mm string's numbers)
    tables = {}
    for name, extra in (("default", []), ("gauge", ["--gauge", gauge])):
        out = tmp_path / f"{name}.json"
        assert main(["strings", "--strings", "polyester", *extra, "--out", str(out)]) == 0
        tables[name] = json.loads(out.read_text())[0]
    capsys.readouterr()
    default, other = tables["default"], tables["gauge"]
    assert other["string"] == f"polyester {gauge} mm"
    thicker = float(gauge) > 1.25
    assert (other["moving_mass_g"] > default["moving_mass_g"]) == thicker
    assert other["e"] != default["e"]
