"""The files of one run, committed together.

Every file a command writes (tables, their sidecars, plots, figures) is first written to a
temporary file in its target's own directory; when the command has succeeded, all of them
are renamed into place at once, and when it has not (an error, Ctrl-C) all of them are
removed: a run leaves either nothing new or its complete, consistent set of files.

The renames of a run hold an exclusive lock on each target directory (``flock`` on the
directory itself; no lock file is created, and where ``fcntl`` is missing the lock is
skipped), so that two runs writing the same files leave one run's files, never a mix.  The
previous file of each target is kept (a hard link, or a copy) until every rename has
succeeded, so that a failed rename puts back the files already replaced (one that cannot be
put back is kept, and named in the error).  Ctrl-C, SIGTERM and SIGHUP during the renames
are held back until they are done; inside :func:`stoppable`, SIGTERM and SIGHUP end a run as
Ctrl-C does.
"""

from __future__ import annotations

import contextlib
import functools
import os
import secrets
import shutil
import signal
import sys
import tempfile
import threading
from pathlib import Path

try:
    import fcntl
except ImportError:  # Windows: no advisory locks; the renames stay all or nothing
    fcntl = None

PREFIX = ".racket-impact-"
"""The start of every temporary file's name (short: a target's name may be the longest its
directory allows)."""

STOPS = tuple(
    getattr(signal, name) for name in ("SIGINT", "SIGTERM", "SIGHUP") if hasattr(signal, name)
)
"""The signals that end a run (those the platform has): held back during the renames."""

_OPEN = threading.local()  # each thread's transactions being built, innermost last


class Stopped(KeyboardInterrupt):
    """A run ended by SIGTERM or SIGHUP inside :func:`stoppable`: a KeyboardInterrupt, so
    that its files are removed as on Ctrl-C.

    Parameters
    ----------
    signum : int
        The signal.
    """

    def __init__(self, signum: int):
        super().__init__(signum)
        self.signum = signum


def interrupted(prefix: str, err: KeyboardInterrupt, written: bool) -> int:
    """A run ended by Ctrl-C (or by SIGTERM or SIGHUP, ``err.signum``): one line on stderr,
    and the shell's status for the signal (128 + its number).

    Parameters
    ----------
    prefix : str
        The command, as its messages start (``racket-impact ball``).
    err : KeyboardInterrupt
        What ended it (:class:`Stopped` for SIGTERM or SIGHUP).
    written : bool
        Whether the run's files were all put in place before it ended.
    """
    signum = getattr(err, "signum", signal.SIGINT)
    how = "interrupted" if signum == signal.SIGINT else f"stopped by {signal.Signals(signum).name}"
    done = "its files were all written" if written else "no file written"
    print(f"{prefix}: {how}; {done}", file=sys.stderr)
    return 128 + signum


@functools.cache
def _mode() -> int:
    """The permissions a new file gets under the process's umask (a temporary file is made
    private; the output it becomes should not be).  The umask is read where the system
    shows it (Linux), not set and set back: another thread may create files meanwhile.
    """
    try:
        with open("/proc/self/status") as status:
            umask = next(int(line.split()[1], 8) for line in status if line.startswith("Umask:"))
    except (OSError, StopIteration, IndexError, ValueError):  # not Linux (or a kernel < 4.7)
        umask = os.umask(0)
        os.umask(umask)
    return 0o666 & ~umask


def _naming(err: OSError, target) -> OSError:
    """``err`` naming the output as given, not its temporary file."""
    return OSError(err.errno, err.strerror or str(err), str(target))


def _remove(path) -> None:
    with contextlib.suppress(OSError):
        os.unlink(path)


class Outputs:
    """The files of one run: written to temporary files, renamed into place together by
    :meth:`commit` or removed by :meth:`discard`.

    Attributes
    ----------
    committed : bool
        Whether :meth:`commit` has put every file in place.
    """

    def __init__(self):
        self._files = []  # (target, temporary file), in the order written
        self._made = []  # directories created for the run, outermost first
        self.committed = False

    def write(self, target, writer) -> None:
        """Write one output to a temporary file beside ``target``.

        Parameters
        ----------
        target : str or Path
            The file the output becomes when the run is committed.
        writer : callable
            Called with the temporary file's path (a str); writes the whole output there.
            An OSError it raises is raised again naming ``target``, not the temporary file.
        """
        target = Path(target)
        try:
            handle, temp = tempfile.mkstemp(prefix=PREFIX, dir=target.parent)
        except OSError as err:
            raise _naming(err, target) from None
        self._files.append((target, temp))
        try:
            os.close(handle)
            os.chmod(temp, _mode())
            writer(temp)
        except BaseException as err:
            self._files.remove((target, temp))
            _remove(temp)
            if isinstance(err, OSError):
                raise _naming(err, target) from None
            raise

    def directory(self, path) -> None:
        """Create the directory ``path`` and any missing parents, removed again if the run
        is discarded.

        Parameters
        ----------
        path : str or Path
            The directory.
        """
        path = Path(path)
        for folder in reversed([path, *path.parents]):
            if not folder.exists():
                try:
                    folder.mkdir()
                except FileExistsError:  # made meanwhile by someone else: not the run's
                    continue
                self._made.append(folder)

    def commit(self) -> None:
        """Rename every output into place (the last write of a target wins), or, if one
        rename fails, put back what was there and remove everything new (a previous file
        that cannot be put back is kept under its second name, which the error names).
        """
        staged = dict(self._files)
        for target, temp in self._files:
            if staged[target] != temp:
                _remove(temp)
        self._files = list(staged.items())
        if not staged:
            self._made, self.committed = [], True
            return
        with _interrupts_held(), _locked({target.parent for target in staged}):
            backups, placed, kept = {}, [], {}
            try:
                for target, temp in staged.items():
                    try:
                        backups[target] = _backup(target)
                        os.replace(temp, target)
                    except OSError as err:
                        raise _naming(err, target) from None
                    placed.append(target)
            except BaseException as err:
                for target in reversed(placed):
                    backup = backups[target]
                    try:
                        if backup is None:
                            os.unlink(target)
                        else:
                            os.replace(backup, target)
                    except OSError:
                        if backup is not None:  # the previous file, under its second name
                            kept[target] = backup
                self.discard()
                if kept:
                    raise _keeping(err, kept) from None
                raise
            finally:
                for backup in backups.values():
                    if backup is not None and backup not in kept.values():
                        _remove(backup)
            self._files, self._made = [], []
            self.committed = True

    def discard(self) -> None:
        """Remove every temporary file, and the directories created for the run."""
        for _, temp in self._files:
            _remove(temp)
        for folder in reversed(self._made):
            with contextlib.suppress(OSError):
                folder.rmdir()
        self._files, self._made = [], []


def _keeping(err: BaseException, kept: dict) -> OSError:
    """``err`` (a failed rename) telling where the previous files that could not be put
    back are kept (``kept``: each target -> its second name).
    """
    reason = err.strerror if isinstance(err, OSError) and err.strerror else str(err)
    where = ", ".join(f"{target} as {backup}" for target, backup in kept.items())
    return OSError(
        getattr(err, "errno", None),
        f"{reason}; the previous files could not be put back and are kept: {where}",
        getattr(err, "filename", None),
    )


def _backup(target: Path) -> Path | None:
    """A second name in ``target``'s directory for the file ``target`` names now (None if
    there is none): a hard link, or where links are not supported a copy (removed again if
    the copy fails).
    """
    if not os.path.lexists(target):
        return None
    while True:
        backup = target.parent / f"{PREFIX}{secrets.token_hex(6)}"
        try:
            if target.is_symlink():
                os.symlink(os.readlink(target), backup)
            else:
                os.link(target, backup)
        except FileExistsError:
            continue
        except OSError:  # a file system without hard links
            try:
                shutil.copy2(target, backup)
            except BaseException:
                _remove(backup)
                raise
        return backup


@contextlib.contextmanager
def _locked(directories):
    """An exclusive lock on each directory, taken in one order (no two runs deadlock)."""
    handles = []
    try:
        if fcntl is not None:
            distinct = {}
            for folder in directories:
                status = os.stat(folder)
                distinct.setdefault((status.st_dev, status.st_ino), folder)
            for key in sorted(distinct):
                try:
                    handle = os.open(distinct[key], os.O_RDONLY)
                except OSError:  # a directory that can be written but not opened: unlocked
                    continue
                handles.append(handle)
                fcntl.flock(handle, fcntl.LOCK_EX)
        yield
    finally:
        for handle in handles:
            os.close(handle)  # releases its lock


def _handling(handler, signals) -> dict:
    """Set ``handler`` for each of ``signals``; returns what each had (for :func:`_restore`)."""
    return {signum: signal.signal(signum, handler) for signum in signals}


def _restore(previous: dict) -> None:
    for signum, handler in previous.items():
        if handler is None:  # set outside Python: its default
            handler = signal.default_int_handler if signum == signal.SIGINT else signal.SIG_DFL
        signal.signal(signum, handler)


@contextlib.contextmanager
def _interrupts_held():
    """Hold Ctrl-C, SIGTERM and SIGHUP back until the block is done, then deliver them.  A
    handler that records them, rather than a blocked signal mask: another thread (the
    solver's pool) would take a signal this thread blocks, and Python would raise it here all
    the same.  A signal ignored (``nohup``) stays ignored.
    """
    if threading.current_thread() is not threading.main_thread():
        yield  # only the main thread runs Python's signal handlers
        return
    caught = []
    live = [signum for signum in STOPS if signal.getsignal(signum) != signal.SIG_IGN]
    previous = _handling(lambda signum, frame: caught.append(signum), live)
    try:
        yield
    finally:
        _restore(previous)
        for signum in dict.fromkeys(caught):
            signal.raise_signal(signum)


@contextlib.contextmanager
def stoppable():
    """Inside the block, SIGTERM and SIGHUP raise :class:`Stopped` (as Ctrl-C raises
    KeyboardInterrupt), so that a run they end removes its files.  Only in the main thread,
    and only for a signal whose handler is the system's default (one ignored, as under
    ``nohup``, stays ignored).
    """
    if threading.current_thread() is not threading.main_thread():
        yield
        return

    def stop(signum, frame):
        raise Stopped(signum)

    default = [s for s in STOPS if s != signal.SIGINT and signal.getsignal(s) == signal.SIG_DFL]
    previous = _handling(stop, default)
    try:
        yield
    finally:
        _restore(previous)


def _open() -> list:
    if not hasattr(_OPEN, "runs"):
        _OPEN.runs = []
    return _OPEN.runs


@contextlib.contextmanager
def transaction():
    """The files of one run: those written by :func:`write` inside the block are renamed
    into place when it ends normally, and removed when it raises (Ctrl-C included).

    Yields
    ------
    Outputs
        The run's files (``committed`` tells whether they were put in place).
    """
    outputs = Outputs()
    _open().append(outputs)
    try:
        yield outputs
        outputs.commit()
    except BaseException:
        with _interrupts_held():
            outputs.discard()
        raise
    finally:
        _open().remove(outputs)


def write(target, writer) -> None:
    """Write one output as part of the innermost open :func:`transaction`, or on its own
    (written whole, then renamed into place) outside any.

    Parameters
    ----------
    target : str or Path
        The output's file.
    writer : callable
        Called with a temporary file's path (a str); writes the whole output there.
    """
    if _open():
        _open()[-1].write(target, writer)
    else:
        with transaction() as outputs:
            outputs.write(target, writer)


def directory(path) -> None:
    """Create a directory for outputs (and its missing parents) as part of the innermost
    open :func:`transaction` (removed if the run fails), or at once outside any.

    Parameters
    ----------
    path : str or Path
        The directory.
    """
    if _open():
        _open()[-1].directory(path)
    else:
        Path(path).mkdir(parents=True, exist_ok=True)
