"""The ``racket-impact`` console command, light to import: a Ctrl-C while the command line
starts (:mod:`studies.cli` imports numpy, pandas and matplotlib, about half a second) ends
with one line and status 130, as one during a run does.
"""

from __future__ import annotations

import sys

from studies.outputs import interrupted


def main() -> int:
    """Run ``racket-impact`` (:func:`studies.cli.main`) with the process's arguments; returns
    its exit status, 130 for a Ctrl-C before it has started.
    """
    try:
        from studies.cli import main as run

        return run()
    except KeyboardInterrupt as err:
        if "--debug" in sys.argv[1:]:
            raise
        return interrupted("racket-impact", err, written=False)
