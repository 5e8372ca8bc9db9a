"""What a racket is strung with, from the command line and from TOML (issue 35): --string,
--gauge, --pattern, --tension-kg, --played and --string-bed-dt on every command that takes a
racket, the ``[racket.strings]`` keys, the conditions line that names the string, and every
refusal in one line.  The options are read and the rackets built without an impact, so the
file runs in seconds.
"""

import argparse

import pytest
from clihelpers import refusal

from common.units import GRAVITY, LB
from racket import paper_racket
from racket.strings.ert import dt_reading
from studies.cli import build_parser
from studies.cli.racket_options import racket_conditions, racket_from
from studies.cli.rackets import bed_text
from studies.config import load_racket

KP_CM = 9.80665 * 100.0
"""1 kp/cm in N/m: a kilopond is the weight of 1 kg at standard gravity, 9.80665 N."""

TWU_POLYESTER_LOSS = 0.448
"""Polyester's tension loss in TWU's impact test (data/measurements.md sec. 5)."""


def _strung(*options, command="sweep"):
    args = build_parser().parse_args([command, *options])
    racket = racket_from(args)
    return racket, racket_conditions(args, racket)


def _subcommands():
    parser = build_parser()
    sub = next(a for a in parser._actions if isinstance(a, argparse._SubParsersAction))
    return {name: p for name, p in sub.choices.items() if "--tension-lb" in p.format_help()}


def test_every_command_that_takes_a_racket_takes_its_strings_serve_too():
    commands = _subcommands()
    assert "serve" in commands and "sweep" in commands and "specs" in commands
    for name, parser in commands.items():
        said = parser.format_help()
        for flag in ("--string", "--gauge", "--pattern", "--played"):
            assert flag in said, (name, flag)


def test_the_default_racket_is_said_with_its_strings_and_its_beds_stiffness():
    racket, said = _strung()
    assert racket.strings.stringing.describe() == "polyester 1.25 mm 16x19 at 55 lb, fresh"
    assert "(free, polyester 1.25 mm 16x19 at 55 lb, fresh, 30 kN/m)" in said


def test_a_hybrid_at_a_tension_in_kg_is_said_in_kg():
    racket, said = _strung("--string", "gut/poly", "--pattern", "18x20", "--tension-kg", "25")
    strung = racket.strings.stringing
    assert strung.mains.material.name == "natural gut"
    assert strung.crosses.material.name == "polyester"
    assert strung.pattern == (18, 20)
    assert strung.tension == pytest.approx(25 * GRAVITY, rel=1e-12)
    assert "natural gut 1.30 mm/polyester 1.25 mm 18x20 at 25 kg, fresh" in said


def test_a_measured_dt_sets_the_stiffness_and_the_rest_stays_the_rackets():
    racket, said = _strung("--string-bed-dt", "30")
    # the ERT reads the force at 1 cm: the bed's stiffening by then included, so a 30 kp/cm
    # polyester bed is less stiff at its centre than 30 kp/cm at face value
    bed = racket.strings
    assert dt_reading(bed.stiffness, bed.stretch) == pytest.approx(30.0, rel=1e-9)
    assert bed.stiffness < 30 * KP_CM
    assert racket.strings.stringing.tension is None
    assert racket.strings.stringing.mains.material.name == "polyester"
    assert "polyester 1.25 mm 16x19, fresh, DT 30 kp/cm" in said


def test_played_strings_lose_twus_tension_and_the_gauge_takes_mm_or_a_name():
    fresh, _ = _strung()
    played, said = _strung("--played", "--gauge", "17", command="serve")
    ratio = played.strings.stiffness / fresh.strings.stiffness
    assert ratio == pytest.approx(1.0 - TWU_POLYESTER_LOSS, rel=1e-12)
    assert played.strings.stringing.mains.gauge == pytest.approx(1.20e-3)
    assert "polyester 1.20 mm 16x19 at 55 lb, played" in said
    thick, _ = _strung("--gauge", "1.3")
    assert thick.strings.stringing.mains.gauge == pytest.approx(1.3e-3, rel=1e-12)


def test_the_papers_spring_gains_a_string_keeping_its_stiffness():
    racket, said = _strung("--racket", "paper", "--string", "nylon")
    assert racket.strings.stiffness == paper_racket().strings.stiffness
    assert racket.strings.loss > 0.0 and racket.strings.stretch > 0.0
    assert "nylon 1.30 mm 16x19, fresh, 40 kN/m" in said
    _, said = _strung("--racket", "paper", "--tension-lb", "50", "60")
    assert "(free, the paper's linear spring at 50, 60 lb)" in said


def test_a_tension_grid_is_said_as_typed_without_one_stiffness():
    _, said = _strung("--tension-lb", "50", "60", "--played")
    assert "polyester 1.25 mm 16x19 at 50, 60 lb, played)" in said


@pytest.mark.parametrize(
    "argv, said",
    [
        (["sweep", "--gauge", "0.00125"], "--gauge must be in [1, 1.5] mm, got 0.00125 (m typed "),
        (["sweep", "--gauge", "16LL"], "--gauge must be a gauge name (15, 15L"),
        (["sweep", "--tension-kg", "55"], "(lb typed as kg? 55 lb would be 24.95 kg)"),
        (["sweep", "--string-bed-dt", "30000"], "N/m typed as kp/cm? 30000 N/m would be 30.59"),
        (["sweep", "--pattern", "16-19"], "--pattern must be MAINSxCROSSES such as '16x19'"),
        (["sweep", "--pattern", "30x19"], "--pattern mains must be in [12, 22], got 30"),
        (["sweep", "--string", "polx"], "unknown string material 'polx'"),
        (["sweep", "--racket", "paper", "--played"], "--played describes a string"),
        (["sweep", "--tension-lb", "55", "--tension-kg", "25"], "give one of --tension-lb or"),
        (["serve", "--string-bed-dt", "30", "--tension-lb", "55"], "--tension-lb or --string-bed"),
        (["modes", "--string", "gut"], "--string does not apply to modes"),
        (["sweep", "--played", "--played"], "--played given twice"),
    ],
)
def test_each_bad_string_option_is_refused_in_one_line_before_any_impact(argv, said):
    assert said in refusal(argv)


def _toml(tmp_path, text: str):
    path = tmp_path / "racket.toml"
    path.write_text(text)
    return path


def test_a_toml_file_strings_its_racket_as_a_stringer_says(tmp_path):
    racket = load_racket(
        _toml(
            tmp_path,
            """[racket.strings]
string = "gut/poly"
gauge = "17"
pattern = "18x20"
state = "played"
tension_kg = 25
""",
        )
    )
    strung = racket.strings.stringing
    assert strung.describe() == "natural gut/polyester 1.20 mm 18x20 at 55.12 lb, played"
    assert strung.tension == pytest.approx(25 * GRAVITY, rel=1e-12)
    measured = load_racket(_toml(tmp_path, "[racket.strings]\ndt_kp_cm = 30\ngauge = 1.3\n"))
    bed = measured.strings
    assert dt_reading(bed.stiffness, bed.stretch) == pytest.approx(30.0, rel=1e-9)
    assert bed.stringing.mains.gauge == pytest.approx(1.3e-3)  # read on the strings as strung
    assert measured.strings.stringing.mains.gauge == pytest.approx(1.3e-3)
    plain = load_racket(_toml(tmp_path, "[racket]\npreset = 'paper'\n[racket.strings]\n"
                              "stiffness = 3e4\n"))  # fmt: skip
    assert plain.strings.stiffness == 3e4 and plain.strings.plain
    lb = load_racket(_toml(tmp_path, "[racket.strings]\ntension_lb = 60\n"))
    assert lb.strings.stringing.tension == pytest.approx(60 * LB, rel=1e-12)


@pytest.mark.parametrize(
    "text, said",
    [
        ("gauge = 0.00125", "[racket.strings] gauge must be in [1, 1.5] mm, got 0.00125"),
        ("tension_kg = 55", "[racket.strings] tension_kg must be in [9.072, 36.28] kg"),
        ("dt_kp_cm = 30000", "N/m typed as kp/cm? 30000 N/m would be 30.59 kp/cm"),
        ("tension_lb = 55\nstiffness = 3e4", "takes one of tension_lb, tension_kg, stiffness"),
        ("state = 'old'", "[racket.strings] state must be one of 'fresh', 'played'"),
        ("pattern = '16 by 19'", "[racket.strings] pattern must be MAINSxCROSSES"),
        ("gauges = 1.25", "unknown key 'gauges' in [racket.strings]"),
    ],
)
def test_each_bad_strings_key_is_refused_naming_it(tmp_path, text, said):
    with pytest.raises(ValueError) as refused:
        load_racket(_toml(tmp_path, f"[racket.strings]\n{text}\n"))
    assert said in str(refused.value) and "\n" not in str(refused.value)


def test_a_plain_spring_in_toml_needs_a_string_for_a_pattern(tmp_path):
    with pytest.raises(ValueError, match=r"describe a string.*name a string"):
        load_racket(_toml(tmp_path, "[racket]\npreset = 'paper'\n[racket.strings]\n"
                          "pattern = '18x20'\n"))  # fmt: skip


def test_specs_prints_the_beds_stiffness_dt_stretch_loss_and_mass():
    racket, _ = _strung(command="specs")
    said = " ".join(bed_text(racket.strings).split())
    stiffness = racket.strings.stiffness
    dt = dt_reading(stiffness, racket.strings.stretch)
    assert f"{stiffness:.0f} N/m" in said and f"{dt:.3g} kp/cm" in said
    for words in ("stretch", "1/m^2", "loss", "% of what it stores", "g inside the head"):
        assert words in said
    assert "the paper's linear spring: lossless" in " ".join(
        bed_text(paper_racket().strings).split()
    )
