"""``racket-impact court`` (issue 36): does this court play fast?  The presets printed in two
tables within 100 columns, each header with its unit; the unit typed is the unit answered; a
court of one's own; every bad input refused in one line naming the option before any bounce;
the table and its sidecar written together; and the same numbers from the command line as from
:func:`ball.court.bounce` and :func:`ball.court.court_pace_rating` (one truth).  The default
run is shared by the tests (a module-scope fixture), in this process."""

import json
import math

import pandas as pd
import pytest
from clihelpers import help_text, refusal, run_ok, run_writing, sidecar

from ball import BALL_PRESETS, DEFAULT_BALL
from ball.court import COURTS, CPR_ANGLE, CPR_SPEED, Court, bounce, court_pace_rating
from common.units import KMH, MPH
from racket.stroke import RPM
from studies.cli.show import WIDTH


@pytest.fixture(scope="module")
def presets(tmp_path_factory):
    """``racket-impact court`` (grass, clay, hard at the ITF test), with its table."""
    return run_writing(["court"], tmp_path_factory.mktemp("courts"), "courts.json")


def _rows(out: str, name: str) -> list[list[str]]:
    """The printed rows (words) of the court ``name``: the courts' table's, the bounce's."""
    return [line.split() for line in out.splitlines() if line.startswith(f"{name} ")]


def test_the_presets_print_within_100_columns_each_header_with_its_unit(presets):
    out = presets["out"]
    lines = out.splitlines()
    header = " ".join(line.strip() for line in lines[:2])
    assert header.startswith(f"ball {DEFAULT_BALL} at 30 m/s, 16 deg above the court, no spin")
    assert "ITF's test bounce" in header
    assert not [line for line in lines if len(line) > WIDTH]
    for name in COURTS:
        assert len(_rows(out, name)) == 2  # the courts, the ball after
    for unit in ("[m/s]", "[deg]", "[rpm]", "[ms]", "[-]", "slid or", "gripped", "CPR"):
        assert unit in out
    assert "not shown" not in out and "[mph]" not in out


def test_grass_plays_fast_and_clay_slow_in_the_printed_table(presets):
    out = presets["out"]
    assert _rows(out, "grass")[0][-2:] == ["5", "fast"]
    assert _rows(out, "clay")[0][-2:] == ["1", "slow"]
    assert _rows(out, "hard")[0][3] == "assumption" and _rows(out, "grass")[0][3] == "sourced"


def test_the_table_and_its_sidecar_are_written_with_the_conditions(presets):
    rows = json.loads(presets["table"].read_text())
    assert [row["court"] for row in rows] == list(COURTS)
    record = sidecar(presets)
    assert record["command"][0] == "court" and "16 deg above the court" in record["conditions"]
    for row in rows:
        assert row["contact"] in ("slid", "gripped") and 1 <= row["category"] <= 5


def test_the_command_line_gives_what_the_python_api_gives(presets):
    from studies.strokes.court import court_table

    rows = pd.DataFrame(json.loads(presets["table"].read_text()))
    ball = BALL_PRESETS[DEFAULT_BALL].ball()
    for row in rows.itertuples():
        court = COURTS[row.court]
        after = bounce(court, CPR_SPEED, CPR_ANGLE, 0.0, ball)
        cpr, category = court_pace_rating(court, ball)
        assert row.speed_after_m_s == pytest.approx(after.speed_after, rel=1e-12)
        assert row.angle_after_deg == pytest.approx(math.degrees(after.angle_after), rel=1e-12)
        assert row.topspin_after_rpm == pytest.approx(after.spin_after / RPM, rel=1e-12)
        assert row.vx_ratio == pytest.approx(after.vx_ratio, rel=1e-12)
        assert row.e_y == pytest.approx(after.e_y, rel=1e-12)
        assert row.apparent_friction == pytest.approx(after.apparent_friction, rel=1e-12)
        assert row.contact_time_ms == pytest.approx(1e3 * after.contact_time, rel=1e-12)
        assert row.contact == ("slid" if after.slid_throughout else "gripped")
        assert (row.cpr, row.category) == (pytest.approx(cpr, rel=1e-12), category)
        assert (row.friction, row.cor) == (court.friction, court.cor)
    api = court_table()
    assert list(api.columns) == list(rows.columns)
    assert api["cpr"].to_numpy() == pytest.approx(rows["cpr"].to_numpy(), rel=1e-12)


def test_mph_in_mph_out_and_km_h_in_km_h_out(tmp_path):
    path = tmp_path / "c.csv"
    out, _ = run_ok(["court", "clay", "--speed-mph", "60", "--out", str(path)])
    assert "[mph]" in out and "[m/s]" not in out and "at 60 mph" in out
    table = pd.read_csv(path)
    assert table["speed_after_mph"].to_numpy() == pytest.approx(table["speed_after_m_s"] / MPH)
    after = bounce(COURTS["clay"], 60 * MPH, CPR_ANGLE)
    assert table["speed_after_mph"].iloc[0] == pytest.approx(after.speed_after / MPH, rel=1e-10)
    out, _ = run_ok(["court", "grass", "--speed-kmh", "90"])
    assert "[km/h]" in out and "[m/s]" not in out and "at 90 km/h" in out


def test_a_court_of_ones_own_with_the_ball_as_typed(tmp_path):
    path = tmp_path / "own.csv"
    argv = ["court", "grass", "--friction", "0.45", "--cor", "0.85", "--angle", "20",
            "--topspin", "-1500", "--speed", "25", "--out", str(path)]  # fmt: skip
    out, _ = run_ok(argv)
    assert "1500 rpm backspin" in out and "20 deg above the court" in out
    table = pd.read_csv(path)
    assert list(table["court"]) == ["grass", "own court"]
    assert list(table["source"]) == ["sourced", "given"]
    own = table.iloc[1]
    assert (own["friction"], own["cor"]) == (0.45, 0.85)
    assert own["ball_topspin_rpm"] == pytest.approx(-1500.0)
    court = Court("own court", 0.45, 0.85)
    after = bounce(court, 25.0, math.radians(20.0), -1500 * RPM)
    assert own["topspin_after_rpm"] == pytest.approx(after.spin_after / RPM, rel=1e-10)
    assert own["cpr"] == pytest.approx(court_pace_rating(court)[0], rel=1e-12)
    assert len(_rows(out, "own court")) == 2


@pytest.mark.parametrize(
    "argv, said",
    [
        (["--angle", "0"], "--angle must be in (0, 90) deg above the court, got 0"),
        (["--angle", "95"], "--angle must be in (0, 90) deg above the court, got 95"),
        (["--angle", "-16"], "(the angle is above the court, positive: --angle 16?)"),
        (["--angle", "nan"], "--angle must be a finite number"),
        (["--friction", "3", "--cor", "0.8"], "--friction must be in [0, 2], got 3"),
        (["--friction", "53", "--cor", "0.8"], "percent typed as a fraction? 53 % would be 0.53"),
        (["--friction", "0.5", "--cor", "1.5"], "--cor must be in [0.05, 1], got 1.5"),
        (["--friction", "0.5"], "--friction needs --cor"),
        (["--cor", "0.8"], "--cor needs --friction"),
        (["carpet"], "unknown court 'carpet'; the courts: grass, clay, hard"),
        (["clay", "clay"], "court 'clay' is named twice"),
        (["--speed", "100"], "--speed must be in [0.001, 80] m/s, got 100 (mph typed as m/s?"),
        (["--speed-mph", "0"], "--speed-mph must be in"),
        (["--speed", "0.002", "--angle", "10"], "the ball must come down on the court at"),
        (["--topspin", "20000"], "--topspin must be in [-9549, 9549] rpm"),
        (["--angle", "10", "--angle", "12"], "--angle given twice"),
        (["--out", "c.xlsx"], "--out must be a table file ending in"),
        (["--out", "nodir/c.csv"], "--out: directory 'nodir'"),
        (["--ball", "nosuchball"], "nosuchball"),
    ],
)
def test_bad_input_is_one_line_naming_the_option_exit_2_nothing_written(argv, said, workdir):
    output = [] if "--out" in argv else ["--out", "t.csv"]  # would be written
    assert said in refusal(["court", *argv, *output], folder=workdir)


def test_the_help_names_the_courts_and_the_units():
    said = help_text("court")
    for words in (*COURTS, "[deg]", "[rpm]", "[mph]", "--speed-kmh", "--friction", "--cor"):
        assert words in said, words


def test_the_python_api_refuses_bad_courts_in_one_line():
    from studies.strokes.court import court_table

    with pytest.raises(ValueError, match="unknown court 'carpet'"):
        court_table(["carpet"])
    with pytest.raises(ValueError, match="one court or more"):
        court_table([])
    with pytest.raises(TypeError, match=r"courts\[0\]"):
        court_table([0.5])
    with pytest.raises(ValueError, match="must come down at"):
        court_table(["clay"], 0.002, math.radians(10))
    assert list(court_table(["clay"], unit="km/h")["ball_speed_kmh"]) == [
        pytest.approx(CPR_SPEED / KMH)
    ]
