"""The model against published measurements: each band and the model's value."""

from __future__ import annotations

import numpy as np

from studies.plots.axes import _axes
from studies.plots.layout import finish, legend_outside


def plot_validation(table, ax=None, conditions: str | None = None):
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
    conditions : str, optional
        The run's conditions, drawn as the figure's heading; None: none drawn.
    """
    made = ax is None
    ax = _axes(ax, 1, figsize=(7.0, 1.6 + 0.22 * len(table)))
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
    ax.set_xlabel("(value - middle of the measured band) / half its width [-]")
    legend_outside(ax, fontsize="x-small")
    return finish(ax, conditions, made)
