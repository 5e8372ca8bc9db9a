"""Rackets from their spec sheets: a beam model that reproduces the published numbers.

Mass model
----------
The frame has three parts along its length L (x from the tip):

* the **head**, x in [0, h], an elliptical hoop of length h and width h / :data:`HEAD_ASPECT`
  whose area is the head size.  A hoop of uniform mass per arc length puts most of its mass
  where the hoop runs across the axis (at the tip and at the throat end of the head), so its
  mass per unit *axial* length is the arc length per dx, which peaks at both ends.  The strings
  (:data:`STRING_MASS`) are spread over the head as the chord width of the ellipse;
* the **throat** (the arms and shaft), x in [h, L - g], uniform;
* the **handle**, x in [L - g, L] with g = :data:`HANDLE_LENGTH`, uniform.

The three masses (hoop, throat, handle) enter the spec sheet's three mass numbers -- mass,
balance (first moment) and swingweight (moment of inertia about the axis 10 cm from the butt)
-- *linearly*, so they follow from a 3x3 linear solve, exactly.  A spec sheet that needs a
negative mass in one part is refused, with the range of swingweights that a racket of that
mass and balance can have in this model.  A uniform rod of the same mass cannot reproduce a
typical swingweight (its moment of inertia about the centre of mass is a third too small);
the hoop-shaped head can.

Stiffness
---------
The bending stiffness EI is uniform and scaled so that the first free-free frequency is the
spec sheet's f1 (the frequencies scale exactly with sqrt(EI) at a fixed mass distribution).
Spec sheets usually give an RA rating instead; :mod:`racket.flex` models that stiffness test,
but the RA scale has no public calibration, so an RA-only spec sheet is refused with that
reason (see :mod:`racket.flex`).

String bed
----------
:func:`string_bed_stiffness` turns tension and head size into the string-plane stiffness of
the ball-strings spring with a membrane model (see its docstring).
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass

import numpy as np

from beam import SWINGWEIGHT_AXIS, Beam
from common.checks import finite, in_range, positive, shown
from common.units import IN2, LB, POINT
from racket.flex import RA_UNCALIBRATED
from racket.racket import Racket, StringBed

HANDLE_LENGTH = 0.19
"""Length of the uniform handle section [m]: a grip of 7 in (17.8 cm) plus the butt cap."""

HEAD_ASPECT = 1.33
"""Length / width of the elliptical string bed.  A 100 in^2 head of a 27 in racket is about
13.5 in long and 10 in wide (ITF Rules of Tennis, Appendix I, limit the strung surface to
15.5 x 11.5 in; modern mid-plus heads sit near 13.5 x 10)."""

STRING_MASS = 0.017
"""Mass of a set of strings [kg]: strings add 15-20 g to a frame (tennisracket.au,
"Understanding tennis racket specifications"; racquetquest.tennis, "Technology part deux":
"String will add about 17 grams")."""

CONTACT_RADIUS = 0.025
"""Radius [m] over which the ball loads the strings in the membrane model (the contact
patch of a tennis ball on strings is about 5 cm across at 20-30 m/s)."""

MEMBRANE_REFERENCE = (245.0, 100.0 * IN2, 3e4)
"""Calibration of the membrane model: 245 N (55 lb) on a 100 in^2 head gives a string-plane
stiffness of 3e4 N/m (the paper, Sec. VIII)."""

_HEAD_CELLS = 24  # piecewise-constant cells resolving the hoop's mass along the head


def string_bed_stiffness(tension_n: float, head_area_m2: float) -> float:
    """String-plane stiffness [N/m] from the string tension and the head area.

    Membrane model: a circular membrane of radius R under a tension N per unit length,
    pushed by a load spread over a radius a at its centre, has the stiffness
    k = 2 pi N / ln(R / a) (the small-deflection solution of N lap(w) = -p, e.g. Timoshenko
    & Woinowsky-Krieger, Theory of Plates and Shells, membrane limit).  A string bed of
    spacing s has N = T / s, and an elliptical bed behaves like a circle of the same area
    (R. Cross & R. Bower, "Measurements of string tension in a tennis racket", Sports Eng. 4,
    2001: the string-plane frequency depends on the area, not the shape).  So
    k = C T / ln(R / a) with R = sqrt(A / pi), a = :data:`CONTACT_RADIUS`, and the constant C
    (the 2 pi / s and the effect of the frame and string stretch) fixed by
    :data:`MEMBRANE_REFERENCE`.  k rises in proportion to the tension and falls slowly with
    the head size.

    Parameters
    ----------
    tension_n : float
        String (reference) tension [N].
    head_area_m2 : float
        Head (string-bed) area [m^2].
    """
    tension_n = positive("tension", tension_n, "N")
    head_area_m2 = positive("head size", head_area_m2, "m^2")
    radius = np.sqrt(head_area_m2 / np.pi)
    if radius <= 2.0 * CONTACT_RADIUS:
        raise ValueError(
            f"head size must be > {np.pi * (2 * CONTACT_RADIUS) ** 2 / IN2:.0f} in^2 for the "
            f"membrane model, got {head_area_m2 / IN2:.4g} in^2"
        )
    t_ref, a_ref, k_ref = MEMBRANE_REFERENCE
    c = k_ref * np.log(np.sqrt(a_ref / np.pi) / CONTACT_RADIUS) / t_ref
    return float(c * tension_n / np.log(radius / CONTACT_RADIUS))


def head_length(head_area_m2: float) -> float:
    """Length [m] of an elliptical string bed of this area and aspect :data:`HEAD_ASPECT`."""
    return float(np.sqrt(4.0 * head_area_m2 * HEAD_ASPECT / np.pi))


def _ellipse_cells(edges: np.ndarray, head: float):
    """Fractions of the hoop's arc length and of the ellipse's area in each cell.

    The hoop is x = a (1 - cos t), y = +-b sin t (t from 0 at the tip to pi), a = head / 2.
    """
    a, b = head / 2.0, head / (2.0 * HEAD_ASPECT)
    t_edges = np.arccos(np.clip(1.0 - edges / a, -1.0, 1.0))
    nodes, weights = np.polynomial.legendre.leggauss(16)
    arcs, areas = [], []
    for t0, t1 in itertools.pairwise(t_edges):
        t = 0.5 * (t1 - t0) * nodes + 0.5 * (t1 + t0)
        w = 0.5 * (t1 - t0) * weights
        arcs.append(w @ np.hypot(a * np.sin(t), b * np.cos(t)))
        areas.append(w @ (2.0 * b * np.sin(t) * a * np.sin(t)))  # chord width times dx
    arcs, areas = np.array(arcs), np.array(areas)
    return arcs / arcs.sum(), areas / areas.sum()


@dataclass(frozen=True)
class SpecSheet:
    """A racket's published numbers, in SI (built by :func:`spec_sheet` from user units).

    Parameters
    ----------
    length : float
        Overall length [m].
    mass : float
        Strung mass [kg].
    balance : float
        Balance point [m from the butt].
    swingweight : float
        Moment of inertia about the axis 10 cm from the butt [kg m^2].
    f1 : float or None
        First free-free bending frequency of the strung frame [Hz] ...
    ra : float or None
        ... or its RA rating (give one).
    head_area : float
        Head (string-bed) area [m^2].
    string_stiffness : float
        String-plane stiffness [N/m].
    tension : float or None
        String tension [N] if the stiffness came from it, else None.
    """

    length: float
    mass: float
    balance: float
    swingweight: float
    f1: float | None
    ra: float | None
    head_area: float
    string_stiffness: float
    tension: float | None = None

    def __post_init__(self):
        length = positive("length_m", self.length, "m")
        positive("mass_kg", self.mass, "kg")
        balance = positive("balance", self.balance, "m from the butt")
        if not balance < length:
            raise ValueError(
                f"balance must lie on the racket, in (0, {100 * length:g}) cm from the butt, "
                f"got {100 * balance:g} cm"
            )
        positive("swingweight", self.swingweight, "kg m^2")
        if (self.f1 is None) == (self.ra is None):
            raise ValueError("give exactly one frame stiffness: f1_hz or ra")
        positive("head size", self.head_area, "m^2")
        positive("string_stiffness_n_m", self.string_stiffness, "N/m")


@dataclass(frozen=True)
class Profile:
    """The fitted mass split (see the module docstring) [kg]."""

    head_hoop: float
    strings: float
    throat: float
    handle: float
    head_length: float
    handle_length: float


def _basis(sheet: SpecSheet):
    """Stations and the mass-per-length shapes (unit mass) of hoop, strings, throat, handle."""
    length = sheet.length
    head = head_length(sheet.head_area)
    if not head < length - HANDLE_LENGTH - 0.05:
        raise ValueError(
            f"head size {sheet.head_area / IN2:.4g} in^2 is too large for a "
            f"{100 * length:.4g} cm racket: its head ({100 * head:.1f} cm long) leaves less "
            f"than 5 cm of throat above a {100 * HANDLE_LENGTH:.0f} cm handle"
        )
    edges = np.linspace(0.0, head, _HEAD_CELLS + 1)
    stations = np.concatenate([edges, [length - HANDLE_LENGTH, length]])
    widths = np.diff(stations)
    hoop, strings = _ellipse_cells(edges, head)
    shapes = np.zeros((4, widths.size))
    shapes[0, :_HEAD_CELLS] = hoop / widths[:_HEAD_CELLS]
    shapes[1, :_HEAD_CELLS] = strings / widths[:_HEAD_CELLS]
    shapes[2, _HEAD_CELLS] = 1.0 / widths[_HEAD_CELLS]
    shapes[3, _HEAD_CELLS + 1] = 1.0 / widths[_HEAD_CELLS + 1]
    return stations, shapes, head


def _moments(stations: np.ndarray, shapes: np.ndarray, axis: float) -> np.ndarray:
    """Mass, first moment about the tip and moment of inertia about ``axis`` of each shape."""
    widths = np.diff(stations)
    mid = 0.5 * (stations[:-1] + stations[1:])
    cell = shapes * widths
    return np.array([cell.sum(axis=1), cell @ mid, cell @ (widths**2 / 12.0 + (mid - axis) ** 2)])


def fit_profile(sheet: SpecSheet) -> tuple[Beam, Profile]:
    """The beam whose mass, balance, swingweight and f1 equal the spec sheet's.

    Returns the beam (tip at x = 0) and the fitted mass split.  Raises ValueError, with the
    reason, when no positive mass split meets the spec sheet.
    """
    if sheet.f1 is None:
        raise ValueError(RA_UNCALIBRATED)
    if sheet.mass <= STRING_MASS:
        raise ValueError(
            f"mass_kg must exceed the strings' {1e3 * STRING_MASS:g} g, got {sheet.mass!r}"
        )
    stations, shapes, head = _basis(sheet)
    moments = _moments(stations, shapes, sheet.length - SWINGWEIGHT_AXIS)  # (3, 4 parts)
    target = np.array([sheet.mass, sheet.mass * (sheet.length - sheet.balance), sheet.swingweight])
    free = target - STRING_MASS * moments[:, 1]
    parts = moments[:, [0, 2, 3]]
    masses = np.linalg.solve(parts, free)
    if np.any(masses <= 0.0):
        raise ValueError(_infeasible_reason(sheet, parts, free, masses, target[2] - free[2]))
    rho = shapes[[0, 2, 3]].T @ masses + STRING_MASS * shapes[1]
    beam = Beam(tuple(stations), tuple(rho), (1.0,) * rho.size).with_f1(sheet.f1)
    profile = Profile(
        head_hoop=float(masses[0]),
        strings=STRING_MASS,
        throat=float(masses[1]),
        handle=float(masses[2]),
        head_length=head,
        handle_length=HANDLE_LENGTH,
    )
    return beam, profile


def _infeasible_reason(sheet, parts, free, masses, strings_swingweight) -> str:
    """Why no positive split exists: the swingweight range that mass and balance allow."""
    names = ("head hoop", "throat", "handle")
    worst = names[int(np.argmin(masses))]
    # The split is affine in the swingweight: m = m0 + I m1.  Positivity bounds I.
    m1 = np.linalg.solve(parts, [0.0, 0.0, 1.0])
    m0 = masses - free[2] * m1
    lo, hi = 0.0, np.inf
    for a, b in zip(m0, m1, strict=True):
        if b > 0:
            lo = max(lo, -a / b)
        elif b < 0:
            hi = min(hi, -a / b)
        elif a <= 0:
            lo, hi = np.inf, -np.inf
    head = f"a {1e3 * sheet.mass:.4g} g racket balanced at {100 * sheet.balance:.4g} cm"
    got = f"got {1e4 * sheet.swingweight:.4g} kg cm^2 (the {worst} would need negative mass)"
    lo, hi = lo + strings_swingweight, hi + strings_swingweight
    if lo < hi:
        return (
            f"swingweight_kgcm2 must be in ({1e4 * lo:.0f}, {1e4 * hi:.0f}) kg cm^2 for {head} "
            f"and a {sheet.head_area / IN2:.4g} in^2 head, {got}"
        )
    return f"no positive mass distribution gives {head} (the {worst} would need negative mass)"


def _one(kind: str, **given):
    """The one given value among ``given`` (name -> value or None); ValueError otherwise."""
    named = {k: v for k, v in given.items() if v is not None}
    if len(named) != 1:
        raise ValueError(
            f"give exactly one {kind}: {' or '.join(given)}"
            + (f" (got {', '.join(named)})" if named else "")
        )
    return next(iter(named.items()))


SPEC_RANGES = {
    "length_m": (0.45, 0.75, "m"),
    "mass_kg": (0.15, 0.5, "kg"),
    "balance_cm": (20.0, 50.0, "cm from the butt"),
    "balance_pts_hl": (-24.0, 24.0, "pts head-light"),
    "swingweight_kgcm2": (100.0, 500.0, "kg cm^2"),
    "f1_hz": (60.0, 400.0, "Hz"),
    "ra": (40.0, 90.0, ""),
    "head_size_in2": (60.0, 140.0, "in^2"),
    "head_size_cm2": (387.0, 903.0, "cm^2"),  # 60-140 in^2
    "tension_lb": (20.0, 80.0, "lb"),
    "tension_n": (89.0, 356.0, "N"),  # 20-80 lb
    "string_stiffness_n_m": (5e3, 2e5, "N/m"),
}
"""The range of each spec-sheet input, in its own unit, checked before the fit.  Generous
around real rackets: the ITF allows at most 73.7 cm (29 in) of length and a strung surface
of 39.4 x 29.2 cm (an ellipse of 140 in^2) (ITF Rules of Tennis, Appendix II); junior
rackets start at 19 in (48 cm); strung adult rackets weigh 230-370 g, balance 30-36 cm, and
swing 280-360 kg cm^2 (retailers' spec sheets, e.g. ../shared/data/racket_specs_sample.csv);
frames ring at 100-200 Hz (Taraborrelli et al., Appl. Sci. 2019); strings are strung at
40-65 lb.  The rest (f1 60-400 Hz, string-bed 5e3-2e5 N/m) is this project's assumption."""


def _check_spec(name: str, value) -> float:
    """A spec-sheet value in its range (:data:`SPEC_RANGES`), with a hint at a likely slip
    of unit (grams typed as kg, cm as m)."""
    low, high, unit = SPEC_RANGES[name]
    x = finite(name, value, unit)
    hint = ""
    for factor, slip in ((1e-3, "grams typed as kg?"), (1e-2, "cm typed as m?")):
        if not low <= x <= high and low <= x * factor <= high and name in ("mass_kg", "length_m"):
            hint = f" ({slip} {shown(value)} would be {x * factor:g} {unit})"
    return in_range(name, value, low, high, unit, hint)


def spec_sheet(
    *,
    length_m: float = 0.6858,
    mass_kg: float | None = None,
    swingweight_kgcm2: float | None = None,
    balance_cm: float | None = None,
    balance_pts_hl: float | None = None,
    f1_hz: float | None = None,
    ra: float | None = None,
    head_size_in2: float | None = None,
    head_size_cm2: float | None = None,
    tension_lb: float | None = None,
    tension_n: float | None = None,
    string_stiffness_n_m: float | None = None,
) -> SpecSheet:
    """A :class:`SpecSheet` from the units of spec sheets (see :func:`from_specs`); every
    value is first checked against its range (:data:`SPEC_RANGES`)."""
    given = {k: v for k, v in locals().items() if v is not None}
    for required in ("mass_kg", "swingweight_kgcm2"):
        if required not in given:
            raise ValueError(f"the spec sheet needs {required}")
    for name, value in given.items():
        _check_spec(name, value)
    length = positive("length_m", length_m, "m")
    name, value = _one("balance", balance_cm=balance_cm, balance_pts_hl=balance_pts_hl)
    if name == "balance_cm":
        balance = positive("balance_cm", value, "cm from the butt") / 100.0
    else:  # points head-light: 1/8 in each, counted from the middle
        balance = length / 2.0 - finite("balance_pts_hl", value, "pts") * POINT
    name, value = _one("head size", head_size_in2=head_size_in2, head_size_cm2=head_size_cm2)
    area = positive(name, value, name[-3:]) * (IN2 if name.endswith("in2") else 1e-4)
    name, value = _one(
        "string bed",
        tension_lb=tension_lb,
        tension_n=tension_n,
        string_stiffness_n_m=string_stiffness_n_m,
    )
    tension = None
    if name == "string_stiffness_n_m":
        k_strings = positive(name, value, "N/m")
    else:
        tension = positive(name, value, name[-2:]) * (LB if name == "tension_lb" else 1.0)
        k_strings = string_bed_stiffness(tension, area)
    name, value = _one("frame stiffness", f1_hz=f1_hz, ra=ra)
    return SpecSheet(
        length=length,
        mass=positive("mass_kg", mass_kg, "kg"),
        balance=balance,
        swingweight=positive("swingweight_kgcm2", swingweight_kgcm2, "kg cm^2") * 1e-4,
        f1=positive("f1_hz", value, "Hz") if name == "f1_hz" else None,
        ra=positive("ra", value) if name == "ra" else None,
        head_area=area,
        string_stiffness=k_strings,
        tension=tension,
    )


def from_specs(*, support: str = "free", **specs) -> Racket:
    """A racket whose mass, balance, swingweight and f1 equal a spec sheet's.

    Parameters
    ----------
    length_m : float
        Overall length [m]; default 0.6858 (27 in).
    mass_kg : float
        Strung mass [kg].
    balance_cm, balance_pts_hl : float
        Balance [cm from the butt], or points head-light (1 pt = 1/8 in from the middle;
        negative = head-heavy).  Give one.
    swingweight_kgcm2 : float
        Swingweight [kg cm^2] about the axis 10 cm from the butt (strung).
    f1_hz, ra : float
        Frame stiffness: first free-free bending frequency [Hz], or the RA rating.  Give
        one; ``ra`` is refused until the RA scale is calibrated (see :mod:`racket.flex`).
    head_size_in2, head_size_cm2 : float
        Head (string-bed) area.  Give one.
    tension_lb, tension_n, string_stiffness_n_m : float
        String tension [lb or N] (membrane model :func:`string_bed_stiffness`), or the
        string-plane stiffness [N/m].  Give one.
    support : str
        As in :class:`~racket.Racket` ("free", "clamped-head" or "hand-held").

    Returns
    -------
    Racket
        Its beam has the fitted profile (:func:`fit_profile`); its strings span the head.

    Raises
    ------
    ValueError
        For a missing, doubled or non-physical spec, or a spec sheet no positive mass
        distribution can meet (with the swingweight range that would be possible).
    """
    sheet = spec_sheet(**specs)
    beam, profile = fit_profile(sheet)
    return Racket(beam, StringBed(sheet.string_stiffness, (0.0, profile.head_length)), support)
