"""Studies on top of the physics: sweeps, tables, plots, the command line and the page.

The root holds what serves many jobs: sweeps (:mod:`~studies.sweeps`), tables and outputs
with their sidecars (:mod:`~studies.tables`, :mod:`~studies.outputs`,
:mod:`~studies.provenance`), the conditions line (:mod:`~studies.conditions`), TOML input
(:mod:`~studies.config`), scale-out (:mod:`~studies.scale`, :mod:`~studies.scheduler`), the
serve and its what-ifs (:mod:`~studies.serve`), the paper reproduced
(:mod:`~studies.paper`), the drop, the ball's bounce, the feel, the spec report and the TWU
table.  Each job of its own has a room: :mod:`studies.face` (face maps, sweet spots,
landmarks), :mod:`studies.strings`, :mod:`studies.strokes` (strokes and courts),
:mod:`studies.bat`, :mod:`studies.plots`, :mod:`studies.validation`, the command line
:mod:`studies.cli` and the interactive page :mod:`studies.page`.  Import a study from its
module (``from studies.sweeps import sweep``): this package itself loads nothing heavy,
so that the command line starts fast.
"""

from common.version import __version__

__all__ = ["__version__"]
