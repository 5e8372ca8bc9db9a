"""Plots of a ball: colliding with another ball or a wall, dropped, its COR against the
stiffness ratio, and its bounce on a rigid surface against the impact speed.
"""

from __future__ import annotations

import numpy as np

from ball import Ball, LinearSpring, SineLaw, collide, unhappy_cor
from studies.plots.axes import _axes
from studies.plots.layout import finish, legend_outside
from studies.plots.units import speed_scale


def plot_collision(
    collision,
    ax=None,
    title: str | None = None,
    names=("ball a", "ball b"),
    unit: str = "m/s",
    conditions: str | None = None,
):
    """A two-ball collision against time, as in the paper's Figs. 2-4: force; compressions
    X, Y and X_T = X + Y; velocities of both bodies.

    Parameters
    ----------
    collision : Collision
        A :func:`ball.collide` result (SI).
    ax : sequence of 3 Axes, optional
        The Axes of the three panels; None: a new figure's.
    title : str, optional
        Title of the top panel; None: the COR.
    names : (str, str)
        What the two bodies are, e.g. ("unhappy", "happy") or ("tennis", "wall").
    unit : str
        The velocities' unit, one of :data:`common.units.SPEED_UNITS` (the one the user
        typed).
    conditions : str, optional
        The run's conditions, drawn as the figure's heading; None: none drawn.
    """
    size = speed_scale(unit)
    made = ax is None
    axes = _axes(ax, 3)
    h = collision.history
    t = 1e3 * h.t
    a, b = names
    axes[0].plot(t, h.force, color="C0", label="contact force F")
    axes[0].set_ylabel("force [N]")
    axes[1].plot(t, 1e3 * h.compression_a, color="C1", label=f"X ({a})")
    axes[1].plot(t, 1e3 * h.compression_b, color="C2", label=f"Y ({b})")
    axes[1].plot(t, 1e3 * h.total_compression, color="k", ls="--", label="X_T = X + Y")
    axes[1].set_ylabel("compression [mm]")
    axes[2].plot(t, h.velocity_a / size, color="C1", label=a)
    axes[2].plot(t, h.velocity_b / size, color="C2", label=b)
    axes[2].set_ylabel(f"velocity [{unit}]")
    axes[2].set_xlabel("time [ms]")
    for panel in axes:
        legend_outside(panel)
    axes[0].set_title(title or f"e = {collision.e:.3f}")
    return finish(axes, conditions, made)


def plot_drop(result, ax=None, conditions: str | None = None):
    """A dropped ball's contact (:func:`studies.drop.drop`): the force [N] and the ball's
    compression [mm] against time [ms].

    Parameters
    ----------
    result : Drop
        The drop.
    ax : sequence of 2 Axes, optional
        The Axes of the two panels; None: a new figure's.
    conditions : str, optional
        The run's conditions, drawn as the figure's heading; None: none drawn.
    """
    made = ax is None
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
    return finish(axes, conditions, made)


def plot_cor_vs_stiffness(
    ax=None,
    k0: float = 2e4,
    ratios=None,
    mass: float = 0.0103,
    speed: float = 4.0,
    conditions: str | None = None,
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
    conditions : str, optional
        The run's conditions, drawn as the figure's heading; None: none drawn.
    """
    made = ax is None
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
    ax.set_xlabel("k2 / k0 [-]")
    ax.set_ylabel("e [-]")
    legend_outside(ax)
    return finish(ax, conditions, made)


def plot_rigid_bounce(
    table,
    ax=None,
    radius: float | None = None,
    bands=None,
    unit: str = "m/s",
    conditions: str | None = None,
):
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
        The ITF bands of the ball's type (:mod:`ball.catalog`), for a tennis ball; None
        (any other ball): no tennis measurement is drawn.
    unit : str
        The impact speed's unit, one of :data:`common.units.SPEED_UNITS` (the one the user
        typed).
    conditions : str, optional
        The run's conditions, drawn as the figure's heading; None: none drawn.
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

    size = speed_scale(unit)
    made = ax is None
    ax = _axes(ax, 4)
    v = table["speed_m_s"] / size

    def sourced(axis, value, band, scale, label):
        low, high, mid = scale * band[0], scale * band[1], scale * value
        axis.errorbar([ITF_DROP_SPEED / size], [mid], yerr=[[mid - low], [high - mid]], fmt="s",
                      color="k", capsize=4, label=label)  # fmt: skip

    tennis = bands is not None
    ax[0].plot(v, table["e"], "o-", label="simulated")
    if tennis:
        cor = bands.cor
        sourced(ax[0], 0.5 * (cor[0] + cor[1]), cor, 1.0, "ITF rebound band (254 cm drop)")
        if bands == TYPE_2_BANDS:
            ax[0].errorbar(
                [CALIBRATION_SPEED / size],
                [COR_AT_30],
                fmt="D",
                color="tab:red",
                yerr=[[COR_AT_30 - COR_AT_30_RANGE[0]], [COR_AT_30_RANGE[1] - COR_AT_30]],
                capsize=4,
                label=f"type 2 at {CALIBRATION_SPEED / size:.3g} {unit}: assumed, with its range",
            )
    ax[0].set_ylabel("COR on a rigid surface [-]")
    ax[1].plot(v, 1e3 * table["contact_time_s"], "o-", label="simulated")
    if tennis:
        sourced(ax[1], *DROP_CONTACT_TIME, 1e3, "about 4 ms (Cross 2000), accepted band")
    ax[1].ticklabel_format(axis="y", useOffset=False)  # a constant is not noise
    low, high = ax[1].get_ylim()
    if high - low < 0.05 * max(abs(high), 1e-9):  # a flat curve: a sensible range around it
        middle = 0.5 * (low + high)
        ax[1].set_ylim(0.8 * middle, 1.2 * middle)
    ax[1].set_ylabel("contact time [ms]")
    ax[2].plot(v, 1e-3 * table["peak_force_N"], "o-", label="simulated")
    ax[2].set_ylabel("peak force [kN]")
    ax[3].plot(v, 1e3 * table["peak_compression_m"], "o-", label="simulated")
    if tennis:
        sourced(ax[3], *DROP_COMPRESSION, 1e3, "about 6 mm (Cross), accepted band")
    if radius is not None:
        ax[3].axhline(1e3 * radius, ls="--", color="gray", label="ball radius")
    ax[3].set_ylabel("peak compression [mm]")
    ax[3].set_xlabel(f"impact speed [{unit}]")
    for panel in ax:
        legend_outside(panel)
    return finish(ax, conditions, made)
