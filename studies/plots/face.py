"""A map over the string face: one field on the grid, the landmarks drawn on it."""

from __future__ import annotations

import numpy as np
from matplotlib.patches import Ellipse

from studies.maps import SWEET_FRACTION


def plot_face_map(face_map, field: str = "e_A", ax=None):
    """A :class:`studies.maps.FaceMap` as filled contours over the face, tip up: the
    string bed's outline, where the ball's centre may land (dotted), the first mode's node
    line, the centre of percussion for a hand at the grip, and the sweet area's edge with
    its area.

    Parameters
    ----------
    face_map : FaceMap
    field : str
        One of :data:`studies.maps.FIELDS` (default ``"e_A"``).
    ax : Axes, optional
    """
    from studies.maps import FIELDS

    if field not in FIELDS or getattr(face_map, field) is None:
        have = [f for f in FIELDS if getattr(face_map, f) is not None]
        raise ValueError(f"field must be one of {have}, got {field!r}")
    if ax is None:
        import matplotlib.pyplot as plt

        _, ax = plt.subplots(figsize=(5.2, 7.2))
    strings = face_map.strings
    y_cm = 100 * face_map.offsets
    x_cm = np.broadcast_to(100 * face_map.positions[:, None], y_cm.shape)
    values = getattr(face_map, field)
    filled = ax.contourf(y_cm, x_cm, values, levels=14, cmap="viridis")
    ax.figure.colorbar(filled, ax=ax, label=_FIELD_LABELS[field])
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
    ax.plot(0.0, cop, "X", color="k", mec="w", ms=9, label="centre of percussion (hand pivot)")
    ax.contour(
        y_cm, x_cm, face_map.e_A, levels=[face_map.sweet_threshold],
        colors="r", linewidths=1.5,
    )  # fmt: skip
    ax.plot(
        [],
        [],
        color="r",
        label=f"sweet area (e_A within {100 * SWEET_FRACTION:g} %): "
        f"{face_map.sweet_area_cm2:.0f} cm$^2$",
    )
    ax.set_aspect("equal")
    ax.set_xlim(-half - 1, half + 1)
    ax.set_ylim(100 * strings.extent[1] + 1, 100 * strings.extent[0] - 1)  # tip up
    ax.set_xlabel("offset from the axis [cm] (+ towards 3 o'clock)")
    ax.set_ylabel("distance from the tip [cm]")
    ax.set_title(f"{_FIELD_LABELS[field]}\nball at {face_map.speed:g} m/s")
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.1), fontsize="small")
    return ax


_FIELD_LABELS = {
    "e": "e (Eq. 21) [-]",
    "e_A": "apparent COR e_A [-]",
    "exit_speed": "exit speed, racket at rest [m/s]",
    "exit_speed_swung": "exit speed, swung racket [m/s]",
    "vibration_energy": "vibration energy / incoming energy [-]",
    "roll_rate": "twist rate [rad/s]",
}
