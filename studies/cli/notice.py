"""The first run's notice: numba compiles the solver once per install (then loads it from
its on-disk cache), and the command line says so before that wait, not after it.

:func:`compile_watch` watches a command from a thread: as soon as numba begins to compile
any of the solver's functions (:func:`_compiling`) and any of its kernels has no fresh on-disk
cache, it says that the solver is being compiled (once), and
:func:`racket.solver.dispatch.compile_notice` stays silent.  A run refused for its input ends
before anything is compiled, and says one line.  (Numba
first compiles the block exponentials, :mod:`racket.solver.expm`, then the kernel, whose own notice
came only then: 7-22 s of silence, issue 28.)
"""

from __future__ import annotations

import contextlib
import importlib
import sys
import threading

EVERY = 0.1
"""How often the watch looks [s]."""

KERNELS = ("racket.solver.kernel", "racket.solver.lockstep", "racket.solver.budget")
"""The modules of the solver's compiled functions: the kernels that
:func:`racket.solver.dispatch.compile_notice` announces and the energy budget that reads their
results (all are compiled on a machine's first run of the solver)."""


def _cold_kernels() -> list:
    """The numba functions of the kernels' modules (:data:`KERNELS`) whose on-disk cache is
    missing or stale: numba compiles them, and all they call, on their first run (an
    unreadable cache counts as fresh: numba will say so itself).  A function inlined
    wherever it is called (``inline="always"``) is never compiled, or cached, on its own.
    """
    cold = []
    for name in KERNELS:
        module = importlib.import_module(name)
        for function in list(vars(module).values()):
            cache_file = getattr(getattr(function, "_cache", None), "_cache_file", None)
            if getattr(function, "__module__", None) != name or cache_file is None:
                continue
            if function.targetoptions.get("inline") == "always":
                continue
            if function.signatures:  # compiled already in this process
                continue
            try:
                fresh = bool(cache_file._load_index())
            except Exception:
                fresh = True
            if not fresh:
                cold.append(function)
    return cold


def _compiling(modules=None) -> bool:
    """Whether numba has begun to compile any of the solver's cached functions in this
    process: a first call that found no fresh on-disk cache counts a miss before it compiles
    (the dispatcher's ``stats.cache_misses``).  Not the solver's modules being imported: a
    run refused for its input may import them (the default racket's limits) and end before
    anything is compiled, and on a cold cache its one line then came with the notice.

    Parameters
    ----------
    modules : dict, optional
        Module name -> module to look in; default :data:`sys.modules`.
    """
    for name, module in list((sys.modules if modules is None else modules).items()):
        if not name.startswith("racket.solver.") or module is None:
            continue
        for function in list(vars(module).values()):
            stats = getattr(function, "stats", None)
            if getattr(function, "__module__", None) == name and getattr(
                stats, "cache_misses", None
            ):
                return True
    return False


def _watch(done: threading.Event) -> None:
    while not done.wait(EVERY):
        if "numba" not in sys.modules or not _compiling():
            continue
        from racket.solver import COMPILE_SECONDS, announced

        cold = _cold_kernels()
        if cold:
            print(
                f"racket-impact: compiling the solver (once, about {COMPILE_SECONDS:g} s)...",
                file=sys.stderr,
                flush=True,
            )
            announced(cold)  # said: the kernels' own notice is not
        return


@contextlib.contextmanager
def compile_watch():
    """Inside the block, say that the solver is being compiled as soon as it starts to be
    (see the module docstring).
    """
    done = threading.Event()
    watcher = threading.Thread(target=_watch, args=(done,), name="racket-impact-notice")
    watcher.daemon = True
    watcher.start()
    try:
        yield
    finally:
        done.set()
        watcher.join()
