"""Every racket Tennis Warehouse University measured, through the spec-sheet fit.

The TWU table (``tests/data/twu_racquets_half.csv``: 622 strung rackets, every other row of
the TWU racquet database as scraped in the public repository ``PeterTsai23/racquet_savant``,
July 2024; columns and provenance in ``tests/data/README.md``) gives each racket's head size,
length, beam width, mass, balance, swingweight, twistweight and free vibration frequency.
:func:`fit_table` fits every row with :func:`racket.specs.fit_profile` (mass, balance and
swingweight, the measured frequency as ``f1_hz``) and reports, per row, whether it fits or is
refused and why; the twistweight the mass model predicts when it is not given; and how
closely the fit meets it when it is.  ``python -m studies.twu [CSV]`` prints the summary.

The twistweight is a validation here, not a calibration: no parameter of the roll inertia
was fitted to these rows.  One row did set a range: the handle's lower bound (30 g,
:mod:`racket.specs.parts`) was lowered for the Head Graphene Instinct PWR, so that row's fit
calibrates and does not validate.
"""

from __future__ import annotations

import re
import sys
from pathlib import Path

import numpy as np
import pandas as pd

from beam import SWINGWEIGHT_AXIS
from common.units import INCH
from racket.specs import fit_profile, spec_sheet
from racket.specs.mass_fit import fit_masses

TWU_TABLE = Path(__file__).resolve().parents[1] / "tests" / "data" / "twu_racquets_half.csv"
"""The TWU table (622 rows; provenance in ``tests/data/README.md``)."""

TENSION_LB = 55.0
"""String tension given to every row [lb] (assumption: the table has none; it sets only the
string bed, not the mass fit)."""

EXACT = 1e-9
"""Largest relative difference between the fitted and the measured mass, balance,
swingweight and frequency for a row to count as fitted exactly."""

REASONS = {
    "spec range": "a number outside the spec sheet's accepted range",
    "swingweight above reach": "swingweight too high for the mass and balance",
    "swingweight below reach": "swingweight too low for the mass and balance",
    "balance": "balance out of reach for the mass",
    "mass_kg": "mass out of reach",
    "head size": "head too large for the length",
}
"""The named reasons a sheet is refused, keyed by what the refusal's message starts with
(:func:`refusal_reason`)."""

_RANGE = re.compile(r"^\w+ must be in \[")  # spec_sheet's range check
_SWING = re.compile(
    r"^swingweight_kgcm2 must be in \(?([-\d.]+)(?:, ([-\d.]+)\))?.* got ([-\d.]+)$"
)


def sheet_keywords(row) -> dict:
    """The :func:`racket.from_specs` keywords of a row of the TWU table.

    Parameters
    ----------
    row : Mapping
        A row with the table's columns (length in in, head size in^2, beam width mm, weight
        g, balance cm from the butt, swingweight kg cm^2, vibration frequency Hz).
    """
    return dict(
        length_m=float(row["Length (in)"]) * INCH,
        mass_kg=float(row["Weight (g)"]) / 1e3,
        balance_cm=float(row["Balance (cm)"]),
        swingweight_kgcm2=float(row["Swingweight (kg cm^2)"]),
        head_size_in2=float(row["Headsize (sq in)"]),
        beam_width_mm=float(row["Beam Width (mm)"]),
        f1_hz=float(row["Vibration Frequency (Hz)"]),
        tension_lb=TENSION_LB,
    )


def refusal_reason(message: str) -> str:
    """The named reason (a value of :data:`REASONS`) of a refusal's message; ValueError
    for a message no reason names.

    Parameters
    ----------
    message : str
        The ValueError's text from :func:`racket.specs.fit_profile`.
    """
    if _RANGE.match(message):
        return REASONS["spec range"]
    match = _SWING.match(message)
    if match:
        low, high, got = match.groups()
        side = "above" if float(got) > float(high or low) else "below"
        return REASONS[f"swingweight {side} reach"]
    for start, reason in REASONS.items():
        if message.startswith(start):
            return reason
    raise ValueError(f"unclassified refusal: {message}")


def recoil_to_rod(row) -> float:
    """The row's recoil weight (moment of inertia about the centre of mass) over a uniform
    rod's of its mass and length, M L^2 / 12 [-]: a racket carries mass at both ends, so
    this is near 1.2 (1.21 +/- 0.08 over the TWU table); far from it, the sheet is suspect.

    Parameters
    ----------
    row : Mapping
        A row of the TWU table.
    """
    specs = sheet_keywords(row)
    mass, length = specs["mass_kg"], specs["length_m"]
    arm = specs["balance_cm"] / 100.0 - SWINGWEIGHT_AXIS
    recoil = specs["swingweight_kgcm2"] * 1e-4 - mass * arm**2
    return float(recoil / (mass * length**2 / 12.0))


def fit_row(row) -> dict:
    """Fit one row of the TWU table: whether it fits or why it is refused, the fit's largest
    relative miss of mass, balance, swingweight and frequency, the twistweight predicted
    without it and the fit's miss when it is given.

    Parameters
    ----------
    row : Mapping
        A row of the TWU table.

    Returns
    -------
    dict
        ``status`` ("fit" or "refused"), ``reason`` (:data:`REASONS`' value, or ""),
        ``message``, ``recoil_to_rod``, ``worst_relative_miss``,
        ``twistweight_measured_kgcm2``, ``twistweight_predicted_kgcm2`` (fitted without it),
        ``twistweight_error_kgcm2`` (predicted minus measured) and
        ``twistweight_given_miss_kgcm2`` (fitted with it, minus it); NaN where not fitted.
    """
    measured = float(row["Twistweight (kg cm^2)"])
    out = dict(
        status="fit",
        reason="",
        message="",
        recoil_to_rod=recoil_to_rod(row),
        worst_relative_miss=np.nan,
        twistweight_measured_kgcm2=measured,
        twistweight_predicted_kgcm2=np.nan,
        twistweight_error_kgcm2=np.nan,
        twistweight_given_miss_kgcm2=np.nan,
    )
    try:
        sheet = spec_sheet(**sheet_keywords(row))
        beam, profile = fit_profile(sheet)
    except ValueError as err:
        return out | dict(status="refused", reason=refusal_reason(str(err)), message=str(err))
    out["worst_relative_miss"] = max(
        abs(got / want - 1.0)
        for got, want in (
            (beam.mass, sheet.mass),
            (beam.balance, sheet.balance),
            (beam.swingweight, sheet.swingweight),
            (beam.modes.frequencies[0], sheet.f1),
        )
    )
    predicted = beam.twistweight_kgcm2
    # the same mass fit fit_profile makes, now with the twistweight (the beam's stiffness and
    # modes do not change the roll inertia)
    given = fit_masses(
        profile.layout, sheet.mass, sheet.balance, sheet.swingweight, measured * 1e-4
    )
    out.update(
        twistweight_predicted_kgcm2=predicted,
        twistweight_error_kgcm2=predicted - measured,
        twistweight_given_miss_kgcm2=1e4 * given.twistweight_residual,
    )
    return out


def fit_table(table: pd.DataFrame) -> pd.DataFrame:
    """:func:`fit_row` of every row of ``table``, beside the row's brand, model and specs.

    Parameters
    ----------
    table : DataFrame
        Rows of the TWU table (:data:`TWU_TABLE`'s columns).
    """
    fits = pd.DataFrame([fit_row(row) for _, row in table.iterrows()], index=table.index)
    return pd.concat([table, fits.drop(columns="twistweight_measured_kgcm2")], axis=1)


def summary(result: pd.DataFrame) -> dict:
    """The numbers the docs quote, from a :func:`fit_table` result.

    Parameters
    ----------
    result : DataFrame
        The result of :func:`fit_table`.

    Returns
    -------
    dict
        ``rows``, ``fit``, ``refused``, ``refused_share``, ``reasons`` (count of each),
        ``worst_relative_miss``; the twistweight predicted without it, minus measured:
        ``twist_median`` (signed), ``twist_abs_median``, ``twist_abs_p90`` [kg cm^2]; with
        it given: ``twist_met`` (rows where parts in range meet it exactly) and, of the others,
        ``twist_miss_median``, ``twist_miss_p90`` and ``twist_miss_max`` (absolute) [kg cm^2].
    """
    fitted = result[result.status == "fit"]
    error = fitted.twistweight_error_kgcm2
    miss = fitted.twistweight_given_miss_kgcm2.abs()
    missed = miss[miss > 0.0]  # fit_masses returns 0.0 when the parts meet it
    return dict(
        rows=len(result),
        fit=len(fitted),
        refused=len(result) - len(fitted),
        refused_share=(len(result) - len(fitted)) / len(result),
        reasons=result.reason[result.status == "refused"].value_counts().to_dict(),
        worst_relative_miss=float(fitted.worst_relative_miss.max()),
        twist_median=float(error.median()),
        twist_abs_median=float(error.abs().median()),
        twist_abs_p90=float(error.abs().quantile(0.9)),
        twist_met=len(fitted) - len(missed),
        twist_miss_median=float(missed.median()) if len(missed) else 0.0,
        twist_miss_p90=float(missed.quantile(0.9)) if len(missed) else 0.0,
        twist_miss_max=float(missed.max()) if len(missed) else 0.0,
    )


def main(argv: list[str] | None = None) -> None:
    """Fit the TWU table (the path in ``argv``, default :data:`TWU_TABLE`) and print the
    summary and the refused rows.

    Parameters
    ----------
    argv : list of str, optional
        Command-line arguments: an optional path to the table.
    """
    argv = sys.argv[1:] if argv is None else argv
    result = fit_table(pd.read_csv(argv[0] if argv else TWU_TABLE))
    for name, value in summary(result).items():
        print(f"{name:20s} {value}")
    refused = result[result.status == "refused"]
    print(refused[["Brand", "Model", "recoil_to_rod", "reason", "message"]].to_string())


if __name__ == "__main__":
    main()
