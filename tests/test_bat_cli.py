"""``racket-impact bat sweep|bbcor|feel`` (issue 37): the default run's header names the bat,
the ball, the pitch and the swing, its lines fit 100 columns, its table and sidecar are written
together and give the same numbers as :func:`studies.bat.sweep.bat_sweep` (one truth, the same
defaults); the unit typed is the unit answered; the certification and the handle's motion;
every bad input refused in one line naming the option, status 2, nothing written; an option
that belongs to another question refused; a bat of one's own from TOML.  Each run is in this
process (the R161's modes are built once)."""

import json

import pandas as pd
import pytest
from clihelpers import help_text, refusal, run_main, run_ok, run_writing, sidecar

from ball import BASEBALL_PRESETS, DEFAULT_BASEBALL
from bat import DEFAULT_BAT
from bat import certification as cert
from common.units import MPH
from studies.bat.certification import BBCOR_UNCERTAINTY
from studies.bat.sweep import DEFAULT_SWING, PITCH_SPEED, _preset, bat_sweep
from studies.cli import build_parser
from studies.cli.show import WIDTH


@pytest.fixture(scope="module")
def default(tmp_path_factory):
    """``racket-impact bat --out t.json --plot p.png``: Nathan's high-speed case."""
    return run_writing(["bat"], tmp_path_factory.mktemp("bat"), "t.json", "p.png")


def test_the_command_defaults_to_the_one_bat_ball_pitch_and_swing():
    args = build_parser().parse_args(["bat"])
    assert args.action == "sweep" and args.bat == [DEFAULT_BAT] and args.ball == DEFAULT_BASEBALL
    assert args.pitch is None and args.omega is None  # the studies' own defaults, said in help
    text = help_text("bat")  # the help quotes the same constants
    for default in (f"default {PITCH_SPEED:g} m/s", f"default {DEFAULT_SWING.cm_speed:g} m/s",
                    f"default {DEFAULT_SWING.angular_velocity:g}"):  # fmt: skip
        assert default in text


def test_the_default_run_says_its_conditions_and_fits_the_width(default):
    out = default["out"]
    header = " ".join(line.strip() for line in out.splitlines()[:2])
    assert header.startswith(f"bat {DEFAULT_BAT} (R161 (wood)")
    assert f"ball {DEFAULT_BASEBALL} at 40 m/s" in header and "24 m/s" in header
    assert "51 rad/s" in header
    assert not [line for line in out.splitlines() if len(line) > WIDTH]
    assert "peak exit speed" in out and "sweet zone" in out and default["err"] == ""
    assert default["plot"].stat().st_size > 0


def test_the_table_and_its_sidecar_are_the_studys_numbers(default):
    rows = pd.DataFrame(json.loads(default["table"].read_text()))
    api = bat_sweep(_preset(DEFAULT_BAT), BASEBALL_PRESETS[DEFAULT_BASEBALL].ball())
    assert len(rows) == len(api.table) == 45
    assert rows["exit_speed_m_s"].to_numpy() == pytest.approx(
        api.table["exit_speed_m_s"].to_numpy(), rel=1e-9
    )
    total = rows["position_from_knob_cm"] + rows["position_from_tip_cm"]
    assert total.to_numpy() == pytest.approx(84.0)
    assert sidecar(default)["command"][0] == "bat"


def test_the_unit_typed_is_the_unit_answered(tmp_path):
    table = tmp_path / "mph.csv"
    out, _ = run_ok(["bat", "--pitch-mph", "90", "--cm-speed-mph", "54", "--points", "5",
                     "--out", str(table)])  # fmt: skip
    assert "90 mph" in out and "54 mph" in out and "[mph]" in out and "[m/s]" not in out
    rows = pd.read_csv(table)
    assert rows["exit_speed_mph"].to_numpy() == pytest.approx(rows["exit_speed_m_s"] / MPH)
    status, out, _ = run_main(["bat", "--pitch-kmh", "145", "--points", "3"])
    assert status == 0 and "145 km/h" in out and "[km/h]" in out


def test_bbcor_prints_and_writes_the_certification_numbers(tmp_path):
    table = tmp_path / "c.csv"
    out, _ = run_ok(["bat", "bbcor", "--pitch-mph", "136", "--out", str(table)])
    rows = pd.read_csv(table)
    assert list(rows["method"]) == ["pivoted rig", "free bat"]
    for column in ("bbcor", "collision_efficiency", "besr", "bpf", "passes", "test_speed_mph"):
        assert column in rows
    assert rows["test_speed_mph"].iloc[0] == pytest.approx(136.0)
    assert "BBCOR" in out and "136 mph" in out and "the limit 0.500" in out


def _said(out: str) -> str:
    """The printed lines unwrapped (a wrapped line's indent joined back)."""
    return " ".join(out.split("\n  "))


@pytest.fixture(scope="module")
def wood_and_alloy(tmp_path_factory):
    """``racket-impact bat bbcor --bat r161 alloy``: both bats near the limit."""
    return run_writing(["bat", "bbcor", "--bat", "r161", "alloy"],
                       tmp_path_factory.mktemp("bbcor"), "c.csv")  # fmt: skip


def test_a_bbcor_within_the_models_uncertainty_of_the_limit_is_not_called(wood_and_alloy):
    """The wooden R161 and the alloy land within BBCOR_UNCERTAINTY of the limit: each line
    says by how much and that the model cannot call it, as does the table's verdict."""
    rows = pd.read_csv(wood_and_alloy["table"]).set_index(["bat", "method"])
    said = _said(wood_and_alloy["out"])
    for bat in ("r161", "alloy"):
        rig = rows.loc[(bat, "pivoted rig")]
        margin = rig["bbcor"] - cert.BBCOR_LIMIT
        assert abs(margin) < BBCOR_UNCERTAINTY and rig["verdict"] == "cannot call"
        side = "above" if margin > 0 else "below"
        line = (f"{bat}: BBCOR {rig['bbcor']:.4f} at {rig['position_from_knob_cm']:.1f} cm from "
                f"the knob, {abs(margin):.4f} {side} the limit 0.500: within the model's "
                f"uncertainty of the limit (+/- {BBCOR_UNCERTAINTY:.2f}")  # fmt: skip
        assert line in said, said
    assert "passes the limit" not in said and "fails the limit" not in said


def test_the_hollow_bat_says_a_beam_has_no_trampoline_wall(wood_and_alloy, tmp_path):
    said = _said(wood_and_alloy["out"])
    assert "alloy: hollow, but a beam has no wall: the trampoline effect" in said
    assert "r161: hollow" not in said
    record = sidecar(wood_and_alloy)  # the sidecar's conditions are the header's
    assert "alloy: hollow, without its wall's trampoline effect (a beam)" in record["conditions"]
    out, _ = run_ok(["bat", "--bat", "alloy", "--points", "3"])
    assert "alloy: hollow, but a beam has no wall" in _said(out)
    out, _ = run_ok(["bat", "--points", "3"])
    assert "hollow" not in out


@pytest.mark.parametrize(("ball", "verdict"), [("baseball-low-speed", "fails"),
                                               ("softball-44-375", "passes")])  # fmt: skip
def test_a_verdict_far_from_the_limit_is_said_bare(ball, verdict, tmp_path):
    """A ball of e0 0.66 or 0.44 puts the R161's BBCOR far from the limit: the verdict is
    said plainly, without the uncertainty."""
    table = tmp_path / "c.csv"
    out, _ = run_ok(["bat", "bbcor", "--ball", ball, "--out", str(table)])
    rig = pd.read_csv(table).set_index("method").loc["pivoted rig"]
    assert abs(rig["bbcor"] - cert.BBCOR_LIMIT) > BBCOR_UNCERTAINTY
    assert rig["verdict"] == verdict
    said = _said(out)
    assert f"from the knob {verdict} the limit 0.500 (ball's own COR" in said
    assert "uncertainty" not in said and "hollow" not in said


def test_feel_says_what_the_bat_leaves_out(tmp_path):
    """Nathan's bat, free and undamped: one line says the bat's own damping and the hands'
    are left out, and the conditions (the sidecar's) say so too; a damped bat in the hands
    leaves nothing out, and no line is printed."""
    run = run_writing(["bat", "feel", "--duration-ms", "3"], tmp_path, "f.csv")
    said = _said(run["out"])
    assert "Left out: the bat's own damping and the hands': the ringing never dies away" in said
    assert "left out: the bat's own damping and the hands'" in sidecar(run)["conditions"]
    path = tmp_path / "damped.toml"
    path.write_text(BAT_TOML + "damping = 0.05\n")
    out, _ = run_ok(["bat", "feel", "--bat", str(path), "--support", "hand-held",
                     "--duration-ms", "3"])  # fmt: skip
    assert "left out" not in out.lower()


def test_feel_writes_the_handles_motion_at_the_points_asked(tmp_path):
    table = tmp_path / "f.csv"
    out, _ = run_ok(["bat", "feel", "--handle", "6", "13", "--duration-ms", "3", "--out",
                     str(table)])  # fmt: skip
    rows = pd.read_csv(table)
    assert sorted(set(rows["point_from_knob_cm"])) == [6.0, 13.0]
    assert rows["t_s"].max() == pytest.approx(3e-3, rel=0.01)
    assert "energy in each bending mode" in out and "impact 68.0 cm from the knob" in out


def test_nathans_pivoted_case_runs_from_the_command_line():
    out, _ = run_ok(["bat", "--support", "pivoted", "--pivot-from-knob", "15", "--clamps", "0",
                     "--omega", "56", "--from", "50", "--points", "3"])  # fmt: skip
    assert "pivoted 15 cm from the knob, a single pivot point" in out
    assert "turning at 56 rad/s about 15 cm from the knob" in out


@pytest.mark.parametrize(
    ("words", "says"),
    [
        (["--pitch", "400"], "--pitch must be in [0.001, 300] m/s, got 400 (mph typed as m/s?"),
        (["--omega", "487"], "rpm typed as rad/s? 487 rpm would be 51 rad/s"),
        (["--from", "0.5"], "--from 0.5 cm is on the knob: m typed as cm? 0.5 m would be 50 cm"),
        (["--to", "95"], "--to must be in [0, 84] cm from the knob, got 95"),
        (["--from", "5"], "--from 5 cm is not beyond the point the bat turns about"),
        (["--pivot-from-knob", "0.15"], "m typed as cm? 0.15 m would be 15 cm"),
        (["--support", "pivoted", "--clamps", "25.4"], "mm typed as cm? 25.4 mm would be 2.54"),
        (["--clamps", "1"], "--clamps does not apply to a free bat"),
        (["--support", "pivoted", "--cm-speed", "20"], "--cm-speed does not apply to a pivoted"),
        (["--support", "hand-held", "--omega", "50"], "--omega does not apply to a hand-held"),
        (["--omega", "0", "--cm-speed", "3"], "--cm-speed does not apply with --omega 0"),
        (["--at", "60"], "--at does not apply to bat sweep"),
        (["bbcor", "--omega", "40"], "--omega does not apply to bat bbcor"),
        (["feel", "--from", "50"], "--from does not apply to bat feel"),
        (["feel", "--bat", "r161", "alloy"], "bat feel follows one bat: give one --bat"),
        (["feel", "--at", "0.68"], "--at 0.68 cm is on the knob: m typed as cm?"),
        (["feel", "--duration-ms", "0.5"], "seconds typed as ms? 0.5 s would be 500 ms"),
        (["--bat", "nope"], "argument --bat: unknown bat preset 'nope'; presets: r161, alloy"),
        (["--bat", "r161", "r161"], "--bat 'r161' is given twice"),
        (["--ball", "nope"], "unknown ball preset 'nope'"),
    ],
)
def test_a_bad_input_is_refused_in_one_line_and_nothing_is_written(words, says, workdir):
    words = words if words[0] in ("bbcor", "feel") else ["sweep", *words]
    assert says in refusal(["bat", *words, "--out", "t.csv", "--plot", "p.png"], folder=workdir)


def test_an_option_twice_is_refused_by_the_parser():
    status, _, err = run_main(["bat", "--omega", "50", "--omega", "51"])
    assert status == 2 and "--omega given twice" in err


BAT_TOML = """[bat]
name = "my ash bat"
profile = [[0.0, 0.0505], [0.02, 0.0505], [0.03, 0.035], [0.12, 0.026], [0.45, 0.036],
           [0.60, 0.057], [0.70, 0.063], [0.84, 0.0643]]
density = 649.0
youngs_modulus = 1.814e10
shear_modulus = 1.05e9
"""


def test_a_bat_of_ones_own_from_toml_beside_a_preset(tmp_path):
    path = tmp_path / "ash.toml"
    path.write_text(BAT_TOML)
    table = tmp_path / "two.csv"
    out, _ = run_ok(["bat", "--bat", str(path), "r161", "--points", "3", "--out", str(table)])
    assert "bat ash (my ash bat" in out and "bat r161 (R161 (wood)" in out
    assert sorted(set(pd.read_csv(table)["bat"])) == ["ash", "r161"]


def test_a_bad_toml_bat_is_refused_with_its_unit_slip(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "mm.toml").write_text(BAT_TOML.replace("0.0643", "64.3"))
    status, _, err = run_main(["bat", "--bat", "mm.toml", "--out", "t.csv"])
    assert status == 2 and "mm typed as m? 64.3 mm would be 0.0643 m" in err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["mm.toml"]


def test_rerun_makes_the_same_table(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    assert run_main(["bat", "--points", "3", "--out", "t.csv"])[0] == 0
    first = (tmp_path / "t.csv").read_bytes()
    (tmp_path / "t.csv").unlink()
    assert run_main(["rerun", "t.csv.meta.json"])[0] == 0
    assert (tmp_path / "t.csv").read_bytes() == first
