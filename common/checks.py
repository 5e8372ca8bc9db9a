"""Input checks shared by every layer.

Each check raises ``ValueError`` whose message names the argument, the value it got (as
the user gave it, a plain number) and the valid range, so that a user (or the CLI, which
prints the message as one line) can see at once what to change.  The checks return the
value as a float so that callers can write ``self_k = positive("k", k, "N/m")``.
"""

from __future__ import annotations

import math
import numbers

import numpy as np

SPEED_RANGE = (1e-3, 300.0)
"""Impact and swing speeds [m/s] racket-impact accepts: from 1 mm/s to well above the
fastest recorded serve (73 m/s, 163 mph).  The solvers are scale-free and resolve far more;
outside this range a number is almost surely a typo (or the wrong unit)."""


FASTEST_STROKE = 73.0
"""The fastest recorded serve [m/s] (163 mph; an assumption as to the exact record, which
is about this): a speed typed in m/s above it is more likely mph typed as m/s."""


def _unit(unit: str) -> str:
    return f" {unit}" if unit else ""


def shown(value) -> str:
    """``value`` as a message quotes it: a number plainly (0.325, not np.float64(0.325)).

    Parameters
    ----------
    value : object
        The value to quote.
    """
    if isinstance(value, bool | np.bool_):
        return repr(bool(value))
    if isinstance(value, numbers.Integral):
        return str(int(value))
    if isinstance(value, numbers.Real):
        x = float(value)
        return str(int(x)) if x.is_integer() and abs(x) < 1e15 else repr(x)
    return repr(value)


def finite(name: str, value, unit: str = "") -> float:
    """Return ``value`` as a float; raise ``ValueError`` if it is not a finite real number.

    Parameters
    ----------
    name : str
        The argument's name, as the message quotes it.
    value : object
        The value to check, in ``unit``.
    unit : str, optional
        Its unit, as the message quotes it (e.g. ``"m/s"``); "" for none.
    """
    if isinstance(value, bool | np.bool_ | str):
        raise ValueError(f"{name} must be a finite number{_unit(unit)}, got {shown(value)}")
    try:
        x = float(value)
    except (TypeError, ValueError, OverflowError):
        raise ValueError(
            f"{name} must be a finite number{_unit(unit)}, got {shown(value)}"
        ) from None
    if not math.isfinite(x):
        raise ValueError(f"{name} must be a finite number{_unit(unit)}, got {shown(value)}")
    return x


def positive(name: str, value, unit: str = "") -> float:
    """Return ``value`` as a float; raise ``ValueError`` unless it is finite and > 0.

    Parameters
    ----------
    name : str
        The argument's name, as the message quotes it.
    value : object
        The value to check, in ``unit``.
    unit : str, optional
        Its unit, as the message quotes it (e.g. ``"m/s"``); "" for none.
    """
    x = finite(name, value, unit)
    if x <= 0.0:
        raise ValueError(f"{name} must be > 0{_unit(unit)}, got {shown(value)}")
    return x


def non_negative(name: str, value, unit: str = "") -> float:
    """Return ``value`` as a float; raise ``ValueError`` unless it is finite and >= 0.

    Parameters
    ----------
    name : str
        The argument's name, as the message quotes it.
    value : object
        The value to check, in ``unit``.
    unit : str, optional
        Its unit, as the message quotes it (e.g. ``"m/s"``); "" for none.
    """
    x = finite(name, value, unit)
    if x < 0.0:
        raise ValueError(f"{name} must be >= 0{_unit(unit)}, got {shown(value)}")
    return x


GRAMS_AS_KG = (1e-3, "grams typed as kg?")
"""A slip of unit for :func:`in_range`'s ``slips``: a mass in g where kg are asked for."""

CM_AS_M = (1e-2, "cm typed as m?")
"""A slip of unit for :func:`in_range`'s ``slips``: a length in cm where m are asked for."""

KN_AS_N = (1e3, "kN/m typed as N/m?")
"""A slip of unit for :func:`in_range`'s ``slips``: a stiffness in kN/m where N/m are asked
for."""


def in_range(
    name: str, value, low: float, high: float, unit: str = "", hint: str = "", slips=()
) -> float:
    """Return ``value`` as a float; raise ``ValueError`` unless ``low <= value <= high``
    (``hint`` is appended to the message, e.g. a likely cause; so is the first of ``slips``
    that would bring the value into the range).

    Parameters
    ----------
    name : str
        The argument's name, as the message quotes it.
    value : object
        The value to check, in ``unit``.
    low, high : float
        The bounds [``unit``], inclusive, in ``unit``.
    unit : str, optional
        Its unit, as the message quotes it (e.g. ``"m/s"``); "" for none.
    hint : str, optional
        Appended to the message, e.g. a likely cause.
    slips : sequence of (float, str), optional
        Likely slips of unit, each the factor [-] that turns the value typed into ``unit``
        and what the slip is (:data:`GRAMS_AS_KG`, :data:`CM_AS_M`, :data:`KN_AS_N`): a
        value out of the range that one of them brings into it is quoted with it, e.g.
        "(grams typed as kg? 57 would be 0.057 kg)".
    """
    x = finite(name, value, unit)
    if not low <= x <= high:
        for factor, slip in slips:
            if low <= x * factor <= high:
                hint = f" ({slip} {shown(value)} would be {x * factor:g}{_unit(unit)}){hint}"
                break
        raise ValueError(
            f"{name} must be in [{low:g}, {high:g}]{_unit(unit)}, got {shown(value)}{hint}"
        )
    return x


def speed(name: str, value, allow_zero: bool = False) -> float:
    """A speed [m/s] in :data:`SPEED_RANGE` (or 0 if ``allow_zero``), as a float.

    Parameters
    ----------
    name : str
        The argument's name, as the message quotes it.
    value : object
        The speed [m/s].
    allow_zero : bool, optional
        Accept 0 m/s too.
    """
    x = finite(name, value, "m/s")
    if allow_zero and x == 0.0:
        return x
    return in_range(name, x, *SPEED_RANGE, "m/s" + (" (or 0)" if allow_zero else ""))


def finite_array(name: str, values, unit: str = "") -> np.ndarray:
    """Return ``values`` as a float array; raise ``ValueError`` on NaN, inf or non-numbers.

    Parameters
    ----------
    name : str
        The argument's name, as the message quotes it.
    values : array_like
        The values to check [``unit``], in ``unit``.
    unit : str, optional
        Its unit, as the message quotes it (e.g. ``"m/s"``); "" for none.
    """
    try:
        a = np.asarray(values, dtype=float)
    except (TypeError, ValueError, OverflowError):
        raise ValueError(
            f"{name} must be finite numbers{_unit(unit)}, got {shown(values)}"
        ) from None
    if not np.all(np.isfinite(a)):
        index = np.flatnonzero(~np.isfinite(a))[0]
        bad = np.asarray(values, dtype=object).ravel()[index]
        raise ValueError(f"{name} must be finite numbers{_unit(unit)}, got {shown(bad)}")
    return a
