"""Plots of simulation results (matplotlib).

Every function takes results computed elsewhere, an optional ``ax`` (an Axes, or a
sequence of Axes for the multi-panel plots) and optional ``conditions`` (what the results
are for, :func:`studies.conditions.conditions_line`, drawn as the figure's heading), draws,
and returns the Axes; none calls ``show()``.  A figure a plot makes is laid out so that
everything fits (:mod:`studies.plots.layout`).  Positions along the racket are distances
from the tip, in cm on the plots; the plots that show speeds take ``unit`` (m/s, mph or
km/h: the one the user typed).
"""

from studies.plots.ball import plot_collision, plot_cor_vs_stiffness, plot_drop, plot_rigid_bounce
from studies.plots.face import plot_face_map
from studies.plots.feel import plot_hand_feel
from studies.plots.racket import (
    draw_racket,
    plot_cor_along_racket,
    plot_cor_comparison,
    plot_impact,
    plot_modes,
)
from studies.plots.serve import plot_serve_what_if
from studies.plots.validation import plot_validation

__all__ = [
    "draw_racket",
    "plot_collision",
    "plot_cor_along_racket",
    "plot_cor_comparison",
    "plot_cor_vs_stiffness",
    "plot_drop",
    "plot_face_map",
    "plot_hand_feel",
    "plot_impact",
    "plot_modes",
    "plot_rigid_bounce",
    "plot_serve_what_if",
    "plot_validation",
]
