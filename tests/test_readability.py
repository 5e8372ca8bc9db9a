"""What the command line prints and draws reads as a coach or a stringer would (issue 28):
every table printed by default fits in 100 columns, with a unit (or [-]) on each numeric
header; every plot's axis labels carry a unit or say [-], its legends name no raw column
and sit off the data; re-contacts are said; the sweet spots lie on the strings."""

import re

import matplotlib
import numpy as np
import pandas as pd
import pytest

matplotlib.use("Agg")

from studies.cli import main
from studies.cli.show import WIDTH, label, table_lines
from studies.sweeps import COLUMNS

EXAMPLES = __import__("pathlib").Path(__file__).parent.parent / "examples"

DEFAULT_RUNS = [
    ["sweep"], ["map"], ["serve"], ["serve", "--what-if"], ["collide"], ["drop"], ["ball"],
    ["ball", "--list"], ["modes"], ["specs", "--racket", "pure-drive-2021"], ["feel"],
    ["sweetspots", "--racket", "pure-drive-2021"], ["compare"], ["validate"],
    ["sweep", "--racket", str(EXAMPLES / "profile_racket.toml")],
    ["serve", "--racket-speed-mph", "100", "110", "120"],
]  # fmt: skip


@pytest.mark.parametrize("argv", DEFAULT_RUNS, ids=" ".join)
def test_every_default_run_prints_at_most_100_columns(
    argv, capsys, monkeypatch, validation_once, bounce_once
):
    from studies.cli import show

    made = []  # every header a table printed: (column, numeric, label)

    def recording(column, numeric=True):
        made.append((column, numeric, label(column, numeric)))
        return made[-1][2]

    monkeypatch.setattr(show, "label", recording)
    assert main(argv) == 0
    out = capsys.readouterr().out
    bare = [(c, text) for c, numeric, text in made if numeric and not _UNIT.search(text)]
    assert not bare, bare  # a numeric header without a unit, not listed as dimensionless
    wide = [line for line in out.splitlines() if len(line) > WIDTH]
    assert not wide, wide
    assert "not shown" not in out  # the default tables fit whole


_UNIT = re.compile(r"\[[^\]]+\]")  # "[m/s]", "[-]"


def test_every_sweep_column_has_a_unit_or_says_it_is_dimensionless():
    numeric = [c for c in COLUMNS if c != "self_consistent"]
    for column in [*numeric, "speed_m_s", "tension_N", "f1_Hz", "string_stiffness_N_m",
                   "nodes_cm_from_tip", "serve_simulated_mph", "peak_compression_m"]:  # fmt: skip
        assert re.search(r"\[[^\]]+\]$", label(column)), column
    assert label("contact_time_s") == "contact time [s]"
    assert label("e") == "e [-]" and label("nodes_cm_from_tip") == "nodes from tip [cm]"
    assert label("mode") == "mode [-]" and label("damping_ratio") == "damping ratio [-]"
    assert label("stiffness") == "stiffness"  # neither a unit nor listed: no "[-]" made up


def test_a_printed_table_labels_its_headers_and_folds_per_row_units():
    table = pd.DataFrame({"position_from_tip_cm": [50.25], "e": [0.9123], "ball": ["x"]})
    header = " ".join(table_lines(table)[:-1])
    assert "[cm]" in header and "e [-]" in header and "ball [-]" not in header
    rows = pd.DataFrame({"quantity": ["mass", "balance"], "value": [321.0, 33.0],
                         "unit": ["g", "cm from the butt"]})  # fmt: skip
    text = "\n".join(table_lines(rows))
    assert "mass [g]" in text and "balance [cm] from the butt" in text
    assert "value [-]" not in text  # the rows carry their units


def test_compare_prints_racket_columns_and_writes_what_it_printed(tmp_path, capsys):
    out_file = tmp_path / "summary.csv"
    argv = ["compare", "--points", "11", "--tension-lb", "55", "48", "--out", str(out_file)]
    assert main(argv) == 0
    out = capsys.readouterr().out
    assert "pure-drive-2021 55 lb" in out and "pro-staff-97l-cv 55 lb" in out
    # not an "exit" of a racket at rest (the label's unit may fold under its row)
    assert re.search(r"^best rebound, racket at rest( \[m/s\]|\s.*\n\[m/s\])", out, re.M)
    assert "exit" not in out
    summary = pd.read_csv(out_file)
    assert len(summary) == 4 and "largest_rebound_at_rest_mph" in summary  # 2 rackets x 2
    assert main([*argv[:-2], "--out", str(tmp_path / "long.csv"), "--long"]) == 0
    assert len(pd.read_csv(tmp_path / "long.csv")) == 4 * 11


def test_mph_in_gives_mph_out(capsys):
    assert main(["sweep", "--speed-mph", "30", "40", "--points", "3"]) == 0
    out = capsys.readouterr().out
    assert "[mph]" in out and "[m/s]" not in out
    assert main(["map", "--speed-mph", "40", "--grid", "5", "4"]) == 0
    assert "ball at 40 mph" in capsys.readouterr().out
    assert main(["ball", "--speeds-mph", "20"]) == 0
    assert "[mph]" in capsys.readouterr().out
    assert main(["collide", "--va-mph", "30"]) == 0
    out = capsys.readouterr().out
    assert "velocity after [mph]" in out and "[m/s]" not in out
    assert main(["sweep", "--swing-speed", "30", "--points", "3"]) == 0
    out = capsys.readouterr().out
    assert "[m/s]" in out and "[mph]" not in out  # m/s in, m/s out: no exit speed in mph
    assert main(["sweep", "--swing-speed-mph", "60", "--points", "3"]) == 0
    out = capsys.readouterr().out
    assert "impact" in out and "[mph]" in out and "[m/s]" not in out


def test_sentences_give_each_number_its_unit(capsys):
    for argv in (["sweep", "--points", "3"], ["modes"], ["feel"],
                 ["map", "--grid", "5", "4"]):  # fmt: skip
        assert main(argv) == 0
        out = capsys.readouterr().out
        assert "cm from the tip" in out and not re.search(r"\d( m)? from the tip", out), out
    assert main(["drop"]) == 0
    said = re.search(
        r"^e (\S+) \(bounce/drop height = e\u00b2 = (\S+)\)$", capsys.readouterr().out, re.M
    )
    assert said and float(said[2]) == pytest.approx(float(said[1]) ** 2, abs=1e-3)


def test_recontacts_are_flagged_with_one_line_saying_what_they_are(capsys):
    assert main(["sweep", "--racket", str(EXAMPLES / "profile_racket.toml")]) == 0
    lines = capsys.readouterr().out.splitlines()
    out = "\n".join(lines)
    first_row = next(i for i, line in enumerate(lines) if re.match(r"^\s*-?\d", line))
    header = " ".join(lines[first_row - 3 : first_row])  # the table's header, under the
    assert "re-contacts" in header and "[-]" in header  # conditions and the rows-shown line
    assert "re-contacts: at" in out and "caught again by the vibrating frame" in out


def test_an_offset_sweep_is_clipped_to_the_elliptical_bed(capsys):
    assert main(["sweep", "--racket", "pure-drive-2021", "--offset", "2", "--points",
                 "5"]) == 0  # fmt: skip
    assert "the sweep is clipped to them" in capsys.readouterr().out
    assert main(["sweep", "--racket", "pure-drive-2021", "--offset", "8", "--from",
                 "1"]) == 2  # fmt: skip
    assert "narrow --from/--to" in capsys.readouterr().err


def test_the_sweet_spots_lie_on_the_strings_in_a_players_words(capsys):
    from racket import CATALOG, TENNIS_BALL_RADIUS
    from studies.face.landmarks import HAND_FROM_BUTT
    from studies.face.sweetspots import sweet_spots

    racket = CATALOG["pure-drive-2021"].racket()
    table = sweet_spots(racket, __import__("studies.config").config.load_ball("itf-type-2"))
    start, end = racket.strings.extent
    inside = table["from_tip_cm"] / 100
    assert (inside >= start + TENNIS_BALL_RADIUS - 1e-12).all()
    assert (inside <= end - TENNIS_BALL_RADIUS + 1e-12).all()
    assert main(["sweetspots", "--racket", "pure-drive-2021"]) == 0
    out = capsys.readouterr().out
    assert "node of the first mode (150 Hz)" in out
    hand = 100 * (racket.beam.length - HAND_FROM_BUTT)  # mid-grip, said from the tip
    assert f"centre of percussion (hand at {hand:.1f} cm)" in out
    assert "value" not in out[: out.index("node of the first mode")]  # the header


def test_feel_reports_the_modes_frequency_not_a_spectral_bin(capsys):
    from dataclasses import replace

    from racket import CATALOG
    from racket.feel import hand_feel
    from studies.config import load_ball

    racket = CATALOG["pure-drive-2021"].racket()
    free = replace(racket, support="free")
    feel = hand_feel(free, load_ball("itf-type-2"), free.strings.center, 16.5)
    hz, of_mode = feel.strongest()
    # the first mode's (damped: a few 1e-5 below the undamped), not a 20 Hz bin's 140 or 160
    assert of_mode and hz == pytest.approx(free.beam.modes.frequencies[0], rel=1e-4)
    assert main(["feel", "--support", "free"]) == 0
    assert f"strongest vibration       {hz:.1f} Hz" in capsys.readouterr().out


# ----- plots -------------------------------------------------------------------------------
PLOT_RUNS = [
    ["sweep", "--points", "9", "--speed-mph", "30", "40"],
    ["sweep", "--points", "21", "--racket", str(EXAMPLES / "profile_racket.toml")],
    ["map", "--grid", "5", "4"],
    ["serve", "--what-if"],
    ["collide", "--b", "wall"],
    ["drop"],
    ["ball", "happy", "--speeds", "5", "10"],
    ["ball"],
    ["modes"],
    ["specs", "--racket", "pure-drive-2021"],
    ["feel"],
    ["compare", "--points", "11"],
    ["validate"],
]
_RAW = re.compile(r"\b[a-z]+_[a-z]+(_[a-zA-Z0-9]+)*\b")  # a column's name: speed_m_s
_NUMBER = re.compile(r"(?<![\w.-])(?<!Eq\. )\d+(\.\d+)?(?![\w.-])")  # not V1, mode-1, Eq. 21
_SAID = re.compile(r"\d\s?(mph|m/s|lb|Hz|cm|mm|ms|kg|g|N/m|N|J|s|m|%)(?![\w/])")  # 30 mph


def _drawn(argv, tmp_path, monkeypatch):
    """The Axes a command would save with --plot."""
    made = []
    for module in ("sweep", "files", "serve", "balls", "validate"):
        monkeypatch.setattr(f"studies.cli.{module}.save_plot", lambda axes, path: made.append(axes))
    assert main([*argv, "--plot", str(tmp_path / "p.png")]) == 0
    assert len(made) == 1
    return np.atleast_1d(made[0])[0].figure


@pytest.mark.parametrize("argv", PLOT_RUNS, ids=" ".join)
def test_every_plot_labels_its_axes_with_units_and_keeps_its_legends_off_the_data(
    argv, tmp_path, monkeypatch, capsys, validation_once, bounce_once
):
    fig = _drawn(argv, tmp_path, monkeypatch)
    fig.canvas.draw()
    for ax in fig.axes:
        for text in (ax.get_xlabel(), ax.get_ylabel()):
            if text:
                assert re.search(r"\[[^\]]+\]", text), text  # a unit, or [-]
        legend = ax.get_legend()
        if legend is None:
            continue
        for entry in legend.get_texts():
            assert not _RAW.search(entry.get_text()), entry.get_text()
            if _NUMBER.search(entry.get_text()):  # a number: its unit, or [-], beside it
                assert _UNIT.search(entry.get_text()) or _SAID.search(entry.get_text()), (
                    entry.get_text()
                )
        box, area = legend.get_window_extent(), ax.get_window_extent()
        overlap_x = min(box.x1, area.x1) - max(box.x0, area.x0)
        overlap_y = min(box.y1, area.y1) - max(box.y0, area.y0)
        assert overlap_x <= 1 or overlap_y <= 1, (argv, [t.get_text() for t in legend.get_texts()])
    texts = [
        t.get_text() for ax in fig.axes if ax.get_legend() for t in ax.get_legend().get_texts()
    ]
    if argv[0] == "collide":
        assert "wall" in texts and not any("ball b" in t for t in texts)
    if argv[:2] == ["ball", "happy"]:
        assert not any("ITF" in t or "type 2" in t for t in texts)  # not a tennis ball
    if argv[0] == "ball" and len(argv) == 1:
        assert any("ITF" in t for t in texts)
        assert not fig.axes[1].yaxis.get_major_formatter().get_offset()  # no 1e-12+2.25
    if argv[0] == "sweep" and "--speed-mph" in argv:
        assert any("ball at 30 mph" in t for t in texts)
    if argv[0] == "sweep" and "profile_racket.toml" in argv[-1]:
        assert any(t.startswith("re-contact") for t in texts)
    import matplotlib.pyplot as plt

    plt.close(fig)


@pytest.mark.parametrize("depth", range(0, 40, 3))
def test_a_wrapped_conditions_line_never_starts_a_line_with_a_number(depth, tmp_path, capsys):
    """Wherever the racket's file lies, its path's length moves the conditions line's wrap:
    no wrapped line may start with a number (a reader takes it for the table's first row)."""
    folder = tmp_path / ("d" * depth) / "racket"
    folder.mkdir(parents=True)
    toml = folder / "profile_racket.toml"
    toml.write_text((EXAMPLES / "profile_racket.toml").read_text())
    assert main(["sweep", "--racket", str(toml), "--points", "3"]) == 0
    lines = capsys.readouterr().out.splitlines()
    header_end = next(i for i, line in enumerate(lines) if line.split()[:1] == ["from"])
    assert header_end >= 1 and "16.5 m/s" in " ".join(lines[:header_end])
    assert not any(re.match(r"^\s*-?\d", line) for line in lines[:header_end])


def test_say_conditions_keeps_every_number_with_its_words_at_any_wrap(capsys):
    from studies.cli.files import say_conditions

    for pad in range(120):
        say_conditions(f"racket {'x' * pad}.toml (free, strings 35 kN/m), ball itf-type-2 "
                       "at 16.5 m/s, -3.2 cm from the tip, the racket at rest")  # fmt: skip
        lines = capsys.readouterr().out.splitlines()
        assert not any(re.match(r"^\s*-?\d", line) for line in lines), lines
        assert " ".join(line.strip() for line in lines).endswith(
            "at 16.5 m/s, -3.2 cm from the tip, the racket at rest"
        )
