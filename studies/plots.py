"""Plots of simulation results (matplotlib).

Every function takes results computed elsewhere and an optional ``ax`` (an Axes, or a
sequence of Axes for the multi-panel plots), draws, and returns the Axes; none calls
``show()``.  Positions along the racket are distances from the tip, in cm on the plots.
"""

from __future__ import annotations

import numpy as np
from matplotlib.patches import Ellipse, Rectangle

from ball import Ball, LinearSpring, SineLaw, collide, unhappy_cor
from racket import Racket
from studies.landmarks import center_of_percussion, hand_pivot, percussion_centre
from studies.maps import SWEET_FRACTION
from studies.sweeps import PARAMETERS


def _axes(ax, count: int):
    """``count`` Axes: the ones given, or a new figure's."""
    if ax is None:
        import matplotlib.pyplot as plt

        _, ax = plt.subplots(count, 1, sharex=True, figsize=(6.4, 2.2 + 1.8 * count), squeeze=False)
        return ax[:, 0] if count > 1 else ax[0, 0]
    if count > 1 and len(np.atleast_1d(ax)) != count:
        raise ValueError(f"ax must be {count} Axes, got {ax!r}")
    return ax


def _curves(result):
    """(label, position, e, e_A, not self-consistent) per grid point of a sweep table (its
    parameter columns, :data:`studies.sweeps.PARAMETERS`), or the one of an Impact; each
    sorted along the racket.
    """
    if hasattr(result, "columns"):
        keys = [c for c in PARAMETERS.values() if c in result.columns]
        groups = result.groupby(keys, sort=False) if keys else [((), result)]
        for key, g in groups:
            values = key if isinstance(key, tuple) else (key,)
            label = ", ".join(
                f"{k} {v:g}" if isinstance(v, float) else f"{k} {v}"
                for k, v in zip(keys, values, strict=True)
            )
            flagged = ~g["self_consistent"].to_numpy(bool) if "self_consistent" in g else None
            yield _sorted(label, g["position_from_tip_m"], g["e"], g["e_A"], flagged)
        return
    yield _sorted(
        "",
        np.atleast_1d(result.position),
        np.atleast_1d(result.e),
        np.atleast_1d(result.e_A),
        ~np.atleast_1d(result.self_consistent),
    )


def _sorted(label, x, e, e_a, flagged):
    """One curve of :func:`_curves`, as float arrays sorted along the racket."""
    x, e, e_a = (np.asarray(v, dtype=float) for v in (x, e, e_a))
    flagged = np.zeros(x.size, bool) if flagged is None else np.asarray(flagged, bool)
    order = np.argsort(x)
    return label, x[order], e[order], e_a[order], flagged[order]


def draw_racket(racket: Racket, ax, y0: float, height: float):
    """Draw the racket to scale along x (cm from the tip), in the band [y0, y0 + height].

    Parameters
    ----------
    racket : Racket
        The racket to draw.
    ax : Axes
        The Axes to draw on (x in cm from the tip).
    y0 : float
        Bottom of the band [data units], in the Axes' y data units.
    height : float
        Height of the band [data units], in the Axes' y data units.
    """
    length = racket.beam.length * 100
    start, end = (100 * v for v in racket.strings.extent)
    mid = y0 + 0.5 * height
    ax.add_patch(
        Rectangle(
            (end, mid - 0.08 * height), length - end, 0.16 * height, color="0.35", label="_frame"
        )
    )
    ax.add_patch(
        Ellipse(
            ((start + end) / 2, mid), end - start + 2.0, height, fill=False, lw=2.5, color="0.35"
        )
    )
    ax.add_patch(
        Ellipse(
            ((start + end) / 2, mid),
            end - start,
            0.82 * height,
            facecolor="0.9",
            edgecolor="none",
            hatch="++",
            label="_strings",
        )
    )
    ax.add_patch(
        Rectangle(
            (100 * hand_pivot(racket) - 6, mid - 0.14 * height),
            12,
            0.28 * height,
            color="0.15",
            label="_grip",
        )
    )


def _simulated_cop(result, racket: Racket, pivot: float):
    """The centre of percussion [m from the tip] from one curve's impacts
    (:func:`studies.landmarks.percussion_centre`), or None if they are not of a racket at
    rest along its axis or it is not among them.

    Parameters
    ----------
    result : Impact or DataFrame
        As in :func:`plot_cor_along_racket`, with one curve.
    racket : Racket
        The racket hit.
    pivot : float
        The pivot [m from the tip].
    """
    if hasattr(result, "columns"):
        names = ("position_from_tip_m", "v_cm_m_s", "omega_rad_s", "swing_speed_m_s")
        if not all(n in result.columns for n in names) or (
            "offset_m" in result.columns and np.any(result["offset_m"].to_numpy() != 0.0)
        ):
            return None
        x, v_cm, omega, moving = (result[n].to_numpy(float) for n in names)
    else:
        if result.offset is not None and np.any(np.asarray(result.offset) != 0.0):
            return None
        x, v_cm, omega, moving = (
            np.atleast_1d(np.asarray(v, float))
            for v in (result.position, result.v_cm, result.omega, result.swing_speed)
        )
    if x.size < 2 or np.any(moving != 0.0):
        return None
    order = np.argsort(x)
    cop = percussion_centre(racket, x[order], v_cm[order], omega[order], pivot)
    return None if np.isnan(cop) else cop


def plot_cor_along_racket(result, racket: Racket, ax=None, pivot: float | None = None):
    """E and e_A along the racket, with the racket drawn to scale below the curves.

    Marks the mode-1 node, the centre of percussion for a pivot at the hand (default
    :func:`studies.landmarks.hand_pivot`; from the impacts, :func:`studies.landmarks.
    percussion_centre`, for one curve of a racket at rest, else the rigid-body formula),
    the points of largest e and largest e_A, and
    (with a cross) the unhappy-ball impacts that have no self-consistent Xo.  A sweep table
    over a grid draws one pair of curves per grid point, labelled with its parameters.

    Parameters
    ----------
    result : Impact or DataFrame
        An :func:`racket.impact` over many positions, or a :func:`studies.sweep` table.
    racket : Racket
        The racket the result is for.
    ax : Axes, optional
        The Axes to draw on; None: a new figure's.
    pivot : float, optional
        Pivot of the centre of percussion [m from the tip]; None: the hand
        (:func:`studies.landmarks.hand_pivot`).
    """
    ax = _axes(ax, 1)
    curves = list(_curves(result))
    single = len(curves) == 1
    lows, tops, marked = [0.0], [1.0], False
    for k, (label, x, e, e_a, flagged) in enumerate(curves):
        cm = 100 * x
        if single:
            e_style = dict(color="C0", label="e (Eq. 21, rigid-body motion)")
            a_style = dict(color="C1", lw=2, label="e_A = V1/v1 (apparent)")
        else:
            e_style = dict(color=f"C{k}", label=f"e ({label})")
            a_style = dict(color=f"C{k}", lw=1.5, ls="--", label=f"e_A ({label})")
        ax.plot(cm, e, lw=2, **e_style)
        ax.plot(cm, e_a, **a_style)
        if np.any(flagged):
            label = "_" if marked else "no self-consistent Xo"
            ax.plot(cm[flagged], e[flagged], "x", color="k", ms=7, label=label)
            marked = True
        lows.append(np.nanmin(e_a))
        tops.append(np.nanmax(e))
    if single:
        _, x, e, e_a, _ = curves[0]
        cm = 100 * x
        i, j = int(np.argmax(e)), int(np.argmax(e_a))
        for k, y, mark, name in ((i, e, "o", "e"), (j, e_a, "s", "e_A")):
            color = "C0" if name == "e" else "C1"
            label = f"largest {name} {y[k]:.3f} at {cm[k]:.1f} cm"
            ax.plot(cm[k], y[k], mark, color=color, ms=8, label=label)
    node = racket.beam.modes.nodes(1)[0]
    ax.axvline(100 * node, color="C2", ls="--", label=f"mode-1 node {100 * node:.1f} cm")
    pivot = hand_pivot(racket) if pivot is None else pivot
    cop = _simulated_cop(result, racket, pivot) if single else None
    how = "" if cop is not None else " (rigid body)"
    cop = center_of_percussion(racket, pivot) if cop is None else cop
    ax.axvline(100 * cop, color="C3", ls=":", label=f"centre of percussion{how} {100 * cop:.1f} cm")
    low, top = min(lows), max(tops)
    band = 0.35 * (top - low)
    draw_racket(racket, ax, low - 1.15 * band, band)
    ax.set_xlim(-2, 100 * racket.beam.length + 2)
    ax.set_ylim(low - 1.25 * band, top + 0.05)
    ax.set_xlabel("impact point [cm from the tip]")
    ax.set_ylabel("coefficient of restitution")
    ax.legend(loc="upper right", fontsize="small")
    return ax


def plot_cor_comparison(results, ax=None, show_apparent: bool = True):
    """E along the strings for several rackets on one Axes.

    Parameters
    ----------
    results : mapping label -> Impact or DataFrame
        For each racket, an :func:`racket.impact` over many positions or a
        :func:`studies.sweep` table (e.g. from :func:`studies.sweeps.compare`).
    ax : Axes, optional
        The Axes to draw on; None: a new figure's.
    show_apparent : bool
        Also draw e_A (dashed, same colour).
    """
    ax = _axes(ax, 1)
    for k, (label, result) in enumerate(results.items()):
        curves = list(_curves(result))
        if len(curves) != 1:
            raise ValueError(
                f"results[{label!r}] must hold one curve, got a table over a grid "
                f"({', '.join(c[0] for c in curves[:3])}, ...)"
            )
        _, x, e, e_a, _ = curves[0]
        color = f"C{k}"
        best = int(np.argmax(e))
        ax.plot(
            100 * x,
            e,
            color=color,
            lw=2,
            label=f"{label}: e, largest {e[best]:.3f} at {100 * x[best]:.1f} cm",
        )
        if show_apparent:
            ax.plot(100 * x, e_a, color=color, ls="--", lw=1.2, label="_e_A")
    ax.set_xlabel("impact point [cm from the tip]")
    ax.set_ylabel("coefficient of restitution")
    ax.set_title("e (solid) and e_A (dashed) along the strings" if show_apparent else "e")
    ax.legend(loc="lower center", fontsize="small")
    return ax


def plot_impact(result, ax=None):
    """Force, compressions and velocities of one impact against time (three panels); the
    impact point's velocity is split into its dc (rigid-body) and ac (vibration) parts.

    Parameters
    ----------
    result : Impact
        An :func:`racket.impact` at one position with ``histories=True`` (SI).
    ax : sequence of 3 Axes, optional
        The Axes of the three panels; None: a new figure's.
    """
    if result.t is None:
        raise ValueError("plot_impact needs the histories: impact(..., histories=True)")
    axes = _axes(ax, 3)
    t = 1e3 * result.t
    axes[0].plot(t, result.force, color="C0", label="contact force")
    axes[0].set_ylabel("force [N]")
    axes[1].plot(t, 1e3 * result.ball_compression, color="C1", label="ball compression")
    axes[1].plot(t, 1e3 * result.string_deflection, color="C2", label="string deflection")
    axes[1].set_ylabel("compression [mm]")
    axes[2].plot(t, result.ball_velocity, color="C1", label="ball")
    axes[2].plot(t, result.point_velocity, color="k", label="impact point, total")
    axes[2].plot(
        t,
        result.point_velocity_dc_history,
        color="C0",
        ls="--",
        label="impact point, dc (rigid body)",
    )
    axes[2].plot(
        t,
        result.point_velocity_ac_history,
        color="C3",
        ls=":",
        label="impact point, ac (vibration)",
    )
    axes[2].set_ylabel("velocity [m/s]")
    axes[2].set_xlabel("time [ms]")
    for a in axes:
        a.legend(fontsize="small")
    axes[0].set_title(
        f"impact at {100 * float(result.position):.1f} cm from the tip, "
        f"e = {float(result.e):.3f}, e_A = {float(result.e_A):.3f}"
    )
    return axes


def plot_modes(racket: Racket, ax=None, count: int = 4):
    """The first ``count`` bending-mode shapes along the racket, frequencies in the legend
    and nodes marked.

    Parameters
    ----------
    racket : Racket
        The racket whose modes to draw.
    ax : Axes, optional
        The Axes to draw on; None: a new figure's.
    count : int, optional
        Bending modes to draw (at most as many as the beam has).
    """
    ax = _axes(ax, 1)
    modes = racket.beam.modes
    count = min(count, modes.count - 2)
    x = np.linspace(0.0, racket.beam.length, 400)
    shapes = modes.shape(x)[2 : 2 + count]
    for k, shape in enumerate(shapes, start=1):
        scale = np.abs(shape).max()
        ax.plot(
            100 * x,
            shape / scale,
            color=f"C{k - 1}",
            label=f"mode {k}: {modes.frequencies[k - 1]:.0f} Hz",
        )
        nodes = modes.nodes(k)
        ax.plot(100 * nodes, np.zeros_like(nodes), "o", color=f"C{k - 1}", ms=5)
    ax.axhline(0, color="0.6", lw=0.8)
    start, end = (100 * v for v in racket.strings.extent)
    ax.axvspan(start, end, color="0.9", label="strings")
    ax.set_xlabel("position [cm from the tip]")
    ax.set_ylabel("mode shape (normalised)")
    ax.legend(fontsize="small")
    return ax


def plot_collision(collision, ax=None, title: str | None = None):
    """A two-ball collision against time, as in the paper's Figs. 2-4: force; compressions
    X, Y and X_T = X + Y; velocities of both balls.

    Parameters
    ----------
    collision : Collision
        A :func:`ball.collide` result (SI).
    ax : sequence of 3 Axes, optional
        The Axes of the three panels; None: a new figure's.
    title : str, optional
        Title of the top panel; None: the COR.
    """
    axes = _axes(ax, 3)
    h = collision.history
    t = 1e3 * h.t
    axes[0].plot(t, h.force, color="C0", label="F")
    axes[0].set_ylabel("force [N]")
    axes[1].plot(t, 1e3 * h.compression_a, color="C1", label="X (ball a)")
    axes[1].plot(t, 1e3 * h.compression_b, color="C2", label="Y (ball b)")
    axes[1].plot(t, 1e3 * h.total_compression, color="k", ls="--", label="X_T = X + Y")
    axes[1].set_ylabel("compression [mm]")
    axes[2].plot(t, h.velocity_a, color="C1", label="ball a")
    axes[2].plot(t, h.velocity_b, color="C2", label="ball b")
    axes[2].set_ylabel("velocity [m/s]")
    axes[2].set_xlabel("time [ms]")
    for a in axes:
        a.legend(fontsize="small")
    axes[0].set_title(title or f"e = {collision.e:.3f}")
    return axes


def plot_drop(result, ax=None):
    """A dropped ball's contact (:func:`studies.drop.drop`): the force [N] and the ball's
    compression [mm] against time [ms].

    Parameters
    ----------
    result : Drop
        The drop.
    ax : sequence of 2 Axes, optional
        The Axes of the two panels; None: a new figure's.
    """
    axes = _axes(ax, 2)
    t = 1e3 * result.t
    axes[0].plot(t, result.force, color="C0")
    axes[0].set_ylabel("contact force [N]")
    axes[1].plot(t, 1e3 * result.compression, color="C1")
    axes[1].set_ylabel("ball compression [mm]")
    axes[1].set_xlabel("time since first contact [ms]")
    axes[0].set_title(
        f"dropped from {result.height:g} m, bounces to {result.bounce_height:.3g} m "
        f"(rebound ratio {result.rebound_ratio:.3f})"
    )
    return axes


def plot_cor_vs_stiffness(
    ax=None, k0: float = 2e4, ratios=None, mass: float = 0.0103, speed: float = 4.0
):
    """E of an unhappy ball (k0) on happy balls against k2/k0: the integration (markers)
    and Eq. 16 (line).

    Parameters
    ----------
    ax : Axes, optional
        The Axes to draw on; None: a new figure's.
    k0 : float, optional
        The unhappy ball's Fo / Xo [N/m].
    ratios : array_like, optional
        Values of k2 / k0 [-] to integrate; None: 16 from 0.05 to 10, spaced geometrically.
    mass : float, optional
        Mass of each ball [kg].
    speed : float, optional
        Speed of the unhappy ball at first touch, the happy ball at rest [m/s].
    """
    ax = _axes(ax, 1)
    ratios = np.geomspace(0.05, 10, 16) if ratios is None else np.asarray(ratios)
    unhappy = Ball(mass, SineLaw(k0))
    simulated = [collide(unhappy, Ball(mass, LinearSpring(r * k0)), speed).e for r in ratios]
    fine = np.geomspace(ratios.min(), ratios.max(), 300)
    ax.plot(
        fine,
        [unhappy_cor(k0, r * k0) for r in fine],
        color="C0",
        label="Eq. 16: (pi k0 - k2)/(pi k0 + k2)",
    )
    ax.plot(ratios, simulated, "o", color="C1", label="integration of Eqs. 7-11")
    ax.axhline(0, color="0.6", lw=0.8)
    ax.set_xscale("log")
    ax.set_xlabel("k2 / k0")
    ax.set_ylabel("e")
    ax.legend(fontsize="small")
    return ax


def plot_serve_what_if(table, ax=None):
    """Serve-speed reduction of a zero-COR ball against string and ball stiffness (the
    table of :func:`studies.serve.serve_what_if`).

    Parameters
    ----------
    table : DataFrame
        The table of :func:`studies.serve.serve_what_if` (stiffness values [N/m]).
    ax : Axes, optional
        The Axes to draw on; None: a new figure's.
    """
    ax = _axes(ax, 1)
    for (varied, group), marker in zip(table.groupby("varied", sort=False), "os", strict=False):
        label = "string-bed stiffness" if varied == "string_stiffness" else "ball stiffness"
        ax.plot(group["value"], group["reduction_simulated_percent"], marker + "-", label=label)
    ax.set_xscale("log")
    ax.set_xlabel("stiffness [N/m]")
    ax.set_ylabel("serve-speed reduction, zero-COR ball [%]")
    ax.legend(fontsize="small")
    return ax


def plot_rigid_bounce(table, ax=None, radius: float | None = None, bands=None):
    """A ball's rigid-surface bounce against impact speed (:func:`studies.bounce.
    rigid_bounce_table`): COR, contact time [ms], peak force [kN] and peak compression [mm],
    with what is sourced at the 254 cm drop (the ITF rebound band of the ball's type, a
    contact time of about 4 ms, a compression of about 6 mm: :mod:`ball.catalog`), the
    assumed COR of the type 2 ball at 30 m/s with its plausible range, and, if given, the
    ball's ``radius`` [m].

    Parameters
    ----------
    table : DataFrame
        The table of :func:`studies.bounce.rigid_bounce_table` (SI columns).
    ax : sequence of 4 Axes, optional
        The Axes of the four panels; None: a new figure's.
    radius : float, optional
        Ball radius [m], drawn on the compression panel; None: not drawn.
    bands : ItfBands, optional
        The ITF bands of the ball's type (:mod:`ball.catalog`); None: the type 2 ball's.
    """
    from ball.catalog import (
        CALIBRATION_SPEED,
        COR_AT_30,
        COR_AT_30_RANGE,
        DROP_COMPRESSION,
        DROP_CONTACT_TIME,
        ITF_DROP_SPEED,
        TYPE_2_BANDS,
    )

    ax = _axes(ax, 4)
    v = table["speed_m_s"]

    def sourced(axis, value, band, scale, label):
        low, high, mid = scale * band[0], scale * band[1], scale * value
        axis.errorbar([ITF_DROP_SPEED], [mid], yerr=[[mid - low], [high - mid]], fmt="s",
                      color="k", capsize=4, label=label)  # fmt: skip

    ax[0].plot(v, table["e"], "o-", label="simulated")
    cor = (bands or TYPE_2_BANDS).cor
    sourced(ax[0], 0.5 * (cor[0] + cor[1]), cor, 1.0, "ITF rebound band (254 cm drop)")
    ax[0].errorbar([CALIBRATION_SPEED], [COR_AT_30], fmt="D", color="tab:red",
                   yerr=[[COR_AT_30 - COR_AT_30_RANGE[0]], [COR_AT_30_RANGE[1] - COR_AT_30]],
                   capsize=4, label="type 2 at 30 m/s: assumed, with its range")  # fmt: skip
    ax[0].set_ylabel("COR on a rigid surface")
    ax[0].legend(fontsize="small")
    ax[1].plot(v, 1e3 * table["contact_time_s"], "o-")
    sourced(ax[1], *DROP_CONTACT_TIME, 1e3, "about 4 ms (Cross 2000), accepted band")
    ax[1].set_ylabel("contact time [ms]")
    ax[1].legend(fontsize="small")
    ax[2].plot(v, 1e-3 * table["peak_force_N"], "o-")
    ax[2].set_ylabel("peak force [kN]")
    ax[3].plot(v, 1e3 * table["peak_compression_m"], "o-")
    sourced(ax[3], *DROP_COMPRESSION, 1e3, "about 6 mm (Cross), accepted band")
    if radius is not None:
        ax[3].axhline(1e3 * radius, ls="--", color="gray", label="ball radius")
    ax[3].legend(fontsize="small")
    ax[3].set_ylabel("peak compression [mm]")
    ax[3].set_xlabel("impact speed [m/s]")
    return ax


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
            [-chord, chord], [x, x], color="tab:orange", ls="--", lw=1.5, label="node of mode 1"
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
    "e": "e (Eq. 21)",
    "e_A": "apparent COR e_A",
    "exit_speed": "exit speed, racket at rest [m/s]",
    "exit_speed_swung": "exit speed, swung racket [m/s]",
    "vibration_energy": "vibration energy / incoming energy",
    "roll_rate": "twist rate [rad/s]",
}


def plot_hand_feel(feel, ax=None):
    """What the hand feels (:class:`racket.feel.HandFeel`): the handle's velocity and
    acceleration at the grip against time (the contact shaded), and the acceleration's
    spectrum.  ``ax``: two Axes, or None for a new figure; returns them.

    Parameters
    ----------
    feel : HandFeel
        What the hand feels (:class:`racket.feel.HandFeel`, SI).
    ax : sequence of 2 Axes, optional
        The Axes of the time and frequency panels; None: a new figure's.
    """
    if ax is None:
        import matplotlib.pyplot as plt

        _, ax = plt.subplots(2, 1, figsize=(6.4, 6.0))
    top, bottom = ax
    t_ms = 1e3 * feel.t
    top.axvspan(0.0, 1e3 * feel.contact_time, color="0.9", label="ball on the strings")
    top.plot(t_ms, feel.velocity, color="C0", label="velocity [m/s]")
    top.set_xlabel("time since first contact [ms]")
    top.set_ylabel("handle velocity [m/s]", color="C0")
    twin = top.twinx()
    twin.plot(t_ms, feel.acceleration / 9.81, color="C3", lw=0.8, label="acceleration")
    twin.set_ylabel("handle acceleration [g]", color="C3")
    top.set_title(
        f"at the grip, {100 * feel.grip_from_butt:.1f} cm from the butt: peak "
        f"{feel.peak_velocity:.2f} m/s, {feel.peak_acceleration / 9.81:.0f} g"
    )
    top.legend(loc="upper right", fontsize="small")
    keep = feel.frequencies <= 2000.0
    bottom.plot(feel.frequencies[keep], feel.spectrum[keep] / 9.81, color="C3")
    bottom.set_xlabel("frequency [Hz]")
    bottom.set_ylabel("acceleration amplitude [g]")
    bottom.set_title(
        f"vibration reaching the hand {1e3 * feel.hand_vibration_energy:.1f} mJ "
        f"(all the hand absorbs {1e3 * feel.hand_energy:.0f} mJ)"
    )
    return ax


def plot_validation(table, ax=None):
    """The model against published measurements (:func:`studies.validation.
    validation_table`), one row per comparison, normalised: each measured band is mapped to
    [-1, 1] (its middle at 0), the published value (black bar) and the model (filled:
    validation, open: calibration; green inside the band, red outside) on the same scale.
    Values beyond +-4 half-bands are drawn at the edge, as a triangle.

    Parameters
    ----------
    table : DataFrame
        The table of :func:`studies.validation.validation_table` (indexed by name).
    ax : Axes, optional
        Where to draw; None: a new figure's.
    """
    if ax is None:
        import matplotlib.pyplot as plt

        _, ax = plt.subplots(figsize=(7.0, 1.6 + 0.22 * len(table)))
    limit = 4.0
    mid = 0.5 * (table["low"] + table["high"]).to_numpy(float)
    half = 0.5 * (table["high"] - table["low"]).to_numpy(float)
    half = np.where(half > 0, half, 1.0)
    y = np.arange(len(table))[::-1]
    measured = (table["measured"].to_numpy(float) - mid) / half
    model = (table["model"].to_numpy(float) - mid) / half
    ax.axvspan(-1.0, 1.0, color="0.9", label="measured band")
    ax.plot(measured, y, "|", color="k", ms=10, label="published value")
    agrees = table["agrees"].to_numpy(bool)
    calibration = (table["kind"] == "calibration").to_numpy(bool)
    for ok, colour in ((True, "tab:green"), (False, "tab:red")):
        for cal, fill in ((False, colour), (True, "none")):
            pick = (agrees == ok) & (calibration == cal)
            if not pick.any():
                continue
            x = np.clip(model[pick], -limit, limit)
            edge = np.abs(model[pick]) >= limit
            label = f"model, {'calibration' if cal else 'validation'}, " + (
                "agrees" if ok else "outside"
            )
            ax.plot(x[~edge], y[pick][~edge], "o", mfc=fill, mec=colour, label=label)
            for marker, side in ((">", x >= limit), ("<", x <= -limit)):
                ax.plot(x[side], y[pick][side], marker, mfc=fill, mec=colour)
    ax.set_yticks(y)
    ax.set_yticklabels(table.index, fontsize="x-small")
    ax.set_xlim(-limit - 0.3, limit + 0.3)
    ax.set_ylim(-0.7, len(table) - 0.3)
    ax.set_xlabel("(value - middle of the measured band) / half its width")
    ax.legend(fontsize="x-small", loc="lower right")
    return ax
