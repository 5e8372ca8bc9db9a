"""Every failure a user can cause: one line naming the input, exit status 2, no traceback,
and nothing written (issue 9, part 4).  Each case runs in-process in an empty directory
holding only the bad files it needs; validation comes before any simulation, so the whole
file runs in seconds."""

import numpy as np
import pytest
from clihelpers import refusal

from ball import WALL, Ball, LinearHysteresis, PowerLawHysteresis, collide
from beam import Beam
from racket import Hand, impact, paper_ball, paper_racket
from studies.cli import main

NUMERIC_FLAGS = {
    "sweep": ["--speed", "--speed-mph", "--speed-kmh", "--string-stiffness", "--f1", "--ra"],
    "compare": ["--speed", "--speed-mph", "--speed-kmh"],
    "serve": ["--racket-speed", "--racket-speed-mph", "--racket-speed-kmh"],
}
POINTS = ["--points", "3"]

CASES = []
for cmd, flags in NUMERIC_FLAGS.items():
    for flag in flags:
        for value in ("0", "-3", "nan", "inf", "1e300"):
            extra = POINTS if cmd != "serve" else []
            CASES.append(([cmd, flag, value, *extra], flag))
for cmd in ("sweep", "compare"):
    for value in ("0", "1", "-3", "1e300", "2.5"):
        CASES.append(([cmd, "--points", value], "--points"))
for flag in ("--from", "--to"):
    for value in ("-3", "nan", "inf", "1e300", "0.5"):
        CASES.append((["sweep", flag, value, *POINTS], flag))
for value in ("-3", "nan", "inf", "1e300"):
    CASES.append((["serve", "--position", value], "--position"))
for value in ("-3", "300", "nan", "inf", "1e300"):
    CASES.append((["serve", "--pivot-cm-from-tip", value], "--pivot-cm-from-tip"))
for flag in ("--target-ball-speed-mph", "--target-ball-speed-kmh"):
    for value in ("0", "-3", "nan", "1e300"):
        CASES.append((["serve", flag, value], flag))
CASES.append((["serve", "--target-ball-speed", "0.05"], "target ball speed must be in"))
for flag in ("--va", "--va-mph", "--va-kmh"):
    for value in ("0", "-3", "nan", "inf", "1e300"):
        CASES.append(
            (["collide", flag, value], flag if value in ("nan", "inf", "1e300") else "--va")
        )
for flag, equal in (("--vb", "4"), ("--vb-mph", "9"), ("--vb-kmh", "14.4")):  # --va 4 m/s
    for value in ("nan", "inf", "1e300", equal):
        CASES.append((["collide", flag, value], flag if value != equal else "--va must exceed"))
for cmd in (["modes"], ["specs", "--racket", "paper"]):
    for value in ("0", "-2", "nan", "1e300", "201"):
        CASES.append(([*cmd, "--count", value], "--count"))

# Bad TOML files of every kind (written by the fixture under these names).
TOML = {
    "not_toml": ("[racket\nmass = ", "is not valid TOML"),
    "not_utf8": (b"[racket]\nmass = 0.3 # \xff\xfe\n", "not_utf8.toml is not valid TOML"),
    "no_table": ("[something]\nx = 1\n", "has no [racket] table"),
    "racket_number": ("racket = 5\n", "[racket] must be a table"),
    "unknown_key": ("[racket]\n[racket.strings]\nstifness = 4e4\n", "unknown key 'stifness'"),
    "negative_mass": ("[racket]\nmass = -0.3\n", "mass must be > 0"),
    "string_mass": ('[racket]\nmass = "heavy"\n', "mass must be a finite number"),
    "lead_number": ("[racket]\nlead_tape = 5\n", "lead_tape in [racket] must be an array"),
    "lead_entry": ("[racket]\nlead_tape = [5]\n", "[racket.lead_tape] must be a table"),
    "lead_far": (
        "[racket]\nlead_tape = [{mass_g = 3, from_tip_cm = 100}]\n",
        "lead_tape from_tip_cm must be in [0, 68.58] cm, got 100",  # pure-drive-2021
    ),
    "lead_negative": (
        "[racket]\nlead_tape = [{mass_g = -3, from_tip_cm = 30}]\n",
        "lead_tape mass_g must be in [0, 200] g, got -3",
    ),
    "lead_key": ("[racket]\nlead_tape = [{grams = 3}]\n", "unknown key 'grams'"),
    "lead_one_side": (
        '[racket]\nlead_tape = [{mass_g = 3, at = "3"}]\n',
        "one side only; give both sides, '3 and 9'",
    ),
    "lead_both_places": (
        '[racket]\nlead_tape = [{mass_g = 3, at = "12", from_tip_cm = 60}]\n',
        "needs mass_g and one of from_tip_cm or at",
    ),
    "hand_key": ("[racket.hand]\ngrip_force = 0.1\n", "unknown key 'grip_force' in [racket.hand]"),
    "hand_grip": ("[racket.hand]\ngrip = 0.1\n", "unknown grip 0.1; grips: light, medium, tight"),
    "hand_negative": ("[racket.hand]\nstiffness = -1\n", "hand stiffness must be > 0"),
    "support": ('[racket]\nsupport = "glued"\n', "support must be one of"),
    "extent_number": ("[racket.strings]\nextent = 5\n", "racket"),
    "strings_text": ('[racket.strings]\nstiffness = "stiff"\n', "stiffness must be a finite"),
    "modes_300": ("[racket]\nn_modes = 300\n", "n_modes must be in [1, 200], got 300"),
    "modes_half": ("[racket]\nn_modes = 2.5\n", "n_modes must be a whole number"),
    "profile_ratio": (
        "[racket]\nstations = [0, 0.3, 0.68]\nmass_per_length = [0.5, 0.5]\n"
        "bending_stiffness = [1.0, 1e14]\n",
        "bending_stiffness must vary by at most 10000 times",
    ),
    "specs_no_mass": (
        "[racket.specs]\nbalance_cm = 33\nswingweight_kgcm2 = 320\nf1_hz = 150\n"
        "head_size_in2 = 100\ntension_lb = 55\n",
        "the spec sheet needs mass_kg",
    ),
    "specs_grams": (
        "[racket.specs]\nmass_kg = 318\nbalance_cm = 33\nswingweight_kgcm2 = 320\n"
        "f1_hz = 150\nhead_size_in2 = 100\ntension_lb = 55\n",
        "mass_kg must be in [0.15, 0.5] kg, got 318 (grams typed as kg?",
    ),
    "specs_cm": (
        "[racket.specs]\nlength_m = 68.58\nmass_kg = 0.318\nbalance_cm = 33\n"
        "swingweight_kgcm2 = 320\nf1_hz = 150\nhead_size_in2 = 100\ntension_lb = 55\n",
        "length_m must be in [0.52, 0.75] m, got 68.58 (cm typed as m?",
    ),
    "specs_points": (
        "[racket.specs]\nmass_kg = 0.318\nbalance_pts_hl = 400\nswingweight_kgcm2 = 320\n"
        "f1_hz = 150\nhead_size_in2 = 100\ntension_lb = 55\n",
        "balance_pts_hl must be in [-24, 24] pts head-light, got 400",
    ),
    "specs_key": (
        "[racket.specs]\nbalance = 33\nmass_kg = 0.32\nswingweight_kgcm2 = 320\n",
        "unknown key 'balance' in [racket.specs]",
    ),
    "specs_ra": (
        "[racket.specs]\nmass_kg = 0.32\nbalance_cm = 33\nra = 95\nswingweight_kgcm2 = 320\n"
        "head_size_in2 = 100\ntension_lb = 55\n",
        "ra must be in [40, 90], got 95",
    ),
    "specs_ra_and_f1": (
        "[racket.specs]\nmass_kg = 0.32\nbalance_cm = 33\nra = 66\nf1_hz = 150\n"
        "swingweight_kgcm2 = 320\nhead_size_in2 = 100\ntension_lb = 55\n",
        "give exactly one frame stiffness: f1_hz or ra or flex_deflection_mm (got f1_hz, ra)",
    ),
    "specs_sw": (
        "[racket.specs]\nmass_kg = 0.32\nbalance_cm = 33\nswingweight_kgcm2 = 420\n"
        "f1_hz = 150\nhead_size_in2 = 100\ntension_lb = 55\n",
        "swingweight_kgcm2 must be in (",
    ),
    "soft_frame": ("[racket]\nf1 = 5\n", "[racket] f1 must be in [20, 2000] Hz, got 5"),
}
BALL_TOML = {
    "ball_number": ("ball = 5\n", "[ball] must be a table"),
    "ball_string": ('ball = "tennis"\n', "[ball] must be a table"),
    "preset_list": ('[ball]\npreset = ["tennis"]\n', "unknown ball preset ['tennis']"),
    "law_unknown": ('[ball]\nmass = 0.05\nlaw = "rubber"\nk = 1e4\n', "unknown law 'rubber'"),
    "law_number": ("[ball]\nmass = 0.05\nlaw = 5\nk = 1e4\n", "unknown law 5"),
    "law_params": ('[ball]\nmass = 0.05\nlaw = "sine"\nk = 1e4\n', "law 'sine' takes k0"),
    "power_e": (
        '[ball]\nmass = 0.057\nlaw = "power-law"\nk = 1e6\na = 1.5\ne = 1e-9\n',
        "e must be in [0.05, 1], got 1e-09",
    ),
    "power_tiny": (
        '[ball]\nmass = 0.057\nlaw = "power-law"\nk = 1e5\na = 1e-3\nb = 1e-3\n',
        "a must be in [0.5, 5], got 0.001",
    ),
    "ball_cor": (
        '[ball]\nmass = 0.05\nlaw = "linear-hysteresis"\nk = 1e4\ne = 1.2\n',
        "e must be in [0, 1]",
    ),
    "soft_ball": ('[ball]\nmass = 0.057\nlaw = "linear-spring"\nk = 1000\n', "too soft"),
}
for name, (_, message) in TOML.items():
    CASES.append((["sweep", "--racket", f"{name}.toml", *POINTS], message))
for name, (_, message) in BALL_TOML.items():
    command = ["sweep", *POINTS] if name == "soft_ball" else ["collide", "--b", "wall"]
    flag = "--ball" if name == "soft_ball" else "--a"
    CASES.append(([*command, flag, f"{name}.toml"], message))
CASES += [
    (["sweep", "--racket", "missing.toml"], "cannot read missing.toml"),
    (["sweep", "--racket", "wooden"], "unknown racket preset 'wooden'"),
    (["sweep", "--ball", "golf"], "unknown ball preset 'golf'"),
    (["collide", "--a", "wall"], "unknown ball preset 'wall'"),
    (["sweep", "--support", "glued"], "invalid choice: 'glued'"),
    (["sweep", "--speed"], "expected at least one argument"),
    (["sweep", "--f1", "150", "--ra", "66", *POINTS], "--ra: not allowed with argument --f1"),
    (["paper", "--bogus"], "unrecognized arguments"),
    # Outputs: checked before any work, nothing written.
    (["sweep", "--out", "t.xlsx", *POINTS], "--out must be a table file ending in"),
    (["sweep", "--plot", "x.jpg", *POINTS], "--plot must be a plot file ending in"),
    (["sweep", "--csv", "t.json", *POINTS], "--csv must be a file ending in .csv"),
    (["sweep", "--csv", "ok.csv", "--json", "nodir/x.json", *POINTS], "--json: directory 'nodir'"),
    (["sweep", "--csv", "same.csv", "--out", "same.csv", *POINTS], "name the same file"),
    (["serve", "--plot", "s.png"], "--plot needs --what-if"),
    (["serve", "--what-if", "--plot", "s.gif"], "--plot must be a plot file"),
    (["collide", "--out", "s.csv", "--history", "s.csv"], "--history and --out name the same file"),
    (["collide", "--plot", "nodir/c.png"], "--plot: directory 'nodir'"),
    (["paper", "--out", ""], "--out must name a directory"),
    (["paper", "--out", "file.txt"], "--out must be a directory"),
    (["paper", "--json", "rows.csv"], "--json must be a file ending in .json"),
    (["modes", "--count", "-2", "--out", "m.csv"], "--count"),
    (["specs", "--racket", "paper", "--out", "nodir/x.csv"], "--out: directory 'nodir'"),
    (["compare", "--plot", "c.txt"], "--plot must be a plot file"),
    # Options given twice, or rackets that would collide under one label.
    (["sweep", "--racket", "paper", "--racket", "pure-drive-2021"], "--racket given twice"),
    (["serve", "--position", "0.1", "--position", "0.2"], "--position given twice"),
    (["collide", "--a", "happy", "--a", "unhappy"], "--a given twice"),
    (["sweep", "--speed", "10", "--speed", "20"], "--speed given twice"),
    (["compare", "--racket", "paper", "--racket", "paper"], "--racket 'paper' is given twice"),
    (["compare", "--racket", "paper"], "compare needs two or more --racket"),
]


@pytest.fixture
def workdir(workdir):
    """The working directory holding the bad files."""
    for name, (text, _) in {**TOML, **BALL_TOML}.items():
        path = workdir / f"{name}.toml"
        path.write_bytes(text if isinstance(text, bytes) else text.encode())
    (workdir / "file.txt").write_text("not a directory\n")
    return workdir


def test_there_are_at_least_a_hundred_cases():
    assert len(CASES) >= 100


@pytest.mark.parametrize("argv, names", CASES, ids=[" ".join(a) for a, _ in CASES])
def test_bad_input_one_line_exit_2_nothing_written(argv, names, workdir):
    assert names in refusal(argv, quiet=False, folder=workdir)  # (a header may come before)


def test_same_file_name_in_two_directories_gives_two_rackets(workdir, capsys):
    for folder, f1 in (("a", 120), ("b", 180)):
        (workdir / folder).mkdir()
        (workdir / folder / "racket.toml").write_text(f"[racket]\nf1 = {f1}\n")
    status = main(["compare", "--racket", "a/racket.toml", "--racket", "b/racket.toml", *POINTS])
    out = capsys.readouterr().out
    assert status == 0
    assert "a/racket.toml" in out and "b/racket.toml" in out
    status = main(["compare", "--racket", "soft=a/racket.toml", "--racket", "stiff=b/racket.toml"])
    out = capsys.readouterr().out
    assert status == 0 and "soft" in out and "stiff" in out


def test_internal_errors_say_so_and_debug_shows_the_traceback(workdir, capsys, monkeypatch):
    import studies.sweeps

    def broken(*args, **kwargs):
        raise KeyError("a bug")

    monkeypatch.setattr(studies.sweeps, "sweep_columns", broken)  # the command line's sweep
    assert main(["sweep", *POINTS]) == 1
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "internal error (KeyError" in err and "--debug" in err
    with pytest.raises(KeyError):
        main(["sweep", "--debug", *POINTS])


def test_a_squashed_ball_warns_in_one_line(workdir, capsys):
    assert main(["collide", "--a", "paper", "--b", "wall", "--va-mph", "100"]) == 0
    err = capsys.readouterr().err
    assert err.count("\n") == 1
    assert "warning: the ball is compressed by 53.4 mm, more than its radius (33.5 mm)" in err


API_CASES = [
    (lambda: impact(paper_racket(), paper_ball(), [], 10.0), "position must give at least one"),
    (lambda: impact(paper_racket(), paper_ball(), [[0.1, 0.2]], 10.0), "flat sequence"),
    (lambda: impact(paper_racket(), paper_ball(), [0.1, None], 10.0), "got None"),
    (lambda: impact(paper_racket(), paper_ball(), np.float64(0.325), 10.0), "got 0.325"),
    (lambda: impact(paper_racket(), paper_ball(), 0.1, 1e300), "speed must be in"),
    (lambda: impact(paper_racket(), paper_ball(), 0.1, 5e-324), "speed must be in"),
    (lambda: impact(paper_racket(), paper_ball(), 0.1, 10.0, steps_per_contact=10), "steps_per"),
    (lambda: impact(paper_racket(), paper_ball(), 0.1, 10.0, watch_after=-1), "watch_after"),
    (lambda: impact(paper_racket(), paper_ball(), 0.1, 10.0, pivot=5.0), "pivot must lie"),
    (lambda: Beam.uniform(0.68, 0.34, 120.0, n_modes=300), "n_modes must be in [1, 200]"),
    (lambda: PowerLawHysteresis(1e5, 1e-3, 1e-3), "a must be in [0.5, 5]"),
    (lambda: PowerLawHysteresis.with_cor(1e5, 1.5, 1e-9), "e must be in [0.05"),
    (lambda: collide(paper_ball(), WALL, 1e200), "v_a must be in [-300, 300] m/s"),
    (lambda: Ball(-1.0, LinearHysteresis(4e4, 0.75)), "mass must be > 0 kg, got -1"),
    (lambda: Ball(0.057, LinearHysteresis(4e4, 0.75), radius=-1), "radius must be > 0"),
    (lambda: LinearHysteresis(4e4, 1.2), "e must be in [0, 1], got 1.2"),
    (lambda: Hand(stiffness=0.0), "hand stiffness must be > 0"),
]


@pytest.mark.parametrize("call, message", API_CASES, ids=[m for _, m in API_CASES])
def test_api_bad_input_names_the_argument(call, message):
    with pytest.raises(ValueError) as err:
        call()
    assert message in str(err.value)
    assert "np.float64" not in str(err.value)
