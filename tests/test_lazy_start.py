"""A light start (issue 47): ``import racket`` loads none of numpy, scipy, numba, pandas or
matplotlib; ``racket-impact sweep`` loads neither pandas, matplotlib nor the page, nor the
modules of the other commands, nor the oblique impact's and the stroke's; ``racket-impact
paper`` loads no pandas; ``python -m studies.cli`` runs as the console command; the packages
whose names load on first use (:mod:`common.lazy`) offer the same names as before, and their
source lists them alike for its readers; the sweep's CSV, written without pandas, is pandas'
own, byte for byte.
"""

import ast
import importlib
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from common.blas import BLAS_THREADS
from studies.cli.files import write_table
from studies.tables import frame

ROOT = Path(__file__).resolve().parent.parent
LAZY = ("racket", "ball", "beam", "racket.solver", "studies.cli")
"""The packages whose public names load on first use."""


def _loaded(code: str, *modules: str) -> set[str]:
    """Which of ``modules`` a fresh Python has loaded after running ``code`` (at its exit)."""
    probe = (
        "import atexit, sys\n"
        "atexit.register(lambda: print('loaded:', "
        f"*[m for m in {modules!r} if m in sys.modules]))\n"
        f"{code}\n"
    )
    done = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    return set(done.stdout.splitlines()[-1].split()[1:])


def test_import_racket_loads_nothing_heavy():
    heavy = ("numpy", "scipy", "numba", "pandas", "matplotlib")
    assert _loaded("import racket", *heavy) == set()


def test_a_sweep_loads_no_pandas_matplotlib_page_or_other_command(tmp_path):
    code = (
        "import sys\n"
        f"sys.argv = ['racket-impact', 'sweep', '--points', '3', '--out', {str(tmp_path)!r} + "
        "'/s.csv']\n"
        "from studies.entry import main\n"
        "assert main() == 0\n"
    )
    unwanted = ("pandas", "matplotlib", "shiny", "studies.page", "studies.cli.bat",
                "studies.cli.paper", "scipy.optimize", "racket.solver.oblique",
                "racket.stroke")  # fmt: skip
    assert _loaded(code, *unwanted, "numba") == {"numba"}  # (and it ran the kernel)
    assert (tmp_path / "s.csv").exists()


def test_paper_loads_no_pandas(tmp_path):
    code = (
        "import sys\n"
        f"sys.argv = ['racket-impact', 'paper', '--out', {str(tmp_path / 'figures')!r}]\n"
        "import studies.cli.paper\n"
        "studies.cli.paper.IDLE_CORES = 1e9  # the figures drawn here, where we look\n"
        "from studies.entry import main\n"
        "assert main() == 0\n"
    )
    assert _loaded(code, "pandas", "matplotlib") == {"matplotlib"}  # (and it drew the figures)
    assert len(list((tmp_path / "figures").glob("*.png"))) == 8


def test_python_m_runs_the_console_command():
    code = (
        "import atexit, gc, runpy, sys\n"
        "atexit.register(lambda: print('frozen:', gc.get_freeze_count() > 0))\n"
        "sys.argv = ['racket-impact', '--version']\n"
        "runpy.run_module('studies.cli', run_name='__main__')\n"
    )
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    assert done.stdout.startswith("racket-impact ")
    assert done.stdout.splitlines()[-1] == "frozen: True"  # studies.entry.main's exit


def test_python_m_runs_blas_on_one_thread_as_the_console_command():
    """``python -m studies.cli`` imports the package, and numpy with it, before the
    ``__main__`` that would set BLAS's threads: the package sets them itself while Python
    locates the module (``sys.argv[0]`` is "-m" then), unless the environment set them; an
    import by another program's ``python -m`` leaves them alone."""
    probe = (
        "import os, sys\n"
        "sys.argv[0] = '-m'  # as while python -m locates the module\n"
        "sys.orig_argv = [sys.executable, '-m', sys.argv[1]]\n"
        "import studies.cli, threadpoolctl\n"
        "print(os.environ.get('OPENBLAS_NUM_THREADS'), max(p['num_threads'] for p in\n"
        "      threadpoolctl.threadpool_info() if p['user_api'] == 'blas'))\n"
    )
    cores = len(os.sched_getaffinity(0))  # (OpenBLAS runs on at most as many threads)
    unset = {k: v for k, v in os.environ.items() if k not in BLAS_THREADS}
    cases = (
        ("studies.cli", None, ["1", "1"]),
        ("studies.cli", "2", ["2", str(min(2, cores))]),
        ("other.tool", None, ["None"]),
    )  # fmt: skip (another's: unset, any count)
    for module, given, printed in cases:
        env = unset if given is None else {**unset, "OPENBLAS_NUM_THREADS": given}
        done = subprocess.run([sys.executable, "-c", probe, module], capture_output=True,
                              text=True, env=env)  # fmt: skip
        assert done.returncode == 0, done.stderr
        assert done.stdout.split()[: len(printed)] == printed


def _lists(package: str) -> tuple[set, set, set, set]:
    """The names a lazy package's source gives: under ``if TYPE_CHECKING:``, to
    :func:`common.lazy.lazy_names`, in ``__all__``, and those it binds at once."""
    module = importlib.import_module(package)
    tree = ast.parse(Path(module.__file__).read_text())
    guarded, handed, listed, eager = set(), set(), set(), set()
    for node in tree.body:
        if isinstance(node, ast.If) and ast.unparse(node.test) == "TYPE_CHECKING":
            guarded |= {a.name for n in node.body for a in n.names}
        elif isinstance(node, ast.ImportFrom):
            eager |= {a.asname or a.name for a in node.names}
        elif isinstance(node, ast.FunctionDef | ast.ClassDef):
            eager.add(node.name)
        elif isinstance(node, ast.Assign):
            target, value = ast.unparse(node.targets[0]), node.value
            if target == "__all__":
                listed = set(ast.literal_eval(value))
            elif isinstance(value, ast.Call) and ast.unparse(value.func) == "lazy_names":
                by_module = ast.literal_eval(value.args[1])
                handed = {name for names in by_module.values() for name in names}
            else:
                eager.add(target)
    return guarded, handed, listed, eager


@pytest.mark.parametrize("package", LAZY)
def test_a_lazy_package_lists_its_names_alike_and_offers_them_all(package):
    guarded, handed, listed, eager = _lists(package)
    assert guarded == handed
    assert handed == listed - eager  # the rest bound at once (__version__, baseball, main)
    module = importlib.import_module(package)
    assert listed <= set(dir(module))
    for name in listed:
        assert getattr(module, name) is not None
    with pytest.raises(AttributeError, match="no attribute 'nonesuch'"):
        module.nonesuch  # noqa: B018


def test_a_lazy_package_still_offers_its_submodules_and_its_definers():
    import racket
    from racket.racket import Racket

    assert racket.Racket is Racket
    assert racket.specs.catalog.CATALOG is racket.CATALOG  # a submodule named, imported


def test_the_function_named_as_its_module_stays_the_function():
    code = "import ball.baseball\nfrom ball import baseball\nassert callable(baseball)"
    assert _loaded(code) == set()


def test_the_sweep_csv_written_without_pandas_is_pandas_own(tmp_path):
    words = np.array(["free", "hand-held", "a, quoted", "free"], dtype=object)
    columns = {
        "x_m": np.array([0.1, 1e-5, np.nan, 123456789.123]),
        "e": np.array([np.inf, -0.0, 0.5, 2.0 / 3.0]),
        "self_consistent": np.array([True, False, True, True]),
        "recontacts": np.array([0, 1, 2, 0]),
        "support": words,
    }
    write_table(columns, str(tmp_path / "mine.csv"))
    frame(columns).to_csv(tmp_path / "pandas.csv", index=False)
    assert (tmp_path / "mine.csv").read_bytes() == (tmp_path / "pandas.csv").read_bytes()
    table = frame(columns)
    assert isinstance(table["support"].dtype, pd.CategoricalDtype)
    assert list(table["support"].cat.categories) == ["free", "hand-held", "a, quoted"]
