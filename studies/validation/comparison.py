"""One measured number beside the model's value under its conditions, and the two kinds
of comparison (calibration, validation).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field

KINDS = ("validation", "calibration")
"""The kinds of comparison: a number the model was not set from, or one it was."""

COLUMNS = ("quantity", "conditions", "measured", "low", "high", "model", "agrees", "kind", "source",
           "band_from", "gap")  # fmt: skip
"""The columns of :func:`validation_table`."""


@dataclass(frozen=True)
class Comparison:
    """One measured number and the model's value under its conditions.

    Attributes
    ----------
    name : str
        Short identifier (the test's id).
    quantity : str
        What is compared, with its unit.
    conditions : str
        The measurement's conditions, as the model runs them.
    measured : float
        The published value [the unit of ``quantity``].
    low, high : float
        The band the model must fall in [the unit of ``quantity``].
    source : str
        Where the value was read.
    kind : str
        ``"validation"`` or ``"calibration"`` (:data:`KINDS`).
    band : str
        Where the band comes from: the source's own, or an assumption (said so).
    model : callable
        Returns the model's value (same unit as ``measured``).
    spread : callable, optional
        Returns how far [the unit of ``quantity``] the model's value moves under the
        measurement's stated input scatter (root-sum-square of each input's half range): the
        band widens by it on both sides, in quadrature (:meth:`limits`); None: no input
        scatter stated.
    gap : str
        Why a calibration row lies outside its band: the calibration's compromise, said by
        ``validate`` beside the row, never silent; empty for a row that holds
        (``tests/test_one_band.py`` keeps the two together).
    """

    name: str
    quantity: str
    conditions: str
    measured: float
    low: float
    high: float
    source: str
    kind: str
    band: str
    model: Callable[[], float] = field(repr=False, compare=False)
    spread: Callable[[], float] | None = field(default=None, repr=False, compare=False)
    gap: str = ""

    def __post_init__(self):
        if self.kind not in KINDS:
            raise ValueError(f"kind must be one of {KINDS}, got {self.kind!r}")
        if not self.low <= self.high:
            raise ValueError(f"{self.name}: band must have low <= high, got {self.low, self.high}")

    def agrees(self, value: float) -> bool:
        """Whether ``value`` lies in the band, low to high.

        Parameters
        ----------
        value : float
            The model's value [the unit of ``quantity``].
        """
        low, high = self.limits()
        return bool(low <= value <= high)

    def limits(self) -> tuple[float, float]:
        """The band [the unit of ``quantity``]: ``low`` to ``high``, each side's distance from
        the measured value combined in quadrature with the model's :attr:`spread` under the
        inputs' scatter, if any (independent uncertainties).
        """
        if self.spread is None:
            return self.low, self.high
        spread = float(self.spread())
        below = math.hypot(self.measured - self.low, spread)
        above = math.hypot(self.high - self.measured, spread)
        return self.measured - below, self.measured + above
