"""The solver's room: the time-stepping machinery that drives a racket's modes with a
ball's force law in series with the string bed (paper Sec. VII).

The model (:mod:`racket.racket`, :mod:`racket.system`, the hand, the head, the swing, the
presets and specs) describes a racket; this package computes what happens when a ball
hits it, and never the other way round (``tests/test_structure.py`` keeps the model from
importing it).  Its public face is small:

* :func:`impact` and its :class:`Impact` result;
* :func:`oblique_impact` (:class:`ObliqueImpact`), a spinning ball meeting the strings
  obliquely, and :func:`hit` (:class:`StrokeImpact`), a stroke and the ball's flight after
  (issue 36);
* :func:`load_kernel`, to compile the kernels before the first impact;
* :class:`Unanswered`, the refusal (a ValueError) of an impact the model cannot answer, with
  the closing speed up to which it answers (:mod:`~racket.solver.closure`);
* :data:`F1_MIN` and :data:`DEFAULT_STEPS_PER_CONTACT`, the solver's limits and default
  resolution;
* :func:`one_blas_thread`, for a caller that runs impacts on several threads of its own;
* :func:`system_steps`, a racket system's exact step (the feel's hand force uses it);
* :data:`COMPILE_SECONDS` and :func:`announced`, for a program that announces the kernels'
  first compilation itself.

Inside: :mod:`~racket.solver.driver` (:func:`impact`), :mod:`~racket.solver.stepper`
(the time step and the kernel's inputs), :mod:`~racket.solver.layout` (the kernel's interface),
:mod:`~racket.solver.kernel` and :mod:`~racket.solver.lockstep` (one impact at a time, or a
tile together), :mod:`~racket.solver.ball_kernel` (the force solve of each law),
:mod:`~racket.solver.expm` (the blocks' exact steps), :mod:`~racket.solver.dispatch`
(threads), :mod:`~racket.solver.outcome` and :mod:`~racket.solver.budget` (e, e_A and the
energy budget at separation), :mod:`~racket.solver.closure` (what a passive impact allows,
checked after every impact) and :mod:`~racket.solver.unhappy_search` (the unhappy ball's
self-consistent Xo); :mod:`~racket.solver.oblique` and :mod:`~racket.solver.stroke_hit`
(the tangential contact on the strings, :mod:`ball.grip`, driven by the head-on force
history), whose names load on first use (:mod:`common.lazy`: a head-on impact, as a sweep's,
imports neither, nor the stroke's model).  :mod:`~racket.solver.cache_stamp` drops numba's
on-disk cache when any of these files has changed (numba alone would notice a change in a
kernel's own file only).
"""

from pathlib import Path
from typing import TYPE_CHECKING

from common.lazy import lazy_names
from racket.solver.cache_stamp import drop_stale_cache
from racket.solver.closure import Unanswered
from racket.solver.dispatch import COMPILE_SECONDS, announced, one_blas_thread
from racket.solver.driver import (
    DEFAULT_STEPS_PER_CONTACT,
    F1_MIN,
    Impact,
    impact,
    load_kernel,
)
from racket.solver.steps import system_steps

if TYPE_CHECKING:  # loaded on first use (common.lazy): a head-on impact needs neither
    from racket.solver.oblique import ObliqueImpact, oblique_impact
    from racket.solver.stroke_hit import StrokeImpact, hit

drop_stale_cache(Path(__file__).parent)  # before any kernel loads its cache (they load lazily)

__all__ = [
    "COMPILE_SECONDS",
    "DEFAULT_STEPS_PER_CONTACT",
    "F1_MIN",
    "Impact",
    "ObliqueImpact",
    "StrokeImpact",
    "Unanswered",
    "announced",
    "hit",
    "impact",
    "load_kernel",
    "oblique_impact",
    "one_blas_thread",
    "system_steps",
]

__getattr__, __dir__ = lazy_names(
    __name__,
    {
        "racket.solver.oblique": ("ObliqueImpact", "oblique_impact"),
        "racket.solver.stroke_hit": ("StrokeImpact", "hit"),
    },
)
