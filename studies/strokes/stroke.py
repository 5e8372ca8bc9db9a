"""Strokes hit (issue 36): the ball's speed, launch and spin after each :class:`racket.Stroke`,
one row per stroke, in a player's units (degrees, rpm, ms), and the speed plotted against the
spin.

Each row is one :func:`racket.hit` (the oblique impact on the face at the stroke's closing
speed, the racket's motion superposed): the stroke as given (head speed, path, face, swing
across, the incoming ball), then the ball after it (exit speed, launch angle, spin and its
topspin, sidespin and rifle-spin parts), the contact time, whether the ball slid on the
strings for the whole contact or gripped them, and the part of the ball's speed away from
the face that the racket's own speed gave it.  What the strings do sideways (mains and
crosses sliding on each other, dry or lubricated, or held still) is a
:class:`racket.strings.sideways.BedSideways` (``side``; :func:`racket.strings.sideways.sideways`),
said in words by :func:`bed_words`.

Angles are in degrees and spins in rpm in the tables (the :class:`racket.Stroke` itself
takes radians and rad/s); speeds are in m/s, and also in mph or km/h with ``unit``.
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from dataclasses import replace

import numpy as np
import pandas as pd

from common.checks import ArgumentTypeError, finite, finite_array, shown
from common.typechecks import choice, flag, instance, quoted
from common.units import SPEED_SUFFIXES, SPEED_UNITS
from racket import STROKES, Stroke, hit
from racket.strings.sideways import BedSideways
from racket.stroke import RPM
from studies.arguments import ball_argument, racket_argument
from studies.tables import speeds_in

SPEED_COLUMNS = ("head_speed", "ball_speed", "exit_speed")
"""The speeds of a stroke table (``*_m_s``, and ``*_mph`` or ``*_kmh`` with ``unit``): the
racket point's and the incoming ball's before, the ball's after."""


VALIDATED = ("topspin-forehand",)
"""The presets whose spin ``validate`` finds within measurement, each as it is
(``tests/test_validation.py`` checks that these, and only these, agree)."""


def spin_note(strokes) -> str:
    """One short line naming the strokes of ``strokes`` (as :func:`stroke_table` takes them)
    whose spin lies outside what ``validate`` supports: a preset not in :data:`VALIDATED`, or
    any stroke changed from its preset; "" if none.

    Parameters
    ----------
    strokes : Stroke or dict or sequence
        As :func:`stroke_table`.
    """
    outside = [name for name, s in _strokes(strokes)
               if name not in VALIDATED or STROKES.get(name) != s]  # fmt: skip
    if not outside:
        return ""
    checked = ", ".join(VALIDATED)
    return (f"spin not validated for {', '.join(dict.fromkeys(outside))}: validate checks "
            f"the {checked} preset's only (docs/validation.md)")  # fmt: skip


def _strokes(strokes) -> list[tuple[str, Stroke]]:
    """``strokes`` as (name, Stroke) pairs: a dict name -> Stroke, or a sequence of pairs
    (a name may repeat: a grid of one stroke's angles) or of Strokes; one Stroke is a
    sequence of one.  A Stroke given without a name is named after the preset it is
    (:data:`racket.STROKES`), or "stroke".
    """
    if isinstance(strokes, Stroke):
        strokes = [strokes]
    if isinstance(strokes, str | bytes) or not isinstance(strokes, dict | Iterable):
        raise ArgumentTypeError(
            f"strokes must be a Stroke, a dict name -> Stroke or a sequence of (name, Stroke) "
            f"pairs, got {quoted(strokes)} (e.g. racket.STROKES)"
        )
    pairs = list(strokes.items()) if isinstance(strokes, dict) else list(strokes)
    if not pairs:
        raise ValueError("strokes must hold one stroke or more, got none")
    checked = []
    for k, pair in enumerate(pairs):
        if isinstance(pair, Stroke):
            pair = (_preset_name(pair), pair)
        if not (isinstance(pair, tuple | list) and len(pair) == 2):
            raise ValueError(
                f"strokes must be a dict name -> Stroke, (name, Stroke) pairs or Strokes, got "
                f"{quoted(pair)} at {k}"
            )
        name, stroke = pair
        instance(f"strokes[{k}] name", name, str, "a str")
        instance(f"stroke {name!r}", stroke, Stroke, "a racket.Stroke")
        checked.append((name, stroke))
    return checked


def _preset_name(stroke: Stroke) -> str:
    """The name of the preset (:data:`racket.STROKES`) ``stroke`` is, or "stroke"."""
    return next((name for name, preset in STROKES.items() if preset == stroke), "stroke")


def _moves(racket) -> None:
    """Refuse a racket that cannot swing, naming its support: a clamped head."""
    if racket.support == "clamped-head":
        raise ValueError(
            "racket must move for a stroke (support 'free' or 'hand-held'), got support "
            "'clamped-head': a clamped head cannot swing"
        )


def _degrees(name: str, values, default: float) -> list[float]:
    """Angles [deg] to sweep, finite (the Stroke checks their range); ``default`` [rad]
    alone for None.
    """
    if values is None:
        return [math.degrees(default)]
    array = np.atleast_1d(finite_array(name, values, "deg"))
    if array.ndim != 1 or array.size == 0:
        raise ValueError(f"{name} must be one angle or more [deg], got {shown(values)}")
    return [float(a) for a in array]


def _deg(angle: float) -> float:
    """An input angle [rad] in degrees, as typed: -12, not -12.000000000000002."""
    return round(math.degrees(angle), 9)


def stroke_row(name: str, stroke: Stroke, impact) -> dict:
    """One row of :func:`stroke_table`: the stroke and the ball after it (SI speeds, angles in
    degrees, spins in rpm).

    Parameters
    ----------
    name : str
        The stroke's name.
    stroke : Stroke
        The stroke.
    impact : StrokeImpact
        Its :func:`racket.hit`.
    """
    f = impact.flight
    return {
        "stroke": name,
        "shaft": stroke.shaft,
        "head_speed_m_s": stroke.head_speed,
        "path_deg": _deg(stroke.path_angle),
        "face_deg": _deg(stroke.face_angle),
        "across_deg": _deg(stroke.swing_across),
        "ball_speed_m_s": stroke.ball_speed,
        "ball_angle_deg": _deg(stroke.ball_angle),
        "ball_topspin_rpm": stroke.topspin / RPM,
        "ball_sidespin_rpm": stroke.sidespin / RPM,
        "position_from_tip_cm": 100.0 * impact.position,
        "offset_cm": 100.0 * impact.offset,
        "exit_speed_m_s": f.speed,
        "launch_deg": math.degrees(f.launch_angle),
        "direction_deg": math.degrees(f.direction),
        "spin_rpm": math.copysign(f.spin_rate, f.topspin) / RPM,
        "topspin_rpm": f.topspin / RPM,
        "sidespin_rpm": f.sidespin / RPM,
        "rifle_spin_rpm": f.rifle_spin / RPM,
        "contact_time_ms": 1e3 * impact.contact_time,
        "contact": "slid" if impact.slid_throughout else "gripped",
        "grip_time_ms": 1e3 * float(np.atleast_1d(impact.oblique.grip.grip_time)[0]),
        "racket_share": impact.racket_share,
    }


def stroke_table(
    strokes,
    racket,
    ball,
    position=None,
    side: BedSideways | None = None,
    unit: str = "m/s",
    offset: float | None = None,
) -> pd.DataFrame:
    """The ball after each stroke, one row per stroke.

    Parameters
    ----------
    strokes : Stroke or dict or sequence
        Name -> :class:`racket.Stroke` (e.g. :data:`racket.STROKES`), or (name, Stroke)
        pairs (a name may repeat), or Strokes (each named after the preset it is, or
        "stroke"); one Stroke is a list of one.
    racket : Racket
        The racket (free or hand-held; a clamped head is refused, naming its support).
    ball : Ball
        The ball.
    position : float, optional
        The impact point [m from the tip]; default the string bed's centre.
    side : BedSideways, optional
        The bed sideways (:func:`racket.strings.sideways.sideways`); default the racket's bed's,
        dry strings that slide.
    unit : str, optional
        "m/s", "mph" or "km/h": the speeds also in this unit (``*_mph``, ``*_kmh``), the one
        the user typed.
    offset : float, optional
        The impact point's distance from the long axis [m, + towards 3 o'clock]; default on
        the axis.

    Returns
    -------
    DataFrame
        ``stroke`` (the name), ``shaft``, the inputs ``head_speed_m_s``, ``path_deg``,
        ``face_deg``, ``across_deg``, ``ball_speed_m_s``, ``ball_angle_deg``,
        ``ball_topspin_rpm``, ``ball_sidespin_rpm``, the impact point
        ``position_from_tip_cm`` and ``offset_cm``, and the ball after: ``exit_speed_m_s``,
        ``launch_deg`` (above the horizontal), ``direction_deg`` (+ to the left),
        ``spin_rpm`` (its rate, signed as its topspin: < 0 for a ball with backspin),
        ``topspin_rpm``, ``sidespin_rpm``, ``rifle_spin_rpm``, ``contact_time_ms``,
        ``contact`` ("slid": the ball slid on the strings throughout; "gripped"),
        ``grip_time_ms`` and ``racket_share`` [-] (the part of the ball's speed away from
        the face that the racket's speed gave it).

    Examples
    --------
    >>> from racket import STROKES, default_ball, default_racket
    >>> table = stroke_table({"volley": STROKES["volley"]}, default_racket(), default_ball())
    >>> table["contact"].iloc[0] in ("slid", "gripped")
    True
    """
    pairs = _strokes(strokes)
    racket, ball = racket_argument(racket), ball_argument(ball)
    _moves(racket)
    if position is not None:
        position = finite("position", position, "m from the tip")
    instance("side", side, BedSideways | type(None), "a BedSideways or None",
             " (racket.strings.sideways.sideways(racket.strings) makes one)")  # fmt: skip
    choice("unit", unit, tuple(SPEED_UNITS))
    rows = [stroke_row(name, s, hit(s, racket, ball, position, offset=offset, side=side))
            for name, s in pairs]  # fmt: skip
    return speeds_in(pd.DataFrame(rows), unit, SPEED_COLUMNS)


def sweep_angles(
    base: Stroke,
    path_angles_deg,
    face_angles_deg,
    racket,
    ball,
    position=None,
    side: BedSideways | None = None,
    name: str = "stroke",
    unit: str = "m/s",
    offset: float | None = None,
) -> pd.DataFrame:
    """The ball after ``base`` with each racket path and face angle: one row per
    combination, the paths outermost (:func:`stroke_table`'s columns).

    Parameters
    ----------
    base : Stroke
        The stroke whose angles vary.
    path_angles_deg, face_angles_deg : float or sequence of float or None
        The racket paths and face angles [deg] (:class:`racket.Stroke`: path + rising, face
        + open); None: the base's.
    racket, ball, position, side, unit, offset :
        As in :func:`stroke_table`.
    name : str, optional
        Every row's ``stroke``.

    Raises
    ------
    ValueError
        For an angle out of its range, or a combination where the racket misses the ball
        (before any impact).
    """
    instance("base", base, Stroke, "a racket.Stroke")
    instance("name", name, str, "a str")
    paths = _degrees("path_angles_deg", path_angles_deg, base.path_angle)
    faces = _degrees("face_angles_deg", face_angles_deg, base.face_angle)
    strokes = [
        (name, replace(base, path_angle=math.radians(p), face_angle=math.radians(f)))
        for p in paths
        for f in faces
    ]
    return stroke_table(strokes, racket, ball, position, side, unit, offset)


def bed_words(side: BedSideways, lubricated: bool = False) -> str:
    """What the ball meets sideways, in words for a conditions line: "ball-string friction
    0.444, mains and crosses sliding on dry crossings (friction 0.086)", "... on lubricated
    crossings", "... strings held still".

    Parameters
    ----------
    side : BedSideways
        The bed sideways.
    lubricated : bool, optional
        The strings were lubricated (said as such).
    """
    instance("side", side, BedSideways, "a BedSideways")
    lubricated = flag("lubricated", lubricated)
    said = f"ball-string friction {side.ball_friction:.3g}"
    if not side.slides:
        return f"{said}, strings held still"
    dry = "lubricated" if lubricated else "dry"
    return (f"{said}, mains and crosses sliding on {dry} crossings (friction "
            f"{side.string_friction:.3g})")  # fmt: skip


def plot_speed_spin(table: pd.DataFrame, ax=None, unit: str = "m/s", conditions=None):
    """The ball's exit speed against its spin (signed: backspin < 0) after each stroke (a
    table of :func:`stroke_table`), each stroke labelled: by its name beside its point, or
    for a stroke of several rows (angles swept) one line per face angle, along the path, in
    a legend beside the Axes.

    Parameters
    ----------
    table : DataFrame
        A table of :func:`stroke_table` or :func:`sweep_angles`.
    ax : Axes, optional
        The Axes to draw on; None: a new figure's.
    unit : str, optional
        The speed's unit, "m/s", "mph" or "km/h" (the table must hold its column).
    conditions : str, optional
        What the strokes were hit with, drawn as the figure's heading; None: none drawn.
    """
    from studies.plots.axes import _axes
    from studies.plots.layout import finish, legend_outside

    choice("unit", unit, tuple(SPEED_UNITS))
    column = f"exit_speed_{SPEED_SUFFIXES[unit]}"
    if column not in table:
        raise ValueError(f"table has no {column} column: make it with unit={unit!r}")
    made = ax is None
    ax = _axes(ax, 1)
    several = table["stroke"].duplicated().any()
    # a swept stroke: one line per face angle, its points in the order of the path
    keys = ["stroke", "face_deg"] if several else ["stroke"]
    groups = list(table.sort_values("path_deg").groupby(keys, sort=False))
    for key, group in groups:
        name = f"{key[0]}, face {key[1]:+g} deg" if several else key[0]
        ax.plot(group["spin_rpm"], group[column], "o-" if len(group) > 1 else "o", label=name)
        if not several:
            row = group.iloc[0]
            ax.annotate(name, (row["spin_rpm"], row[column]), xytext=(5, 4),
                        textcoords="offset points", fontsize="small")  # fmt: skip
    ax.set_xlabel("spin after the stroke [rpm] (< 0: backspin)")
    ax.set_ylabel(f"ball's exit speed [{unit}]")
    ax.margins(0.15)
    ax.axvline(0.0, color="0.7", linewidth=0.8)  # backspin to its left, topspin to its right
    if several:
        legend_outside(ax)
    return finish(ax, conditions, made)
