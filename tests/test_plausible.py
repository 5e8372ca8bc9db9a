"""Plausibility in every unit and input path, km/h in and out, and honest numbers in the
outputs (issue 33): a speed beyond any recorded stroke warns whether typed in m/s, mph or
km/h (a racket head's against its own, lower bound); a TOML spec sheet is asked about as the
flags are; round-off is never printed as a negative loss; a refused range is quoted at the
precision it needs; a Parquet output without its library is refused before any work.
"""

import importlib.util
import re
from types import SimpleNamespace

import pytest

from common.checks import FASTEST_HEAD, FASTEST_STROKE, SPEED_RANGE, ends, in_range
from common.units import KMH, MPH, SPEED_SUFFIXES, SPEED_UNITS
from studies.cli import build_parser, main


def _run(argv, capsys):
    try:
        status = main(argv)
    except SystemExit as done:
        status = done.code
    out, err = capsys.readouterr()
    return status, out, err


def test_km_h_is_a_unit_of_speed():
    assert KMH == pytest.approx(1 / 3.6) and SPEED_UNITS == {"m/s": 1.0, "mph": MPH, "km/h": KMH}
    assert set(SPEED_SUFFIXES) == set(SPEED_UNITS)
    assert FASTEST_STROKE / KMH == pytest.approx(263.4)  # the serve record, as reported
    assert 31.0 < FASTEST_HEAD < FASTEST_STROKE  # above the pros' mean head speed, below the ball


@pytest.mark.parametrize(
    "argv, said",
    [
        (["serve", "--racket-speed-mph", "180"], "--racket-speed-mph 180 mph is faster than any "
         "recorded stroke (a racket head's fastest, estimated, about 115 mph)"),
        (["serve", "--racket-speed-kmh", "300"], "--racket-speed-kmh 300 km/h is faster than any "
         "recorded stroke (a racket head's fastest, estimated, about 184 km/h)"),
        (["serve", "--racket-speed", "60"], "--racket-speed 60 m/s is faster than any recorded "
         "stroke (a racket head's fastest, estimated, about 51.2 m/s)"),
        (["serve", "--target-ball-speed-mph", "250"], "--target-ball-speed-mph 250 mph is faster "
         "than any recorded stroke (the serve record, about 164 mph)"),
        (["serve", "--target-ball-speed-kmh", "280"], "--target-ball-speed-kmh 280 km/h is "
         "faster than any recorded stroke (the serve record, about 263 km/h)"),
        (["sweep", "--speed-kmh", "300", "--points", "3"], "--speed-kmh 300 km/h is faster"),
        (["ball", "--speeds-mph", "15", "200"], "--speeds-mph 200 mph is faster"),
        (["collide", "--va-kmh", "300"], "--va-kmh 300 km/h is faster"),
    ],
)  # fmt: skip
def test_a_speed_beyond_any_stroke_warns_in_every_unit(argv, said, capsys):
    """Allowed (the solvers are scale-free), but asked about, in the unit typed."""
    status, _, err = _run(argv, capsys)
    assert status == 0, err
    assert said in err, err


def test_a_usual_speed_in_any_unit_is_not_asked_about(capsys):
    for argv in (["serve", "--racket-speed-mph", "100"], ["serve", "--racket-speed-kmh", "150"]):
        status, _, err = _run(argv, capsys)
        assert status == 0 and "faster than" not in err, err


def test_each_slip_names_the_option_it_meant(capsys):
    """150 m/s is neither a ball nor a head speed: 150 mph or 150 km/h, each with its option."""
    status, _, err = _run(["sweep", "--speed", "150", "--points", "3"], capsys)
    assert status == 0
    assert "mph typed as m/s? 150 mph would be 67.06 m/s (--speed-mph 150)" in err, err
    assert "km/h typed as m/s? 150 km/h would be 41.67 m/s (--speed-kmh 150)" in err, err


@pytest.mark.parametrize("flags", [["--speeds", "7"], ["--speeds-mph", "15"]])
def test_a_speed_is_given_in_one_unit(flags, capsys):
    status, out, err = _run(["ball", *flags, "--speeds-kmh", "25"], capsys)
    assert status == 2 and out == "" and "not allowed with argument" in err


def test_km_h_in_km_h_out(tmp_path, capsys):
    import pandas as pd

    out_file = tmp_path / "b.csv"
    status, out, err = _run(["ball", "--speeds-kmh", "25.42", "--out", str(out_file)], capsys)
    assert status == 0, err
    assert out.startswith("ball itf-type-2 head on into a rigid wall at 25.42 km/h"), out
    assert "[km/h]" in "".join(out.splitlines()[1:4]), out  # (its header)
    table = pd.read_csv(out_file)
    assert table["speed_kmh"].iloc[0] == pytest.approx(25.42)
    assert table["speed_m_s"].iloc[0] == pytest.approx(25.42 / 3.6)
    status, out, err = _run(["collide", "--va-kmh", "14.4"], capsys)
    assert status == 0 and "velocity after [km/h]" in out, out


def test_speed_unit_is_the_unit_typed():
    from studies.cli.options import speed_unit

    parse = build_parser().parse_args
    assert speed_unit(parse(["collide"]), "va", "vb") == "m/s"
    assert speed_unit(parse(["collide", "--vb-mph", "2"]), "va", "vb") == "mph"
    assert speed_unit(parse(["collide", "--va-kmh", "20"]), "va", "vb") == "km/h"


def test_km_h_columns_are_labelled_in_km_h():
    from studies.cli.show import label

    assert label("exit_speed_kmh") == "exit speed [km/h]"
    assert label("serve_simulated_kmh") == "serve (simulated) [km/h]"


def test_a_toml_tension_in_kg_is_asked_about_as_the_flag_is(tmp_path, capsys):
    sheet = tmp_path / "sheet.toml"
    sheet.write_text(
        "[racket.specs]\nlength_m = 0.6858\nmass_kg = 0.318\nbalance_cm = 33\n"
        "swingweight_kgcm2 = 320\nf1_hz = 150\nhead_size_in2 = 100\ntension_lb = 25\n"
    )
    status, _, err = _run(["modes", "--racket", str(sheet)], capsys)
    assert status == 0, err
    assert (
        "[racket.specs] tension_lb 25 lb is below what rackets are strung at (40-65 lb): kg "
        "typed as lb? 25 kg would be 55.12 lb" in err
    ), err


def test_round_off_is_never_printed_as_a_negative_loss(capsys):
    """An elastic ball on the wall loses nothing: -3e-13 J of round-off is said as 0."""
    status, out, err = _run(["collide", "--a", "happy", "--b", "wall"], capsys)
    assert status == 0, err
    lost = next(line for line in out.splitlines() if line.startswith("energy lost [J]"))
    assert lost.split()[-1] == "0", out


def test_a_real_energy_gain_is_refused_as_a_fault():
    from studies.cli.balls import ROUND_OFF, energy_lost

    def collision(lost, initial=0.08):
        return SimpleNamespace(energy_lost=lost, energy_initial=initial)

    assert energy_lost(collision(-3e-13)) == 0.0 and energy_lost(collision(2e-13)) == 0.0
    assert energy_lost(collision(0.03)) == 0.03
    with pytest.raises(RuntimeError, match="gained"):
        energy_lost(collision(-10 * ROUND_OFF * 0.08))


@pytest.mark.parametrize(
    "low, high, said",
    [
        (SPEED_RANGE[0] / MPH, SPEED_RANGE[1] / MPH, "0.002237, 671"),
        (SPEED_RANGE[0] / KMH, SPEED_RANGE[1] / KMH, "0.0036, 1080"),
        (-300.0, 300.0, "-300, 300"),
        (1e3, 1e7, "1000, 1e+07"),
        (0.05, 1.0, "0.05, 1"),
        (20 * 4.4482216152605, 80 * 4.4482216152605, "88.97, 355.8"),
        (1.00001, 1.00002, "1.00001, 1.00002"),  # more digits only where the ends would meet
    ],
)
def test_a_range_is_quoted_at_the_precision_it_needs(low, high, said):
    assert ends(low, high) == said
    with pytest.raises(ValueError) as err:
        in_range("--x", 1e9, low, high, "u")
    assert f"--x must be in [{said}] u, got 1000000000" in str(err.value)
    quoted = [float(v) for v in said.split(", ")]  # rounded inwards: every value quoted is
    assert all(in_range("--x", v, low, high) == v for v in quoted)  # accepted


def test_a_refused_speed_quotes_its_range_plainly(capsys):
    status, _, err = _run(["sweep", "--speed-mph", "1000", "--points", "3"], capsys)
    assert status == 2 and "--speed-mph must be in [0.002237, 671] mph, got 1000" in err, err


def test_a_parquet_output_without_its_library_is_refused_before_any_work(
    tmp_path, capsys, monkeypatch
):
    found = importlib.util.find_spec

    def without_engines(name, *args, **kwargs):
        return None if name in ("pyarrow", "fastparquet") else found(name, *args, **kwargs)

    monkeypatch.setattr(importlib.util, "find_spec", without_engines)
    out_file = tmp_path / "c.parquet"
    status, out, err = _run(["collide", "--out", str(out_file)], capsys)
    assert status == 2 and out == "", out  # nothing computed, nothing printed
    assert len(err.strip().splitlines()) == 1, err
    assert re.search(r"--out: Parquet output needs pyarrow: pip install 'racket-impact\[parquet\]'",
                     err), err  # fmt: skip
    assert not out_file.exists()
