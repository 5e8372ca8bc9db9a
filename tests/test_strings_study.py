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
        assert row["dt_kp_cm"] == pytest.approx(bed.stiffness / KP_PER_CM, rel=1e-12)
        assert row["stretch_1_m2"] == pytest.approx(bed.stretch, rel=1e-12)
        assert row["loss_percent"] == pytest.approx(100 * bed.loss, rel=1e-12)
    # the same tension for all: the same small-deflection stiffness, not the same stretch
    assert np.allclose(table["dt_kp_cm"], table["dt_kp_cm"].iloc[0])
    assert table["stretch_1_m2"].nunique() > 1


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
