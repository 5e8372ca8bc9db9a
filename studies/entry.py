"""The ``racket-impact`` console command, light to import: a Ctrl-C while the command line
starts (:mod:`studies.cli` imports numpy, pandas and matplotlib, about half a second) ends
with one line and status 130, as one during a run does.
"""

from __future__ import annotations

import signal
import sys


def interrupted(prefix: str, err: KeyboardInterrupt, written: bool) -> int:
    """A run ended by Ctrl-C (or by SIGTERM or SIGHUP, ``err.signum``): one line on stderr,
    and the shell's status for the signal (128 + its number).

    Parameters
    ----------
    prefix : str
        The command, as its messages start (``racket-impact ball``).
    err : KeyboardInterrupt
        What ended it (:class:`studies.outputs.Stopped` for SIGTERM or SIGHUP).
    written : bool
        Whether the run's files were all put in place before it ended.
    """
    signum = getattr(err, "signum", signal.SIGINT)
    how = "interrupted" if signum == signal.SIGINT else f"stopped by {signal.Signals(signum).name}"
    done = "its files were all written" if written else "no file written"
    print(f"{prefix}: {how}; {done}", file=sys.stderr)
    return 128 + signum


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
