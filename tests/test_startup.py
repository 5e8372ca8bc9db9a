"""Start-up: the command line imports what a command needs, and says before the first
run's wait that the solver is being compiled; ``paper`` puts off the garbage collector's full
collections while it runs."""

import os
import re
import subprocess
import sys

import pytest


def _python(code, **env):
    done = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, env={**os.environ, **env}
    )
    assert done.returncode == 0, done.stderr
    return done.stdout.strip()


def test_the_command_line_imports_no_pandas_numba_or_matplotlib_before_a_command():
    loaded = _python(
        "import sys, studies.cli; studies.cli.build_parser(); "
        "print(*[m for m in ('pandas', 'numba', 'matplotlib', 'scipy') if m in sys.modules])"
    )
    assert loaded == ""


def test_a_refused_command_imports_no_pandas():
    loaded = _python(
        "import sys, contextlib, io\n"
        "from studies.cli import main\n"
        "with contextlib.redirect_stderr(io.StringIO()):\n"
        "    assert main(['sweep', '--points', '0']) == 2\n"
        "print(*[m for m in ('pandas', 'numba', 'matplotlib') if m in sys.modules])"
    )
    assert loaded == ""


@pytest.mark.parametrize("empty", [True, False])
def test_a_cold_solver_is_told_apart_from_a_cached_one(empty, tmp_path):
    env = {"NUMBA_CACHE_DIR": str(tmp_path)} if empty else {}
    warm = (
        ""
        if empty
        # every kernel run (and cached) once: one impact, and a batch
        else (
            "import numpy as np; from racket import impact, paper_racket, paper_ball; "
            "impact(paper_racket(), paper_ball(), 0.1, 10.0); "
            "impact(paper_racket(), paper_ball(), np.linspace(0.0, 0.32, 200), 10.0); "
        )
    )
    cold = _python(
        warm + "from studies.cli.notice import _cold_kernels; print(len(_cold_kernels()))", **env
    )
    assert (int(cold) > 0) is empty


def test_a_refusal_on_a_cold_solver_says_one_line_and_no_notice(tmp_path):
    """An input refused once the solver's modules are imported (the string options check
    against the default racket) ends before anything compiles: one line, no "compiling"
    notice, however soon the watch looks (a fresh checkout's tests saw it)."""
    said = _python(
        "import contextlib, io, numba\n"
        "import studies.cli.notice as notice\n"
        "notice.EVERY = 1e-4\n"
        "from studies.cli import main\n"
        "err = io.StringIO()\n"
        "with contextlib.redirect_stderr(err):\n"
        "    assert main(['sweep', '--gauge', '0.00125']) == 2\n"
        "print(err.getvalue())",
        NUMBA_CACHE_DIR=str(tmp_path),
    )
    assert len(said.splitlines()) == 1 and "--gauge must be in" in said, said


def test_the_watch_waits_for_a_compilation_not_an_import():
    """:func:`studies.cli.notice._compiling`: a solver function that missed its cache (in
    a module of its own: this process's real kernels may have been compiled here)."""
    import types

    from studies.cli import notice

    def kernel():
        pass

    module = types.ModuleType("racket.solver.fake_kernel")
    kernel.__module__ = module.__name__
    kernel.stats = types.SimpleNamespace(cache_misses={})
    module.kernel = kernel
    modules = {module.__name__: module, "studies.fake": module}
    assert not notice._compiling(modules)
    kernel.stats.cache_misses["(float64,)"] = 1
    assert notice._compiling(modules)
    assert not notice._compiling({"studies.fake": module})  # the solver's modules alone


def test_paper_draws_the_same_figures_on_processes_of_their_own(tmp_path, monkeypatch, capsys):
    import studies.cli.paper as paper
    from studies.cli import main

    written = {}
    for idle, folder in ((-100.0, "pool"), (100.0, "here")):  # always, never worth it
        monkeypatch.setattr(paper, "IDLE_CORES", idle)
        assert main(["paper", "--out", str(tmp_path / folder)]) == 0
        written[folder] = {p.name: p.read_bytes() for p in (tmp_path / folder).glob("*.png")}
        out, err = capsys.readouterr()
        assert re.search(r"\b(\d+) of \1 claims reproduced", out)
        assert "compressed by" in err  # a figure's warning, said by the command
    assert len(written["pool"]) == 8
    assert written["pool"] == written["here"]


def test_paper_puts_off_full_collections_while_it_runs():
    import gc

    from studies.cli.paper import _no_full_collections

    before = gc.get_threshold()
    with _no_full_collections():
        assert gc.get_threshold()[:2] == before[:2]  # the young ones still made
        if len(before) > 2 and before[2]:  # (a generational collector's third threshold)
            assert gc.get_threshold()[2] == 2**31 - 1
    assert gc.get_threshold() == before
    with pytest.raises(RuntimeError), _no_full_collections():  # restored after an error too
        raise RuntimeError
    assert gc.get_threshold() == before
