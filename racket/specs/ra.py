"""The frame's first free bending frequency from its RA rating: a regression on 622 rackets.

RA is the stiffness index of the Babolat RDC, the number every spec sheet prints: a static
test, "supporting the racquet at the handle and in the throat while a force is applied to
the tip; the stiffness index is a measurement of how much the racquet tip is deflected"
(Tennis Warehouse University, "Racquet vibration explained").  Babolat publishes neither the
load nor the scale, so RA cannot be turned into a stiffness by beam theory; what can be done
is to read the first free bending frequency f1, which the model needs, off rackets measured
both ways.

Tennis Warehouse University measured both on the strung rackets of its racquet database: the
table ``tests/data/twu_racquets_half.csv`` (every other row, 622 of 1244, of the database as
scraped in the public repository ``PeterTsai23/racquet_savant``, July 2024; provenance in
``tests/data/README.md``) holds each racket's ``RA Stiffness`` and ``Vibration Frequency
(Hz)`` (freely suspended frames, 97-198 Hz).  Over it, by least squares,

    f1 = :data:`RA_INTERCEPT` + :data:`RA_SLOPE` RA  (RA 55, 66, 74: 124, 150, 168 Hz),

with r = 0.873 and a residual scatter (standard deviation, 620 degrees of freedom) of
:data:`RA_SCATTER` = 5.6 Hz; half the rackets lie within 2.7 Hz of the line, 90 % within
8.9 Hz, and a few far off it (the Wilson Burn FST 99S, RA 74, rings 37 Hz below).  The RA
range of the table is 44-76: outside it (``ra`` is accepted from 40 to 90, giving 89-206 Hz)
the line is extrapolated.

Adding the strung mass and the length (``extra=("mass_kg", "length_m")`` of
:func:`fit_ra_regression`) gives f1 = 17.3 + 2.223 RA - 118.4 Hz/kg M + 32.7 Hz/m L with a
scatter of 4.9 Hz (r = 0.904): the mass is significant (at a given tip stiffness a heavier
frame rings lower) but narrows the band by only 12 %, and the length adds nothing once the
mass is in (its coefficient is 0.7 standard errors from zero).  An added variable is kept
when it shrinks the scatter below :data:`CLEAR_GAIN` of RA alone's; these do not, so the
model uses RA alone (which also needs nothing else from the sheet and is not extrapolated
for a racket lighter or heavier than the table's 242-365 g).

To re-fit (the tests do, and compare with the constants below to 1e-9)::

    import csv
    with open("tests/data/twu_racquets_half.csv", newline="") as f:
        fit = fit_ra_regression(csv.DictReader(f))
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from dataclasses import dataclass

import numpy as np

from common.checks import in_range
from common.units import INCH
from racket.specs.sheet import SPEC_RANGES

COLUMNS = {
    "f1": ("Vibration Frequency (Hz)", 1.0),
    "ra": ("RA Stiffness", 1.0),
    "mass_kg": ("Weight (g)", 1e-3),
    "length_m": ("Length (in)", INCH),
}
"""The TWU table's column of each variable, and the factor to SI (g to kg, in to m)."""

RA_INTERCEPT = -3.9851652893484655
"""Intercept a [Hz] of f1 = a + b RA (least squares over the 622 rows of
``tests/data/twu_racquets_half.csv``, TWU racquet database as scraped in July 2024; fitted
by :func:`fit_ra_regression` on 2026-11-24)."""

RA_SLOPE = 2.328890935495055
"""Slope b [Hz per RA point] of f1 = a + b RA (same fit as :data:`RA_INTERCEPT`)."""

RA_SCATTER = 5.618105199748102
"""Residual standard deviation [Hz] of the same fit (622 rows, 620 degrees of freedom): the
frequency of a racket of given RA is known to about this much."""

RA_ROWS = 622
"""Rackets (rows of the TWU table) the stored regression was fitted on."""

CLEAR_GAIN = 0.75
"""A variable added to RA is kept when it brings the regression's scatter below this
fraction of RA alone's (assumption: a band a quarter narrower is worth asking the user for
more; the mass and length narrow it by 12 %, so RA alone is kept)."""


@dataclass(frozen=True)
class Regression:
    """A least-squares fit f1 = intercept + sum(slopes * variables) (:func:`fit_ra_regression`).

    Attributes
    ----------
    variables : tuple of str
        The variables, ``"ra"`` first, then any of ``"mass_kg"`` and ``"length_m"``.
    intercept : float
        Intercept [Hz].
    slopes : tuple of float
        Slope of each variable [Hz per unit of the variable: per RA point, Hz/kg, Hz/m].
    scatter : float
        Residual standard deviation [Hz] (rows less coefficients as degrees of freedom).
    r : float
        Correlation of the fitted with the measured frequencies [-].
    count : int
        Rows fitted.
    """

    variables: tuple
    intercept: float
    slopes: tuple
    scatter: float
    r: float
    count: int


def _number(row: Mapping, column: str, index: int) -> float:
    """The row's value in ``column`` as a finite float; ValueError naming the row and column."""
    value = row.get(column) if isinstance(row, Mapping) else None
    try:
        x = float(value)
    except (TypeError, ValueError):
        x = np.nan
    if not np.isfinite(x):
        raise ValueError(
            f"row {index + 1} of the table: {column!r} must be a number, got {value!r}"
        )
    return x


def fit_ra_regression(rows: Iterable[Mapping], extra: tuple = ()) -> Regression:
    """The least-squares line f1 = a + b RA (plus a slope for each of ``extra``) over rows
    of the TWU racquet table.

    Parameters
    ----------
    rows : iterable of mapping
        The table's rows by column name, as :class:`csv.DictReader` yields them; the columns
        of :data:`COLUMNS` that the fit uses must hold numbers (RA [-], frequency [Hz],
        weight [g], length [in]).
    extra : tuple of str, optional
        Variables fitted beside RA: ``"mass_kg"``, ``"length_m"`` (converted to SI).

    Returns
    -------
    Regression
        The coefficients (frequency in Hz, variables in SI), the scatter and r.
    """
    extra = tuple(extra)
    unknown = [name for name in extra if name not in COLUMNS or name in ("f1", "ra")]
    if unknown or len(set(extra)) != len(extra):
        raise ValueError(f"extra must name distinct variables of mass_kg, length_m, got {extra}")
    variables = ("ra", *extra)
    data = np.array(
        [
            [_number(row, COLUMNS[name][0], i) * COLUMNS[name][1] for name in ("f1", *variables)]
            for i, row in enumerate(rows)
        ]
    ).reshape(-1, 1 + len(variables))
    count = data.shape[0]
    if count <= len(variables) + 1:
        raise ValueError(
            f"the fit needs more than {len(variables) + 1} rows for {len(variables) + 1} "
            f"coefficients, got {count}"
        )
    f1 = data[:, 0]
    design = np.column_stack([np.ones(count), data[:, 1:]])
    coefficients = np.linalg.lstsq(design, f1, rcond=None)[0]
    fitted = design @ coefficients
    residual = f1 - fitted
    return Regression(
        variables=variables,
        intercept=float(coefficients[0]),
        slopes=tuple(float(c) for c in coefficients[1:]),
        scatter=float(np.sqrt(residual @ residual / (count - design.shape[1]))),
        r=float(np.corrcoef(fitted, f1)[0, 1]),
        count=count,
    )


def f1_from_ra(ra: float) -> float:
    """The first free bending frequency [Hz] of a strung frame of RA rating ``ra`` by the
    stored regression (:data:`RA_INTERCEPT`, :data:`RA_SLOPE`; uncertain by
    :data:`RA_SCATTER`).

    Parameters
    ----------
    ra : float
        RA rating [-], in the range of :data:`~racket.specs.sheet.SPEC_RANGES`.
    """
    low, high, _ = SPEC_RANGES["ra"]
    return RA_INTERCEPT + RA_SLOPE * in_range("ra", ra, low, high)


def ra_note(ra: float) -> str:
    """One line saying which f1 [Hz] the RA rating ``ra`` [-] gives, with the scatter and
    the regression's source, e.g. "f1 from RA 66: 150 +/- 6 Hz (TWU regression, 622 rackets)".

    Parameters
    ----------
    ra : float
        RA rating [-], in the range of :data:`~racket.specs.sheet.SPEC_RANGES`.
    """
    return (
        f"f1 from RA {ra:g}: {f1_from_ra(ra):.0f} +/- {RA_SCATTER:.0f} Hz (TWU regression, "
        f"{RA_ROWS} rackets)"
    )
