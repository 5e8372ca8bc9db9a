"""The serve's what-ifs plotted: the zero-COR ball's reduction over string and ball
stiffness (Sec. VIII).
"""

from __future__ import annotations

from studies.plots.axes import _axes
from studies.plots.layout import finish, legend_outside


def plot_serve_what_if(table, ax=None, conditions: str | None = None):
    """Serve-speed reduction of a zero-COR ball against string and ball stiffness (the
    table of :func:`studies.serve.serve_what_if`).

    Parameters
    ----------
    table : DataFrame
        The table of :func:`studies.serve.serve_what_if` (stiffness values [N/m]).
    ax : Axes, optional
        The Axes to draw on; None: a new figure's.
    conditions : str, optional
        The run's conditions, drawn as the figure's heading; None: none drawn.
    """
    made = ax is None
    ax = _axes(ax, 1)
    for (varied, group), marker in zip(table.groupby("varied", sort=False), "os", strict=False):
        label = "string-bed stiffness" if varied == "strings" else "ball stiffness"
        ax.plot(group["value"], group["reduction_simulated_percent"], marker + "-", label=label)
    ax.set_xscale("log")
    ax.set_xlabel("stiffness [N/m]")
    ax.set_ylabel("serve-speed reduction, zero-COR ball [%]")
    legend_outside(ax)
    return finish(ax, conditions, made)
