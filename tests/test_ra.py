"""The RA rating: the regression of f1 on RA over the 622 TWU rackets (re-fitted from the
table, checked against the TWU medians and an independent least-squares solve), and ``ra``
accepted wherever a frame stiffness is given (from_specs, TOML, the CLI, the page)."""

import csv
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from ball import BALL_PRESETS, DEFAULT_BALL
from racket import CATALOG, from_specs, impact
from racket.specs.ra import (
    CLEAR_GAIN,
    RA_INTERCEPT,
    RA_ROWS,
    RA_SCATTER,
    RA_SLOPE,
    f1_from_ra,
    fit_ra_regression,
)
from studies.cli import main
from studies.config import load_racket
from studies.page.dashboard import MY_SHEET, PageInputs, page_racket

TWU = Path(__file__).parent / "data" / "twu_racquets_half.csv"  # see data/README.md
SHEET = dict(mass_kg=0.321, balance_cm=33.0, swingweight_kgcm2=325, head_size_in2=100,
             tension_lb=55)  # fmt: skip


def _fit(extra=()):
    with open(TWU, newline="") as f:
        return fit_ra_regression(csv.DictReader(f), extra=extra)


def _table() -> pd.DataFrame:
    return pd.read_csv(TWU)


def _f1(racket) -> float:
    return float(racket.beam.modes.frequencies[0])


def test_the_stored_coefficients_are_a_refit_of_the_table():
    fit = _fit()
    assert fit.variables == ("ra",)
    assert fit.count == RA_ROWS == len(_table())
    assert fit.intercept == pytest.approx(RA_INTERCEPT, abs=1e-9)
    assert fit.slopes[0] == pytest.approx(RA_SLOPE, abs=1e-9)
    assert fit.scatter == pytest.approx(RA_SCATTER, abs=1e-9)


def test_the_fit_agrees_with_an_independent_line():
    table = _table()
    ra, f1 = table["RA Stiffness"].to_numpy(), table["Vibration Frequency (Hz)"].to_numpy()
    slope, intercept = np.polyfit(ra, f1, 1)
    fit = _fit()
    assert fit.slopes[0] == pytest.approx(slope, rel=1e-10)
    assert fit.intercept == pytest.approx(intercept, rel=1e-8)
    assert fit.r == pytest.approx(np.corrcoef(ra, f1)[0, 1], rel=1e-12)
    residual = f1 - np.polyval([slope, intercept], ra)
    assert fit.scatter == pytest.approx(np.std(residual, ddof=2), rel=1e-10)


@pytest.mark.parametrize("ra", [55, 66, 74])
def test_ra_gives_the_twu_median_frequency_within_the_scatter(ra):
    table = _table()
    near = (table["RA Stiffness"] - ra).abs() <= 1.0  # the rackets rated ra - 1 to ra + 1
    median = table.loc[near, "Vibration Frequency (Hz)"].median()
    print(f"\nRA {ra}: fit {f1_from_ra(ra):.1f} Hz, TWU median {median:.1f} Hz ({near.sum()} rows)")
    assert near.sum() >= 5
    assert abs(f1_from_ra(ra) - median) <= RA_SCATTER
    assert _f1(from_specs(ra=ra, **SHEET)) == pytest.approx(f1_from_ra(ra), rel=1e-9)


def test_mass_and_length_do_not_clearly_help():
    alone, more = _fit(), _fit(extra=("mass_kg", "length_m"))
    print(f"\nscatter: RA alone {alone.scatter:.2f} Hz, with mass and length {more.scatter:.2f} Hz")
    assert more.variables == ("ra", "mass_kg", "length_m")
    assert more.r > alone.r and more.scatter < alone.scatter  # they help a little ...
    assert more.scatter > CLEAR_GAIN * alone.scatter  # ... not enough to ask for them


def test_bad_rows_and_variables_are_named():
    with pytest.raises(ValueError, match=r"row 2 of the table: 'RA Stiffness' must be a number"):
        fit_ra_regression(
            [
                {"RA Stiffness": "66", "Vibration Frequency (Hz)": "150"},
                {"RA Stiffness": "", "Vibration Frequency (Hz)": "150"},
            ]
        )
    with pytest.raises(ValueError, match="the fit needs more than 2 rows"):
        fit_ra_regression([{"RA Stiffness": "66", "Vibration Frequency (Hz)": "150"}])
    with pytest.raises(ValueError, match="extra must name distinct variables"):
        fit_ra_regression([], extra=("swingweight",))
    with pytest.raises(ValueError, match=r"ra must be in \[40, 90\], got 95"):
        f1_from_ra(95)


def test_ra_in_a_toml_file_and_the_specs_command(tmp_path, capsys):
    path = tmp_path / "ra.toml"
    lines = [f"{key} = {value}" for key, value in (SHEET | {"ra": 70}).items()]
    path.write_text("[racket.specs]\n" + "\n".join(lines) + "\n")
    assert _f1(load_racket(str(path))) == pytest.approx(f1_from_ra(70), rel=1e-7)
    assert main(["specs", "--racket", str(path), "--count", "1"]) == 0
    out = capsys.readouterr().out
    lines = out.splitlines()
    said = 1 + next(i for i, line in enumerate(lines[1:]) if not line.startswith("  "))
    assert lines[0].startswith("racket ")  # the conditions (long path: folded), then the note
    note = f"f1 from RA 70: {f1_from_ra(70):.0f} +/- {RA_SCATTER:.0f} Hz (TWU regression, "
    assert note + f"{RA_ROWS} rackets)" in lines[said]
    row = next(line for line in lines[said + 1 :] if "f1 from RA 70" in line)  # the fit table
    assert f"TWU regression of {RA_ROWS} rackets" in row


def test_ra_on_the_sweep_command_line(tmp_path, capsys):
    table = tmp_path / "sweep.csv"
    argv = ["sweep", "--racket", "pure-drive-2021", "--ra", "60", "70", "--points", "2"]
    assert main([*argv, "--speed", "10", "--csv", str(table)]) == 0
    assert "f1 from RA 60" in capsys.readouterr().out
    swept = sorted(set(pd.read_csv(table)["f1_Hz"]))
    assert swept == pytest.approx([f1_from_ra(60), f1_from_ra(70)], rel=1e-9)


def test_ra_on_the_page():
    racket = page_racket(PageInputs(racket=MY_SHEET, f1_hz=None, ra=70))
    assert _f1(racket) == pytest.approx(f1_from_ra(70), rel=1e-9)


@pytest.mark.parametrize(
    "given",
    [
        dict(f1_hz=150, ra=66),
        dict(ra=66, flex_deflection_mm=5, flex_load_n=100),
        dict(f1_hz=150, flex_deflection_mm=5, flex_load_n=100),
        dict(f1_hz=150, ra=66, flex_deflection_mm=5, flex_load_n=100),
        dict(),
    ],
)
def test_exactly_one_frame_stiffness_in_one_line_naming_the_three(given):
    with pytest.raises(ValueError) as err:
        from_specs(**SHEET, **given)
    message = str(err.value)
    assert "\n" not in message and message.startswith("give exactly one frame stiffness")
    assert all(name in message for name in ("f1_hz", "ra", "flex_deflection_mm"))
    assert "cannot" not in message  # all three work


def test_the_scatter_matters_at_the_tip_not_at_the_centre():
    entry = CATALOG["pure-drive-2021"]
    ball = BALL_PRESETS[DEFAULT_BALL].ball()
    e = []
    sheet = {k: v for k, v in entry.specs.items() if k != "ra"}
    for f1 in f1_from_ra(entry.specs["ra"]) + np.array([-RA_SCATTER, RA_SCATTER]):
        racket = from_specs(**(sheet | {"f1_hz": f1}))
        e.append(impact(racket, ball, [racket.strings.extent[0], racket.strings.center], 10.0).e)
    tip, centre = np.subtract(e[1], e[0])
    print(f"\ne across the band: tip {e[0][0]:.4f} -> {e[1][0]:.4f}, centre {e[0][1]:.4f} -> "
          f"{e[1][1]:.4f}")  # fmt: skip
    assert tip > 0 and abs(tip) > 3 * abs(centre)  # a stiffer frame keeps more power at the tip
