"""The racket-impact command line: every subcommand, output files, and bad input."""

import json
import subprocess
import sys

import pandas as pd
import pytest

from studies.cli import main

EXAMPLES = __import__("pathlib").Path(__file__).parent.parent / "examples"


def run(capsys, *args):
    status = main(list(args))
    out, err = capsys.readouterr()
    return status, out, err


def test_paper_writes_table_json_and_figures(tmp_path, capsys):
    status, out, _ = run(
        capsys, "paper", "--out", str(tmp_path / "figs"), "--json", str(tmp_path / "paper.json")
    )
    assert status == 0
    assert "claims reproduced within tolerance" in out
    rows = json.loads((tmp_path / "paper.json").read_text())
    assert set(rows[0]) == {"claim", "paper", "simulated", "tolerance", "ok"}
    assert all(r["ok"] for r in rows)
    pngs = sorted(p.name for p in (tmp_path / "figs").glob("*.png"))
    assert "cor_along_racket.png" in pngs and "fig3_soft_happy_ball.png" in pngs
    assert all((tmp_path / "figs" / p).stat().st_size > 10_000 for p in pngs)


@pytest.mark.parametrize("suffix", [".csv", ".json", ".parquet"])
def test_sweep_outputs(tmp_path, capsys, suffix):
    path = tmp_path / f"sweep{suffix}"
    status, out, _ = run(
        capsys, "sweep", "--points", "7", "--speed", "10", "20", "--out", str(path)
    )
    assert status == 0 and "largest e" in out
    table = {".csv": pd.read_csv, ".json": pd.read_json, ".parquet": pd.read_parquet}[suffix](path)
    assert len(table) == 14
    assert {"position_from_tip_m", "e", "e_A", "speed_m_s", "e_van_zandt"} <= set(table.columns)
    assert table["e"].between(0, 1).all()


def test_sweep_toml_racket_mph_and_plot(tmp_path, capsys):
    status, _out, _ = run(capsys, "sweep", "--racket", str(EXAMPLES / "stiff_racket.toml"),
                          "--ball", str(EXAMPLES / "hertz_ball.toml"), "--speed-mph", "45",
                          "--points", "5", "--csv", str(tmp_path / "s.csv"),
                          "--plot", str(tmp_path / "e.svg"))  # fmt: skip
    assert status == 0
    assert (tmp_path / "e.svg").read_text().startswith("<?xml")
    assert len(pd.read_csv(tmp_path / "s.csv")) == 5


def test_serve_one_swing_tip_ward_is_faster_in_the_unit_typed(tmp_path, capsys):
    """The same swing (racket-head speed 100 mph at the string centre, pivot at the wrist):
    5 cm towards the tip the point moves faster and the ball leaves faster; mph in, mph out,
    the positions echoed; no zero-COR row unless --what-if."""
    out_file = str(tmp_path / "serve.json")
    status, out, _ = run(
        capsys, "serve", "--racket", "pure-drive-2021", "--racket-speed-mph", "100",
        "--position", "17.32", "12.32", "--out", out_file,
    )  # fmt: skip
    assert status == 0 and "at 100 mph head speed" in out and "zero-COR" not in out
    assert "17.32" in out and "12.32" in out  # cm from the tip, as typed
    assert "(simulated)" in out and "[mph]" in out and "[m/s]" not in out and "the tip" in out
    assert "about the wrist (5 cm beyond the butt)" in out  # the pivot, said
    centre, tipward = json.loads((tmp_path / "serve.json").read_text())
    assert tipward["point_speed_mph"] > centre["point_speed_mph"]
    assert tipward["serve_simulated_mph"] > centre["serve_simulated_mph"]
    status, out, _ = run(capsys, "serve", "--what-if")
    assert status == 0 and "zero-COR" in out


def test_serve_what_if_plot(tmp_path, capsys):
    status, _, _ = run(capsys, "serve", "--what-if", "--plot", str(tmp_path / "w.pdf"))
    assert status == 0
    assert (tmp_path / "w.pdf").read_bytes()[:4] == b"%PDF"


def test_collide(tmp_path, capsys):
    status, out, _ = run(
        capsys, "collide", "--history", str(tmp_path / "h.csv"), "--plot", str(tmp_path / "c.png")
    )
    assert status == 0
    values = dict(line.rsplit(None, 1) for line in out.strip().splitlines())
    assert float(values["happy's velocity after [m/s]"]) == pytest.approx(3.034, abs=0.002)
    assert float(values["e [-]"]) == pytest.approx(0.517, abs=0.002)
    assert {"t_s", "force_N"} <= set(pd.read_csv(tmp_path / "h.csv").columns)


def test_collide_with_wall(capsys):
    status, out, _ = run(capsys, "collide", "--a", "paper", "--b", "wall", "--va", "20")
    assert status == 0 and "e [-]                              0.75" in out
    assert "wall's velocity after [m/s]" in out


def test_modes(tmp_path, capsys):
    status, out, _ = run(
        capsys, "modes", "--racket", "paper", "--count", "3", "--out", str(tmp_path / "m.csv")
    )
    assert status == 0
    assert "swingweight       326.9 kg cm^2" in out
    modes = pd.read_csv(tmp_path / "m.csv")
    assert modes["frequency_Hz"].round(1).tolist() == [120.0, 330.8, 648.5]


def test_specs_of_a_catalogue_racket(capsys):
    status, out, _ = run(capsys, "specs", "--racket", "pure-drive-2021")
    assert status == 0
    assert "f1 from RA 66: 150 +/- 6 Hz (TWU regression, 622 rackets)" in out  # its sheet's RA
    assert "tennisaddict.fr" in out  # the sources are printed
    assert "fitted parts and their plausible ranges" in out and "butt cap" in out
    assert "sources of the parts' ranges:" in out and "racket_specs_sample.csv" in out
    modes = out[out.index("modes: free-free") : out.index("sweet spots")]
    assert "rocking" in modes and "held" in modes and "[Hz]" in modes  # the held modes' column
    assert "flex-test tip stiffness" in out


def test_specs_of_the_example_sheet_with_lead_tape(tmp_path, capsys):
    status, out, _ = run(capsys, "specs", "--racket", str(EXAMPLES / "my_racket_specs.toml"),
                         "--out", str(tmp_path / "m_eff.csv"),
                         "--plot", str(tmp_path / "modes.png"))  # fmt: skip
    assert status == 0
    assert "added point masses" in out
    table = pd.read_csv(tmp_path / "m_eff.csv")
    assert list(table.columns) == [
        "position_from_tip_m",
        "position_from_tip_cm",
        "effective_mass_kg",
    ]
    assert table["effective_mass_kg"].is_monotonic_increasing  # light tip, heavy throat
    assert (tmp_path / "modes.png").stat().st_size > 10_000


def test_compare_two_rackets(tmp_path, capsys):
    status, out, _ = run(
        capsys,
        "compare",
        "--racket",
        "paper",
        "--racket",
        str(EXAMPLES / "my_racket_specs.toml"),
        "--points",
        "11",
        "--support",
        "hand-held",
        "--out",
        str(tmp_path / "cmp.csv"),
        "--long",
        "--plot",
        str(tmp_path / "cmp.png"),
    )
    assert status == 0
    assert "my_racket_specs" in out and "largest e [-]" in out
    table = pd.read_csv(tmp_path / "cmp.csv")
    assert table["racket"].unique().tolist() == ["paper", "my_racket_specs"]
    assert len(table) == 22
    assert (tmp_path / "cmp.png").stat().st_size > 10_000


def test_sweep_spec_racket_free_and_hand_held(capsys):
    status, out, _ = run(
        capsys,
        "sweep",
        "--racket",
        str(EXAMPLES / "my_racket_specs.toml"),
        "--support",
        "free",
        "hand-held",
        "--points",
        "3",
    )
    assert status == 0
    assert "hand-held" in out


def test_installed_script_exits_2_without_traceback(tmp_path):
    proc = subprocess.run(
        [sys.executable, "-m", "studies.cli", "sweep", "--from", "200"],
        capture_output=True,
        text=True,
        cwd=tmp_path,
    )
    assert proc.returncode == 2
    assert proc.stderr.count("\n") == 1 and "Traceback" not in proc.stderr


def test_ball_prints_and_writes_the_rigid_bounce_against_speed(tmp_path, capsys):
    toml = tmp_path / "ball.toml"
    toml.write_text(
        '[ball]\nmass = 0.057\nlaw = "growing-hysteresis"\nk = 1e6\na = 1.4\ne0 = 0.82\n'
        "slope = 8.0\n"
    )
    status, out, _ = run(
        capsys,
        "ball",
        str(toml),
        "--speeds",
        "7",
        "30",
        "--out",
        str(tmp_path / "b.csv"),
        "--plot",
        str(tmp_path / "b.png"),
    )
    assert status == 0 and "contact" in out and "time [s]" in out
    table = pd.read_csv(tmp_path / "b.csv")
    assert list(table["speed_m_s"]) == [7.0, 30.0]
    assert table["e"].iloc[1] < table["e"].iloc[0]  # this ball's COR falls with speed
    assert (tmp_path / "b.png").stat().st_size > 0
    status, out, _ = run(capsys, "ball", "--speeds-mph", "20")
    assert status == 0 and "[mph]" in out and "[m/s]" not in out  # mph in, mph out
    assert "0.7309" in out  # the ITF type 2 ball's e at 20 mph (8.941 m/s)
