"""One truth: the command line and the Python API, as the guides show it, give the same
number for one serve, one sweep point and one face-map point; every command defaults to the
same racket, ball and speed; positions are given from the tip everywhere; every output
names its conditions (the page's side: tests/test_page_truth.py)."""

import json

import numpy as np
import pandas as pd
import pytest

from ball.catalog import DEFAULT_BALL, TWU_SPEED
from common.units import MPH
from racket import DEFAULT_RACKET, default_ball, default_racket
from studies.cli import build_parser, main


def run(capsys, *args):
    status = main(list(args))
    out, err = capsys.readouterr()
    return status, out, err


def test_one_serve_the_same_from_the_command_line_and_python(tmp_path, capsys):
    from studies.serve import serve_table

    out = tmp_path / "serve.json"
    status, _, _ = run(capsys, "serve", "--racket-speed-mph", "100", "--position", "12.32",
                       "--out", str(out))  # fmt: skip
    assert status == 0
    cli = json.loads(out.read_text())[0]["serve_simulated_mph"]
    api = serve_table(default_racket(), default_ball(), 0.1232, 100 * MPH, zero_cor=False)
    assert cli == pytest.approx(
        float(api["serve_simulated_mph"].iloc[0]), rel=1e-8
    )  # (BLAS threads: round-off)


def test_one_sweep_point_the_same_from_the_command_line_and_python(tmp_path, capsys):
    from studies.sweeps import sweep

    out = tmp_path / "sweep.json"
    status, _, _ = run(capsys, "sweep", "--from", "10", "--to", "20", "--points", "2",
                       "--out", str(out))  # fmt: skip
    assert status == 0
    cli = pd.read_json(out)
    api = sweep(default_racket(), default_ball(), np.array([0.10, 0.20]), TWU_SPEED)
    assert cli["e"].to_numpy() == pytest.approx(
        api["e"].to_numpy(), rel=1e-8
    )  # (BLAS threads: round-off)
    assert cli["position_from_tip_cm"].to_numpy() == pytest.approx([10.0, 20.0])


def test_one_face_map_point_the_same_from_the_command_line_and_python(tmp_path, capsys):
    from studies.face.maps import face_map

    out = tmp_path / "map.json"
    status, _, _ = run(capsys, "map", "--grid", "5", "4", "--out", str(out))
    assert status == 0
    cli = pd.read_json(out)
    api = face_map(default_racket(), default_ball(), TWU_SPEED, grid=(5, 4)).to_frame()
    assert cli["e_A"].to_numpy() == pytest.approx(
        api["e_A"].to_numpy(), rel=1e-8
    )  # (BLAS threads: round-off)


RACKET_COMMANDS = ("sweep", "map", "serve", "feel", "modes", "specs", "sweetspots", "drop")


@pytest.mark.parametrize("command", RACKET_COMMANDS)
def test_every_command_defaults_to_the_one_racket_and_ball(command):
    args = build_parser().parse_args([command])
    assert args.racket == DEFAULT_RACKET
    if hasattr(args, "ball"):
        assert args.ball == DEFAULT_BALL
    if hasattr(args, "speed") and command != "sweep":
        assert args.speed == TWU_SPEED


@pytest.mark.parametrize("command", [c for c in RACKET_COMMANDS if c != "drop"] + ["compare"])
def test_every_racket_option_on_every_command_that_takes_a_racket(command):
    words = ["--tension-lb", "55", "--lead", "3@12", "2@3/9"]
    if command not in ("serve",):  # a serve swings a free racket: no hand
        words += ["--support", "hand-held", "--grip", "tight"]
    args = build_parser().parse_args([command, *words])
    assert args.lead == ["3@12", "2@3/9"]


def test_lead_tape_from_the_command_line_moves_mass_where_typed(capsys):
    status, out, _ = run(capsys, "modes", "--lead", "5@12")
    assert status == 0 and "lead 5@12" in out
    bare = default_racket()
    taped = bare.with_lead_tape(0.005, "12")
    assert f"{1e3 * taped.beam.mass:.1f}"[:3] == "326"  # 321 g + 5 g at the tip
    assert f"mass              {taped.beam.mass:.4f} kg" in out


def test_a_grip_on_a_free_racket_is_refused_in_one_line(capsys):
    status, _, err = run(capsys, "sweep", "--grip", "tight")
    assert status == 2 and "--support hand-held" in err and len(err.strip().splitlines()) == 1


def test_the_version(capsys):
    with pytest.raises(SystemExit) as stop:
        main(["--version"])
    assert stop.value.code == 0
    assert capsys.readouterr().out.startswith("racket-impact ")


@pytest.mark.parametrize(
    "words",
    [
        ["sweep", "--points", "5"],
        ["serve"],
        ["map", "--grid", "4", "4"],
        ["sweetspots"],
        ["modes"],
        ["compare", "--points", "5"],
    ],
)
def test_every_printed_table_has_a_header_naming_racket_ball_and_speed(words, capsys):
    status, out, _ = run(capsys, *words)
    assert status == 0
    first = out.splitlines()[0]
    assert first.startswith("racket ") and DEFAULT_RACKET in first
    if words[0] not in ("modes",):
        lines = out.splitlines()
        wrapped = next(i for i, line in enumerate(lines[1:], 1) if not line.startswith("  "))
        header = " ".join(line.strip() for line in lines[:wrapped])  # wrapped at WIDTH
        assert f"ball {DEFAULT_BALL}" in header


def test_the_sidecar_records_the_conditions(tmp_path, capsys):
    out = tmp_path / "s.csv"
    status, printed, _ = run(capsys, "sweep", "--points", "3", "--speed-mph", "40",
                             "--tension-lb", "58", "--out", str(out))  # fmt: skip
    assert status == 0
    sidecar = json.loads((tmp_path / "s.csv.meta.json").read_text())
    said = sidecar["conditions"]
    assert said in " ".join(printed.split("\n  "))
    for part in (DEFAULT_RACKET, DEFAULT_BALL, "40 mph", "58 lb", "free"):
        assert part in said


def test_km_h_in_km_h_out(capsys):
    status, out, _ = run(capsys, "serve", "--racket-speed-kmh", "150")
    assert status == 0 and "[km/h]" in out and "150 km/h" in out


def test_positions_are_from_the_tip_in_every_output_of_a_run(tmp_path, capsys):
    """No two outputs of the same run name a position in different conventions: the
    printed table, the closing line, the file and the plot's axis all count from the tip."""
    import matplotlib

    matplotlib.use("Agg")
    out, plot = tmp_path / "s.csv", tmp_path / "s.png"
    status, printed, _ = run(capsys, "sweep", "--points", "9", "--out", str(out),
                             "--plot", str(plot))  # fmt: skip
    assert status == 0
    assert "butt" not in printed and "from the tip" in printed
    assert not [c for c in pd.read_csv(out).columns if "butt" in c]


def test_a_cut_table_says_so_and_cuts_every_group_alike(capsys):
    status, out, _ = run(capsys, "sweep", "--points", "300", "--speed", "10", "20", "30")
    assert status == 0 and "rows shown" in out
    rows = [line.split() for line in out.splitlines() if line[:1] == " " and
            line.split()[0].replace(".", "").isdigit()]  # fmt: skip
    by_speed = {}
    for row in rows:
        by_speed.setdefault(row[-1], []).append(row[0])
    assert len(by_speed) == 3 and len({tuple(v) for v in by_speed.values()}) == 1
