"""The parts of a strung racket and where their mass sits: the mass model of the spec fit.

Seen face-on (x along the racket from the tip, y across it), a racket is

* a **bumper** (bumper guard and the grommets under it) along the top of the hoop, from 10
  to 2 o'clock (:data:`BUMPER_HALF_ANGLE`);
* the **hoop**, the frame around the head with its grommets: an ellipse of uniform mass per
  arc length whose centre line is :data:`FRAME_INSET` outside the string bed;
* the **strings**, spread evenly over the elliptical string bed (length / width
  :data:`~racket.strings.head.HEAD_ASPECT`, area the head size);
* the **throat**, from the bottom of the hoop to the handle, uniform along the racket, its
  two arms closing linearly from :data:`THROAT_SPREAD` of the head's half width to the
  axis;
* the **handle** (the frame's shaft, the pallet and the grip), uniform over
  :data:`HANDLE_LENGTH` less the butt cap;
* the **butt cap**, uniform over the last :data:`BUTT_CAP_LENGTH`.

Each part's mass is unknown within a plausible range (:data:`PARTS`, with sources); the
spec fit (:mod:`racket.specs.mass_fit`) chooses them.  Everything here is per unit mass of a
part, on the cells of a piecewise-uniform beam, so the beam built from the fitted masses has
exactly the moments the fit used.
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass

import numpy as np

from beam import SWINGWEIGHT_AXIS
from common.units import IN2
from racket.strings.head import HEAD_ASPECT, Hoop, ellipse_axes


@dataclass(frozen=True)
class Part:
    """A part of the racket and its plausible mass range.

    Parameters
    ----------
    name : str
        What it is.
    low, high : float
        Plausible range of its mass [kg].
    typical : float
        Its mass in a typical 300 g strung racket [kg]; the fit stays as close to the
        typical split as the spec sheet lets it.
    source : str
        Where the range comes from.
    """

    name: str
    low: float
    high: float
    typical: float
    source: str


_FRAME_TUBE = (
    "the frame's mean is about 1.6 g/cm: an unstrung frame of 250-330 g (the sample's "
    "unstrung weights) over some 170 cm of tube"
)
PARTS = (
    Part(
        "bumper", 0.003, 0.030, 0.006,
        "assumption: a nylon bumper guard over 10-2 o'clock, a few grams; the high end "
        "allows lead under the bumper, as stringers fit for players (Racquet Sports "
        "Industry, 'Lead tape beneath the bumperguard', 2007)",
    ),
    Part(
        "hoop", 0.060, 0.200, 0.110,
        f"assumption: about 95 cm of frame tube with its grommets at 0.6-2 g/cm; {_FRAME_TUBE}",
    ),
    Part(
        "strings", 0.012, 0.024, 0.016,
        "strung minus unstrung weight of the 139 sheets of tests/data/"
        "racket_specs_sample.csv: 12-22 g for all but 3 (median 16 g)",
    ),
    Part(
        "throat", 0.015, 0.120, 0.060,
        f"assumption: two arms, some 30 cm of frame tube, at 0.5-4 g/cm; {_FRAME_TUBE}",
    ),
    Part(
        "handle", 0.030, 0.160, 0.085,
        "assumption: the frame's shaft, the pallet and the grip; a synthetic grip weighs "
        "'high single digits to mid-teens of grams' (tennisyard.com, 'Tennis grips: how to "
        "know when to replace'), a leather one about 10 g more (Tennis.com, 'Question of the "
        "day: leather grips', 2012); the low end is some 17 cm of a light frame's tube at "
        "1 g/cm, a thin foam pallet and a synthetic grip (the super-light handles of head-heavy "
        "frames: the Head Graphene Instinct PWR of the TWU table needs 32 g); the high end "
        "allows weight in the handle",
    ),
    Part(
        "butt cap", 0.004, 0.030, 0.012,
        "assumption: a plastic cap of some 10 g; the high end allows the counterweight "
        "players put inside it (healthfully.com, 'How to install a butt cap on a tennis "
        "racquet')",
    ),
)  # fmt: skip
"""The parts, in the order of :class:`Layout`'s rows."""

HANDLE_LENGTH = 0.19
"""Length of the handle, butt cap included [m]: a grip of 7 in (17.8 cm) plus the cap."""

BUTT_CAP_LENGTH = 0.015
"""Length of the butt cap along the racket [m] (assumption: the flared end of the grip)."""

FRAME_INSET = 0.008
"""Distance from the string bed's edge to the hoop's centre line [m] (assumption: half of
an in-plane frame section about 12 mm deep plus the grommet)."""

BUMPER_HALF_ANGLE = np.radians(60.0)
"""The bumper covers the hoop within this angle of 12 o'clock (10 to 2 o'clock)
(assumption, from the usual bumper guards)."""

THROAT_SPREAD = 0.5
"""Half-spacing of the throat's arms where they leave the hoop, as a fraction of the hoop's
half width (assumption); it sets only their small share of the roll inertia."""

HANDLE_SECTION = 0.028
"""Width and depth of the handle's section [m] (a size-3 grip is 4 3/8 in, 11 cm, round;
its octagon is about 2.8 cm across); it sets the handle's own small roll inertia as a solid
section, (w**2 + d**2) / 12 per unit mass."""

_HEAD_CELLS = 24  # cells resolving the hoop, bumper and strings along the head
_THROAT_CELLS = 8  # cells along the throat (its arms' roll inertia, the stiffness profile)
_HANDLE_CELLS = 4
_GAUSS = np.polynomial.legendre.leggauss(16)


@dataclass(frozen=True)
class Layout:
    """The model's cells and each part's share of them, for one length and head size.

    Attributes
    ----------
    stations : ndarray
        Cell boundaries [m from the tip].
    mass_shapes : ndarray (parts, cells)
        Mass per length of each part per unit part mass [1/m].
    roll_shapes : ndarray (parts, cells)
        Roll inertia per length of each part per unit part mass [m].
    hoop : Hoop
        The frame's centre line around the head.
    strings_extent : (float, float)
        Where the string bed is [m from the tip].
    strings_width : float
        Its width [m].
    """

    stations: np.ndarray
    mass_shapes: np.ndarray
    roll_shapes: np.ndarray
    hoop: Hoop
    strings_extent: tuple
    strings_width: float

    @property
    def strings_area(self) -> float:
        """Area of the string bed [m^2]."""
        extent = self.strings_extent
        return float(np.pi * 0.25 * (extent[1] - extent[0]) * self.strings_width)

    @property
    def head_length(self) -> float:
        """Length of the head, from the tip to the bottom of the hoop [m]."""
        return 2.0 * self.hoop.center

    def moments(self) -> np.ndarray:
        """Per unit mass of each part (columns): mass, first moment about the tip,
        moment of inertia about the swingweight axis, and roll inertia (rows), computed as
        :class:`~beam.Beam` computes them for its uniform cells.
        """
        st = self.stations
        widths = np.diff(st)
        mid = 0.5 * (st[:-1] + st[1:])
        axis = st[-1] - SWINGWEIGHT_AXIS
        cell = self.mass_shapes * widths
        return np.array(
            [
                cell.sum(axis=1),
                cell @ mid,
                cell @ (widths**2 / 12.0 + (mid - axis) ** 2),
                self.roll_shapes @ widths,
            ]
        )


def _hoop_cells(edges: np.ndarray, hoop: Hoop, t_max: float = np.pi):
    """Arc length and integral of y**2 ds of the hoop within each cell, for its parametric
    angle t in [0, t_max] (x = a (1 - cos t), y = b sin t; both sides).
    """
    a, b = hoop.center, hoop.half_width
    t_edges = np.minimum(np.arccos(np.clip(1.0 - edges / a, -1.0, 1.0)), t_max)
    nodes, weights = _GAUSS
    arcs, rolls = [], []
    for t0, t1 in itertools.pairwise(t_edges):
        t = 0.5 * (t1 - t0) * nodes + 0.5 * (t1 + t0)
        ds = 0.5 * (t1 - t0) * weights * np.hypot(a * np.sin(t), b * np.cos(t))
        arcs.append(2.0 * ds.sum())
        rolls.append(2.0 * ds @ (b * np.sin(t)) ** 2)
    return np.array(arcs), np.array(rolls)


def _strings_cells(edges: np.ndarray, center: float, a: float, b: float):
    """Area and integral of w**3 / 12 dx (w the chord width) of the string bed's ellipse
    within each cell.
    """
    u = np.clip((edges - center) / a, -1.0, 1.0)
    primitive = a * b * (u * np.sqrt(1.0 - u**2) + np.arcsin(u))
    nodes, weights = _GAUSS
    rolls = []
    for u0, u1 in itertools.pairwise(u):
        s = 0.5 * (u1 - u0) * nodes + 0.5 * (u1 + u0)
        w = 2.0 * b * np.sqrt(1.0 - s**2)
        rolls.append(0.5 * (u1 - u0) * a * weights @ (w**3 / 12.0))
    return np.diff(primitive), np.array(rolls)


def layout(length: float, head_area: float) -> Layout:
    """The cells and part shapes of a racket ``length`` [m] long with a string bed of
    ``head_area`` [m^2]; ValueError if the head leaves no room for a throat.

    Parameters
    ----------
    length : float
        Overall racket length [m].
    head_area : float
        Area of the string bed [m^2].
    """
    a_s, b_s = ellipse_axes(head_area, HEAD_ASPECT)
    hoop = Hoop(a_s + FRAME_INSET, b_s + FRAME_INSET)
    head = 2.0 * hoop.center
    handle_start = length - HANDLE_LENGTH
    if not head < handle_start - 0.05:
        raise ValueError(
            f"head size {head_area / IN2:.4g} in^2 is too large for a {100 * length:.4g} cm "
            f"racket: its head ({100 * head:.1f} cm long) leaves less than 5 cm of throat "
            f"above a {100 * HANDLE_LENGTH:.0f} cm handle"
        )
    head_edges = np.linspace(0.0, head, _HEAD_CELLS + 1)
    stations = np.concatenate(
        [
            head_edges,
            np.linspace(head, handle_start, _THROAT_CELLS + 1)[1:],
            np.linspace(handle_start, length - BUTT_CAP_LENGTH, _HANDLE_CELLS + 1)[1:],
            [length],
        ]
    )
    widths = np.diff(stations)
    n = widths.size
    mass = np.zeros((len(PARTS), n))
    roll = np.zeros((len(PARTS), n))
    h = slice(0, _HEAD_CELLS)
    # the bumper: the hoop's arc up to the polar angle BUMPER_HALF_ANGLE
    t_bumper = np.arctan(hoop.center / hoop.half_width * np.tan(BUMPER_HALF_ANGLE))
    for row, t_max in ((0, t_bumper), (1, np.pi)):
        arcs, rolls = _hoop_cells(head_edges, hoop, t_max)
        mass[row, h], roll[row, h] = arcs / arcs.sum(), rolls / arcs.sum()
    areas, rolls = _strings_cells(head_edges, FRAME_INSET + a_s, a_s, b_s)
    mass[2, h], roll[2, h] = areas / areas.sum(), rolls / areas.sum()
    t = slice(_HEAD_CELLS, _HEAD_CELLS + _THROAT_CELLS)
    mass[3, t] = 1.0 / (handle_start - head)
    # arms at +-y0 (1 - s), s from 0 to 1 down the throat: mean y**2 over each cell
    y0 = THROAT_SPREAD * hoop.half_width
    s = (stations[_HEAD_CELLS : _HEAD_CELLS + _THROAT_CELLS + 1] - head) / (handle_start - head)
    mean_sq = y0**2 * np.diff((s - 1.0) ** 3 / 3.0) / np.diff(s)
    roll[3, t] = mass[3, t] * mean_sq
    section = 2.0 * HANDLE_SECTION**2 / 12.0
    g = slice(_HEAD_CELLS + _THROAT_CELLS, n - 1)
    mass[4, g] = 1.0 / (HANDLE_LENGTH - BUTT_CAP_LENGTH)
    mass[5, n - 1] = 1.0 / BUTT_CAP_LENGTH
    roll[4:] = mass[4:] * section
    mass[:, h] /= widths[h]
    roll[:, h] /= widths[h]
    return Layout(
        stations=stations,
        mass_shapes=mass,
        roll_shapes=roll,
        hoop=hoop,
        strings_extent=(FRAME_INSET, FRAME_INSET + 2.0 * a_s),
        strings_width=2.0 * b_s,
    )
