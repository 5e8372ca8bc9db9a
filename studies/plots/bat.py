"""Bats (issue 37): the exit speed along the barrel with its peak and sweet zone, BBCOR along
the barrel against the limit, and the handle's motion after an impact.  Positions along a bat
are in cm from the knob, as Nathan and bat makers give them.
"""

from __future__ import annotations

from studies.plots.axes import _axes
from studies.plots.layout import finish, legend_outside
from studies.plots.units import speed_scale

FROM_KNOB = "impact point from the knob [cm]"
"""The label of a position axis along a bat."""


def _many(results) -> list:
    """One result or several, as a list."""
    return list(results) if isinstance(results, list | tuple) else [results]


def plot_exit_speed(sweeps, ax=None, unit: str | None = None, conditions: str | None = None):
    """The exit (batted-ball) speed along the bat of one sweep or several
    (:class:`studies.bat.sweep.BatSweep`), each with its peak marked and its sweet zone shaded.

    Parameters
    ----------
    sweeps : BatSweep or sequence of BatSweep
        What :func:`studies.bat.sweep.bat_sweep` returned.
    ax : Axes, optional
        The Axes to draw on; None: a new figure's.
    unit : str, optional
        "m/s", "mph" or "km/h"; default the first sweep's.
    conditions : str, optional
        What the sweeps are of, drawn as the figure's heading; None: none drawn.
    """
    sweeps = _many(sweeps)
    unit = unit or sweeps[0].unit
    scale = speed_scale(unit)

    def draw(ax, sweep, colour: str) -> None:
        table = sweep.table
        name = str(table["bat"].iloc[0])
        ax.plot(table["position_from_knob_cm"], table["exit_speed_m_s"] / scale, color=colour,
                label=name)  # fmt: skip
        low, high = sweep.sweet_zone
        ax.axvspan(100 * low, 100 * high, color=colour, alpha=0.12,
                   label=f"{name}: sweet zone {100 * low:.1f}-{100 * high:.1f} cm")  # fmt: skip
        ax.plot(100 * sweep.peak_from_knob, sweep.peak_exit_speed / scale, "o", color=colour,
                label=f"{name}: peak {sweep.peak_exit_speed / scale:.4g} {unit} at "
                f"{100 * sweep.peak_from_knob:.1f} cm")  # fmt: skip

    return _along_barrel(sweeps, ax, f"exit speed [{unit}]", conditions, draw)


def plot_bbcor(tests, ax=None, conditions: str | None = None):
    """BBCOR along the barrel of one bat or several (:class:`studies.bat.certification.BbcorTest`),
    the location of its maximum marked, against the limit.

    Parameters
    ----------
    tests : BbcorTest or sequence of BbcorTest
        What :func:`studies.bat.certification.bbcor_test` returned.
    ax : Axes, optional
        The Axes to draw on; None: a new figure's.
    conditions : str, optional
        What the tests are of, drawn as the figure's heading; None: none drawn.
    """
    from bat.certification import BBCOR_LIMIT

    def draw(ax, test, colour: str) -> None:
        along = test.along
        name = str(along["bat"].iloc[0])
        ax.plot(along["position_from_knob_cm"], along["bbcor"], color=colour, label=name)
        ax.plot(100 * test.from_knob, test.bbcor, "o", color=colour,
                label=f"{name}: BBCOR {test.bbcor:.4f} at "
                f"{100 * test.from_knob:.1f} cm")  # fmt: skip

    def limit(ax) -> None:
        ax.axhline(BBCOR_LIMIT, color="0.3", ls="--", label=f"limit {BBCOR_LIMIT:.3f}")

    return _along_barrel(tests, ax, "BBCOR [-]", conditions, draw, limit)


def _along_barrel(results, ax, ylabel: str, conditions, draw, then=None):
    """One bat's result or several (``results``) along the barrel: each drawn by ``draw(ax,
    result, colour)`` in a colour of its own, then ``then(ax)`` if given, on ``ax`` (None: a
    new figure's); the axes labelled (``ylabel``), the legend outside, ``conditions`` as the
    heading.
    """
    made = ax is None
    ax = _axes(ax, 1)
    for k, result in enumerate(_many(results)):
        draw(ax, result, f"C{k}")
    if then is not None:
        then(ax)
    ax.set_xlabel(FROM_KNOB)
    ax.set_ylabel(ylabel)
    legend_outside(ax)
    return finish(ax, conditions, made)


def plot_handle(feel, ax=None, conditions: str | None = None):
    """The handle's motion after an impact (:class:`studies.bat.feel.BatFeel`), at each point
    read: its displacement (the vibration's part dashed) and its velocity, against time (the
    contact shaded).  ``ax``: two Axes, or None for a new figure; returns them.

    Parameters
    ----------
    feel : BatFeel
        What :func:`studies.bat.feel.bat_feel` returned.
    ax : sequence of 2 Axes, optional
        The displacement's and the velocity's Axes; None: a new figure's.
    conditions : str, optional
        What the impact was, drawn as the figure's heading; None: none drawn.
    """
    made = ax is None
    ax = _axes(ax, 2, figsize=(6.4, 6.4))
    top, bottom = ax
    t_ms = 1e3 * feel.t
    for panel in ax:
        panel.axvspan(0.0, 1e3 * feel.contact_time, color="0.9")
    vibration = feel.vibration_displacement
    for k, z in enumerate(feel.points_from_knob):
        colour, where = f"C{k}", f"{100 * z:g} cm from the knob"
        top.plot(t_ms, 1e3 * feel.displacement[k], color=colour, label=where)
        top.plot(t_ms, 1e3 * vibration[k], color=colour, ls="--", lw=0.8,
                 label=f"{where}: vibration")  # fmt: skip
        bottom.plot(t_ms, feel.velocity[k], color=colour, label=where)
    top.set_ylabel("handle displacement [mm]")
    top.set_title(f"ball at {100 * feel.from_knob:.1f} cm from the knob; the contact shaded")
    bottom.set_ylabel("handle velocity [m/s]")
    bottom.set_xlabel("time since first contact [ms]")
    legend_outside(top)
    legend_outside(bottom)
    return finish(ax, conditions, made)
