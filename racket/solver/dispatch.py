"""Running the time-steppers: which kernel, on how many threads.

A batch of at least ``LOCKSTEP_MIN`` impacts per thread runs in the lockstep kernel
(:mod:`racket.solver.lockstep`), a smaller one in the scalar kernel
(:mod:`racket.solver.kernel`); both
give the same numbers, bit for bit.  The kernels release the GIL, so the impacts of a batch
are shared out between threads; numba loads (and on a machine's first run compiles) the
kernels on first use, not on ``import racket``.
"""

from __future__ import annotations

import os
import sys
import threading
from concurrent.futures import ThreadPoolExecutor, wait
from contextlib import contextmanager

COMPILE_SECONDS = 60
"""About how long numba takes to compile the solver on a 2-core machine: measured 54 s for the
default racket's sweep on an empty cache (2026-11-30, load 0.8; 12-15 s before the real string
bed and the lockstep kernel)."""

IMPACTS_PER_THREAD = 8
"""Smallest share of a batch's impacts worth a thread of its own (one impact takes about
20 us; handing work to a thread about as long)."""

LOCKSTEP_MIN = 16
"""Smallest share of a thread's impacts run in lockstep (:mod:`racket.solver.lockstep`); fewer run
one at a time (:mod:`racket.solver.kernel`).  Measured by ``benchmarks/sweep.py`` (the paper
racket, a linear ball, 2 threads, the two kernels interleaved): the lockstep kernel takes as
long as the scalar one at 16 impacts per thread, 1.4x less time at 24, 1.5-2x at 100 and
2.2x at 5000 (8 per thread: 0.75x)."""


def run_kernel(args, count: int) -> None:
    """Run the kernel suited to ``count`` impacts on as many threads as they are worth.

    Parameters
    ----------
    args : tuple
        The kernels' arguments before the slice: frame, points, ball, controls and outputs
        (:func:`racket.solver.kernel.run_impacts`).
    count : int
        Impacts in the batch [-].
    """
    threads = max(1, min(pool_size(), count // IMPACTS_PER_THREAD))
    if count >= LOCKSTEP_MIN * threads:
        from racket.solver.lockstep import run_lockstep as run  # numba loads on first use
    else:
        from racket.solver.kernel import run_impacts as run
    if id(run) in _READY:  # (the usual case, without a context manager's cost)
        _run_on_threads(run, args, count, threads)
        return
    with compile_notice(run):
        _run_on_threads(run, args, count, threads)


@contextmanager
def lockstep_from(count: int):
    """Within the block, run batches in lockstep from ``count`` impacts per thread instead
    of ``LOCKSTEP_MIN``, to compare the two kernels (not thread-safe).

    Parameters
    ----------
    count : int
        Impacts per thread [-] from which a batch runs in lockstep: 0 for every batch, a
        huge number for none.
    """
    global LOCKSTEP_MIN
    saved, LOCKSTEP_MIN = LOCKSTEP_MIN, count
    try:
        yield
    finally:
        LOCKSTEP_MIN = saved


_BLAS = []  # the threadpoolctl controller, made once numpy's and scipy's BLAS are loaded


@contextmanager
def one_blas_thread():
    """Inside the block, BLAS runs on one thread: numpy's and scipy's (two libraries, scipy's
    loaded with :mod:`scipy.linalg`, which the frame's modes use, so imported here before
    the controller is made, or it would not be limited).  Its worker threads would compete
    with the kernel's for the cores; and a racket's caches (its modes, its static
    flexibility) computed on several BLAS threads differ in their last bits, e by up to
    1e-9: on one thread everywhere, a study gives the same bits wherever its parts run.
    """
    if not _BLAS:
        import scipy.linalg  # noqa: F401  (its BLAS, to be limited too)
        from threadpoolctl import ThreadpoolController

        _BLAS.append(ThreadpoolController())
    with _BLAS[0].limit(limits=1, user_api="blas"):
        yield


def run_rows(run, args, count: int) -> None:
    """Run ``run(*args, start, stop, step)`` (a compiled function that releases the GIL,
    e.g. :func:`ball.grip_kernel.grip_kernel`) over ``count`` rows on as many threads as they are
    worth (:data:`IMPACTS_PER_THREAD` each at least).

    Parameters
    ----------
    run : callable
        The function.
    args : tuple
        Its arguments before the slice.
    count : int
        Rows [-].
    """
    _run_on_threads(run, args, count, max(1, min(pool_size(), count // IMPACTS_PER_THREAD)))


def _run_on_threads(run, args, count: int, threads: int):
    """Run ``run(*args, start, stop, step)`` (a kernel, which releases the GIL) over the
    ``count`` impacts on ``threads`` threads (this one and ``threads - 1`` of the kernels'
    pool), thread t taking impacts t, t + T, t + 2T, ...: neighbouring impacts take about
    as long, so the threads finish together, each with one call.
    """
    if threads < 2:
        run(*args, 0, count, 1)
        return
    size = pool_size()
    pool = _POOL.get(size)
    if pool is None:
        pool = _POOL[size] = ThreadPoolExecutor(size - 1, "racket-impact-kernel")
    helpers = [pool.submit(run, *args, t, count, threads) for t in range(1, threads)]
    try:
        run(*args, 0, count, threads)  # this thread works too
    finally:
        wait(helpers)  # none still writes into the outputs when this returns or raises
    for done in helpers:
        done.result()  # re-raises an error of theirs


def pool_size() -> int:
    """Threads of the kernel's pool: numba's ``NUMBA_NUM_THREADS`` (the cores available, or
    the environment variable).
    """
    if not _CONFIG:
        from numba import config  # numba loads on first use (import time)

        _CONFIG.append(config)
    return max(1, _CONFIG[0].NUMBA_NUM_THREADS)


_CONFIG = []  # numba's config module, once imported


_POOL = {}
"""The kernel's thread pool (by its size, should ``NUMBA_NUM_THREADS`` change), made on first
use and kept (starting threads for each call cost about 1 ms); a forked child makes its own
(its parent's threads do not exist in it)."""

os.register_at_fork(after_in_child=_POOL.clear)


@contextmanager
def compile_notice(function, after: float = 1.0):
    """Say on stderr that ``function`` is being compiled (once per install: the compiled
    kernel is cached on disk) if its first call of this process takes more than ``after``
    seconds; loading the cached kernel takes well under a second.

    Parameters
    ----------
    function : numba dispatcher
        The kernel about to be called.
    after : float, optional
        Seconds [s] to wait before saying so.
    """
    if id(function) in _READY or getattr(function, "signatures", True):  # compiled / no JIT
        _READY.add(id(function))
        yield
        return
    timer = threading.Timer(
        after,
        lambda: print(
            f"racket-impact: compiling the solver (once, about {COMPILE_SECONDS:g} s)...",
            file=sys.stderr,
            flush=True,
        ),
    )
    timer.start()
    try:
        yield
    finally:
        timer.cancel()


_READY = set()  # ids of the kernels known to be compiled (or announced) in this process


def announced(functions) -> None:
    """Record that the compilation of ``functions`` (numba dispatchers) has been said (by the
    command line's watch, :mod:`studies.cli.notice`): :func:`compile_notice` stays silent.

    Parameters
    ----------
    functions : iterable of numba dispatchers
        The kernels whose compilation was announced.
    """
    _READY.update(id(f) for f in functions)
