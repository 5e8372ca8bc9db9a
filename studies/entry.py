"""The ``racket-impact`` console command, light to import: a Ctrl-C while the command line
starts (:mod:`studies.cli` imports numpy and the physics, a few tenths of a second) ends
with one line and status 130, as one during a run does.
"""

from __future__ import annotations

import atexit
import gc
import sys

from common.blas import one_blas_thread_unless_set
from studies.outputs import interrupted


def main() -> int:
    """Run ``racket-impact`` (:func:`studies.cli.main`) with the process's arguments; returns
    its exit status, 130 for a Ctrl-C before it has started.

    The process ends with the command: at its exit, every object is frozen
    (:func:`gc.freeze`) first, so that the interpreter's last garbage collections pass
    over none of what numba, scipy and the rest loaded (a third of a second after a sweep;
    its files are closed by then, each by the code that wrote it).  BLAS runs on one
    thread unless the environment says otherwise (:mod:`common.blas`).
    """
    atexit.register(gc.freeze)
    one_blas_thread_unless_set()  # before numpy loads (common.blas)
    try:
        from studies.cli import main as run

        return run()
    except KeyboardInterrupt as err:
        if "--debug" in sys.argv[1:]:
            raise
        return interrupted("racket-impact", err, written=False)
