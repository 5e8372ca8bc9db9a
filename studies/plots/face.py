"""A map over the string face: one field on the grid, the landmarks drawn on it."""

from __future__ import annotations

import numpy as np
from matplotlib.patches import Ellipse

from studies.face.maps import SWEET_FRACTION
from studies.plots.axes import _axes
from studies.plots.layout import FROM_TIP, finish
from studies.plots.units import speed_scale

_SPEEDS = ("exit_speed", "exit_speed_swung")
"""The fields that are speeds (shown in the unit typed)."""

_AT_REST = ("e_A", "exit_speed")
"""The fields whose largest values are the sweet area's: e_A, and the exit speed off the
racket at rest, which is e_A times the ball's speed."""

LEVELS = 14
"""How many filled contours a face map has, about (spread at round values over its values,
:class:`matplotlib.ticker.MaxNLocator`, as :meth:`matplotlib.axes.Axes.contourf` spreads a
count)."""

_LARGER_IS_BETTER = ("e", "exit_speed_swung")
"""The other fields whose peak region (within :data:`studies.face.maps.SWEET_FRACTION` of their
largest value) is drawn: players seek their largest values."""


def plot_face_map(
    face_map,
    field: str = "e_A",
    ax=None,
    unit: str = "m/s",
    conditions: str | None = None,
    levels=LEVELS,
):
    """A :class:`studies.face.maps.FaceMap` as filled contours over the face, tip up: the
    string bed's outline, where the ball's centre may land (dotted), the first mode's node
    line, the centre of percussion for a hand at the grip, and the region of the field's own
    largest values: the sweet area (e_A within :data:`studies.face.maps.SWEET_FRACTION` of its
    largest, with its area) over e_A and the exit speed off the racket at rest; over e and
    the swung racket's exit speed, where they are within that fraction of their own largest
    (marked); none over the vibration and the twist rate.

    Parameters
    ----------
    face_map : FaceMap
    field : str
        One of :data:`studies.face.maps.FIELDS` (default ``"e_A"``).
    ax : Axes, optional
        The Axes to draw on; None: a new figure's.
    unit : str
        The unit of speeds (the exit speeds, the ball's speed), one of
        :data:`common.units.SPEED_UNITS` (the one the user typed).
    conditions : str, optional
        The run's conditions, drawn as the figure's heading; None: none drawn.
    levels : int or array_like
        The filled contours: how many, spread over this map's own values (default
        :data:`LEVELS`), or their edges, increasing [the field's unit: ``unit`` for a speed,
        else as its colour bar says]: the colour scale runs from the first to the last, so
        that maps drawn with the same edges share one scale (equal colours, equal values;
        :func:`shared_levels`).
    """
    from studies.face.maps import FIELDS

    if field not in FIELDS or getattr(face_map, field) is None:
        have = [f for f in FIELDS if getattr(face_map, f) is not None]
        raise ValueError(f"field must be one of {have}, got {field!r}")
    size = speed_scale(unit)
    made = ax is None
    ax = _axes(ax, 1, figsize=(5.6, 7.6))
    strings = face_map.strings
    y_cm = 100 * face_map.offsets
    x_cm = np.broadcast_to(100 * face_map.positions[:, None], y_cm.shape)
    values = getattr(face_map, field) / (size if field in _SPEEDS else 1.0)
    label = _FIELD_LABELS[field].format(unit=unit)
    filled = ax.contourf(y_cm, x_cm, values, levels=levels, cmap="viridis")
    ax.figure.colorbar(filled, ax=ax, label=label, shrink=0.8)
    length = 100 * (strings.extent[1] - strings.extent[0])
    width = 100 * strings.full_width
    margin = 100 * face_map.margin
    centre = (0.0, 100 * strings.center)
    ax.add_patch(Ellipse(centre, width, length, fill=False, color="k", lw=1.5))
    ax.add_patch(
        Ellipse(centre, width - 2 * margin, length - 2 * margin, fill=False, color="k", ls=":")
    )
    half = 0.5 * width
    for x in 100 * face_map.node:  # the node line across the bed (as Racket.check_points)
        chord = half * np.sqrt(max(0.0, 1.0 - float(strings.rho2(x / 100))))
        ax.plot(
            [-chord, chord],
            [x, x],
            color="tab:orange",
            ls="--",
            lw=1.5,
            label="node of the first mode",
        )
    cop = 100 * face_map.center_of_percussion
    ax.plot(
        0.0,
        cop,
        "X",
        color="k",
        mec="w",
        ms=9,
        label="centre of percussion (hand pivot)",
    )
    _peak_region(ax, face_map, field, y_cm, x_cm, values)
    ax.set_aspect("equal")
    ax.set_xlim(-half - 1, half + 1)
    ax.set_ylim(100 * strings.extent[1] + 1, 100 * strings.extent[0] - 1)  # tip up
    ax.set_xlabel("offset from the axis [cm] (+ towards 3 o'clock)")
    ax.set_ylabel(FROM_TIP)
    ax.set_title(f"{label}\nball at {face_map.speed / size:.4g} {unit}")
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.1), fontsize="small")
    return finish(ax, conditions, made)


def shared_levels(face_maps, field: str = "e_A", unit: str = "m/s"):
    """Edges of filled contours spanning ``field`` over all ``face_maps`` (about
    :data:`LEVELS` of them, at round values, as one map spreads them over its own values), for
    :func:`plot_face_map`'s ``levels``: maps drawn with them share one colour scale.

    Parameters
    ----------
    face_maps : iterable of FaceMap
        The maps to be drawn on one scale.
    field : str
        One of :data:`studies.face.maps.FIELDS`, as :func:`plot_face_map` takes it.
    unit : str
        The unit of speeds, as :func:`plot_face_map` takes it.

    Returns
    -------
    ndarray
        The edges, increasing, the first at or below the smallest value of every map and the
        last at or above the largest.
    """
    from matplotlib.ticker import MaxNLocator

    size = speed_scale(unit) if field in _SPEEDS else 1.0
    values = [np.asarray(getattr(face, field)) / size for face in face_maps]
    low = min(float(np.min(v)) for v in values)
    high = max(float(np.max(v)) for v in values)
    return MaxNLocator(LEVELS + 1, min_n_ticks=1).tick_values(low, high)


def _peak_region(ax, face_map, field: str, y_cm, x_cm, values) -> None:
    """Draw the edge of the region of ``field``'s own largest values (red), labelled: the
    sweet area over the fields at rest that share it, else the region within
    :data:`studies.face.maps.SWEET_FRACTION` of the field's largest value on the grid with that
    value marked, for the fields players want large; nothing for the others.
    """
    if field in _AT_REST:
        level, label = (
            face_map.sweet_threshold,
            (
                f"sweet area (e_A within {100 * SWEET_FRACTION:g} %): "
                f"{face_map.sweet_area_cm2:.0f} cm$^2$"
            ),
        )
        grid = face_map.e_A
    elif field in _LARGER_IS_BETTER:
        grid = values
        level = (1.0 - SWEET_FRACTION) * np.max(grid)
        i, j = np.unravel_index(np.argmax(grid), grid.shape)
        words = _FIELD_LABELS[field].split(" [")[0]
        label = f"{words} within {100 * SWEET_FRACTION:g} % of its largest"
        ax.plot(y_cm[i, j], x_cm[i, j], "*", color="r", mec="w", ms=12, label="largest")
    else:
        return
    if np.max(grid) > level:
        ax.contour(y_cm, x_cm, grid, levels=[level], colors="r", linewidths=1.5)
    ax.plot([], [], color="r", label=label)


_FIELD_LABELS = {
    "e": "e (Eq. 21) [-]",
    "e_A": "apparent COR e_A [-]",
    "exit_speed": "exit speed, racket at rest [{unit}]",
    "exit_speed_swung": "exit speed, swung racket [{unit}]",
    "vibration_energy": "vibration energy / incoming energy [-]",
    "roll_rate": "twist rate [rad/s]",
}
