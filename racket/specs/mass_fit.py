"""The part masses that meet a spec sheet: a constrained least-squares fit.

The spec sheet's mass, balance (first moment) and swingweight, and where given the
twistweight (roll inertia), are linear in the part masses of :mod:`racket.specs.parts`:
``A m = t``.  With more parts than numbers there are many solutions; the fit takes the one
closest to a typical racket's split (each part's distance measured in its plausible range)
with every part inside its range:

    minimise sum_i ((m_i - typical_i) / (high_i - low_i))**2
    subject to A m = t and low_i <= m_i <= high_i.

Mass, balance and swingweight are met exactly (to rounding; a sheet within
:data:`KEY_DIGITS` of a recorded one reads its record, to a relative 1e-9) whenever a
racket with parts in their ranges can meet them; otherwise the sheet is refused, naming the
quantity and the range such rackets reach (found by linear programming).  A twistweight is
met exactly when it can be, else as closely as the parts allow, and the residual is
reported.

The fits of the catalogue's sheets are recorded (:mod:`racket.specs.fitted`): a process that
builds a catalogue racket, every command's default, reads them there, what the fit gives
(to its last bits on the machine that recorded them, alike on every machine), and does not
import :mod:`scipy.optimize` (a few tenths of a second) to fit them again.
"""

from __future__ import annotations

import hashlib
from dataclasses import dataclass

import numpy as np

from beam import SWINGWEIGHT_AXIS
from common.units import IN2, POINT
from racket.specs.fitted import FITTED
from racket.specs.parts import PARTS, Layout

_NAMES = ("mass", "first moment", "swingweight", "twistweight")
_SOFT_WEIGHT = 1e6  # weight of a twistweight that cannot be met exactly, against the prior


@dataclass(frozen=True)
class MassFit:
    """The fitted part masses.

    Attributes
    ----------
    masses : ndarray
        Mass of each part of :data:`~racket.specs.parts.PARTS` [kg].
    twistweight_residual : float or None
        Fitted minus given twistweight [kg m^2] when one was given (0 when met exactly).
    """

    masses: np.ndarray
    twistweight_residual: float | None = None


def _bounds():
    low = np.array([p.low for p in PARTS])
    high = np.array([p.high for p in PARTS])
    return low, high


def typical_split(mass: float) -> np.ndarray:
    """The typical part masses [kg] of a racket of ``mass`` [kg]: the frame's parts (hoop,
    throat, handle) scaled so that the parts add up to ``mass``, then kept in range.

    Parameters
    ----------
    mass : float
        Strung racket mass [kg].
    """
    low, high = _bounds()
    typical = np.array([p.typical for p in PARTS])
    frame = np.array([p.name in ("hoop", "throat", "handle") for p in PARTS])
    rest = mass - typical[~frame].sum()
    typical[frame] *= max(rest, 0.0) / typical[frame].sum()
    return np.clip(typical, low, high)


def _linprog(c, a_eq, b_eq):
    from scipy.optimize import linprog

    low, high = _bounds()
    return linprog(c, A_eq=a_eq, b_eq=b_eq, bounds=list(zip(low, high, strict=True)))


def _reachable(row, a_eq, b_eq) -> tuple[float, float] | None:
    """Smallest and largest ``row @ m`` over parts in range with ``a_eq m = b_eq``."""
    lo, hi = _linprog(row, a_eq, b_eq), _linprog(-row, a_eq, b_eq)
    if lo.status != 0 or hi.status != 0:
        return None
    return float(lo.fun), float(-hi.fun)


def _interval(lo: float, hi: float, got: float, digits: int = 0) -> tuple[str, str]:
    """``"(lo, hi)"`` and ``got`` printed with the fewest decimals (at least ``digits``) that
    show ``got`` outside the interval; one value when the interval is a point.
    """
    for d in range(digits, 7):
        r_lo, r_hi, r_got = (round(v, d) for v in (lo, hi, got))
        if not r_lo <= r_got <= r_hi:
            break
    if round(lo, d) == round(hi, d):
        return f"{lo:.{d}f} (the only value reachable)", f"{got:.{d}f}"
    return f"({lo:.{d}f}, {hi:.{d}f})", f"{got:.{d}f}"


def _refusal(
    moments: np.ndarray,
    target: np.ndarray,
    length: float,
    head_area: float,
    recoil_given: bool = False,
) -> str:
    """Why no racket with plausible parts meets the sheet: the first of mass, balance and
    swingweight (or recoil weight, if the sheet gave that instead) that cannot be met,
    with the range that can.
    """
    mass, first = target[0], target[1]
    low, high = _bounds()
    parts = "with every part in its plausible range (racket.specs.parts.PARTS)"
    if not low.sum() <= mass <= high.sum():
        span, got = _interval(low.sum(), high.sum(), mass, 3)
        return f"mass_kg must be in {span} kg for a racket {parts}, got {got}"
    reach = _reachable(moments[1], moments[:1], target[:1])
    lo, hi = (length - r / mass for r in reversed(reach))
    balance = length - first / mass
    if not lo <= balance <= hi:
        pts = [(length / 2 - b) / POINT for b in (lo, hi)]
        span, got = _interval(100 * lo, 100 * hi, 100 * balance, 1)
        return (
            f"balance must be in {span} cm from the butt ({pts[0]:.0f} to {pts[1]:.0f} pts "
            f"head-light) for a {1e3 * mass:.4g} g racket {parts}, got {got} cm"
        )
    lo, hi = _reachable(moments[2], moments[:2], target[:2])
    name, shift = "swingweight_kgcm2", 0.0
    if recoil_given:  # parallel axes: recoil weight = swingweight - M (balance - 10 cm)^2
        name, shift = "recoil_weight_kgcm2", mass * (balance - SWINGWEIGHT_AXIS) ** 2
    span, got = _interval(1e4 * (lo - shift), 1e4 * (hi - shift), 1e4 * (target[2] - shift))
    return (
        f"{name} must be in {span} kg cm^2 for a {1e3 * mass:.4g} g racket balanced at "
        f"{100 * balance:.4g} cm with a {head_area / IN2:.4g} in^2 head {parts}, got {got}"
    )


def _least_distance(a_eq, b_eq, typical, soft=None) -> np.ndarray:
    """Parts in range closest to ``typical`` with ``a_eq m = b_eq`` (and ``soft = (row,
    value)`` met as closely as possible), in scaled variables z = (m - low) / (high - low).
    """
    from scipy.optimize import minimize

    low, high = _bounds()
    span = high - low
    scale = np.abs(b_eq)
    a = a_eq * span / scale[:, None]
    b = (b_eq - a_eq @ low) / scale
    z_typ = (typical - low) / span
    if soft is not None:
        row, value = soft
        s_row, s_val = row * span / abs(value), (value - row @ low) / abs(value)

    def cost(z):
        d = z - z_typ
        f, g = 0.5 * d @ d, d.copy()
        if soft is not None:
            r = s_row @ z - s_val
            f, g = f + 0.5 * _SOFT_WEIGHT * r * r, g + _SOFT_WEIGHT * r * s_row
        return f, g

    start = _linprog(np.zeros(len(PARTS)), a_eq, b_eq).x
    result = minimize(
        cost,
        (start - low) / span,
        jac=True,
        method="SLSQP",
        bounds=[(0.0, 1.0)] * len(PARTS),
        constraints={"type": "eq", "fun": lambda z: a @ z - b, "jac": lambda z: a},
        options={"ftol": 1e-15, "maxiter": 500},
    )
    z = np.clip(result.x, 0.0, 1.0)
    # Polish: meet the equalities to rounding by the least change of the parts off their
    # bounds (the step is of the size of SLSQP's tolerance, far inside the ranges).
    # lstsq gives the least-norm step even when the free parts are fewer than the equalities
    # or dependent (many parts at their bounds).
    free = (z > 1e-9) & (z < 1.0 - 1e-9)
    z[free] += np.linalg.lstsq(a[:, free], b - a @ z, rcond=None)[0]
    return low + span * z


def _problem(layout: Layout, mass: float, balance: float, swingweight: float):
    """The racket's length [m], the parts' moments (:meth:`Layout.moments`) and the
    targets ``A m = t`` of mass, first moment about the tip and swingweight.
    """
    length = float(layout.stations[-1])
    return length, layout.moments(), np.array([mass, mass * (length - balance), swingweight])


KEY_DIGITS = 10
"""Significant digits of each input that key a fit in the record of fits: the moments come
out of a matrix product and trigonometry, whose last bits follow the machine's BLAS and
maths library (every sheet of the catalogue differed in them between two of this
project's machines), so the key reads each input to ten significant digits (a relative
1e-10 to 1e-9) and a fit is read alike on every machine; a sheet changed by more than that
is fitted afresh, and one changed by less reads the record (its masses then meet the sheet
to that relative 1e-9, not to rounding).  An input within a few units in the last place of
a rounding boundary would still be keyed apart on two machines (the catalogue's sit some
1e4 units from one; ``tests/test_fitted.py`` nudges them by 3)."""


def _key(moments, target, typical, twistweight) -> str:
    """SHA-256 [hex] of every input of a fit, each to :data:`KEY_DIGITS` significant digits:
    the moments, the targets, the typical split, the parts' ranges and the twistweight
    (None: none given).
    """
    low, high = _bounds()
    twist = np.nan if twistweight is None else twistweight
    values = np.concatenate([np.ravel(p) for p in (moments, target, typical, low, high, [twist])])
    values = values.astype(float) + 0.0  # (-0.0 read as 0.0)
    text = " ".join(f"{v:.{KEY_DIGITS - 1}e}" for v in values)
    return hashlib.sha256(text.encode()).hexdigest()


def fit_key(
    layout: Layout,
    mass: float,
    balance: float,
    swingweight: float,
    twistweight: float | None = None,
) -> str:
    """The key of :func:`fit_masses`'s fit of these arguments in the record of fits,
    :data:`racket.specs.fitted.FITTED`: a digest of every input of the fit, so that a changed
    input (a part's range, the layout) finds no record and is fitted afresh.

    Parameters
    ----------
    layout, mass, balance, swingweight, twistweight
        As for :func:`fit_masses`.
    """
    _, moments, target = _problem(layout, mass, balance, swingweight)
    return _key(moments, target, typical_split(mass), twistweight)


def fit_masses(
    layout: Layout,
    mass: float,
    balance: float,
    swingweight: float,
    twistweight: float | None = None,
    recoil_given: bool = False,
    recorded: bool = True,
) -> MassFit:
    """Part masses [kg] meeting ``mass`` [kg], ``balance`` [m from the butt] and
    ``swingweight`` [kg m^2] exactly, and ``twistweight`` (roll inertia) [kg m^2] if given
    as closely as the parts allow; ValueError naming the quantity and its reachable range
    when no racket with plausible parts has them (the recoil weight rather than the
    swingweight if ``recoil_given``: the sheet gave that instead).

    Parameters
    ----------
    layout : Layout
        Where the parts sit (:func:`~racket.specs.parts.layout`).
    mass : float
        Strung racket mass [kg].
    balance : float
        Balance point [m from the butt].
    swingweight : float
        Moment of inertia about the swingweight axis, 10 cm from the butt [kg m^2].
    twistweight : float, optional
        Moment of inertia about the long axis [kg m^2]; None: not fitted.
    recoil_given : bool, optional
        The sheet gave the recoil weight, from which ``swingweight`` was derived: a refusal
        names the recoil weight.
    recorded : bool, optional
        Read the fit from the record of fits (:data:`racket.specs.fitted.FITTED`, the
        catalogue's sheets) when it is there (default); False: fit afresh (how the record
        is made and checked).
    """
    length, moments, target = _problem(layout, mass, balance, swingweight)
    typical = typical_split(mass)
    record = FITTED.get(_key(moments, target, typical, twistweight)) if recorded else None
    if record is not None:
        _, masses, residual = record
        return MassFit(np.array(masses), residual)
    if _linprog(np.zeros(len(PARTS)), moments[:3], target).status != 0:
        raise ValueError(_refusal(moments[:3], target, length, layout.strings_area, recoil_given))
    if twistweight is None:
        return MassFit(_least_distance(moments[:3], target, typical))
    with_roll = np.append(target, twistweight)
    if _linprog(np.zeros(len(PARTS)), moments, with_roll).status == 0:
        return MassFit(_least_distance(moments, with_roll, typical), 0.0)
    masses = _least_distance(moments[:3], target, typical, soft=(moments[3], twistweight))
    return MassFit(masses, float(moments[3] @ masses - twistweight))
