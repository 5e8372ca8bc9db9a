"""Plots along the racket: e and e_A against the impact point (with the racket drawn
beside them), several rackets compared, one impact's histories, and the mode shapes.
"""

from __future__ import annotations

import numpy as np
from matplotlib.patches import Ellipse, Rectangle

from racket import Racket
from studies.landmarks import hand_pivot, percussion_centre, rigid_centre_of_percussion
from studies.plots.axes import _axes
from studies.sweeps import PARAMETERS

_SAID = {  # a sweep parameter's column -> (words, the column in the unit typed, its unit)
    "speed_m_s": ("ball at", ("speed_mph", "mph"), "m/s"),
    "string_stiffness_N_m": ("strings", None, "N/m"),
    "tension_N": ("strung at", ("tension_lb", "lb"), "N"),
    "f1_Hz": ("f1", None, "Hz"),
}


def _said(key: str, g) -> str:
    """One grid point's value of the parameter column ``key`` in words, with its unit (in
    mph or lb when the table has those columns, as the command line adds when they were
    typed).
    """
    value = g[key].iloc[0]
    if key not in _SAID:
        return str(value)
    words, typed, unit = _SAID[key]
    if typed is not None and typed[0] in g:
        value, unit = g[typed[0]].iloc[0], typed[1]
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


def _legend_outside(ax) -> None:
    """The legend to the right of the Axes, off the data."""
    ax.legend(loc="upper left", bbox_to_anchor=(1.02, 1.0), fontsize="small", borderaxespad=0)


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
    lows, tops, marked, caught = [0.0], [1.0], False, False
    for k, (label, x, e, e_a, flagged, again) in enumerate(curves):
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
        if np.any(again):
            label = "_" if caught else RECONTACT
            ax.plot(cm[again], e[again], "o", mfc="none", color="k", ms=8, label=label)
            caught = True
        lows.append(np.nanmin(e_a))
        tops.append(np.nanmax(e))
    if single:
        _, x, e, e_a, _, _ = curves[0]
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
    cop = rigid_centre_of_percussion(racket, pivot) if cop is None else cop
    ax.axvline(100 * cop, color="C3", ls=":", label=f"centre of percussion{how} {100 * cop:.1f} cm")
    low, top = min(lows), max(tops)
    band = 0.35 * (top - low)
    draw_racket(racket, ax, low - 1.15 * band, band)
    ax.set_xlim(-2, 100 * racket.beam.length + 2)
    ax.set_ylim(low - 1.25 * band, top + 0.05)
    ax.set_xlabel("impact point [cm from the tip]")
    ax.set_ylabel("coefficient of restitution [-]")
    _legend_outside(ax)
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
        _, x, e, e_a, _, again = curves[0]
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
        if np.any(again):
            label = RECONTACT if not any(RECONTACT == t.get_label() for t in ax.lines) else "_"
            ax.plot(100 * x[again], e[again], "o", mfc="none", color="k", ms=8, label=label)
    ax.set_xlabel("impact point [cm from the tip]")
    ax.set_ylabel("coefficient of restitution [-]")
    ax.set_title("e (solid) and e_A (dashed) along the strings" if show_apparent else "e")
    _legend_outside(ax)
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
        a.legend(loc="upper left", bbox_to_anchor=(1.02, 1.0), fontsize="small")
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
    ax.set_ylabel("mode shape (normalised) [-]")
    _legend_outside(ax)
    return ax
