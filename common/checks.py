"""Input checks shared by every layer.

Each check raises ``ValueError`` whose message names the argument, the value it got (as
the user gave it, a plain number) and the valid range, so that a user (or the CLI, which
prints the message as one line) can see at once what to change.  The checks return the
value as a float so that callers can write ``self_k = positive("k", k, "N/m")``.
"""

from __future__ import annotations

import math
import numbers
import os
import warnings
from decimal import ROUND_CEILING, ROUND_FLOOR, Decimal

import numpy as np

from common.units import GRAVITY, IN2, INCH, KMH, LB, MPH, OUNCE, SPEED_UNITS

SPEED_RANGE = (1e-3, 300.0)
"""Impact and swing speeds [m/s] racket-impact accepts: from 1 mm/s to well above the
fastest recorded serve (73 m/s, 163 mph).  The solvers are scale-free and resolve far more;
outside this range a number is almost surely a typo (or the wrong unit)."""


FASTEST_STROKE = 263.4 * KMH
"""The fastest recorded serve [m/s]: 263.4 km/h (163.7 mph, 73.2 m/s), Sam Groth, Busan
2012, as reported (e.g. sports-qa.com, "How fast does the fastest tennis serve travel",
2023; a Challenger radar, not ratified).  A ball speed typed above it, in any unit, is asked
about: mph or km/h typed as m/s, km/h typed as mph?"""

FASTEST_HEAD = 0.70 * FASTEST_STROKE
"""The fastest racket-head (string centre) speed [m/s] a stroke is taken to reach: 51.2 m/s
(115 mph, 184 km/h).  **An assumption**: no record of head speeds is kept; this is the
serve record times 0.70, the ratio of racket to ball speed of professional strokes
(tennisspeedresearch.blogspot.com, "Introduction to racket speed", 2006).  High-performance
players' fast serves reach 31.0 m/s at the head's centre on average (Elliott, Marshall &
Noffal, J. Appl. Biomech. 11 (1995) 433), and the model's record serve off the Pure Drive's
string centre needs 49.7 m/s (``studies.serve.head_speed_for``).  A head speed typed above
it, in any unit, is asked about."""


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


class ArgumentTypeError(TypeError, ValueError):
    """An argument of the wrong type (None, a word, a list... where a number or a Racket is
    asked for): a ``TypeError``, as Python has it, and a ``ValueError`` too, as every other
    bad input here is, so that whoever catches those (the command line does) catches it.
    """


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
    if type(value) is float:  # (the usual case, spared the tests of other kinds)
        x = value
    else:
        try:
            if isinstance(value, bool | np.bool_ | str | os.PathLike):
                raise TypeError
            x = float(value)
        except (TypeError, ValueError):
            raise ArgumentTypeError(_not_finite(name, value, unit)) from None
        except OverflowError:
            raise ValueError(_not_finite(name, value, unit)) from None
    if not math.isfinite(x):
        raise ValueError(_not_finite(name, value, unit))
    return x


def _not_finite(name: str, value, unit: str) -> str:
    return f"{name} must be a finite number{_unit(unit)}, got {shown(value)}"


def positive(name: str, value, unit: str = "") -> float:
    """Return ``value`` as a float; raise ``ValueError`` unless it is finite and > 0.

    Parameters
    ----------
    name, value, unit
        As in :func:`finite`.
    """
    x = finite(name, value, unit)
    if x <= 0.0:
        raise ValueError(f"{name} must be > 0{_unit(unit)}, got {shown(value)}")
    return x


def non_negative(name: str, value, unit: str = "") -> float:
    """Return ``value`` as a float; raise ``ValueError`` unless it is finite and >= 0.

    Parameters
    ----------
    name, value, unit
        As in :func:`finite`.
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

MM_AS_M = (1e-3, "mm typed as m?", "mm")
"""A length in mm where m are asked for."""

MM_AS_CM = (0.1, "mm typed as cm?", "mm")
"""A length in mm where cm are asked for."""

KG_AS_G = (1e3, "kg typed as g?", "kg")
"""A mass in kg where grams are asked for (lead tape: 0.005 for 5 g)."""

# The slips below quote the value typed in its likely unit: "645 cm^2 would be 99.98 in^2".
MPH_AS_M_S = (MPH, "mph typed as m/s?", "mph")
"""A speed in mph where m/s are asked for."""

KMH_AS_M_S = (KMH, "km/h typed as m/s?", "km/h")
"""A speed in km/h where m/s are asked for."""

RPM_AS_RAD_S = (2.0 * math.pi / 60.0, "rpm typed as rad/s?", "rpm")
"""A spin in rpm typed where rad/s is asked (a slip :func:`slip_hints` names)."""

KMH_AS_MPH = (KMH / MPH, "km/h typed as mph?", "km/h")
"""A speed in km/h where mph are asked for."""

SPEED_SLIPS = {"m/s": (MPH_AS_M_S, KMH_AS_M_S), "mph": (KMH_AS_MPH,), "km/h": ()}
"""The slips of unit that make a speed typed in each unit of
:data:`common.units.SPEED_UNITS` look too fast (a speed in a smaller unit typed as a larger
one; none makes one typed in km/h too fast: mph or m/s typed as km/h look slower)."""

N_AS_LB = (1.0 / LB, "newtons typed as lb?", "N")
"""A string tension in N where lb are asked for."""

KG_AS_LB = (GRAVITY / LB, "kg typed as lb?", "kg")
"""A string tension in kg (as European stringing machines show it) where lb are asked for."""

LB_AS_N = (LB, "lb typed as N?", "lb")
"""A string tension in lb where N are asked for."""

KG_AS_N = (GRAVITY, "kg typed as N?", "kg")
"""A string tension in kg where N are asked for."""

INCH_AS_M = (INCH, "inches typed as m?", "in")
"""A length in inches where m are asked for (racket lengths are quoted in inches)."""

INCH_AS_CM = (100 * INCH, "inches typed as cm?", "in")
"""A length in inches where cm are asked for (balances are quoted in inches)."""

M_AS_CM = (100.0, "m typed as cm?", "m")
"""A length in m where cm are asked for."""

CM2_AS_IN2 = (1e-4 / IN2, "cm^2 typed as in^2?", "cm^2")
"""A head size in cm^2 where in^2 are asked for."""

IN2_AS_CM2 = (1e4 * IN2, "in^2 typed as cm^2?", "in^2")
"""A head size in in^2 where cm^2 are asked for."""

KGM2_AS_KGCM2 = (1e4, "kg m^2 typed as kg cm^2?", "kg m^2")
"""A moment of inertia (swingweight) in kg m^2 where kg cm^2 are asked for."""

KGCM2_AS_KGM2 = (1e-4, "kg cm^2 typed as kg m^2?", "kg cm^2")
"""A moment of inertia (swingweight) in kg cm^2, as spec sheets give it, where kg m^2 are
asked for."""

OZ_AS_KG = (OUNCE, "ounces typed as kg?", "oz")
"""A mass in ounces where kg are asked for (racket weights are quoted in oz)."""

S_AS_MS = (1e3, "seconds typed as ms?", "s")
"""A duration in s where ms are asked for."""


def slip_hints(value, low: float, high: float, unit: str = "", slips=(), instead=None) -> str:
    """The likely slips of unit that bring ``value`` into ``[low, high]``, as a message
    quotes them ("grams typed as kg? 57 would be 0.057 kg"; several joined by "; "), or ""
    if none does.

    Parameters
    ----------
    value : float
        The value typed [``unit``, as asked for].
    low, high : float
        The bounds [``unit``] the value should lie in.
    unit : str, optional
        The unit asked for.
    slips : sequence of tuple, optional
        Each (factor [-] that turns the value typed into ``unit``, what the slip is[, the
        unit the value was likely typed in]), e.g. :data:`GRAMS_AS_KG`, :data:`MPH_AS_M_S`.
    instead : callable, optional
        Given the unit a slip's value was likely typed in, the text that follows the slip,
        e.g. the option to use: " (--speed-mph 120)".
    """
    x, hints = float(value), []
    for factor, slip, *typed in slips:
        if low <= x * factor <= high:
            was = f"{shown(value)}{_unit(typed[0]) if typed else ''}"
            converted = float(f"{x * factor:.4g}")  # 4 digits, no exponent below 1e6
            after = instead(typed[0]) if instead and typed else ""
            hints.append(f"{slip} {was} would be {converted:g}{_unit(unit)}{after}")
    return "; ".join(hints)


def in_range(
    name: str, value, low: float, high: float, unit: str = "", hint: str = "", slips=()
) -> float:
    """Return ``value`` as a float; raise ``ValueError`` unless ``low <= value <= high``
    (``hint`` is appended to the message, e.g. a likely cause; so are the ``slips`` that
    would bring the value into the range).

    Parameters
    ----------
    name, value, unit
        As in :func:`finite`.
    low, high : float
        The bounds [``unit``], inclusive, in ``unit``.
    hint : str, optional
        Appended to the message, e.g. a likely cause.
    slips : sequence of tuple, optional
        Likely slips of unit (:func:`slip_hints`: :data:`GRAMS_AS_KG`, :data:`CM_AS_M`,
        :data:`KN_AS_N`, ...): a value out of the range that one of them brings into it is
        quoted with it, e.g. "(grams typed as kg? 57 would be 0.057 kg)".
    """
    x = finite(name, value, unit)
    if not low <= x <= high:
        slipped = slip_hints(value, low, high, unit, slips)
        hint = f" ({slipped}){hint}" if slipped else hint
        raise ValueError(
            f"{name} must be in [{ends(low, high)}]{_unit(unit)}, got {shown(value)}{hint}"
        )
    return x


def whole(name: str, value, low: int, high: int) -> int:
    """Return ``value`` as an int; raise ``ValueError`` unless it is a whole number in
    ``[low, high]`` (an :class:`ArgumentTypeError` if it is not a number at all).

    Parameters
    ----------
    name : str
        The argument's name, as the message quotes it.
    value : object
        The value to check [-].
    low, high : int
        The bounds [-], inclusive.
    """
    x = in_range(name, value, low, high)
    if x != int(x):
        raise ValueError(f"{name} must be a whole number in [{low}, {high}], got {x:g}")
    return int(x)


def ends(low: float, high: float, digits: int = 4) -> str:
    """The range ``[low, high]`` as a message quotes it, "low, high": each end to ``digits``
    significant digits (more only where the two would meet), rounded inwards, so that every
    value between the ends quoted is accepted ("0.002237, 671" for 0.00223694-671.081).

    Parameters
    ----------
    low, high : float
        The range's ends [any unit], ``low <= high``.
    digits : int, optional
        Significant digits of each end.
    """
    for places in range(digits, 18):
        said = [rounded(low, places, ROUND_CEILING), rounded(high, places, ROUND_FLOOR)]
        if float(said[0]) <= float(said[1]):
            return ", ".join(said)
    return f"{low!r}, {high!r}"


def rounded(x: float, digits: int, rounding: str) -> str:
    """``x`` to ``digits`` significant digits, rounded up or down (``rounding``, a
    :mod:`decimal` rounding: ROUND_CEILING or ROUND_FLOOR), as :g.

    Parameters
    ----------
    x : float
        The number [any unit].
    digits : int
        Significant digits.
    rounding : str
        :data:`decimal.ROUND_CEILING` or :data:`decimal.ROUND_FLOOR`.
    """
    if not math.isfinite(x) or x == 0.0:
        return f"{x:g}"
    exact = Decimal(repr(float(x)))  # the shortest decimal that is x: 0.05, not 0.05000...03
    step = Decimal(1).scaleb(exact.adjusted() - digits + 1)
    said = float(exact.quantize(step))  # the nearest, if x is it but for round-off (3.6e-3)
    if abs(said - x) > 1e-12 * abs(x):
        said = float(exact.quantize(step, rounding=rounding))
    return f"{said:.{digits}g}" if digits > 6 else f"{said:g}"


def suspect(
    name: str, value, usual: tuple, unit: str, slips, why: str, instead=None, always=False
) -> None:
    """Warn (``UserWarning``) when ``value``, possible, lies outside the ``usual`` range and
    a slip of unit brings it in (or, if ``always``, whether or not one does): "--tension-lb
    25 lb is below what rackets are strung at (40-65 lb): kg typed as lb? 25 kg would be
    55.12 lb".  Refuse the impossible with :func:`in_range`; this only asks.

    Parameters
    ----------
    name : str
        The argument's name, as the message quotes it.
    value : float
        The value typed [``unit``].
    usual : (float, float)
        Where such values usually lie [``unit``].
    unit : str
        The unit asked for.
    slips : sequence of tuple
        Likely slips of unit (:func:`slip_hints`).
    why : str
        What makes the value suspect, e.g. "faster than any recorded stroke (about 73 m/s)".
    instead : callable, optional
        Given the unit a fitting slip's value was likely typed in, the text that follows
        that slip, e.g. the option to use (:func:`slip_hints`).
    always : bool, optional
        Warn outside ``usual`` even when no slip fits (``why`` alone then).
    """
    x = float(value)
    if usual[0] <= x <= usual[1]:
        return
    slipped = slip_hints(value, *usual, unit, slips, instead)
    said = f"{name} {shown(value)}{_unit(unit)} is {why}"
    if slipped:
        warnings.warn(f"{said}: {slipped}", stacklevel=3)
    elif always:
        warnings.warn(said, stacklevel=3)


def too_fast(
    name: str, value, unit: str, fastest: float, what: str, instead=None, kind: str = "stroke"
) -> None:
    """Warn (``UserWarning``, :func:`suspect`) when the speed ``value`` [``unit``], of either
    sign, is faster than ``fastest`` [m/s], naming the slips of unit that would explain it
    (:data:`SPEED_SLIPS`): "--speed-mph 180 mph is faster than any recorded stroke (the
    serve record, about 164 mph)".

    Parameters
    ----------
    name, instead
        As in :func:`suspect`.
    value : float
        The speed typed [``unit``].
    unit : str
        Its unit: a key of :data:`common.units.SPEED_UNITS`.
    fastest : float
        The fastest plausible speed [m/s]: :data:`FASTEST_STROKE` or :data:`FASTEST_HEAD`.
    what : str
        What ``fastest`` is, as the message says it ("the serve record").
    kind : str, optional
        What the speed is of, as the message says it: "stroke" (default), "pitch".
    """
    limit = fastest / SPEED_UNITS[unit]
    why = f"faster than any recorded {kind} ({what}, about {limit:.3g} {unit})"
    suspect(name, value, (-limit, limit), unit, SPEED_SLIPS[unit], why, instead, always=True)


STRUNG_AT_LB = (40.0, 65.0)
"""What rackets are usually strung at [lb]: an assumption, not a measurement (the project's
measurements give none; :data:`racket.strings.tension.TENSION_RANGE_LB` accepts 20-80 lb).  A
tension below it that is one in kg is asked about."""


def loose_tension(name: str, value_lb) -> None:
    """Warn (``UserWarning``, :func:`suspect`) when a string tension [lb] lies below
    :data:`STRUNG_AT_LB` and is one in kg typed as lb ("--tension-lb 25 lb is below what
    rackets are strung at (40-65 lb): kg typed as lb? 25 kg would be 55.12 lb").

    Parameters
    ----------
    name : str
        The argument's name, as the message quotes it (a flag or a TOML key).
    value_lb : float
        The tension typed [lb].
    """
    low, high = STRUNG_AT_LB
    why = f"below what rackets are strung at ({low:g}-{high:g} lb)"
    suspect(name, value_lb, STRUNG_AT_LB, "lb", (KG_AS_LB,), why)


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
    name, unit
        As in :func:`finite`.
    values : array_like
        The values to check [``unit``], in ``unit``.
    """
    if type(values) is np.ndarray and values.dtype == float:  # (spared the other kinds' tests)
        a = values
    else:
        try:
            if isinstance(values, str | bytes | os.PathLike):  # numpy would read "4" as 4.0
                raise TypeError
            a = np.asarray(values, dtype=float)
        except (TypeError, ValueError):
            raise ArgumentTypeError(
                f"{name} must be finite numbers{_unit(unit)}, got {shown(values)}"
            ) from None
        except OverflowError:
            raise ValueError(
                f"{name} must be finite numbers{_unit(unit)}, got {shown(values)}"
            ) from None
    if np.count_nonzero(np.isfinite(a)) < a.size:  # (a reduction, .all(), costs 5x more)
        index = np.flatnonzero(~np.isfinite(a))[0]
        bad = np.asarray(values, dtype=object).ravel()[index]
        raise ValueError(f"{name} must be finite numbers{_unit(unit)}, got {shown(bad)}")
    return a


def impact_positions(position) -> np.ndarray:
    """Impact positions [m from the tip] as a 1-D array of at least one: ValueError if they
    are not a number or a flat sequence of numbers, or there are none.

    Parameters
    ----------
    position : float or array_like
        The positions [m from the tip].
    """
    x = finite_array("position", position, "m from the tip")
    if x.ndim > 1:
        raise ValueError(
            f"position must be a number or a flat sequence of numbers [m from the tip], "
            f"got an array of shape {x.shape}"
        )
    x = np.atleast_1d(x)
    if x.size == 0:
        raise ValueError("position must give at least one impact point, got none")
    return x
