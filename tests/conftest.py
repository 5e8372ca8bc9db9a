"""Test configuration: hypothesis, and the solver compiled beside the first tests.

* No "explain" phase: it traces every line a failing example runs, which through solve_ivp
  turns a quick failure report into many minutes.
* On CI (``CI`` set) the examples are derandomized, so every CI run checks the same cases
  and a failure is reproducible; local runs draw new examples each time.
* The solver's kernel takes numba 12-15 s to compile on a fresh checkout (then it is cached
  on disk).  A second process compiles it while the modules that never run it
  (``SOLVER_FREE``) run first, on the other core; before the first test that may run it,
  this process waits for that one and loads the cached kernel, so that no test's captured
  output holds the one-off "compiling the solver" notice.  A module wrongly listed would
  only compile the kernel a second time, in this process, not fail.
"""

import os
import subprocess
import sys

import pytest
from hypothesis import Phase, settings

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
_COMPILER = {}  # the process compiling the kernel, while it may still run


def pytest_configure(config):
    """Start compiling (or loading) the kernel in a second process."""
    _COMPILER["process"] = subprocess.Popen(
        [sys.executable, "-c", _LOAD], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL
    )


def pytest_collection_modifyitems(items):
    """The modules that never run the kernel first (the sort keeps the order within)."""
    items.sort(key=lambda item: item.module.__name__.rpartition(".")[2] not in SOLVER_FREE)


def pytest_runtest_setup(item):
    """Before the first test that may run the kernel: wait for the second process, then load
    the kernel it cached."""
    if "process" in _COMPILER and item.module.__name__.rpartition(".")[2] not in SOLVER_FREE:
        _COMPILER.pop("process").wait()
        from racket.solver import load_kernel

        load_kernel()


def pytest_unconfigure(config):
    """Stop the second process if no test needed the kernel before the session ended."""
    process = _COMPILER.pop("process", None)
    if process is not None:
        process.terminate()
        process.wait()


@pytest.fixture
def workdir(tmp_path, monkeypatch):
    """An empty folder made the working directory (where the relative paths typed land)."""
    monkeypatch.chdir(tmp_path)
    return tmp_path
