"""numba's on-disk cache of the solver is dropped when any of the solver's sources changes
(numba alone would keep a kernel whose callee in another file changed: issue 35 met it)."""

from pathlib import Path

import racket.solver
from racket.solver.cache_stamp import STAMP, cache_folders, drop_stale_cache, sources_digest


def _cached(cache: Path) -> list:
    return sorted(p.name for p in [*cache.glob("*.nbi"), *cache.glob("*.nbc")])


def test_the_cache_goes_when_a_source_changes_and_stays_when_none_does(tmp_path):
    (tmp_path / "kernel.py").write_text("def run(): return 1\n")
    (tmp_path / "callee.py").write_text("def f(): return 1\n")
    cache = tmp_path / "__pycache__"
    cache.mkdir()
    for name in ("kernel.run-1.py311.nbi", "kernel.run-1.py311.1.nbc"):
        (cache / name).write_bytes(b"machine code")
    assert drop_stale_cache(tmp_path)  # never stamped: dropped, then stamped
    assert _cached(cache) == [] and (cache / STAMP).read_text() == sources_digest(tmp_path)
    (cache / "kernel.run-1.py311.nbi").write_bytes(b"compiled again")
    assert not drop_stale_cache(tmp_path)  # nothing changed: kept
    assert _cached(cache) == ["kernel.run-1.py311.nbi"]
    (tmp_path / "callee.py").write_text("def f(): return 2\n")  # a callee, another file
    assert drop_stale_cache(tmp_path)
    assert _cached(cache) == []


def test_a_folder_that_cannot_be_written_is_left_as_it_is(tmp_path):
    (tmp_path / "kernel.py").write_text("x = 1\n")
    (tmp_path / "__pycache__").write_text("not a folder")  # the stamp cannot be written
    assert not drop_stale_cache(tmp_path)


def test_the_solver_is_stamped_when_it_is_imported():
    folder = Path(racket.solver.__file__).parent
    stamp = folder / "__pycache__" / STAMP
    assert stamp.read_text() == sources_digest(folder)


def test_a_cache_under_numba_cache_dir_is_stamped_and_dropped_too(tmp_path, monkeypatch):
    source = tmp_path / "src" / "solver"
    source.mkdir(parents=True)
    (source / "kernel.py").write_text("x = 1\n")
    monkeypatch.setenv("NUMBA_CACHE_DIR", str(tmp_path / "numba"))
    user = cache_folders(source)[1]
    assert user.is_relative_to(tmp_path / "numba") and user.parts[-2:] == ("src", "solver")
    user.mkdir(parents=True)
    (user / "kernel.f-1.py311.nbi").write_bytes(b"machine code")
    assert drop_stale_cache(source) and _cached(user) == []
    assert (user / STAMP).read_text() == sources_digest(source)
