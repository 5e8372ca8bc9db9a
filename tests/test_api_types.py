"""The Python API takes what a Python user would pass (issue 34): paths as str or
os.PathLike, and for every other argument its documented type, or a one-line TypeError or
ValueError that names the argument; never an AttributeError (or KeyError, IndexError, ...)
from deep inside, nor a NaN result.

Each public function and class of ``racket``, ``ball`` and ``beam`` (their ``__all__``) and
each function of ``studies`` documented in docs/python.md is called with valid arguments but
one, replaced in turn by each wrong value its kind admits (:data:`WRONG`).  The wrong values
are refused before any impact runs, so the file takes seconds.
"""

import math
import re
from concurrent.futures import ThreadPoolExecutor
from dataclasses import replace
from functools import cache
from pathlib import Path

import numpy as np
import pytest

import ball as ball_api
import beam as beam_api
import racket as racket_api
from ball import (
    WALL,
    Ball,
    baseball,
    collide,
    energy_loss_fraction,
    energy_loss_fraction_lab,
    series_cor,
    series_force,
    serve_speed,
    unhappy_cor,
    unhappy_solution,
    warn_if_squashed,
)
from ball.laws import GrowingHysteresis, LinearHysteresis, LinearSpring, PowerLawHysteresis, SineLaw
from ball.stiffening import StiffeningHysteresis
from bat import Bat, BatSwing
from bat.presets import r161_beam
from beam import Beam, ThickBeam
from racket import (
    CATALOG,
    STROKES,
    Hand,
    Racket,
    String,
    StringBed,
    Stringing,
    Stroke,
    Swing,
    default_racket,
    flex_test_stiffness,
    from_specs,
    hit,
    impact,
    oblique_impact,
    paper_ball,
    paper_racket,
    string_bed_stiffness,
    stringing,
)
from racket.feel import hand_feel
from racket.specs.restring import with_tension
from studies.bounce import rigid_bounce_table
from studies.conditions import conditions_line
from studies.config import (
    ball_from_table,
    load_ball,
    load_racket,
    racket_from_table,
    racket_specs,
    read_toml,
)
from studies.drop import drop
from studies.face.maps import face_map
from studies.face.sweetspots import sweet_spots
from studies.report import spec_report
from studies.serve import head_speed_for, serve_table, serve_what_if, zero_cor_ball
from studies.sweeps import compare, sweep
from studies.tables import history_table, impact_table

EXAMPLES = Path(__file__).parents[1] / "examples"

MISSING = Path("no-such-dir") / "missing.toml"

WRONG = {
    "None": None,
    "word": "x",
    "int": 4,
    "float": 4.0,
    "object": object(),
    "list": [],
    "dict": {},
    "nan": math.nan,
    "path": MISSING,
}
"""The wrong values, by label: each kind of argument (:data:`KINDS`) is given those of them
it must refuse."""

KINDS = {
    "number": ("None", "word", "object", "list", "dict", "nan", "path"),
    "numbers": ("None", "word", "object", "list", "dict", "nan", "path"),
    "array": ("None", "word", "object", "dict", "nan", "path"),
    "sequence": ("None", "word", "int", "float", "object", "nan", "path"),
    "object": tuple(WRONG),
    "word": ("None", "int", "float", "object", "list", "dict", "nan", "path", "word"),
    "text": ("None", "int", "float", "object", "list", "dict", "nan", "path"),
    "flag": ("None", "word", "int", "float", "object", "list", "dict", "nan", "path"),
    "count": ("None", "word", "object", "list", "dict", "nan", "path"),
    "file": ("None", "int", "float", "object", "list", "dict", "nan", "path", "word"),
    "table": ("None", "word", "int", "float", "object", "list", "nan", "path"),
}
"""Which wrong values each kind of argument refuses: a number (4 and 4.0 are numbers), an
array of numbers (one at least), an array (empty allowed), a sequence (empty allowed) of
objects, an object of a class (a Racket, a Ball, a Swing...), a word from a list ("free",
"membrane", "3 and 9"...), any text, a flag (True or False), a whole number, a preset name
or a TOML file (str or os.PathLike: a missing one is refused), a dict (a TOML table).  A kind
followed by "?" also takes None."""


@cache
def made():
    """Valid arguments, made once."""
    racket = paper_racket()
    ball = paper_ball()
    spec = default_racket()
    return {
        "racket": racket,
        "ball": ball,
        "spec": spec,
        "swing": Swing(30.0),
        "beam": racket.beam,
        "strings": racket.strings,
        "hand": racket.hand,
        "law": ball.law,
        "hit": impact(racket, ball, 0.1, 10.0),
        "history": collide(ball, WALL, 10.0).history,
        "specs": dict(CATALOG["pure-drive-2021"].specs),
        "bat_beam": r161_beam(n_modes=4),
    }


def _m(name):
    return lambda: made()[name]


SPEC = r"^spec must|^unknown (racket|ball) preset|missing.toml"
"""What a refused preset or file says: the argument, the preset unknown, or the file."""

# (label, the call, its valid arguments (a value, or a callable that makes it), the kinds of
#  those checked, and what each message must say (a regular expression) if not the argument's name)
CASES = [
    # ---- racket ---------------------------------------------------------------------------
    ("Racket", Racket,
     {"beam": _m("beam"), "strings": _m("strings"), "support": "free", "hand": _m("hand")},
     {"beam": "object", "strings": "object", "support": "word", "hand": "object"}, {}),
    ("Bat", Bat,
     {"beam": _m("bat_beam"), "support": "free", "hand": _m("hand"), "pivot_from_knob": 0.1524,
      "clamp_offset": 0.0254, "name": "bat"},
     {"beam": "object", "support": "word", "hand": "object", "pivot_from_knob": "number",
      "clamp_offset": "number", "name": "text"}, {"support": "bat support"}),
    ("BatSwing", BatSwing, {"angular_velocity": 51.0, "cm_speed": 24.0, "pivot_from_knob": None},
     {"angular_velocity": "number", "cm_speed": "number?", "pivot_from_knob": "number?"}, {}),
    ("StringBed", StringBed,
     {"stiffness": 4e4, "extent": (0.0, 0.32), "width": None, "profile": "uniform",
      "stretch": 900.0, "loss": 0.06},
     {"stiffness": "number", "extent": "numbers", "width": "number?", "profile": "word",
      "stretch": "number", "loss": "number"}, {}),
    ("String", String, {"material": "polyester", "gauge": 1.25e-3},
     {"material": "word", "gauge": "number"}, {}),
    ("Stringing", Stringing,
     {"mains": lambda: String("polyester", 1.25e-3), "crosses": None, "pattern": (16, 19),
      "tension": 245.0, "state": "fresh"},
     {"mains": "object", "crosses": "object?", "tension": "number?", "state": "word"}, {}),
    ("stringing", stringing,
     {"name": "polyester", "gauge": None, "pattern": (16, 19), "tension_n": 245.0,
      "state": "fresh"},
     {"name": "word", "tension_n": "number?", "state": "word"}, {}),
    ("Hand", Hand,
     {"stiffness": 1e4, "damping": 10.0, "grip_length": 0.1, "mass": 0.2,
      "resists_twist": True},
     {"stiffness": "number", "damping": "number", "grip_length": "number", "mass": "number",
      "resists_twist": "flag"}, {}),
    ("Swing", Swing, {"head_speed": 30.0, "pivot_from_tip": 0.7},
     {"head_speed": "number", "pivot_from_tip": "number?"}, {}),
    ("impact", impact,
     {"racket": _m("racket"), "ball": _m("ball"), "position": 0.1, "speed": 10.0,
      "offset": None, "swing_speed": 0.0, "pivot": None, "steps_per_contact": None,
      "watch_after": 0.0, "histories": False},
     {"racket": "object", "ball": "object", "position": "numbers", "speed": "number",
      "offset": "numbers?", "swing_speed": "numbers", "pivot": "number?",
      "steps_per_contact": "count?", "watch_after": "number", "histories": "flag"}, {}),
    ("oblique_impact", oblique_impact,
     {"racket": _m("spec"), "ball": _m("ball"), "position": 0.15, "speed": 10.0,
      "slip_velocity": (1.0, 0.0), "spin": (0.0, 10.0, 0.0), "offset": None,
      "swing_speed": 0.0, "pivot": None, "ball_spin": None, "side": None,
      "steps_per_contact": None},
     {"racket": "object", "ball": "object", "position": "numbers", "speed": "number",
      "slip_velocity": "numbers", "spin": "numbers", "offset": "numbers?",
      "swing_speed": "numbers", "pivot": "number?", "ball_spin": "object?", "side": "object?",
      "steps_per_contact": "count?"}, {}),
    ("Stroke", Stroke,
     {"head_speed": 20.0, "path_angle": 0.3, "face_angle": 0.0, "ball_speed": 15.0,
      "ball_angle": 0.1, "swing_across": 0.0, "topspin": 0.0, "sidespin": 0.0,
      "shaft": "horizontal"},
     {"head_speed": "number", "path_angle": "number", "face_angle": "number",
      "ball_speed": "number", "ball_angle": "number", "swing_across": "number",
      "topspin": "number", "sidespin": "number", "shaft": "word"}, {}),
    ("hit", hit,
     {"stroke": lambda: STROKES["volley"], "racket": _m("spec"), "ball": _m("ball"),
      "position": None, "side": None},
     {"stroke": "object", "racket": "object", "ball": "object", "position": "number?",
      "side": "object?"}, {}),
    ("default_racket", default_racket, {"support": "free"}, {"support": "word"}, {}),
    ("paper_racket", paper_racket, {"support": "free"}, {"support": "word"}, {}),
    ("from_specs", from_specs, _m("specs"),
     {"mass_kg": "number", "balance_cm": "number", "swingweight_kgcm2": "number",
      "f1_hz": "number?", "head_size_in2": "number?", "tension_lb": "number",
      "length_m": "number"}, {}),
    ("from_specs support", lambda support: from_specs(support=support, **made()["specs"]),
     {"support": "free"}, {"support": "word"}, {}),
    ("catalogue racket", lambda support: CATALOG["pure-drive-2021"].racket(support),
     {"support": "free"}, {"support": "word"}, {}),
    ("string_bed_stiffness", string_bed_stiffness, {"tension_n": 240.0, "head_area_m2": 0.065},
     {"tension_n": "number", "head_area_m2": "number"},
     {"tension_n": "tension", "head_area_m2": "head size"}),
    ("flex_test_stiffness", flex_test_stiffness, {"beam": _m("beam"), "throat": 0.32},
     {"beam": "object", "throat": "number"}, {}),
    ("Racket.with_mass", lambda mass_kg, position_m: made()["racket"].with_mass(
        mass_kg, position_m), {"mass_kg": 0.005, "position_m": 0.1},
     {"mass_kg": "number", "position_m": "number"}, {}),
    ("Racket.with_lead_tape", lambda mass_kg, at: made()["racket"].with_lead_tape(mass_kg, at),
     {"mass_kg": 0.005, "at": "3 and 9"}, {"mass_kg": "number", "at": "word"}, {}),
    ("with_tension", with_tension, {"racket": _m("racket"), "tension_n": 240.0},
     {"racket": "object", "tension_n": "number"}, {"tension_n": "tension"}),
    ("hand_feel", hand_feel,
     {"racket": _m("racket"), "ball": _m("ball"), "position": 0.1, "speed": 10.0,
      "offset": None, "duration": 0.05},
     {"racket": "object", "ball": "object", "position": "number", "speed": "number",
      "offset": "number?", "duration": "number"}, {}),
    # ---- ball -----------------------------------------------------------------------------
    ("Ball", Ball, {"mass": 0.057, "law": _m("law"), "radius": 0.033},
     {"mass": "number", "law": "object", "radius": "number?"}, {}),
    ("LinearSpring", LinearSpring, {"k": 4e4}, {"k": "number"}, {}),
    ("LinearHysteresis", LinearHysteresis, {"k": 4e4, "e": 0.75},
     {"k": "number", "e": "number"}, {}),
    ("PowerLawHysteresis", PowerLawHysteresis, {"k": 1e6, "a": 1.5, "b": 3.0},
     {"k": "number", "a": "number", "b": "number"}, {}),
    ("PowerLawHysteresis.with_cor", PowerLawHysteresis.with_cor, {"k": 1e6, "a": 1.5, "e": 0.7},
     {"k": "number", "a": "number", "e": "number"}, {}),
    ("GrowingHysteresis", GrowingHysteresis,
     {"k": 1e6, "a": 1.5, "e0": 0.9, "slope": 0.01, "calibrated_to": None},
     {"k": "number", "a": "number", "e0": "number", "slope": "number",
      "calibrated_to": "number?"}, {}),
    ("SineLaw", SineLaw, {"k0": 4e4}, {"k0": "number"}, {}),
    ("StiffeningHysteresis", StiffeningHysteresis,
     {"k": 3e4, "x_lim": 0.033, "e0": 0.9, "slope": 5.0},
     {"k": "number", "x_lim": "number", "e0": "number", "slope": "number"}, {}),
    ("collide", collide, {"a": _m("ball"), "b": _m("ball"), "v_a": 10.0, "v_b": 0.0,
                          "samples": 50},
     {"a": "object", "b": "object", "v_a": "number", "v_b": "number", "samples": "count"}, {}),
    ("energy_loss_fraction", energy_loss_fraction, {"e": 0.7}, {"e": "number"}, {}),
    ("energy_loss_fraction_lab", energy_loss_fraction_lab,
     {"e": 0.7, "m1": 0.057, "m2": 0.3, "v1": 0.0, "v2": 30.0},
     {"e": "number", "m1": "number", "m2": "number", "v1": "number", "v2": "number"}, {}),
    ("series_cor", series_cor, {"e1": 0.75, "k1": 4e4, "k2": 3e4},
     {"e1": "number", "k1": "number", "k2": "number"}, {}),
    ("series_force", series_force,
     {"laws": lambda: (made()["law"], LinearSpring(3e4)), "z": 0.01, "f_max": 0.0},
     {"laws": "object", "z": "array", "f_max": "array"}, {}),
    ("serve_speed", serve_speed, {"e": 0.8, "m1": 0.057, "m2": 0.2, "v2": 30.0},
     {"e": "number", "m1": "number", "m2": "number", "v2": "number"}, {}),
    ("unhappy_cor", unhappy_cor, {"k0": 4e4, "k2": 3e4}, {"k0": "number", "k2": "number"}, {}),
    ("unhappy_solution", unhappy_solution,
     {"t": 0.001, "m1": 0.057, "m2": 0.3, "k0": 4e4, "k2": 3e4, "v1": 10.0},
     {"t": "array", "m1": "number", "m2": "number", "k0": "number", "k2": "number",
      "v1": "number"}, {}),
    ("warn_if_squashed", warn_if_squashed, {"ball": _m("ball"), "compression": 0.001},
     {"ball": "object", "compression": "numbers"}, {}),
    ("baseball", baseball, {"e0": 0.5, "mass": 0.145}, {"e0": "number", "mass": "number"},
     {}),
    # ---- beam -----------------------------------------------------------------------------
    ("ThickBeam", ThickBeam,
     {"stations": (0.0, 0.84), "mass_per_length": (2.0,), "bending_stiffness": (1e4,),
      "shear_stiffness": (1e6,), "rotary_inertia_per_length": (1e-4,), "n_modes": 4,
      "elements": 40},
     {"stations": "numbers", "mass_per_length": "numbers", "bending_stiffness": "numbers",
      "shear_stiffness": "numbers", "rotary_inertia_per_length": "numbers",
      "n_modes": "count", "elements": "count"}, {}),
    ("ThickBeam.round", ThickBeam.round,
     {"stations": (0.0, 0.4, 0.84), "diameters": (0.03, 0.06), "density": 649.0,
      "youngs_modulus": 1.8e10, "shear_modulus": 1.05e9, "bore": None,
      "shear_coefficient": 1.0},
     {"stations": "numbers", "diameters": "numbers", "density": "number",
      "youngs_modulus": "number", "shear_modulus": "number", "bore": "numbers?",
      "shear_coefficient": "number"}, {}),
    ("Beam", Beam,
     {"stations": (0.0, 0.3, 0.68), "mass_per_length": (0.5, 0.5),
      "bending_stiffness": (100.0, 100.0), "point_masses": (), "damping": 0.005,
      "n_modes": 4, "elements": 40, "roll_inertia_per_length": None,
      "torsional_stiffness": None, "n_torsion_modes": 4},
     {"stations": "numbers", "mass_per_length": "numbers", "bending_stiffness": "numbers",
      "point_masses": "sequence", "damping": "numbers", "n_modes": "count",
      "elements": "count", "roll_inertia_per_length": "numbers?",
      "n_torsion_modes": "count"}, {}),
    ("Beam.uniform", Beam.uniform,
     {"length": 0.68, "mass": 0.34, "f1": 120.0, "damping": 0.005, "n_modes": 4},
     {"length": "number", "mass": "number", "f1": "number", "damping": "numbers",
      "n_modes": "count"}, {}),
    ("Beam.with_f1", lambda f1: made()["beam"].with_f1(f1), {"f1": 150.0}, {"f1": "number"}, {}),
    ("Beam.effective_mass", lambda x: made()["beam"].effective_mass(x), {"x": 0.1},
     {"x": "array"}, {}),
    ("Beam.inertia_about", lambda x: made()["beam"].inertia_about(x), {"x": 0.1},
     {"x": "number"}, {}),
    ("Beam.with_point_masses", lambda mass: made()["beam"].with_point_masses(mass),
     {"mass": (0.1, 0.005)}, {"mass": "object"}, {"mass": "point_masses"}),
    # ---- studies --------------------------------------------------------------------------
    ("load_racket", load_racket, {"spec": "paper"}, {"spec": "file"}, {"spec": SPEC}),
    ("load_ball", load_ball, {"spec": "paper"}, {"spec": "file"}, {"spec": SPEC}),
    ("racket_specs", racket_specs, {"spec": "paper"}, {"spec": "file"}, {"spec": SPEC}),
    ("read_toml", read_toml, {"path": str(EXAMPLES / "hertz_ball.toml")}, {"path": "file"},
     {"path": r"^path must|^cannot read"}),
    ("racket_from_table", racket_from_table, {"table": {"preset": "paper"}},
     {"table": "table"}, {}),
    ("ball_from_table", ball_from_table, {"table": {"preset": "paper"}}, {"table": "table"},
     {}),
    ("sweep", sweep,
     {"racket": _m("racket"), "ball": _m("ball"), "positions": [0.1], "speed": 10.0,
      "string_stiffness": None, "tension": None, "f1": None, "support": None, "offset": None,
      "swing": None, "progress": False, "executor": None},
     {"racket": "object", "ball": "object", "positions": "numbers?", "speed": "numbers",
      "string_stiffness": "numbers?", "tension": "numbers?", "f1": "numbers?",
      "support": "word?", "offset": "numbers?", "swing": "object?", "progress": "flag?",
      "executor": "object?"}, {}),
    ("compare", compare,
     {"rackets": lambda: {"paper": made()["racket"]}, "ball": _m("ball"), "speed": 10.0,
      "points": 2, "swing": None, "tension": None, "equal_effort": False, "progress": False,
      "executor": None},
     {"rackets": "object", "ball": "object", "speed": "number", "points": "count",
      "swing": "object?", "tension": "number?", "equal_effort": "flag", "progress": "flag?",
      "executor": "object?"}, {}),
    ("face_map", face_map,
     {"racket": _m("spec"), "ball": _m("ball"), "speed": 10.0, "swing": None, "grid": (4, 4),
      "margin": None, "executor": None},
     {"racket": "object", "ball": "object", "speed": "number", "swing": "object?",
      "grid": "numbers", "margin": "number?", "executor": "object?"}, {}),
    ("sweet_spots", sweet_spots,
     {"racket": _m("racket"), "ball": _m("ball"), "speed": 10.0, "swing": None,
      "hand_from_tip": None, "points": 11},
     {"racket": "object", "ball": "object", "speed": "number?", "swing": "object?",
      "hand_from_tip": "number?", "points": "count"}, {}),
    ("serve_table", serve_table,
     {"racket": _m("racket"), "ball": _m("ball"), "position": None, "racket_speed": 30.0,
      "pivot_from_tip": None, "zero_cor": False},
     {"racket": "object", "ball": "object", "position": "numbers?", "racket_speed": "number",
      "pivot_from_tip": "number?", "zero_cor": "flag"}, {}),
    ("head_speed_for", head_speed_for,
     {"racket": _m("racket"), "ball": _m("ball"), "target": 40.0, "position": None,
      "pivot_from_tip": None},
     {"racket": "object", "ball": "object", "target": "number", "position": "number?",
      "pivot_from_tip": "number?"}, {}),
    ("serve_what_if", serve_what_if,
     {"racket": _m("racket"), "ball": _m("ball"), "position": None, "racket_speed": 30.0,
      "string_stiffness": [4e4], "ball_stiffness": [4e4], "pivot_from_tip": None},
     {"racket": "object", "ball": "object", "position": "number?", "racket_speed": "number",
      "string_stiffness": "array?", "ball_stiffness": "array?",
      "pivot_from_tip": "number?"}, {}),
    ("zero_cor_ball", zero_cor_ball, {"ball": _m("ball"), "force": 100.0},
     {"ball": "object", "force": "number"}, {}),
    ("rigid_bounce_table", rigid_bounce_table, {"ball": _m("ball"), "speeds": [10.0]},
     {"ball": "object", "speeds": "numbers"}, {"speeds": "speed"}),
    ("drop", drop, {"ball": _m("ball"), "height": 1.0, "onto": None},
     {"ball": "object", "height": "number", "onto": "object?"}, {}),
    ("impact_table", impact_table, {"result": _m("hit")}, {"result": "object"}, {}),
    ("history_table", history_table, {"history": _m("history")}, {"history": "object"}, {}),
    ("spec_report", spec_report,
     {"racket": _m("racket"), "specs": None, "count": 2, "ball": None},
     {"racket": "object", "specs": "table?", "count": "count", "ball": "object?"}, {}),
    ("conditions_line", conditions_line,
     {"racket_name": "paper", "ball_name": "paper", "speed": 10.0, "unit": "m/s",
      "swing": None, "support": None, "grip": None, "strings": None},
     {"racket_name": "text?", "ball_name": "text?", "speed": "numbers?", "unit": "word",
      "swing": "text?", "support": "text?", "grip": "text?", "strings": "text?"}, {}),
]  # fmt: skip


def _wrong_cases():
    for label, call, valid, kinds, says in CASES:
        for name, kind in kinds.items():
            labels = KINDS[kind.rstrip("?")]
            if kind.endswith("?"):
                labels = tuple(w for w in labels if w != "None")
            for wrong in labels:
                yield pytest.param(call, valid, name, WRONG[wrong], says.get(name, name),
                                   id=f"{label}-{name}-{wrong}")  # fmt: skip


def _arguments(valid) -> dict:
    valid = valid() if callable(valid) else valid
    return {k: v() if callable(v) else v for k, v in valid.items()}


@pytest.mark.filterwarnings("ignore")
@pytest.mark.parametrize(("call", "valid", "name", "value", "says"), list(_wrong_cases()))
def test_a_wrong_type_is_refused_in_one_line_naming_the_argument(call, valid, name, value, says):
    arguments = _arguments(valid)
    arguments[name] = value
    try:
        result = call(**arguments)
    except (TypeError, ValueError) as err:
        message = str(err)
        assert re.search(says, message), message
        assert "\n" not in message, message
        return
    pytest.fail(f"{name}={value!r} was taken: {result!r:.200}")


@pytest.mark.parametrize(("label", "call", "valid"), [(c[0], c[1], c[2]) for c in CASES])
def test_the_valid_arguments_are_taken(label, call, valid):
    """The tables' valid arguments are valid (the refusals above are of the one value)."""
    call(**_arguments(valid))


def test_every_public_name_is_in_the_table():
    """Every public function and class of racket, ball and beam is called above, but the
    results (made, not given), the constants and the presets with no arguments."""
    called = {c[1] for c in CASES} | {Beam, Racket}
    results = {
        "Impact",
        "ObliqueImpact",
        "StrokeImpact",
        "Collision",
        "CollisionHistory",
        "Modes",
        "MonotoneLaw",
        "Wall",
    }
    for package in (racket_api, ball_api, beam_api):
        for name in package.__all__:
            thing = getattr(package, name)
            if not callable(thing) or name in results or name.startswith("_"):
                continue
            if name in ("default_ball", "paper_ball"):  # no arguments
                continue
            assert thing in called, f"{package.__name__}.{name} is not in CASES"


# ---- the positives: paths as str or os.PathLike -----------------------------------------


@pytest.mark.parametrize("as_path", [str, Path])
def test_a_toml_file_loads_from_a_str_or_a_path(as_path):
    ball = load_ball(as_path(EXAMPLES / "hertz_ball.toml"))
    assert isinstance(ball, Ball)
    racket = load_racket(as_path(EXAMPLES / "my_racket_specs.toml"))
    assert isinstance(racket, Racket)
    specs, _ = racket_specs(as_path(EXAMPLES / "my_racket_specs.toml"))
    assert specs is not None
    assert "ball" in read_toml(as_path(EXAMPLES / "hertz_ball.toml"))


def test_a_path_loads_what_its_str_loads():
    path = EXAMPLES / "hertz_ball.toml"
    assert load_ball(path) == load_ball(str(path))
    path = EXAMPLES / "stiff_racket.toml"
    assert load_racket(path).beam == load_racket(str(path)).beam


def test_a_missing_path_is_refused_naming_the_file():
    with pytest.raises(ValueError, match=r"missing\.toml"):
        load_ball(MISSING)


def test_an_executor_is_taken_and_a_word_or_count_is_not():
    """executor=: None or a concurrent.futures.Executor; "dask" or 4 refused naming it."""
    racket, ball = made()["racket"], made()["ball"]
    with ThreadPoolExecutor(1) as pool:
        table = sweep(racket, ball, [0.1], 10.0, executor=pool)
    assert np.all(np.isfinite(table["e"]))
    for wrong in ("dask", 4):
        with pytest.raises(TypeError, match=r"executor must be .*Executor.*got"):
            sweep(racket, ball, [0.1], 10.0, executor=wrong)


def test_drop_onto_the_command_lines_word_says_what_to_pass():
    with pytest.raises(TypeError, match=r"onto must be a racket.Racket or None.*clamped-head"):
        drop(made()["ball"], 1.0, onto="strings")


def test_a_number_for_a_swing_says_to_make_a_swing():
    with pytest.raises(TypeError, match=r"swing must be a Swing or None.*Swing\(30"):
        sweep(made()["racket"], made()["ball"], [0.1], 0.0, swing=30.0)


def test_a_type_error_is_a_value_error_too():
    """The command line, which turns a ValueError into its one line, catches these too."""
    with pytest.raises(ValueError, match=r"ball must be"):
        impact(made()["racket"], None, 0.1, 10.0)


def test_a_racket_changed_by_replace_is_checked_again():
    with pytest.raises(TypeError, match="support must be"):
        replace(made()["racket"], support=None)
