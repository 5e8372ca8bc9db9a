"""One way to string a racket (issue 45): a racket that names no strings is strung by one
rule (:data:`racket.specs.strung.STRUNG`) wherever it is typed, so that the same spec sheet
in a TOML file (``racket-impact serve``), in :func:`racket.from_specs` and on the page (its
own code path, as its server calls it) serves the same ball to every digit; the paper's
spring is asked for by name.
"""

from pathlib import Path

import matplotlib
import pandas as pd
import pytest

from common.units import MPH
from racket import CATALOG, default_ball, from_specs
from racket.specs.strung import LINEAR, STRUNG
from studies.cli import main
from studies.page.dashboard import MY_SHEET, PageInputs, page_results
from studies.serve import serve_table

matplotlib.use("Agg")

SHEET = dict(mass_g=305.0, balance_cm=32.5, swingweight_kgcm2=320.0, head_size_in2=98.0,
             f1_hz=155.0)  # fmt: skip
"""A spec sheet as the page takes it (not the page's default, so that nothing is cached)."""
ROUND_OFF = 2e-9
"""How closely the entry points agree [-]."""
TENSION_LB = 53.0
SWING_MPH = 75.0


def _api_sheet() -> dict:
    return dict(
        mass_kg=SHEET["mass_g"] / 1e3, balance_cm=SHEET["balance_cm"],
        swingweight_kgcm2=SHEET["swingweight_kgcm2"], head_size_in2=SHEET["head_size_in2"],
        f1_hz=SHEET["f1_hz"], tension_lb=TENSION_LB,
    )  # fmt: skip


def _toml(tmp_path) -> str:
    path = tmp_path / "my.toml"
    lines = "\n".join(f"{key} = {value!r}" for key, value in _api_sheet().items())
    path.write_text(f"[racket.specs]\n{lines}\n")
    return str(path)


def test_a_spec_sheet_serves_the_same_from_toml_api_and_page(tmp_path, capsys):
    out = tmp_path / "serve.json"
    assert main(["serve", "--racket", _toml(tmp_path), "--racket-speed-mph", repr(SWING_MPH),
                 "--out", str(out)]) == 0  # fmt: skip
    printed = capsys.readouterr().out
    cli = float(pd.read_json(out)["serve_simulated_mph"].iloc[0])
    racket = from_specs(**_api_sheet())
    ball = default_ball()
    api = float(serve_table(racket, ball, None, SWING_MPH * MPH, zero_cor=False)
                ["serve_simulated_mph"].iloc[0])  # fmt: skip
    page = page_results(PageInputs(racket=MY_SHEET, tension_lb=TENSION_LB, swing_mph=SWING_MPH,
                                   **SHEET)).a  # fmt: skip
    assert page.racket.strings == racket.strings
    # to round-off: an impact may differ in its 10th digit with what the process ran before
    # (6e-10 measured; tests/test_page_truth.py ROUND_OFF)
    assert cli == pytest.approx(api, rel=ROUND_OFF)
    assert page.summary["serve_mph"] == pytest.approx(api, rel=ROUND_OFF)
    assert f"{page.summary['serve_mph']:.1f}" == f"{cli:.1f}"
    # the conditions line names the strings
    strung = racket.strings.stringing
    assert strung.describe() in " ".join(printed.split())


def test_a_catalogue_racket_is_its_own_sheet_strung_by_the_rule():
    entry = CATALOG["pro-staff-97l-cv"]
    assert entry.strung == STRUNG  # the catalogue follows the rule too
    assert from_specs(**entry.specs).strings == entry.racket().strings


def test_the_paper_s_spring_by_name():
    sheet = _api_sheet()
    plain = from_specs(**sheet, string=LINEAR)
    assert plain.strings.plain and plain.strings.stringing is None
    strung = from_specs(**sheet)
    assert not strung.strings.plain and strung.strings.moving_mass > 0
    # same stiffness at the centre: the membrane model of the sheet's tension
    assert plain.strings.stiffness == pytest.approx(strung.strings.stiffness, rel=1e-12)
    with pytest.raises(ValueError, match=r"gauge describes a string.*'linear'"):
        from_specs(**sheet, string=LINEAR, gauge="16L")


def test_compare_names_each_racket_s_strings(capsys):
    argv = ["compare", "--points", "3", "--racket", "pure-drive-2021", "--racket", "paper"]
    assert main(argv) == 0
    said = " ".join(capsys.readouterr().out.split())
    strung = CATALOG["pure-drive-2021"].racket().strings.stringing
    assert f"pure-drive-2021: {strung.describe()}" in said
    assert "paper: the paper's linear spring" in said
    assert "each its own strings" not in said


def test_the_paper_s_spring_by_name_from_the_command_line_and_toml(tmp_path, capsys):
    toml = tmp_path / "plain.toml"
    toml.write_text(Path(_toml(tmp_path)).read_text() + '[racket.strings]\nstring = "linear"\n')
    for argv in (["--racket", str(toml)], ["--racket", _toml(tmp_path), "--string", "linear"]):
        out = tmp_path / "serve.json"
        assert main(["serve", *argv, "--out", str(out)]) == 0
        assert "the paper's linear spring" in " ".join(capsys.readouterr().out.split())
        plain = from_specs(**_api_sheet(), string=LINEAR)
        api = serve_table(plain, default_ball(), None, 40.0, zero_cor=False)
        cli = pd.read_json(out)["serve_simulated_m_s"].iloc[0]
        assert cli == pytest.approx(float(api["serve_simulated_m_s"].iloc[0]), rel=ROUND_OFF)
    assert main(["serve", "--string", "linear", "--gauge", "17"]) == 2
    assert "--gauge describes a string, and --string linear is" in capsys.readouterr().err
