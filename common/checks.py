"""Input checks shared by every layer.

Each check raises ``ValueError`` whose message names the argument, the value it got and
the valid range, so that a user (or the CLI, which prints the message as one line) can
see at once what to change.  The checks return the value as a float so that callers can
write ``self_k = positive("k", k, "N/m")``.
"""

from __future__ import annotations

import math

import numpy as np


def _unit(unit: str) -> str:
    return f" {unit}" if unit else ""


def finite(name: str, value, unit: str = "") -> float:
    """Return ``value`` as a float; raise ``ValueError`` if it is not a finite real number."""
    try:
        x = float(value)
    except (TypeError, ValueError):
        raise ValueError(f"{name} must be a finite number{_unit(unit)}, got {value!r}") from None
    if not math.isfinite(x):
        raise ValueError(f"{name} must be a finite number{_unit(unit)}, got {value!r}")
    return x


def positive(name: str, value, unit: str = "") -> float:
    """Return ``value`` as a float; raise ``ValueError`` unless it is finite and > 0."""
    x = finite(name, value, unit)
    if x <= 0.0:
        raise ValueError(f"{name} must be > 0{_unit(unit)}, got {value!r}")
    return x


def non_negative(name: str, value, unit: str = "") -> float:
    """Return ``value`` as a float; raise ``ValueError`` unless it is finite and >= 0."""
    x = finite(name, value, unit)
    if x < 0.0:
        raise ValueError(f"{name} must be >= 0{_unit(unit)}, got {value!r}")
    return x


def in_range(name: str, value, low: float, high: float, unit: str = "") -> float:
    """Return ``value`` as a float; raise ``ValueError`` unless ``low <= value <= high``."""
    x = finite(name, value, unit)
    if not low <= x <= high:
        raise ValueError(f"{name} must be in [{low:g}, {high:g}]{_unit(unit)}, got {value!r}")
    return x


def finite_array(name: str, values, unit: str = "") -> np.ndarray:
    """Return ``values`` as a float array; raise ``ValueError`` on NaN, inf or non-numbers."""
    try:
        a = np.asarray(values, dtype=float)
    except (TypeError, ValueError):
        raise ValueError(f"{name} must be finite numbers{_unit(unit)}, got {values!r}") from None
    if not np.all(np.isfinite(a)):
        bad = a[~np.isfinite(a)].ravel()[0]
        raise ValueError(f"{name} must be finite numbers{_unit(unit)}, got {bad!r}")
    return a
