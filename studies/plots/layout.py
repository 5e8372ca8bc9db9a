"""A figure that fits: legends outside the data with their lines wrapped, long titles wrapped
to the width they have, the run's conditions as the figure's heading, and a figure made here
widened so that its legends leave the Axes most of the width.
"""

from __future__ import annotations

import textwrap

import numpy as np

AXES_WIDTH = 5.0
"""Width [in] the Axes of a figure made here keep beside the legends outside them: the
figure is widened to make room (ASSUMPTION, a choice: about what Axes keep of matplotlib's
default 6.4 in wide figure when nothing stands beside them)."""

LEGEND_CHARACTERS = 40
"""Longest line [characters] of a legend entry beside the Axes; longer entries are wrapped
(ASSUMPTION, a choice: about 2.5 in at the legend's small font, so that a legend never takes
more than half a widened figure)."""

FROM_TIP = "from the tip [cm]"
"""The end of every position axis' label: positions along the racket are measured from the
tip (the top of the head) towards the butt, in cm on the plots."""


def legend_outside(ax, **options) -> None:
    """The legend of ``ax`` to the right of it, off the data, each entry's lines at most
    :data:`LEGEND_CHARACTERS` long (the lines' own labels unchanged).

    Parameters
    ----------
    ax : Axes
        The Axes whose labelled artists the legend names.
    **options
        Passed to :meth:`matplotlib.axes.Axes.legend` (e.g. ``fontsize``).
    """
    handles, labels = ax.get_legend_handles_labels()
    labels = [_fill(label, LEGEND_CHARACTERS) for label in labels]
    place = dict(loc="upper left", bbox_to_anchor=(1.02, 1.0), fontsize="small", borderaxespad=0)
    ax.legend(handles, labels, **(place | options))


def finish(axes, conditions: str | None = None, made: bool = False):
    """Lay out the figure holding ``axes`` so that everything in it fits and return
    ``axes``: a figure made here (``made``) widened until its Axes keep
    :data:`AXES_WIDTH` beside their legends, each Axes' title wrapped to the Axes' width, and
    ``conditions`` (if given) drawn as the figure's heading, wrapped to the figure's width.

    Parameters
    ----------
    axes : Axes or sequence of Axes
        What the plot drew on.
    conditions : str, optional
        What the plot is of (racket, ball, speeds, support, grip, strings:
        :func:`studies.conditions.conditions_line`); None: nothing drawn.
    made : bool
        The figure was made by the plot (it may be resized); False for Axes the caller
        gave.
    """
    fig = np.atleast_1d(axes)[0].figure
    fig.draw_without_rendering()
    for ax in fig.axes:
        room = ax.get_window_extent().width
        if made and ax.get_aspect() == "auto":  # these Axes will be widened to AXES_WIDTH
            room = max(room, AXES_WIDTH * fig.dpi)
        _wrap(ax.title, min(room, 0.96 * fig.bbox.width))
    if made:
        _widen(fig)
    if conditions:
        heading = fig.suptitle(conditions, fontsize="medium")
        _wrap(heading, 0.96 * fig.bbox.width)
    fig.draw_without_rendering()
    return axes


def _widen(fig) -> None:
    """Widen ``fig`` until its narrowest Axes (of the automatic aspect, not a colour bar's)
    is :data:`AXES_WIDTH` wide after the layout; at most three passes (legends do not grow
    with the figure, so one usually does).
    """
    for _ in range(3):
        fig.draw_without_rendering()
        widths = [
            ax.get_position().width * fig.get_figwidth()
            for ax in fig.axes
            if ax.get_aspect() == "auto" and not hasattr(ax, "_colorbar") and ax.get_visible()
        ]
        short = AXES_WIDTH - min(widths, default=AXES_WIDTH)
        if short < 0.05:
            return
        fig.set_figwidth(fig.get_figwidth() + short)


def _wrap(text, width: float) -> None:
    """Wrap the Text artist ``text`` (each of its lines) until it is at most ``width``
    [pixels] wide.
    """
    original = text.get_text()
    longest = max((len(line) for line in original.splitlines()), default=0)
    for characters in range(longest - 2, 10, -2):
        if text.get_window_extent().width <= width:
            return
        text.set_text("\n".join(_fill(line, characters) for line in original.splitlines()))


def _fill(line: str, characters: int) -> str:
    """``line`` wrapped at spaces into lines of at most ``characters`` (a name such as
    "itf-type-2" kept whole).
    """
    return textwrap.fill(line, characters, break_on_hyphens=False, break_long_words=False)
