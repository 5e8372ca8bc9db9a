"""The page's plots (matplotlib): one quantity per Axes, several rackets on it, labels with
units, the legend outside the data (above the Axes, or below the figure).

Each function takes results computed elsewhere (:mod:`studies.page.dashboard`), an optional
``ax`` and the conditions the results are for (:mod:`studies.page.conditions`, drawn as the
figure's heading), draws, and returns the Axes; none calls ``show()``.  Speeds are in mph,
as the page speaks, with m/s on a secondary axis; positions in cm from the tip.
:func:`page_plots` says what each of the page's plots (:data:`PLOTS`) draws for the page's
results: the page draws exactly that.
"""

from __future__ import annotations

import textwrap

import numpy as np

from common.units import MPH

_HEADING_CHARS = 70  # a line of the heading: about 4 in at the small font, in any card


def _axes(ax, figsize=(6.4, 4.0)):
    """The Axes given, or a new figure's (with no layout engine: Shiny lays it out tight,
    and a tight layout keeps the legends placed outside the Axes in the figure).
    """
    if ax is None:
        import matplotlib.pyplot as plt

        _, ax = plt.subplots(figsize=figsize)
    return ax


def _heading(ax, conditions: str | None) -> None:
    """``conditions`` as the figure's heading, in lines of at most :data:`_HEADING_CHARS`
    (the layout makes room for the lines it is given) and wrapped again when drawn, should
    the figure be narrower: the page sizes the figure to its card after the plot is made
    (Shiny), and its tight layout keeps the heading clear of the Axes and the legend above.
    """
    if conditions:
        said = textwrap.fill(conditions, _HEADING_CHARS, break_long_words=False)
        ax.figure.suptitle(said, wrap=True, fontsize="small")


def _legend_above(ax, **style) -> None:
    """The Axes' legend above it, clear of the data (in one row unless ``style`` says)."""
    style = {"loc": "lower left", "ncols": 2, "frameon": False, **style}
    ax.legend(bbox_to_anchor=(0.0, 1.02, 1.0, 0.1), fontsize="small", borderaxespad=0.0,
              **style)  # fmt: skip


def _mph_and_m_s(ax) -> None:
    """A secondary y axis in m/s beside the primary one in mph."""
    ax.secondary_yaxis("right", functions=(lambda v: v * MPH, lambda v: v / MPH)).set_ylabel(
        "[m/s]"
    )


def plot_serve_speeds(
    serves, head_speed_mph: float | None = None, ax=None, conditions: str | None = None
):
    """Serve speed off the string centre against the racket-head speed, one line per
    racket, and a dot at the page's head speed.

    Parameters
    ----------
    serves : mapping label -> DataFrame
        Per racket, :func:`studies.serve.serve` rows with ``head_speed_mph`` and
        ``serve_simulated_mph`` (:attr:`studies.page.dashboard.RacketResults.serves`).
    head_speed_mph : float, optional
        The head speed to mark [mph].
    ax : Axes, optional
    conditions : str, optional
        What the serves are for (racket, ball, swing), drawn as the heading; None: none.
    """
    ax = _axes(ax)
    for k, (label, table) in enumerate(serves.items()):
        head, speed = table["head_speed_mph"], table["serve_simulated_mph"]
        ax.plot(head, speed, color=f"C{k}", lw=2, label=label)
    if head_speed_mph is not None:
        for k, table in enumerate(serves.values()):
            at = np.interp(head_speed_mph, table["head_speed_mph"], table["serve_simulated_mph"])
            ax.plot(head_speed_mph, at, "o", color=f"C{k}", ms=7, label="_at")
        ax.axvline(head_speed_mph, color="0.6", ls=":", lw=1, label="_head")
    ax.set_xlabel("racket-head speed [mph]")
    ax.set_ylabel("serve speed [mph]")
    ax.grid(alpha=0.3)
    _mph_and_m_s(ax)
    _legend_above(ax)
    _heading(ax, conditions)
    return ax


def plot_along_racket(
    tables, column: str, ylabel: str, ax=None, mph: bool = False, conditions: str | None = None
):
    """One quantity along the racket, one line per racket, each racket's string centre
    marked.

    Parameters
    ----------
    tables : mapping label -> DataFrame
        Per racket, an impact table along it with ``position_from_tip_m`` and ``column``
        (:attr:`studies.page.dashboard.RacketResults.along`).
    column : str
        The quantity drawn.
    ylabel : str
        Its label, with its unit (or saying it is dimensionless).
    ax : Axes, optional
    mph : bool
        The quantity is a speed in mph: add the m/s axis.
    conditions : str, optional
        What the tables are for (rackets, ball, speed, swing), drawn as the heading.
    """
    ax = _axes(ax)
    for k, (label, table) in enumerate(tables.items()):
        table = table.sort_values("position_from_tip_m")
        ax.plot(100 * table["position_from_tip_m"], table[column], color=f"C{k}", lw=2,
                label=label)  # fmt: skip
    ax.set_xlabel("impact point [cm from the tip]")
    ax.set_ylabel(ylabel)
    ax.grid(alpha=0.3)
    if mph:
        _mph_and_m_s(ax)
    _legend_above(ax)
    _heading(ax, conditions)
    return ax


def plot_face_map_page(face_map, title: str, ax=None, conditions: str | None = None, levels=None):
    """:func:`studies.plots.plot_face_map` (e_A over the face, speeds in mph), its legend
    titled ``title`` above the Axes (in place of the Axes' title), clear of the axis labels,
    the face and the colour bar, and a shorter x label, clear of the colour bar.

    Parameters
    ----------
    face_map : FaceMap
    title : str
    ax : Axes, optional
    conditions : str, optional
        What the map is for (racket, ball, speed), drawn as the heading.
    levels : array_like, optional
        The edges of the filled contours of e_A [-], shared with the other racket's map so
        that both have one colour scale (:func:`studies.plots.face.shared_levels` of the two
        maps); None: this map's own.
    """
    from studies.plots import plot_face_map

    own = {} if levels is None else {"levels": levels}
    ax = plot_face_map(face_map, ax=_axes(ax, figsize=(4.6, 7.0)), unit="mph", **own)
    ax.set_title("")
    ax.set_xlabel("off the axis [cm] (+: 3 o'clock)")  # short: clear of the colour bar
    _legend_above(ax, loc="lower left", ncols=1, frameon=True, title=title)
    ax.get_legend().set(alignment="left")
    _heading(ax, conditions)
    return ax


def page_plots(r, swing_mph: float) -> dict:
    """What each of the page's plots draws for the page's results ``r``: per output id (a
    key of :data:`PLOTS`), the keyword arguments of its function, only what it draws; a plot
    with nothing to draw (no racket built, or not its racket) is left out.  The face maps of
    A and B share their contours' edges (:func:`studies.plots.face.shared_levels` of both):
    one colour scale, so that a colour is the same e_A on each.

    Parameters
    ----------
    r : PageResults
        The page's results (:func:`studies.page.dashboard.page_results`).
    swing_mph : float
        The page's racket-head speed [mph], marked on the serve plot.
    """
    from studies.plots.face import shared_levels

    sides = {side: one for side, one in (("A", r.a), ("B", r.b)) if one is not None}
    if not sides:
        return {}
    labels = {f"{side}: {one.name}": one for side, one in sides.items()}
    said = r.conditions

    def along(column: str, ylabel: str, key: str, mph: bool = False) -> dict:
        tables = {k: v.along[["position_from_tip_m", column]] for k, v in labels.items()}
        return {"tables": tables, "column": column, "ylabel": ylabel, "mph": mph,
                "conditions": said[key]}  # fmt: skip

    columns = ["head_speed_mph", "serve_simulated_mph"]
    drawn = {
        "serve_plot": {
            "serves": {k: v.serves[columns] for k, v in labels.items()},
            "head_speed_mph": swing_mph,
            "conditions": said["serve"],
        },
        "exit_plot": along("exit_speed_swung_mph", "ball speed [mph]", "exit", mph=True),
        "power_plot": along("e_A", "rebound ratio e_A [-]", "e_A"),
    }
    levels = shared_levels([one.face for one in sides.values()])
    for side, one in sides.items():
        key = f"face_{side.lower()}"
        drawn[key] = {"face_map": one.face, "title": f"{side}: {one.name}",
                      "conditions": said[key], "levels": levels}  # fmt: skip
    return drawn


PLOTS = {
    "serve_plot": plot_serve_speeds,
    "exit_plot": plot_along_racket,
    "power_plot": plot_along_racket,
    "face_a": plot_face_map_page,
    "face_b": plot_face_map_page,
}
"""The page's plots: output id -> the function that draws it (with :func:`page_plots`'
arguments)."""
