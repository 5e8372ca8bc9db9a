"""Studies on many processes or machines: the impacts in chunks on an executor.

:func:`run_calls` runs calls of :func:`racket.impact` on any
:class:`concurrent.futures.Executor`: a ``ProcessPoolExecutor`` (:func:`executor_for` with
``workers``), or a Dask cluster's ``client.get_executor()`` (:func:`executor_for` with a
scheduler's address).  The impact points are cut into chunks of at most
:data:`TASK_IMPACTS`; each impact's result depends on its own inputs only (one time step per
closing speed, :func:`racket.impact`), so the results are bit-identical to a run in this
process.  The pieces:

* a racket used by several tasks has its caches (modes, static flexibility, block systems)
  computed once, on the executor, and travels with them (a racket pickles with the caches it
  has computed), so that no task computes them again (about 50 ms each);
* a worker's kernel runs on one thread (:func:`one_kernel_thread`): the executor's
  processes share the cores, the kernel's threads would oversubscribe them; BLAS runs on one
  thread in every task, here too (:func:`racket.solver.dispatch.one_blas_thread`: a racket's caches
  computed on several BLAS threads differ in their last bits);
* every task has its own key (a run's random token and the task's number), so that a Dask
  client's default ``pure=True`` never hands one task's result to another;
* the warnings of the tasks come back with their results and are said in this process.
"""

from __future__ import annotations

import contextlib
import math
import numbers
import os
import secrets
import select
import signal
import socket
import sys
import threading
import warnings
from collections.abc import Callable, Sequence
from concurrent.futures import Executor
from typing import NamedTuple

import numpy as np

from common.checks import ArgumentTypeError, shown
from common.typechecks import flag
from studies import outputs
from studies.scheduler import SCHEDULER_TIMEOUT, check_scheduler, connected

TASK_IMPACTS = 4096
"""Most impacts in one task: about 65 ms of a worker's time at 16 us per impact (the
1e6-impact benchmark of :func:`studies.sweeps.sweep`), long beside a process pool's 0.1-1 ms
per task and a Dask scheduler's few ms, short enough to share a study out evenly."""

MIN_TASK_IMPACTS = 128
"""Fewest impacts in a task when a study is cut into :data:`MIN_TASKS` (a task's overhead is
then still well under its work)."""

MIN_TASKS = 16
"""Tasks a study is cut into at least, where it has enough impacts: 2-8 workers each get
several, so that they finish together."""

MAX_WORKERS = 1024
"""Most processes ``--workers`` starts."""


class Impacts(NamedTuple):
    """One call of :func:`racket.impact`: impact points (P,) with, per point, an offset and
    a swing speed; the other inputs shared.

    Attributes
    ----------
    racket : Racket
    ball : Ball
    position : ndarray
        (P,) impact points [m from the tip].
    speed : float
        Ball speed towards the strings [m/s].
    offset : ndarray or None
        (P,) distances from the long axis [m], or None (the bending modes only).
    swing_speed : ndarray or float
        (P,) speeds of the impact points towards the ball [m/s], or one for all.
    pivot : float or None
        The swing's pivot [m from the tip], None for a racket at rest or translating.
    """

    racket: object
    ball: object
    position: np.ndarray
    speed: float
    offset: np.ndarray | None = None
    swing_speed: np.ndarray | float = 0.0
    pivot: float | None = None

    def part(self, start: int, stop: int) -> Impacts:
        """The same call on the points ``start:stop``."""

        def cut(values):
            return values[start:stop] if np.ndim(values) else values

        return self._replace(
            position=self.position[start:stop],
            offset=None if self.offset is None else self.offset[start:stop],
            swing_speed=cut(self.swing_speed),
        )


def impacts_of(racket, ball, position, speed, offset=None, swing=None) -> Impacts:
    """An :class:`Impacts` of ``position`` [m from the tip] (and ``offset`` [m] broadcast
    with it), swung by ``swing`` (a :class:`racket.Swing`, its point speeds and pivot for
    this racket) or at rest.

    Parameters
    ----------
    racket, ball, position, speed, offset, swing :
        As in :func:`studies.sweeps.sweep`.
    """
    x = np.atleast_1d(np.asarray(position, dtype=float))
    y = None
    if offset is not None:
        x, y = (np.ascontiguousarray(v) for v in np.broadcast_arrays(x, np.asarray(offset)))
    moved = {} if swing is None else swing.impact_kwargs(racket, x)
    return Impacts(racket, ball, x, speed, y, **moved)


def one_kernel_thread() -> None:
    """Run this process's kernel on one thread (for a worker: its executor's processes
    share the cores).  The kernel's threads are numba's ``NUMBA_NUM_THREADS``
    (:mod:`racket.solver.dispatch`): set in the environment for numba not yet imported, and in its
    configuration otherwise.  BLAS runs on one thread in every task, wherever it runs
    (:func:`racket.solver.dispatch.one_blas_thread`).
    """
    os.environ["NUMBA_NUM_THREADS"] = "1"
    if "numba" in sys.modules:
        from numba import config

        config.NUMBA_NUM_THREADS = 1


def _task(key, home, read, pieces) -> tuple[list, list]:
    """Run ``pieces`` (Impacts) and ``read`` each result (a dict of arrays); also the
    warnings they raised, as (category, message).  ``key`` (the run's token and the task's
    number) makes each task's arguments unique; ``home`` is the submitting process.
    """
    from racket import impact
    from racket.solver import one_blas_thread

    if _here() != home:
        one_kernel_thread()
    with one_blas_thread(), warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        out = [
            read(impact(p.racket, p.ball, p.position, p.speed, offset=p.offset,
                        swing_speed=p.swing_speed, pivot=p.pivot))
            for p in pieces
        ]  # fmt: skip
    return out, [(w.category, str(w.message)) for w in caught]


def _warmed(key, home, piece: Impacts):
    """``piece.racket`` with the caches an impact like ``piece``'s computes (its first
    point), to travel with the tasks that use it.
    """
    _task(key, home, _nothing, [piece.part(0, 1)])
    return piece.racket


def _nothing(result) -> None:
    return None


def _here() -> tuple[str, int]:
    """The machine and id of the process running: a task run elsewhere is on a worker."""
    return socket.gethostname(), os.getpid()


def _chunk(total: int) -> int:
    """Impacts per task for a study of ``total`` impacts (see :data:`TASK_IMPACTS`)."""
    return int(np.clip(math.ceil(total / MIN_TASKS), MIN_TASK_IMPACTS, TASK_IMPACTS))


def executor_argument(executor):
    """``executor``: None (this process), a :class:`concurrent.futures.Executor` or a Dask
    ``Client`` (anything whose ``submit`` returns futures); TypeError (a ValueError too)
    otherwise.

    Parameters
    ----------
    executor : object
        The value given.
    """
    if executor is None or isinstance(executor, Executor):
        return executor
    if not isinstance(executor, str | numbers.Number) and callable(
        getattr(executor, "submit", None)
    ):
        return executor
    raise ArgumentTypeError(
        "executor must be None or a concurrent.futures.Executor (a ProcessPoolExecutor, a Dask "
        "client's get_executor(); studies.scale.executor_for makes either from a number of "
        f"workers or a scheduler's address), got {shown(executor)}"
    )


def run_calls(
    calls: Sequence[Impacts],
    read: Callable,
    executor: Executor | None = None,
    progress: bool | None = None,
    desc: str = "impacts",
) -> list[dict]:
    """Run the ``calls`` of :func:`racket.impact` and ``read`` each result.

    Parameters
    ----------
    calls : sequence of Impacts
    read : callable
        Result (:class:`racket.Impact`) -> dict of 1-D arrays over its points, module level
        (pickled to the workers), e.g. :func:`studies.tables.impact_columns`.
    executor : concurrent.futures.Executor, optional
        Where to run them, cut into tasks of at most :data:`TASK_IMPACTS` impacts (see the
        module docstring); default: one call after the other in this process.
    progress : bool, optional
        Show a progress bar; default: when standard error is a terminal.
    desc : str
        The progress bar's label.

    Returns
    -------
    list of dict
        ``read`` of each call, its arrays over all its points, bit-identical to a run in this
        process.  The tasks' warnings are raised here.
    """
    executor = executor_argument(executor)
    if progress is not None:
        flag("progress", progress)
    key = secrets.token_hex(8)
    if executor is None:
        tasks = [[call] for call in calls]
        done = (_task((key, i), _here(), read, task) for i, task in enumerate(tasks))
        results = list(progress_bar(done, len(tasks), progress, desc))
        index = [[(i, 0)] for i in range(len(calls))]
    else:
        tasks, index = _tasks(calls)
        results = _on(executor, key, read, tasks, progress, desc)
    for _, caught in results:
        for category, message in caught:
            warnings.warn(message, category, stacklevel=2)
    out = []
    for pieces in index:
        parts = [results[t][0][k] for t, k in pieces]
        out.append(parts[0] if len(parts) == 1 else _joined(parts))
    return out


def _joined(parts: list[dict]) -> dict:
    return {name: np.concatenate([part[name] for part in parts]) for name in parts[0]}


def _tasks(calls) -> tuple[list[list[Impacts]], list[list[tuple[int, int]]]]:
    """The calls cut into chunks, packed into tasks, each racket's chunks together (its
    caches computed once per task); also where each call's chunks went, (task, place) in
    order.
    """
    size = _chunk(sum(call.position.size for call in calls))
    by_racket = {}
    for i, call in enumerate(calls):
        by_racket.setdefault(id(call.racket), []).append(i)
    tasks, index = [], [[] for _ in calls]
    for group in by_racket.values():
        load = size  # a new racket starts a new task
        for i in group:
            call, count = calls[i], calls[i].position.size
            for start in range(0, count, size):
                piece = call.part(start, min(start + size, count))
                if load + piece.position.size > size:
                    tasks.append([])
                    load = 0
                index[i].append((len(tasks) - 1, len(tasks[-1])))
                tasks[-1].append(piece)
                load += piece.position.size
    return tasks, index


def _on(executor, key, read, tasks, progress, desc) -> list:
    """Run ``tasks`` on ``executor``, a racket used by several first made to carry its
    caches; their results in order.
    """
    users = {}
    for task in tasks:
        for racket in {id(p.racket): p.racket for p in task}.values():
            users.setdefault(id(racket), []).append(task)
    shared = [next(p for p in group[0] if id(p.racket) == k) for k, group in users.items()
              if len(group) > 1]  # fmt: skip
    futures, home = [], _here()
    try:
        warm = [executor.submit(_warmed, (key, "warm", n), home, p) for n, p in enumerate(shared)]
        carried = {id(p.racket): f.result() for p, f in zip(shared, warm, strict=True)}
        tasks = [[p._replace(racket=carried.get(id(p.racket), p.racket)) for p in task]
                 for task in tasks]  # fmt: skip
        futures = [executor.submit(_task, (key, i), home, read, t) for i, t in enumerate(tasks)]
        return list(progress_bar((f.result() for f in futures), len(futures), progress, desc))
    finally:
        for future in futures:
            future.cancel()  # those not started, after an error or Ctrl-C


def progress_bar(iterable, total: int, progress: bool | None, desc: str):
    """``iterable`` under a tqdm bar on standard error, or as it is.

    Parameters
    ----------
    iterable : iterable
        What the bar follows.
    total : int
        Its items (no bar for fewer than 2).
    progress : bool or None
        Show the bar; None: when standard error is a terminal.
    desc : str
        The bar's label.
    """
    show = sys.stderr.isatty() if progress is None else progress
    if not show or total < 2:
        return iterable
    from tqdm import tqdm

    return tqdm(iterable, total=total, desc=desc)


def cores() -> int:
    """The cores this process may run on (its CPU affinity, where the platform tells it)."""
    if hasattr(os, "sched_getaffinity"):
        return len(os.sched_getaffinity(0))
    return os.cpu_count() or 1


def check_workers(workers, flag: str = "workers") -> int:
    """``workers``, a whole number of processes in [1, :data:`MAX_WORKERS`] (ValueError
    naming ``flag`` otherwise), cut to the :func:`cores` with a warning: a worker runs one
    thread, so more would only share the cores, each holding a solver (0.15-0.23 GB,
    measured).

    Parameters
    ----------
    workers : int
        Processes of a local pool.
    flag : str
        The input's name as the user typed it (``--workers``).
    """
    if isinstance(workers, bool) or not isinstance(workers, (int, np.integer)):
        raise ValueError(f"{flag} must be a whole number of processes, got {workers!r}")
    if not 1 <= workers <= MAX_WORKERS:
        raise ValueError(
            f"{flag} must be in [1, {MAX_WORKERS}] processes (this machine has "
            f"{os.cpu_count()} cores), got {workers}"
        )
    available = cores()
    if workers > available:
        warnings.warn(
            f"{flag} {workers}: this process may use {available} cores; running on "
            f"{available} processes (more would not run faster)",
            stacklevel=2,
        )
        return available
    return int(workers)


def quiet_worker(home: int | None = None) -> None:
    """A pool worker's start (its ``initializer``): Ctrl-C is for the command, which stops
    the pool, not for each worker to report; the kernel on one thread; the worker ends when
    the command does (:func:`die_with`).

    Parameters
    ----------
    home : int, optional
        The command's process id; default this worker's parent (a pool forked or spawned by
        the command; a forkserver's worker is the forkserver's child).
    """
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    one_kernel_thread()
    die_with(os.getppid() if home is None else home)


def die_with(home: int) -> None:
    """Kill this process (SIGKILL) when the process ``home`` ends, however it ends: on Linux
    (5.3 and later), a thread waits on ``home``'s pidfd; elsewhere nothing (a killed
    command's workers are then left waiting for tasks).  Not ``PR_SET_PDEATHSIG``: it
    follows the parent, and a forkserver's worker's parent is the forkserver, which its
    workers keep alive (they hold its pipe), so neither would ever end.

    Parameters
    ----------
    home : int
        The process id to die with.
    """
    if not hasattr(os, "pidfd_open"):
        return
    try:
        handle = os.pidfd_open(home)
    except ProcessLookupError:  # ended already
        os.kill(os.getpid(), signal.SIGKILL)
    except OSError:  # a kernel before 5.3
        return

    def wait():
        ended = select.poll()
        ended.register(handle, select.POLLIN)  # readable when ``home`` has ended
        ended.poll()
        os.kill(os.getpid(), signal.SIGKILL)

    threading.Thread(target=wait, daemon=True, name="racket-impact: die with the command").start()


def _pool_context():
    """A pool's multiprocessing context: forkserver where the platform has it, spawn
    otherwise (a clean process whatever threads this one runs).  The forkserver is started
    with Ctrl-C and SIGHUP blocked, and its workers inherit the block: a signal a terminal
    sends to every process of the command is the command's to answer (it ends its workers),
    not a starting worker's traceback.
    """
    import multiprocessing
    from multiprocessing import forkserver, resource_tracker

    if "forkserver" not in multiprocessing.get_all_start_methods():
        return multiprocessing.get_context("spawn")
    context = multiprocessing.get_context("forkserver")
    context.set_forkserver_preload(["racket.solver", "studies.tables"])
    resource_tracker.ensure_running()  # first: its start unblocks SIGINT and SIGTERM
    quiet = set(outputs.STOPS) - {signal.SIGTERM}  # (a broken pool's workers get SIGTERM)
    unblocked = signal.pthread_sigmask(signal.SIG_BLOCK, quiet)
    try:
        forkserver.ensure_running()
    finally:
        signal.pthread_sigmask(signal.SIG_SETMASK, unblocked)
    return context


def _kill(pool) -> None:
    """End the workers of ``pool`` at once: their tasks' work is not wanted (``shutdown``
    lets the running tasks end, and those already handed to the workers).  Python before
    3.14 (``terminate_workers``) has no public way to them.
    """
    for process in list((pool._processes or {}).values()):
        process.kill()


@contextlib.contextmanager
def executor_for(
    workers: int | None = None,
    scheduler: str | None = None,
    timeout: float = SCHEDULER_TIMEOUT,
    flags: tuple[str, str] = ("workers", "scheduler"),
):
    """An executor for a study: None (this process) when neither is given, a pool of
    ``workers`` processes, or the Dask cluster at ``scheduler`` (``client.get_executor``
    with ``pure=False``); closed when the block ends.  Both are checked, and the scheduler
    reached, before the block runs (ValueError in one line).  A pool's workers end with the
    command, however it ends (:func:`die_with`), and at once when the block raises (Ctrl-C,
    SIGTERM, an error).

    Parameters
    ----------
    workers : int, optional
        Processes of a local pool, in [1, :data:`MAX_WORKERS`], cut to the :func:`cores`
        (:func:`check_workers`; forkserver where the platform has it, spawn otherwise).
    scheduler : str, optional
        A Dask scheduler's address (:func:`studies.scheduler.check_scheduler`), refused
        within ``timeout`` unless a Dask scheduler answers there
        (:func:`studies.scheduler.connected`); needs ``dask[distributed]``
        (``pip install 'racket-impact[scale]'``).
    timeout : float
        The longest the check of ``scheduler`` takes [s].
    flags : tuple of str
        The names of ``workers`` and ``scheduler`` as the user typed them (``--workers``).
    """
    if workers is not None and scheduler is not None:
        raise ValueError(f"give {flags[0]} or {flags[1]}, not both")
    if workers is None and scheduler is None:
        yield None
        return
    if workers is not None:
        from concurrent.futures import ProcessPoolExecutor

        workers = check_workers(workers, flags[0])
        pool = ProcessPoolExecutor(
            workers, _pool_context(), initializer=quiet_worker, initargs=(os.getpid(),)
        )
        try:
            yield pool
        except BaseException:
            _kill(pool)
            raise
        finally:
            pool.shutdown(wait=True, cancel_futures=True)
        return
    client = connected(check_scheduler(scheduler, flags[1]), flags[1], timeout)
    try:
        yield client.get_executor(pure=False)
    finally:
        client.close()
