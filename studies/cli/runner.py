"""A parsed command run: its files put in place together, warnings said once it has
succeeded, bad input one line and status 2, a reader of the output free to go.
"""

from __future__ import annotations

import contextlib
import os
import re
import sys
import warnings

from common.typechecks import asked_by_caller
from racket.solver import Unanswered, one_blas_thread
from studies import outputs
from studies.cli.files import _RUN
from studies.cli.notice import compile_watch
from studies.cli.options import speed_unit
from studies.outputs import interrupted

_SPEEDS = {"speed", "swing_speed", "racket_speed", "pitch", "cm_speed"}
"""The speed options whose unit an unanswered impact's refusal is said in (their ``dest``)."""


class _Stdout:
    """``sys.stdout`` while the command line runs: when its reader has gone (``| head``),
    the rest of the output goes to ``os.devnull``, as Python's documentation advises for
    SIGPIPE, and the run goes on to write its files.

    Parameters
    ----------
    stream : file
        The standard output.
    """

    def __init__(self, stream):
        self._stream = stream

    def write(self, text: str) -> int:
        """Write ``text``, or nothing once the reader has gone; returns its length."""
        try:
            return self._stream.write(text)
        except BrokenPipeError:
            self._gone()
            return len(text)

    def flush(self) -> None:
        """Flush, or nothing once the reader has gone."""
        try:
            self._stream.flush()
        except BrokenPipeError:
            self._gone()

    def _gone(self) -> None:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, self._stream.fileno())  # what is still buffered goes there too
        os.close(devnull)

    def __getattr__(self, name):
        return getattr(self._stream, name)


@contextlib.contextmanager
def _reader_may_go():
    """Inside the block, ``sys.stdout`` is a :class:`_Stdout`, flushed at its end (a reader
    gone shows there, not as Python exits).
    """
    stream = sys.stdout
    if stream is None:  # no standard output at all (``>&-``): print writes nothing
        yield
        return
    sys.stdout = _Stdout(stream)
    try:
        yield
    finally:
        sys.stdout.flush()
        sys.stdout = stream


def _start(
    args, words: list[str], originals: dict | None = None, written_utc: str | None = None
) -> int:
    """Run the parsed ``args`` as the command line ``words``, which its tables' sidecars
    record (``originals``: a rerun's copies of TOML inputs -> the paths first given;
    ``written_utc``: the time of the run a rerun reproduces).
    """
    options = {k: v for k, v in vars(args).items() if k != "func" and not k.startswith("_")}
    outer = dict(_RUN)  # a rerun's own run, restored afterwards
    _RUN.clear()
    _RUN.update(argv=words, command=args.command, options=options, originals=originals or {},
                written_utc=written_utc)  # fmt: skip
    try:
        return _run(args, f"racket-impact {args.command}")
    finally:
        _RUN.clear()
        _RUN.update(outer)


def _run(args, prefix: str) -> int:
    """Run the parsed command, its files put in place together when it returns: warnings
    one line each, said when it has succeeded, bad input status 2 (one line, the warnings
    before it left unsaid), Ctrl-C status 130 and SIGTERM or SIGHUP
    128 + its number (one line; its files removed, as :func:`studies.outputs.stoppable`).
    """
    said = {}  # kind -> line: the first warning of each kind, said when the run succeeds

    def one_line(message, category, filename, lineno, file=None, line=None):
        kind = re.sub(r"\d[\d.eE+-]*", "#", str(message))  # a grid repeats them, new numbers
        said.setdefault(kind, f"{prefix}: warning: {message}")

    with warnings.catch_warnings(), outputs.stoppable():
        warnings.showwarning = one_line
        files = None
        try:
            # BLAS on one thread: the same bits as a study's tasks on --workers or a cluster;
            # the API asks nothing: each option was asked about as typed, in its own unit
            with (
                outputs.transaction() as files,
                compile_watch(),
                one_blas_thread(),
                asked_by_caller(),
            ):
                status = args.func(args)
            for line in said.values():  # (a run refused says one line: its error)
                print(line, file=sys.stderr)
            return status
        except KeyboardInterrupt as err:  # Stopped too: SIGTERM, SIGHUP
            if args.debug:
                raise
            return interrupted(prefix, err, written=files is not None and files.committed)
        except (ValueError, OSError) as err:
            if args.debug:
                raise
            message = err.strerror if isinstance(err, OSError) and err.strerror else str(err)
            if isinstance(err, Unanswered):  # in the unit the speeds were typed in
                message = err.said_in(speed_unit(args, *_SPEEDS.intersection(vars(args))))
            where = f" ({err.filename})" if isinstance(err, OSError) and err.filename else ""
            line = f"{prefix}: error: {message}{where}"
            for copy, original in _RUN.get("originals", {}).items():  # a rerun's TOML copies
                line = line.replace(copy, original)
            print(line, file=sys.stderr)
            return 2
        except Exception as err:
            if args.debug:
                raise
            print(
                f"{prefix}: internal error ({type(err).__name__}: {err}); please report it, "
                "with the command; --debug shows the traceback",
                file=sys.stderr,
            )
            return 1
