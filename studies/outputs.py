"""The files of one run, committed together.

Every file a command writes (tables, their sidecars, plots, figures) is first written to a
temporary file in its target's own directory; when the command has succeeded, all of them
are renamed into place at once, and when it has not (an error, Ctrl-C) all of them are
removed: a run leaves either nothing new or its complete, consistent set of files.

The renames of a run hold an exclusive lock on each target directory (``flock`` on the
directory itself; no lock file is created, and where ``fcntl`` is missing the lock is
skipped), so that two runs writing the same files leave one run's files, never a mix.  The
previous file of each target is kept (a hard link, or a copy) until every rename has
succeeded, so that a failed rename puts back the files already replaced.  Ctrl-C during the
renames is held back until they are done.
"""

from __future__ import annotations

import contextlib
import functools
import os
import secrets
import shutil
import signal
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

_OPEN = threading.local()  # each thread's transactions being built, innermost last


@functools.cache
def _mode() -> int:
    """The permissions a new file gets under the process's umask (a temporary file is made
    private; the output it becomes should not be).
    """
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
        rename fails, put back what was there and remove everything new.
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
            backups, placed = {}, []
            try:
                for target, temp in staged.items():
                    try:
                        backups[target] = _backup(target)
                        os.replace(temp, target)
                    except OSError as err:
                        raise _naming(err, target) from None
                    placed.append(target)
            except BaseException:
                for target in reversed(placed):
                    with contextlib.suppress(OSError):
                        if backups[target] is None:
                            os.unlink(target)
                        else:
                            os.replace(backups[target], target)
                self.discard()
                raise
            finally:
                for backup in backups.values():
                    if backup is not None:
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


def _backup(target: Path) -> Path | None:
    """A second name in ``target``'s directory for the file ``target`` names now (None if
    there is none): a hard link, or where links are not supported a copy.
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
            shutil.copy2(target, backup)
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


@contextlib.contextmanager
def _interrupts_held():
    """Hold Ctrl-C back until the block is done, then deliver it.  A handler that records
    it, rather than a blocked signal mask: another thread (the solver's pool) would take a
    signal this thread blocks, and Python would raise it here all the same.
    """
    if threading.current_thread() is not threading.main_thread():
        yield  # only the main thread ever sees KeyboardInterrupt
        return
    caught = []
    previous = signal.signal(signal.SIGINT, lambda signum, frame: caught.append(signum))
    try:
        yield
    finally:
        signal.signal(signal.SIGINT, signal.default_int_handler if previous is None else previous)
        if caught:
            signal.raise_signal(signal.SIGINT)


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
