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
    ``axes``: a figure made here (``made``) widened so that its Axes keep
    :data:`AXES_WIDTH` beside their legends, each Axes' title wrapped to the Axes' width, and
    ``conditions`` (if given) drawn as the figure's heading, wrapped to the figure's width.

    Nothing is drawn here: the figure's layout engine (matplotlib's constrained layout, for
    a figure made here) places the Axes once, from the extents of their labels, ticks,
    legends and the heading that the renderer measures without drawing, and the figure is
    widened from that in one step (nothing beside the Axes grows with the figure: what it
    gains, its Axes gain). Saving it then draws it twice, as matplotlib saves any figure
    with a layout engine: once to lay it out, nothing rendered, and once to render it.

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
    heading = fig.suptitle(conditions, fontsize="medium") if conditions else None
    _place(fig)
    rooms = [(ax, ax.get_window_extent().width) for ax in fig.axes]
    if made:
        _widen(fig)
    for ax, room in rooms:
        if made and ax.get_aspect() == "auto":  # these Axes were widened to AXES_WIDTH
            room = max(room, AXES_WIDTH * fig.dpi)
        _wrap(ax.title, min(room, 0.96 * fig.bbox.width))
    if heading is not None:
        _wrap(heading, 0.96 * fig.bbox.width)
    return axes


def _place(fig) -> None:
    """Place the Axes of ``fig`` as its layout engine would when drawing it, without drawing
    it: the engine run once (constrained layout measures each Axes' labels, ticks, legends
    and the heading with the renderer), then each Axes' aspect applied; with no engine the
    Axes stay where they are.
    """
    engine = fig.get_layout_engine()
    if engine is None:
        return
    engine.execute(fig)
    for ax in fig.axes:  # as Axes.draw does first: a fixed aspect shrinks the Axes' box
        locator = ax.get_axes_locator()
        ax.apply_aspect(locator(ax, fig._get_renderer()) if locator else None)


def _widen(fig) -> None:
    """Widen ``fig`` so that its narrowest Axes (of the automatic aspect, not a colour
    bar's) is :data:`AXES_WIDTH` wide once laid out again, from where :func:`_place` put
    them: in one step, as nothing beside the Axes grows with the figure.
    """
    widths = [
        ax.get_position().width * fig.get_figwidth()
        for ax in fig.axes
        if ax.get_aspect() == "auto" and not hasattr(ax, "_colorbar") and ax.get_visible()
    ]
    short = AXES_WIDTH - min(widths, default=AXES_WIDTH)
    if short >= 0.05:
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
