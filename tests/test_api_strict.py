"""The Python API as strict as the command line, and refusals that name what was typed
(issue 46, items 6 and 7 of its "Why").

Each example of the issue is a test: a unit slip the API took without a word is refused or
asked about with the command line's hint, naming the argument as the user wrote it; a wrong
kind of argument is refused saying what it takes; a bed too long, in cm or ten times too soft
is refused by its own name, not by a number that follows from it.  Only three tests run an
impact (one stroke, one serve and one stroke on the command line).
"""

import re
import warnings
from dataclasses import replace

import numpy as np
import pytest
from clihelpers import run_main

import studies.bat.sweep as bat_study
from ball import Ball, LinearHysteresis, LinearSpring
from ball.bodies import BALL_MASS_RANGE
from ball.court import COURTS, bounce
from bat import BatSwing
from bat import swing as bat_swing
from common.checks import ArgumentTypeError
from common.typechecks import asked_by_caller, quoted
from racket import (
    STROKES,
    Hand,
    StringBed,
    Stroke,
    Swing,
    default_ball,
    default_racket,
    oblique_impact,
    paper_racket,
    stringing,
)
from racket.strings.sideways import sideways
from racket.strings.stringing import restrung
from racket.swing import equal_effort
from studies.config import TOML_RANGES, load_racket
from studies.serve import serve_table
from studies.strokes.stroke import spin_note, stroke_table

LAW = LinearHysteresis(4e4, 0.75)


def _one_line(err) -> str:
    said = str(err.value)
    assert "\n" not in said, said
    return said


def _asked(make, *args, **kwargs) -> list[str]:
    """The warnings ``make(*args, **kwargs)`` gives, each one line."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        make(*args, **kwargs)
    said = [str(w.message) for w in caught]
    assert all("\n" not in s for s in said), said
    return said


# ---- A1: Ball(57, ...), grams typed as kg ------------------------------------------------
def test_a_ball_in_grams_is_refused_with_the_hint():
    with pytest.raises(ValueError) as err:
        Ball(57, LAW)
    assert _one_line(err).startswith(
        "mass must be in [0.001, 1] kg, got 57 (grams typed as kg? 57 would be 0.057 kg)"
    )
    with pytest.raises(ValueError, match=r"ounces typed as kg\? 5 oz would be 0.1417 kg"):
        Ball(5, LAW)  # 5 kg: 5 g or 5 oz?


@pytest.mark.parametrize("mass", [0.0103, 0.057, 0.145, 0.6, 1e4, 1e12])
def test_a_ball_or_an_immovable_stand_in_is_taken(mass):
    """A ball's mass, or a partner far heavier than any slip explains (a test's 1e12 kg)."""
    assert Ball(mass, LinearSpring(4e4)).mass == mass


def test_the_ball_mass_range_is_the_toml_files():
    assert TOML_RANGES["ball", "mass"][:2] == BALL_MASS_RANGE


# ---- A2: Swing(90) and a bat swing in mph -------------------------------------------------
def test_a_head_speed_in_mph_is_asked_about_with_the_hint():
    said = _asked(Swing, 90)
    assert said == [
        "head_speed 90 m/s is faster than any recorded stroke (a racket head's fastest, "
        "estimated, about 51.2 m/s): mph typed as m/s? 90 mph would be 40.23 m/s; km/h typed "
        "as m/s? 90 km/h would be 25 m/s"
    ]
    assert _asked(Swing, 30.0) == []
    with pytest.raises(ValueError, match=r"^head_speed must be in \[0.001, 300\] m/s, got 400$"):
        Swing(400)  # beyond any swing at all: refused


def test_a_stroke_asks_as_a_swing_does():
    said = _asked(Stroke, 55.0, 0.0, 0.0, 75.0, 0.0)
    assert said[0].startswith("head_speed 55 m/s is faster than any recorded stroke")
    assert said[1].startswith("ball_speed 75 m/s is faster than any recorded stroke (the serve")
    assert "mph typed as m/s? 75 mph would be 33.53 m/s" in said[1]
    assert _asked(lambda: dict(STROKES)) == []  # the presets are usual


def test_serve_table_names_its_own_argument():
    """serve_table's head speed is ``racket_speed``: asked about by that name, once."""
    with pytest.warns(UserWarning) as caught, pytest.raises(ValueError, match="pivot_from_tip"):
        serve_table(paper_racket(), default_ball(), racket_speed=90, pivot_from_tip=5.0)
    said = [str(w.message) for w in caught]
    assert len(said) == 1 and said[0].startswith("racket_speed 90 m/s is faster"), said


def test_a_bat_turned_in_rpm_is_asked_about_with_the_hint():
    assert _asked(BatSwing, 136, cm_speed=24.0) == [
        "angular_velocity 136 rad/s is faster than batters turn a bat (about 76.5 rad/s, "
        "estimated): rpm typed as rad/s? 136 rpm would be 14.24 rad/s; deg/s typed as rad/s? "
        "136 deg/s would be 2.374 rad/s"
    ]
    assert _asked(BatSwing, 51.0, cm_speed=24.0) == []  # Nathan's high-speed swing


def test_a_bat_centre_of_mass_in_mph_is_asked_about_or_refused():
    said = _asked(BatSwing, 51.0, cm_speed=54)
    assert len(said) == 1 and said[0].startswith(
        "cm_speed 54 m/s is faster than batters swing a bat's centre of mass (about 36 m/s, "
        "estimated): mph typed as m/s? 54 mph would be 24.14 m/s"
    )
    with pytest.raises(ValueError) as err:
        BatSwing(51.0, cm_speed=136)
    assert _one_line(err) == (
        "cm_speed must be in [0, 60] m/s, got 136 (km/h typed as m/s? 136 km/h would be 37.78 m/s)"
    )


def test_the_bat_swing_bound_is_the_command_lines():
    assert bat_swing.FASTEST_TURN == pytest.approx(1.5 * bat_study.ANGULAR_VELOCITY)


def test_a_caller_that_has_asked_keeps_the_api_quiet():
    """The command line asks in its options' words; inside asked_by_caller the API does not
    ask again (refusals still come)."""
    with asked_by_caller():
        assert _asked(Swing, 90) == [] and _asked(BatSwing, 136, cm_speed=54) == []
        with pytest.raises(ValueError, match="grams typed as kg"):
            Ball(57, LAW)
    assert len(_asked(Swing, 90)) == 1  # and afterwards it asks again


def test_the_command_line_asks_once_in_its_own_words():
    status, _, err = run_main(["serve", "--racket-speed", "90"])
    assert status == 0, err
    lines = [line for line in err.splitlines() if "warning" in line]
    assert len(lines) == 1 and "--racket-speed 90 m/s is faster" in lines[0], err
    assert "head_speed" not in err and "racket_speed 90" not in err, err


# ---- A3: a spin in rpm typed as rad/s ----------------------------------------------------
SPIN_HINT = "rpm typed as rad/s? 800 rpm would be 83.78 rad/s"


def test_a_stroke_spin_in_rpm_is_asked_about():
    said = _asked(Stroke, 20.0, 0.0, 0.0, 15.0, 0.0, topspin=800)
    assert said == [
        "topspin 800 rad/s is more than any ball in play spins (about 5000 rpm, 523.6 rad/s): "
        + SPIN_HINT
    ]
    assert _asked(Stroke, 20.0, 0.0, 0.0, 15.0, 0.0, topspin=400.0) == []  # 3820 rpm: usual


def test_an_oblique_or_a_bounce_spin_in_rpm_is_asked_about_before_any_work():
    racket, ball = default_racket(), default_ball()
    with pytest.warns(UserWarning, match=re.escape(f"|spin| 800 rad/s is more than any ball in "
                                                   f"play spins (about 5000 rpm, 523.6 rad/s): "
                                                   f"{SPIN_HINT}")):  # fmt: skip
        with pytest.raises(ValueError, match="steps_per_contact"):  # refused before the impact
            oblique_impact(racket, ball, 0.17, 10.0, spin=(0, 800, 0), steps_per_contact=-1)
    with pytest.warns(UserWarning, match=re.escape(f"spin 800 rad/s is more than any ball in "
                                                   f"play spins (about 5000 rpm, 523.6 rad/s): "
                                                   f"{SPIN_HINT}")):  # fmt: skip
        with pytest.raises(ValueError, match="steps"):
            bounce(COURTS["clay"], 20.0, 0.3, spin=800, steps=5)


# ---- A4-A7: the wrong kind of argument, said what it takes --------------------------------
def test_equal_effort_with_a_number_says_what_it_takes():
    with pytest.raises(TypeError) as err:
        equal_effort(30, 0.03, 0.03)
    assert err.type is ArgumentTypeError
    assert _one_line(err) == (
        "swing must be a racket.Swing, got 30 (a head speed? racket.Swing(30) swings about the "
        "wrist)"
    )
    assert equal_effort(Swing(30.0), 0.03, 0.03).head_speed == 30.0


def test_equal_effort_does_not_ask_about_what_it_derives():
    assert _asked(equal_effort, Swing(50.0), 0.036, 0.030) == []  # 52.5 m/s, derived


def test_stringing_with_a_number_says_what_it_takes():
    with pytest.raises(TypeError) as err:
        stringing(5)
    assert err.type is ArgumentTypeError
    assert _one_line(err) == (
        "name must be a preset or MAINS/CROSSES (polyester, nylon, multifilament, natural-gut; "
        "e.g. 'natural-gut/polyester'), got 5"
    )


def test_one_stroke_is_a_list_of_one():
    volley = STROKES["volley"]
    assert spin_note(volley) == spin_note({"volley": volley}) != ""
    assert spin_note([volley]) == spin_note(volley)
    table = stroke_table(volley, default_racket(), default_ball())
    assert list(table["stroke"]) == ["volley"]
    assert "stroke" in spin_note(replace(volley, head_speed=6.0))  # one's own: "stroke"
    with pytest.raises(TypeError, match=r"^strokes must be a Stroke, a dict name -> Stroke"):
        stroke_table(5, default_racket(), default_ball())


@pytest.mark.parametrize("word", ["no", "False", 0, 1, None])
def test_a_flag_must_be_a_flag(word):
    bed = default_racket().strings
    with pytest.raises(TypeError) as err:
        sideways(bed, lubricated=word)
    assert _one_line(err).startswith("lubricated must be True or False, got ")
    with pytest.raises(TypeError, match=r"^slide must be True or False"):
        sideways(bed, slide=word)
    assert sideways(bed, lubricated=True).string_friction < sideways(bed).string_friction


def test_a_racket_for_a_bed_says_which_part_to_give():
    with pytest.raises(TypeError) as err:
        sideways(default_racket())
    assert _one_line(err) == (
        "bed must be a racket.StringBed, got a Racket (a racket's is racket.strings)"
    )


def test_a_long_value_is_quoted_by_its_type():
    assert quoted(default_racket()) == "a Racket" and quoted(4.5) == "4.5"


# ---- A8: oblique_impact's slip velocity of the wrong shape ------------------------------
def test_a_slip_velocity_of_the_wrong_shape_says_the_shape_before_any_work():
    racket, ball = default_racket(), default_ball()
    with pytest.raises(ValueError) as err:
        oblique_impact(racket, ball, [0.15, 0.17], 10.0, slip_velocity=[(1.0, 0.0)] * 3)
    assert _one_line(err) == (
        "slip_velocity must be 2 numbers [m/s], or a row of 2 per impact point (2 points: "
        "shape (2, 2)), got shape (3, 2)"
    )
    with pytest.raises(ValueError, match=r"^spin must be 3 numbers \[rad/s\], or a row of 3 "):
        oblique_impact(racket, ball, [0.15, 0.17], 10.0, spin=np.zeros((3, 3)))
    with pytest.raises(ValueError, match=r"got shape \(3,\)$"):
        oblique_impact(racket, ball, 0.17, 10.0, slip_velocity=(1.0, 0.0, 0.0))


# ---- B1: a bed too long for its frame, not blamed on grip_length ---------------------------
def test_a_bed_too_long_is_named_by_its_extent(tmp_path):
    racket = default_racket()
    with pytest.raises(ValueError) as err:
        replace(racket, strings=replace(racket.strings, extent=(0.0, 0.66)))
    said = _one_line(err)
    assert said.startswith("strings extent (0, 0.66) m from the tip runs into the handle: on "
                           "this 0.6858 m frame the strings must end before its grip")  # fmt: skip
    assert said.endswith("< 0.5858 m from the tip")
    toml = tmp_path / "long.toml"
    toml.write_text("[racket]\n[racket.strings]\nextent = [0.0, 0.66]\n")
    with pytest.raises(ValueError, match=r"^\[racket.strings\] extent \(0, 0.66\) m from the "
                                         r"tip runs into the handle"):  # fmt: skip
        load_racket(toml)


def test_a_grip_too_long_is_named_by_its_length():
    with pytest.raises(ValueError, match=r"^grip_length must end below the strings .* got 0.5$"):
        replace(paper_racket(), hand=Hand(grip_length=0.5))


# ---- B2: a bed in cm, not a moving mass in "grams typed as kg" ----------------------------
def test_a_bed_in_cm_is_named_by_its_extent(tmp_path):
    with pytest.raises(ValueError) as err:
        StringBed(4e4, (5, 37))
    assert _one_line(err) == (
        "extent start must be in [0, 1.5] m from the tip, got 5 (cm typed as m? 5 would be "
        "0.05 m from the tip)"
    )
    with pytest.raises(ValueError, match=r"^extent end .* got 37 \(cm typed as m\? 37 would"):
        stringing("polyester", tension_n=245.0).bed((0.0, 37))
    toml = tmp_path / "cm.toml"
    toml.write_text("[racket]\n[racket.strings]\nextent = [5, 37]\n")
    with pytest.raises(ValueError) as err:
        load_racket(toml)
    said = _one_line(err)
    assert said.startswith("[racket.strings] extent must be in [0, 1.5] m from the tip, got 5 "
                           "(cm typed as m?")  # fmt: skip
    assert "moving mass" not in said and "grams" not in said


# ---- B3: a stiffness in kN/m, not "stretch 1044524" ---------------------------------------
KN_SAID = (
    "stiffness must be in [1000, 1e+07] N/m, got 30 (kN/m typed as N/m? 30 would be 30000 N/m)"
)


@pytest.mark.parametrize(
    "make",
    [
        lambda bed: StringBed(30, bed.extent),
        lambda bed: restrung(bed, stiffness=30),
        lambda bed: bed.stringing.bed(bed.extent, stiffness=30),
        lambda bed: replace(bed, stiffness=30),
    ],
    ids=["StringBed", "restrung", "Stringing.bed", "replace"],
)
def test_a_stiffness_in_kn_per_m_is_named_as_typed(make):
    with pytest.raises(ValueError) as err:
        make(default_racket().strings)
    assert _one_line(err) == KN_SAID


# ---- B4: a trailing slash, not an unknown material '' -------------------------------------
def test_a_hybrid_with_a_side_missing_names_what_was_typed():
    with pytest.raises(ValueError) as err:
        stringing("natural-gut/")
    assert _one_line(err) == (
        "name must give the mains and the crosses either side of '/' (e.g. "
        "'natural-gut/polyester'), got 'natural-gut/'"
    )
    status, out, err = run_main(["stroke", "--string", "natural-gut/"])
    assert status == 2 and out == "", err
    assert err.strip() == (
        "racket-impact stroke: error: --string must give the mains and the crosses either side "
        "of '/' (e.g. 'natural-gut/polyester'), got 'natural-gut/'"
    )


# ---- B5: a stroke on a clamped racket names the clamp -------------------------------------
def test_a_stroke_on_a_clamped_racket_names_the_clamp():
    with pytest.raises(ValueError) as err:
        stroke_table(STROKES, default_racket("clamped-head"), default_ball())
    assert _one_line(err) == (
        "racket must move for a stroke (support 'free' or 'hand-held'), got support "
        "'clamped-head': a clamped head cannot swing"
    )
    status, _, err = run_main(["stroke", "--support", "clamped-head"])
    assert status == 2 and "clamped-head" in err and "--support" in err, err


def test_hit_on_a_clamped_racket_names_the_clamp():
    from racket import hit

    with pytest.raises(ValueError, match=r"got support 'clamped-head': a clamped head cannot"):
        hit(STROKES["volley"], default_racket("clamped-head"), default_ball())
