"""BLAS on one thread in a process that has not yet loaded numpy: the command line's
(:mod:`studies.entry`, ``python -m studies.cli``) and the test suite's.

A racket's modes are a small dense eigenproblem, some 0.05 s on one thread.  OpenBLAS's idle
threads spin while they wait for a core, so that on a busy 2-core machine the same modes took
0.5-3.7 s on two threads (measured for issue 47 with a spec-sheet racket); the kernels run on
threads of their own.  On one thread everywhere a racket's caches come out the same to the
last bit wherever they are made (:func:`racket.solver.dispatch.one_blas_thread`).  A thread
count the user set in the environment is kept.
"""

from __future__ import annotations

import itertools
import os
import sys

BLAS_THREADS = ("OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS")
"""The variables that set BLAS's threads in this process and in those it starts."""


def one_blas_thread_unless_set() -> None:
    """Each of :data:`BLAS_THREADS` set to 1 where the environment does not set it (before
    numpy loads its BLAS; no effect after).
    """
    for variable in BLAS_THREADS:
        os.environ.setdefault(variable, "1")


def located_by_python_m(module: str) -> bool:
    """Whether ``python -m module`` is locating ``module`` (and importing its packages) now:
    ``sys.argv[0]`` is "-m" until the module runs (Python's documentation, "Command line and
    environment"), and ``sys.orig_argv`` names the module.

    Parameters
    ----------
    module : str
        The module's dotted name.
    """
    args = getattr(sys, "orig_argv", ())
    named = ("-m", module) in itertools.pairwise(args) or f"-m{module}" in args
    return sys.argv[:1] == ["-m"] and named
