"""Plots along the racket: e and e_A against the impact point (with the racket drawn to
scale above them), several rackets compared, one impact's histories, and the mode shapes.
Positions are measured from the tip, in cm.
"""

from __future__ import annotations

import numpy as np
from matplotlib.patches import Ellipse, Rectangle

from common.units import SPEED_SUFFIXES, SPEED_UNITS
from racket import Racket
from studies.face.landmarks import hand_pivot, percussion_centre, rigid_centre_of_percussion
from studies.plots.axes import _axes
from studies.plots.layout import FROM_TIP, finish, legend_outside
from studies.plots.units import speed_scale
from studies.sweeps import PARAMETERS

_TYPED_SPEEDS = tuple((f"speed_{SPEED_SUFFIXES[u]}", u) for u in SPEED_UNITS if u != "m/s")
_SAID = {  # a sweep parameter's column -> (words, the columns in units typed, its unit)
    "speed_m_s": ("ball at", _TYPED_SPEEDS, "m/s"),
    "string_stiffness_N_m": ("strings", (), "N/m"),
    "tension_N": ("strung at", (("tension_lb", "lb"),), "N"),
    "f1_Hz": ("f1", (), "Hz"),
}

_NODE = dict(color="k", ls="--")
_COP = dict(color="0.45", ls=":")
"""The landmarks' lines: black and grey, which no curve's colour (:func:`_colours`) is."""


def _colours(count: int) -> list:
    """``count`` colours for curves, distinct from each other and from the landmarks'
    black and grey: tableau's, without its grey, then viridis' for more than nine.
    """
    tableau = ["tab:blue", "tab:orange", "tab:green", "tab:red", "tab:purple", "tab:brown",
               "tab:pink", "tab:olive", "tab:cyan"]  # fmt: skip
    if count <= len(tableau):
        return tableau[:count]
    from matplotlib import colormaps

    return [colormaps["viridis"](v) for v in np.linspace(0.0, 0.9, count)]


def _said(key: str, g) -> str:
    """One grid point's value of the parameter column ``key`` in words, with its unit (in
    mph, km/h or lb when the table has those columns, as the command line adds when they
    were typed).
    """
    value = g[key].iloc[0]
    if key not in _SAID:
        return str(value)
    words, typed, unit = _SAID[key]
    for column, typed_unit in typed:
        if column in g:
            value, unit = g[column].iloc[0], typed_unit
            break
    return f"{words} {value:.4g} {unit}"


def _curves(result):
    """(label, position, e, e_A, not self-consistent, re-contact) per grid point of a
    sweep table (its parameter columns, :data:`studies.sweeps.PARAMETERS`, said in words
    with units), or the one of an Impact; each sorted along the racket.
    """
    if hasattr(result, "columns"):
        keys = [c for c in PARAMETERS.values() if c in result.columns]
        groups = result.groupby(keys, sort=False) if keys else [((), result)]
        for _, g in groups:
            label = ", ".join(_said(k, g) for k in keys)
            flagged = ~g["self_consistent"].to_numpy(bool) if "self_consistent" in g else None
            again = g["recontacts"].to_numpy() > 0 if "recontacts" in g else None
            yield _sorted(label, g["position_from_tip_m"], g["e"], g["e_A"], flagged, again)
        return
    yield _sorted(
        "",
        np.atleast_1d(result.position),
        np.atleast_1d(result.e),
        np.atleast_1d(result.e_A),
        ~np.atleast_1d(result.self_consistent),
        np.atleast_1d(result.recontacts) > 0,
    )


def _sorted(label, x, e, e_a, flagged, again=None):
    """One curve of :func:`_curves`, as float arrays sorted along the racket."""
    x, e, e_a = (np.asarray(v, dtype=float) for v in (x, e, e_a))
    flagged = np.zeros(x.size, bool) if flagged is None else np.asarray(flagged, bool)
    again = np.zeros(x.size, bool) if again is None else np.asarray(again, bool)
    order = np.argsort(x)
    return label, x[order], e[order], e_a[order], flagged[order], again[order]


RECONTACT = "re-contact: the ball caught again by the vibrating strings (e sums both)"
"""The legend of the impacts marked as re-contacts."""


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
    (:func:`studies.face.landmarks.percussion_centre`), or None if they are not of a racket at
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


def plot_cor_along_racket(
    result, racket: Racket, ax=None, pivot: float | None = None, conditions: str | None = None
):
    """E and e_A along the racket, with the racket drawn to scale in its own strip above the
    curves (sharing their x axis, in cm from the tip).

    Marks the mode-1 node, the centre of percussion for a pivot at the hand (default
    :func:`studies.face.landmarks.hand_pivot`; from the impacts, :func:`studies.face.landmarks.
    percussion_centre`, for one curve of a racket at rest, else the rigid-body formula),
    the points of largest e and largest e_A, and
    (with a cross) the unhappy-ball impacts that have no self-consistent Xo.  A sweep table
    over a grid draws one pair of curves per grid point, labelled with its parameters (a
    speed in the unit typed when the table has its ``speed_mph`` or ``speed_kmh`` column).

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
        (:func:`studies.face.landmarks.hand_pivot`).
    conditions : str, optional
        The run's conditions, drawn as the figure's heading; None: none drawn.
    """
    made = ax is None
    ax = _axes(ax, 1)
    curves = list(_curves(result))
    single = len(curves) == 1
    colours = ["tab:blue"] if single else _colours(len(curves))
    marked, caught = False, False
    for colour, (label, x, e, e_a, flagged, again) in zip(colours, curves, strict=True):
        cm = 100 * x
        if single:
            e_style = dict(color="tab:blue", label="e (Eq. 21, rigid-body motion)")
            a_style = dict(color="tab:orange", lw=2, label="e_A = V1/v1 (apparent)")
        else:
            e_style = dict(color=colour, label=f"e ({label})")
            a_style = dict(color=colour, lw=1.5, ls="--", label=f"e_A ({label})")
        ax.plot(cm, e, lw=2, **e_style)
        ax.plot(cm, e_a, **a_style)
        if np.any(flagged):
            label = "_" if marked else "no self-consistent Xo"
            ax.plot(cm[flagged], e[flagged], "x", color="k", ms=7, label=label)
            marked = True
        if np.any(again):
            label = "_" if caught else RECONTACT
            ax.plot(cm[again], e[again], "o", mfc="none", color="k", ms=8, label=label)
            caught = True
    if single:
        _, x, e, e_a, _, _ = curves[0]
        cm = 100 * x
        i, j = int(np.argmax(e)), int(np.argmax(e_a))
        for k, y, mark, name in ((i, e, "o", "e"), (j, e_a, "s", "e_A")):
            color = "tab:blue" if name == "e" else "tab:orange"
            label = f"largest {name} {y[k]:.3f} at {cm[k]:.1f} cm from the tip"
            ax.plot(cm[k], y[k], mark, color=color, ms=8, label=label)
    node = racket.beam.modes.nodes(1)[0]
    ax.axvline(100 * node, **_NODE, label=f"mode-1 node {100 * node:.1f} cm from the tip")
    pivot = hand_pivot(racket) if pivot is None else pivot
    cop = _simulated_cop(result, racket, pivot) if single else None
    how = "" if cop is not None else " (rigid body)"
    cop = rigid_centre_of_percussion(racket, pivot) if cop is None else cop
    ax.axvline(
        100 * cop, **_COP, label=f"centre of percussion{how} {100 * cop:.1f} cm from the tip"
    )
    ax.set_xlim(-2, 100 * racket.beam.length + 2)
    ax.set_xlabel(f"impact point, {FROM_TIP}")
    ax.set_ylabel("coefficient of restitution [-]")
    strip = ax.inset_axes([0.0, 1.03, 1.0, 0.22], sharex=ax)
    draw_racket(racket, strip, 0.0, 1.0)
    strip.set_ylim(-0.05, 1.05)
    strip.set_axis_off()
    legend_outside(ax)
    return finish(ax, conditions, made)


def plot_cor_comparison(
    results, ax=None, show_apparent: bool = True, conditions: str | None = None
):
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
    conditions : str, optional
        The run's conditions, drawn as the figure's heading; None: none drawn.
    """
    made = ax is None
    ax = _axes(ax, 1)
    for colour, (label, result) in zip(_colours(len(results)), results.items(), strict=True):
        curves = list(_curves(result))
        if len(curves) != 1:
            raise ValueError(
                f"results[{label!r}] must hold one curve, got a table over a grid "
                f"({', '.join(c[0] for c in curves[:3])}, ...)"
            )
        _, x, e, e_a, _, again = curves[0]
        best = int(np.argmax(e))
        ax.plot(
            100 * x,
            e,
            color=colour,
            lw=2,
            label=f"{label}: e, largest {e[best]:.3f} at {100 * x[best]:.1f} cm from the tip",
        )
        if show_apparent:
            ax.plot(100 * x, e_a, color=colour, ls="--", lw=1.2, label="_e_A")
        if np.any(again):
            label = RECONTACT if not any(RECONTACT == t.get_label() for t in ax.lines) else "_"
            ax.plot(100 * x[again], e[again], "o", mfc="none", color="k", ms=8, label=label)
    ax.set_xlabel(f"impact point, {FROM_TIP}")
    ax.set_ylabel("coefficient of restitution [-]")
    ax.set_title("e (solid) and e_A (dashed) along the strings" if show_apparent else "e")
    legend_outside(ax)
    return finish(ax, conditions, made)


def plot_impact(result, ax=None, unit: str = "m/s", conditions: str | None = None):
    """Force, compressions and velocities of one impact against time (three panels); the
    impact point's velocity is split into its dc (rigid-body) and ac (vibration) parts.

    Parameters
    ----------
    result : Impact
        An :func:`racket.impact` at one position with ``histories=True`` (SI).
    ax : sequence of 3 Axes, optional
        The Axes of the three panels; None: a new figure's.
    unit : str
        The velocities' unit, one of :data:`common.units.SPEED_UNITS` (the one the user
        typed).
    conditions : str, optional
        The run's conditions, drawn as the figure's heading; None: none drawn.
    """
    if result.t is None:
        raise ValueError("plot_impact needs the histories: impact(..., histories=True)")
    size = speed_scale(unit)
    made = ax is None
    axes = _axes(ax, 3)
    t = 1e3 * result.t
    axes[0].plot(t, result.force, color="C0", label="contact force")
    axes[0].set_ylabel("force [N]")
    axes[1].plot(t, 1e3 * result.ball_compression, color="C1", label="ball compression")
    axes[1].plot(t, 1e3 * result.string_deflection, color="C2", label="string deflection")
    axes[1].set_ylabel("compression [mm]")
    velocities = (
        (result.ball_velocity, dict(color="C1", label="ball")),
        (result.point_velocity, dict(color="k", label="impact point, total")),
        (result.point_velocity_dc_history, dict(color="C0", ls="--",
                                                label="impact point, dc (rigid body)")),
        (result.point_velocity_ac_history, dict(color="C3", ls=":",
                                                label="impact point, ac (vibration)")),
    )  # fmt: skip
    for values, style in velocities:
        axes[2].plot(t, np.asarray(values) / size, **style)
    axes[2].set_ylabel(f"velocity [{unit}]")
    axes[2].set_xlabel("time [ms]")
    for a in axes:
        legend_outside(a)
    axes[0].set_title(
        f"impact at {100 * float(result.position):.1f} cm from the tip, "
        f"e = {float(result.e):.3f}, e_A = {float(result.e_A):.3f}"
    )
    return finish(axes, conditions, made)


def plot_modes(racket: Racket, ax=None, count: int = 4, conditions: str | None = None):
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
    conditions : str, optional
        The run's conditions, drawn as the figure's heading; None: none drawn.
    """
    made = ax is None
    ax = _axes(ax, 1)
    modes = racket.beam.modes
    count = min(count, modes.count - 2)
    x = np.linspace(0.0, racket.beam.length, 400)
    shapes = modes.shape(x)[2 : 2 + count]
    for k, (shape, colour) in enumerate(zip(shapes, _colours(count), strict=True), start=1):
        scale = np.abs(shape).max()
        ax.plot(
            100 * x,
            shape / scale,
            color=colour,
            label=f"mode {k}: {modes.frequencies[k - 1]:.0f} Hz",
        )
        nodes = modes.nodes(k)
        ax.plot(100 * nodes, np.zeros_like(nodes), "o", color=colour, ms=5)
    ax.axhline(0, color="0.6", lw=0.8)
    start, end = (100 * v for v in racket.strings.extent)
    ax.axvspan(start, end, color="0.9", label="strings")
    ax.set_xlabel(f"position along the racket, {FROM_TIP}")
    ax.set_ylabel("mode shape (normalised) [-]")
    legend_outside(ax)
    return finish(ax, conditions, made)
