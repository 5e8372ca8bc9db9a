"""Every option of ``strings``, ``stroke``, ``court`` and ``bat``, and every argument of their
Python API, with a bad value, a unit slip and an extreme (issue 46's acceptance): a refusal is
one line naming the input as typed, with status 2 (ValueError in the API); a slip is a
warning or a refusal that names the slip; never a traceback.  The options are read from the
parser, so that an option added later without an entry in :data:`SLIPS` (or a reason in
:data:`NO_SLIP`) fails :func:`test_every_numeric_option_has_a_slip_case`."""

import argparse
import warnings

import pytest
from clihelpers import run_main

from studies.cli import build_parser

COMMANDS = ("strings", "stroke", "court", "bat")

BASE = {
    "strings": ["strings", "--strings", "polyester"],
    "stroke": ["stroke", "topspin-forehand"],
    "court": ["court", "hard"],
    "bat": ["bat", "sweep"],
}
"""Each command, small."""

NEEDS = {
    ("court", "--friction"): ["--cor", "0.75"],
    ("court", "--cor"): ["--friction", "0.4"],
    ("bat", "--clamps"): ["--support", "pivoted"],
    ("bat", "--at"): ["feel"],
    ("bat", "--handle"): ["feel"],
    ("bat", "--duration-ms"): ["feel"],
}
"""What an option needs beside it to apply (a bat's feel options: the action ``feel``)."""

SLIPS = {
    ("strings", "--tension-lb"): ("250", "error", "newtons typed as lb?"),
    ("strings", "--tension-kg"): ("55", "error", "lb typed as kg?"),
    ("strings", "--string-stiffness"): ("30", "error", "kN/m typed as N/m?"),
    ("strings", "--string-bed-dt"): ("300", "warning", "N/cm typed as kp/cm?"),
    ("strings", "--speed"): ("100", "warning", "mph typed as m/s?"),
    ("strings", "--speed-mph"): ("200", "warning", "km/h typed as mph?"),
    ("strings", "--speed-kmh"): ("400", "warning", "faster than any recorded stroke"),
    ("strings", "--racket-speed"): ("100", "warning", "mph typed as m/s?"),
    ("strings", "--racket-speed-mph"): ("200", "warning", "faster than any recorded stroke"),
    ("strings", "--racket-speed-kmh"): ("400", "warning", "faster than any recorded stroke"),
    ("stroke", "--tension-lb"): ("250", "error", "newtons typed as lb?"),
    ("stroke", "--tension-kg"): ("55", "error", "lb typed as kg?"),
    ("stroke", "--string-stiffness"): ("30", "error", "kN/m typed as N/m?"),
    ("stroke", "--string-bed-dt"): ("300", "warning", "N/cm typed as kp/cm?"),
    ("stroke", "--head-speed"): ("90", "error", "mph typed as m/s?"),
    ("stroke", "--head-speed-mph"): ("200", "error", "km/h typed as mph?"),
    ("stroke", "--head-speed-kmh"): ("400", "error", "--head-speed-kmh must be in"),
    ("stroke", "--path"): ("0.5", "warning", "radians typed as deg?"),
    ("stroke", "--face"): ("0.3", "warning", "radians typed as deg?"),
    ("stroke", "--across"): ("0.02", "warning", "radians typed as deg?"),
    ("stroke", "--ball-speed"): ("100", "error", "mph typed as m/s?"),
    ("stroke", "--ball-speed-mph"): ("200", "error", "km/h typed as mph?"),
    ("stroke", "--ball-speed-kmh"): ("400", "error", "--ball-speed-kmh must be in"),
    ("stroke", "--ball-angle"): ("0.5", "warning", "radians typed as deg?"),
    ("stroke", "--topspin"): ("300", "warning", "rad/s typed as rpm?"),
    ("stroke", "--sidespin"): ("30000", "error", "--sidespin must be in"),
    ("stroke", "--position"): ("0.17", "error", "m typed as cm?"),
    ("stroke", "--offset"): ("0.05", "warning", "m typed as cm?"),
    ("court", "--friction"): ("40", "error", "percent typed as a fraction?"),
    ("court", "--cor"): ("75", "error", "percent typed as a fraction?"),
    ("court", "--speed"): ("67", "warning", "mph typed as m/s?"),
    ("court", "--speed-mph"): ("200", "error", "km/h typed as mph?"),
    ("court", "--speed-kmh"): ("400", "error", "--speed-kmh must be in"),
    ("court", "--angle"): ("0.3", "warning", "radians typed as deg?"),
    ("court", "--topspin"): ("30000", "error", "--topspin must be in"),
    ("bat", "--pitch"): ("136", "warning", "typed as m/s?"),
    ("bat", "--pitch-mph"): ("300", "warning", "faster than any recorded pitch"),
    ("bat", "--pitch-kmh"): ("600", "warning", "faster than any recorded pitch"),
    ("bat", "--cm-speed"): ("54", "warning", "mph typed as m/s?"),
    ("bat", "--cm-speed-mph"): ("150", "error", "km/h typed as mph?"),
    ("bat", "--cm-speed-kmh"): ("300", "error", "--cm-speed-kmh must be in"),
    ("bat", "--omega"): ("500", "error", "rpm typed as rad/s?"),
    ("bat", "--pivot-from-knob"): ("0.15", "error", "m typed as cm?"),
    ("bat", "--clamps"): ("0.05", "warning", "m typed as cm?"),
    ("bat", "--from"): ("0.1", "error", "m typed as cm?"),
    ("bat", "--to"): ("0.1", "error", "m typed as cm?"),
    ("bat", "--at"): ("0.5", "error", "m typed as cm?"),
    ("bat", "--handle"): ("0.1", "error", "m typed as cm?"),
    ("bat", "--duration-ms"): ("0.02", "error", "seconds typed as ms?"),
}
"""Each numeric option's unit slip: the value, what it gets, and the words that name it."""

NO_SLIP = {
    ("bat", "--points"): "a count: no unit to slip",
}
"""The numeric options without a unit to slip, and why."""

NAMES = {"--racket", "--ball", "--string", "--gauge", "--pattern", "--lead", "--bat"}
"""The options that take a name (a preset, a file, a material, a size): a bad one is refused."""


def _options(command):
    parser = build_parser()
    sub = next(a for a in parser._actions if isinstance(a, argparse._SubParsersAction))
    return [a for a in sub.choices[command]._actions if a.option_strings and a.nargs != 0]


NUMERIC = [
    (c, a.option_strings[-1]) for c in COMMANDS for a in _options(c) if a.type in (int, float)
]
NAMED = [(c, a.option_strings[-1]) for c in COMMANDS for a in _options(c)
         if a.option_strings[-1] in NAMES]  # fmt: skip


def _said(argv):
    status, _, err = run_main(argv)
    assert "Traceback" not in err, err
    return status, [line for line in err.splitlines() if line.strip()]


def _argv(command, option, value):
    base = BASE[command]
    extra = NEEDS.get((command, option), [])
    if extra[:1] == ["feel"]:
        return ["bat", "feel", option, value]
    return [*base, *extra, option, value]


def _refused(command, option, value, words=None):
    status, lines = _said(_argv(command, option, value))
    assert status == 2, lines
    assert len(lines) == 1, lines
    assert lines[0].startswith(f"racket-impact {command}: error: "), lines
    assert option in lines[0], lines
    if words:
        assert words in lines[0], lines


def test_every_numeric_option_has_a_slip_case():
    assert set(NUMERIC) == set(SLIPS) | set(NO_SLIP)


@pytest.mark.parametrize("value", ["nan", "abc"])
@pytest.mark.parametrize("command, option", NUMERIC, ids=[" ".join(c) for c in NUMERIC])
def test_a_bad_value_is_refused_naming_the_option(command, option, value):
    _refused(command, option, value)


@pytest.mark.parametrize("value", ["1e300", "-1e300"])
@pytest.mark.parametrize("command, option", NUMERIC, ids=[" ".join(c) for c in NUMERIC])
def test_an_extreme_is_refused_naming_the_option_and_its_range(command, option, value):
    _refused(command, option, value)


@pytest.mark.parametrize("command, option", list(SLIPS), ids=[" ".join(c) for c in SLIPS])
def test_a_unit_slip_is_named(command, option):
    value, kind, words = SLIPS[command, option]
    if kind == "error":
        _refused(command, option, value, words)
        return
    status, lines = _said(_argv(command, option, value))
    assert status == 0, lines
    said = [
        line for line in lines if line.startswith(f"racket-impact {command}: warning: {option}")
    ]
    assert said and words in said[0], lines


@pytest.mark.parametrize("command, option", NAMED, ids=[" ".join(c) for c in NAMED])
def test_a_bad_name_is_refused_naming_the_option(command, option):
    _refused(command, option, "no-such-thing")


# ----- the Python API ---------------------------------------------------------------------
def _stroke(**changed):
    from racket import STROKES, Stroke

    base = STROKES["topspin-forehand"]
    fields = {k: getattr(base, k) for k in Stroke.__dataclass_fields__}
    return Stroke(**(fields | changed))


def _bounce(**changed):
    from ball.court import COURTS, bounce

    return bounce(**({"court": COURTS["hard"], "speed": 30.0, "angle": 0.3} | changed))


def _bat_swing(**changed):
    from bat import BatSwing

    return BatSwing(**({"angular_velocity": 51.0, "cm_speed": 24.0} | changed))


def _string_table(**changed):
    from racket import default_ball, default_racket
    from studies.strings.table import string_table

    args = {"racket": default_racket(), "ball": default_ball(), "speed": 16.5, "head_speed": 40.0}
    return string_table(**(args | {"strings": ("polyester",)} | changed))


API = {
    "Stroke": (
        _stroke,
        {
            "head_speed": 90.0,
            "ball_speed": 100.0,
            "topspin": 800.0,
            "path_angle": 1e300,
            "face_angle": 1e300,
            "ball_angle": 1e300,
            "swing_across": 1e300,
            "sidespin": 1e300,
        },
    ),
    "bounce": (_bounce, {"speed": 1e300, "angle": 1e300, "spin": 800.0}),
    "BatSwing": (
        _bat_swing,
        {"angular_velocity": 136.0, "cm_speed": 54.0, "pivot_from_knob": 15.0},
    ),
    "string_table": (
        _string_table,
        {"speed": 1e300, "head_speed": 1e300, "gauge": 125.0, "dt": 300.0},
    ),
}
"""Each API call, and for each argument a slip or an extreme."""

API_CASES = [(name, arg) for name, (_, args) in API.items() for arg in args]


@pytest.mark.parametrize("name, argument", API_CASES, ids=[" ".join(c) for c in API_CASES])
def test_every_api_argument_refuses_nan_and_names_its_slip_or_extreme(name, argument):
    call, values = API[name]
    with pytest.raises((ValueError, TypeError)) as bad:
        call(**{argument: float("nan")})
    assert argument in str(bad.value) and "\n" not in str(bad.value)
    with warnings.catch_warnings(record=True) as said:
        warnings.simplefilter("always")
        try:
            call(**{argument: values[argument]})
        except (ValueError, TypeError) as refused:
            assert argument in str(refused) and "\n" not in str(refused), refused
            return
    named = [str(w.message) for w in said if argument in str(w.message)]
    assert named, [str(w.message) for w in said]
