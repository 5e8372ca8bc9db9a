"""Unit slips (issue 28): a value whose magnitude suggests another unit gets a hint naming
that unit and the value converted, on the command line's flags and in TOML files; the
impossible is refused (exit 2, one line), the possible but suspect is asked about (a
warning once the run has succeeded)."""

import re

import pytest

from common.checks import (
    GRAMS_AS_KG,
    KMH_AS_M_S,
    KMH_AS_MPH,
    MPH_AS_M_S,
    OZ_AS_KG,
    in_range,
    slip_hints,
)
from common.units import IN2, INCH, KMH, LB, MPH, OUNCE
from studies.cli import main

SHEET = {
    "length_m": "0.6858",
    "mass_kg": "0.318",
    "balance_cm": "33",
    "swingweight_kgcm2": "320",
    "f1_hz": "150",
    "head_size_in2": "100",
    "tension_lb": "52",
}


def _sheet(tmp_path, key, value):
    """A spec-sheet racket whose ``key`` is ``value`` (the others a real racket's)."""
    keys = {k: v for k, v in SHEET.items() if k.split("_")[0] != key.split("_")[0]}
    keys[key] = value
    path = tmp_path / "sheet.toml"
    path.write_text("[racket.specs]\n" + "".join(f"{k} = {v}\n" for k, v in keys.items()))
    return ["modes", "--racket", str(path)]


def _toml(tmp_path, text):
    path = tmp_path / "slip.toml"
    path.write_text(text)
    return path


# (command, refused or warned, the likely unit, the value typed in it, converted, unit asked)
CASES = [
    (["serve", "--racket-speed", "110"], "warn", "mph", "110 mph", 110 * MPH, "m/s"),
    (["sweep", "--speed", "120", "--points", "3"], "warn", "mph", "120 mph", 120 * MPH, "m/s"),
    (["feel", "--speed", "90"], "warn", "mph", "90 mph", 90 * MPH, "m/s"),
    (["sweep", "--speed", "150", "--points", "3"], "warn", "km/h", "150 km/h", 150 * KMH, "m/s"),
    (["serve", "--racket-speed-mph", "180"], "warn", "km/h", "180 km/h", 180 * KMH / MPH, "mph"),
    (["serve", "--target-ball-speed-mph", "250"], "warn", "km/h", "250 km/h", 250 * KMH / MPH,
     "mph"),
    (["serve", "--position", "0.17"], "refuse", "m", "0.17 m", 17.0, "cm from the tip"),
    (["feel", "--position", "0.17"], "refuse", "m", "0.17 m", 17.0, "cm from the tip"),
    (["sweep", "--from", "0.05"], "refuse", "m", "0.05 m", 5.0, "cm from the tip"),
    (["sweep", "--tension-lb", "245", "--points", "3"], "refuse", "newtons", "245 N",
     245 / LB, "lb"),
    (["compare", "--tension-lb", "25", "--points", "3"], "warn", "kg", "25 kg", 25 * 9.80665 / LB,
     "lb"),
    (["serve", "--pivot-cm-from-tip", "0.5"], "refuse", "m", "0.5 m", 50.0, "cm"),
    (["feel", "--duration-ms", "0.05"], "refuse", "seconds", "0.05 s", 50.0, "ms"),
    (["sweep", "--string-stiffness", "40", "--points", "3"], "refuse", "kN/m", "40", 40000.0,
     "N/m"),
    (["drop", "--height-m", "254"], "refuse", "cm", "254", 2.54, "m"),
    ("sheet", "head_size_in2", "645", "refuse", "cm^2", "645 cm^2", 645e-4 / IN2, "in^2"),
    ("sheet", "head_size_cm2", "100", "refuse", "in^2", "100 in^2", 100 * IN2 * 1e4, "cm^2"),
    ("sheet", "balance_cm", "12.4", "refuse", "inches", "12.4 in", 12.4 * 100 * INCH, "cm"),
    ("sheet", "balance_cm", "0.33", "refuse", "m", "0.33 m", 33.0, "cm"),
    ("sheet", "swingweight_kgcm2", "0.0325", "refuse", "kg m^2", "0.0325 kg m^2", 325.0,
     "kg cm^2"),
    ("sheet", "twistweight_kgcm2", "0.0015", "refuse", "kg m^2", "0.0015 kg m^2", 15.0,
     "kg cm^2"),
    ("sheet", "mass_kg", "11.3", "refuse", "ounces", "11.3 oz", 11.3 * OUNCE, "kg"),
    ("sheet", "mass_kg", "318", "refuse", "grams", "318", 0.318, "kg"),
    ("sheet", "length_m", "27", "refuse", "inches", "27 in", 27 * INCH, "m"),
    ("sheet", "tension_n", "55", "refuse", "lb", "55 lb", 55 * LB, "N"),
    ("sheet", "tension_lb", "240", "refuse", "newtons", "240 N", 240 / LB, "lb"),
    ("sheet", "tension_lb", "25", "warn", "kg", "25 kg", 25 * 9.80665 / LB, "lb"),
    ("sheet", "string_stiffness_n_m", "30", "refuse", "kN/m", "30", 30000.0, "N/m"),
    ("toml", "[racket]\nmass = 11.3\n", None, "refuse", "ounces", "11.3 oz", 11.3 * OUNCE, "kg"),
    ("toml", "[ball]\nmass = 2\nlaw = 'linear-spring'\nk = 4e4\n", None, "refuse", "ounces",
     "2 oz", 2 * OUNCE, "kg"),
]  # fmt: skip


def _argv(case, tmp_path):
    if case[0] == "sheet":
        _, key, value, *expected = case
        return _sheet(tmp_path, key, value), expected
    if case[0] == "toml":
        _, text, _, *expected = case
        path = _toml(tmp_path, text)
        kind = "ball" if text.startswith("[ball]") else "racket"
        return (["ball", str(path)] if kind == "ball" else ["modes", "--racket", str(path)]), (
            expected
        )
    return case[0], list(case[1:])


def _said(value: float) -> str:
    return f"{float(f'{value:.4g}'):g}"


@pytest.mark.parametrize("case", CASES, ids=lambda c: " ".join(map(str, c[:3])))
def test_a_unit_slip_names_the_likely_unit_and_the_value_converted(case, tmp_path, capsys):
    argv, (how, likely, typed, converted, unit) = _argv(case, tmp_path)
    try:
        status = main(argv)
    except SystemExit as done:
        status = done.code
    out, err = capsys.readouterr()
    asked = unit.split(" from")[0]  # "cm from the tip": cm
    hint = f"{likely} typed as {asked}? {typed} would be {_said(converted)} {unit}"
    if how == "refuse":
        assert status == 2 and out == ""
        said = [line for line in err.splitlines() if "compiling the solver" not in line]
        assert len(said) == 1, err  # one line (beside a first run's compile notice)
    else:
        assert status == 0
        assert "warning" in err
    assert hint in err, err


def test_the_slips_are_the_units_factors():
    """The factors are the units' sizes, not numbers typed twice."""
    assert slip_hints(100, 0.0, 73.0, "m/s", [MPH_AS_M_S]) == (
        "mph typed as m/s? 100 mph would be 44.7 m/s"
    )
    assert MPH_AS_M_S[0] == MPH and OZ_AS_KG[0] == OUNCE
    assert KMH_AS_M_S[0] == KMH and KMH_AS_MPH[0] == pytest.approx(1.609344**-1)
    # a value two slips could explain names both
    with pytest.raises(ValueError) as err:
        in_range("[ball] mass", 2, 0.001, 1.0, "kg", slips=(GRAMS_AS_KG, OZ_AS_KG))
    assert re.search(r"grams typed as kg\? 2 would be 0\.002 kg; ounces typed as kg\?", str(err))


def test_a_value_no_slip_explains_gets_the_range_only(capsys):
    assert main(["serve", "--position", "-3"]) == 2
    err = capsys.readouterr().err
    assert "must be in" in err and "typed as" not in err


def test_a_usual_value_is_not_asked_about(capsys):
    assert main(["compare", "--tension-lb", "55", "--points", "3"]) == 0
    assert "typed as" not in capsys.readouterr().err


def test_a_speed_above_any_stroke_is_asked_about_even_without_a_slip(capsys):
    """250 mph is no km/h slip (250 km/h is 155 mph, still too fast), but still suspect
    (200 m/s, the case before issue 46, is now beyond what the model answers: refused)."""
    assert main(["serve", "--racket-speed-mph", "250"]) == 0
    err = capsys.readouterr().err
    assert "--racket-speed-mph 250 mph is faster than any recorded stroke" in err, err
    assert "typed as" not in err
