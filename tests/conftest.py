"""Test configuration: hypothesis, and the solver compiled beside the first tests.

* No "explain" phase: it traces every line a failing example runs, which through solve_ivp
  turns a quick failure report into many minutes.
* On CI (``CI`` set) the examples are derandomized, so every CI run checks the same cases
  and a failure is reproducible; local runs draw new examples each time.
* The solver's kernel takes numba about a minute to compile on a fresh checkout (then it is cached
  on disk).  A second process compiles it while the modules that never run it
  (``SOLVER_FREE``) run first, on the other core; before the first test that may run it,
  this process waits for that one and loads the cached kernel, so that no test's captured
  output holds the one-off "compiling the solver" notice.  A module wrongly listed would
  only compile the kernel a second time, in this process, not fail.
* Under pytest-xdist (the README's command runs ``-n auto``, set in pyproject.toml) only the
  controller starts that second process; it writes a marker file when it ends, whether it
  compiled or failed, and each worker waits for the marker before its first test that may
  run the kernel.
* One BLAS thread in every process of the suite (``BLAS_THREADS``, set before numpy loads
  its BLAS, and inherited by the processes the tests start): the suite already runs one
  worker a core, beside the kernel's own threads, and OpenBLAS's idle threads spin while
  they wait, so that on a busy machine a racket's modes (a dense eigenproblem, built for
  every racket) took 30 times the CPU on two threads as on one.  One thread is also what
  the studies run on (:func:`racket.solver.one_blas_thread`): the same bits in every test.
* What several tests simulate alike is simulated once a process (a worker) and shared: the
  validation table of every comparison (``validation_rows``, and ``validation_once`` for
  ``racket-impact validate``) and a ball's rigid-wall bounce table (``bounce_once``, for
  ``racket-impact ball``).  A test that asks for them runs the command as before; only the
  simulation behind it is not repeated.
"""

import os
import subprocess
import sys
import tempfile
import time

import pytest
from hypothesis import Phase, settings

from common.blas import BLAS_THREADS

for _variable in BLAS_THREADS:  # (as the command line, common.blas; set whatever was set)
    os.environ[_variable] = "1"
if "numpy" in sys.modules:  # loaded before this file (by a plugin): limit it now
    from threadpoolctl import threadpool_limits

    threadpool_limits(limits=1, user_api="blas")

settings.register_profile(
    "racket-impact",
    phases=[Phase.explicit, Phase.reuse, Phase.generate, Phase.target, Phase.shrink],
    derandomize=bool(os.environ.get("CI")),
)
settings.load_profile("racket-impact")

SOLVER_FREE = {
    "test_string_options",
    "test_stringing",
    "test_ball_validation",
    "test_beam",
    "test_timoshenko",
    "test_bounce",
    "test_closed_forms",
    "test_collision_properties",
    "test_docstrings",
    "test_monotone_collisions",
    "test_paper_collisions",
    "test_unhappy_analytic",
}
"""Test modules that never run the racket solver's compiled kernel."""

_LOAD = "from racket.solver import load_kernel; load_kernel()"
_MARKER = "RACKET_IMPACT_KERNEL_MARKER"  # the file the second process writes when it ends
_COMPILER = {}  # the process compiling the kernel, while it may still run


def _worker(config) -> bool:
    return hasattr(config, "workerinput")


def pytest_configure(config):
    """Start compiling (or loading) the kernel in a second process (in xdist's controller
    only; its workers wait for the marker that process writes)."""
    if _worker(config):
        _COMPILER["marker"] = os.environ[_MARKER]
        return
    fd, marker = tempfile.mkstemp(prefix="racket-impact-kernel-")
    os.close(fd)
    os.remove(marker)
    os.environ[_MARKER] = marker  # the workers, started after this hook, inherit it
    _COMPILER["marker"] = marker
    code = f"try:\n    {_LOAD}\nfinally:\n    open({marker!r}, 'w').close()"
    _COMPILER["process"] = subprocess.Popen(
        [sys.executable, "-c", code], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL
    )


LONGEST = {
    "test_page_picture",
    "test_app",
    "test_scale",
    "test_startup",
    "test_scale_script",
}
"""Test modules holding the longest single tests or module fixtures (the page photographed and
driven in Chromium, a dask cluster, processes of their own: 15-65 s each on two busy cores),
begun right after :data:`SOLVER_FREE`: xdist's worksteal hands each worker a half of the list
and lets an idle one take the end of the other's, so one of these left near the end ran
alone while the other worker idled."""


def _order(item) -> int:
    name = item.module.__name__.rpartition(".")[2]
    return 0 if name in SOLVER_FREE else 1 if name in LONGEST else 2


def pytest_collection_modifyitems(items):
    """The modules that never run the kernel first, then the longest (the sort keeps the
    order within)."""
    items.sort(key=_order)


def pytest_runtest_setup(item):
    """Before the first test that may run the kernel: wait for the second process, then load
    the kernel it cached."""
    if "marker" in _COMPILER and item.module.__name__.rpartition(".")[2] not in SOLVER_FREE:
        marker = _COMPILER.pop("marker")
        process = _COMPILER.pop("process", None)
        if process is not None:
            process.wait()
        while not os.path.exists(marker):
            time.sleep(0.1)
        from racket.solver import load_kernel

        load_kernel()


def pytest_unconfigure(config):
    """Stop the second process if no test needed the kernel before the session ended, and
    remove its marker."""
    process = _COMPILER.pop("process", None)
    if process is not None:
        process.terminate()
        process.wait()
    if not _worker(config):
        marker = os.environ.pop(_MARKER, None)
        if marker is not None and os.path.exists(marker):
            os.remove(marker)


@pytest.fixture
def workdir(tmp_path, monkeypatch):
    """An empty folder made the working directory (where the relative paths typed land)."""
    monkeypatch.chdir(tmp_path)
    return tmp_path


@pytest.fixture(scope="session")
def validation_rows():
    """``studies.validation.validation_table()``, run once in this process (10-15 s of CPU):
    the modules that read it take a copy each (their ``table``), and :func:`validation_once`
    hands it to ``racket-impact validate``."""
    from studies.validation.table import validation_table  # not the name a test replaces

    return validation_table()


@pytest.fixture
def validation_once(monkeypatch, request):
    """``studies.validation.validation_table()`` (every comparison, what ``racket-impact
    validate`` prints) served from :func:`validation_rows`, a copy each call, run at the first
    such call; a call with its own comparisons still runs them."""
    import studies.validation as validation
    from studies.validation.table import validation_table

    def once(items=None):
        if items is None:
            return request.getfixturevalue("validation_rows").copy()
        return validation_table(items)

    monkeypatch.setattr(validation, "validation_table", once)


@pytest.fixture(scope="session")
def _bounce_tables():
    """The rigid-wall bounce tables this process has simulated, by ball and speeds."""
    return {}


@pytest.fixture
def bounce_once(monkeypatch, _bounce_tables):
    """``studies.bounce.rigid_bounce_table`` simulated once a process for each ball and
    speeds (``racket-impact ball``'s table: the default one, 10 impacts, takes 10 s of
    CPU), a copy each call; a ball that cannot be a key is simulated every time."""
    import numpy as np

    import studies.bounce as bounce

    simulate = bounce.rigid_bounce_table

    def once(ball, speeds=bounce.DEFAULT_SPEEDS):
        try:
            key = (ball, tuple(float(v) for v in np.atleast_1d(speeds)))
            table = _bounce_tables.get(key)
        except (TypeError, ValueError):  # no key: let the function say what is wrong
            return simulate(ball, speeds)
        if table is None:
            table = _bounce_tables[key] = simulate(ball, speeds)
        return table.copy()

    monkeypatch.setattr(bounce, "rigid_bounce_table", once)
