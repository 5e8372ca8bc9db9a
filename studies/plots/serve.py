"""The serve's what-ifs plotted: the zero-COR ball's reduction over string and ball
stiffness (Sec. VIII).
"""

from __future__ import annotations

import numpy as np

from studies.plots.axes import _axes
from studies.plots.layout import finish, legend_outside


def plot_serve_what_if(table, ax=None, conditions: str | None = None):
    """Serve-speed reduction of a zero-COR ball against string and ball stiffness (the
    table of :func:`studies.serve.serve_what_if`, or its columns).

    Parameters
    ----------
    table : DataFrame or dict
        The table of :func:`studies.serve.serve_what_if` (stiffness values [N/m]), or its
        columns (:func:`studies.serve.serve_what_if_columns`).
    ax : Axes, optional
        The Axes to draw on; None: a new figure's.
    conditions : str, optional
        The run's conditions, drawn as the figure's heading; None: none drawn.
    """
    made = ax is None
    ax = _axes(ax, 1)
    cases, value = np.asarray(table["varied"]), np.asarray(table["value"])
    reduction = np.asarray(table["reduction_simulated_percent"])
    for varied, marker in zip(dict.fromkeys(cases.tolist()), "os", strict=False):
        label = "string-bed stiffness" if varied == "strings" else "ball stiffness"
        case = cases == varied
        ax.plot(value[case], reduction[case], marker + "-", label=label)
    ax.set_xscale("log")
    ax.set_xlabel("stiffness [N/m]")
    ax.set_ylabel("serve-speed reduction, zero-COR ball [%]")
    legend_outside(ax)
    return finish(ax, conditions, made)
