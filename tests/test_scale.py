"""Scale-out: studies on a process pool and on a Dask cluster, bit-identical to a run in
this process (studies.scale)."""

import os
import pickle
import subprocess
import sys
from concurrent.futures import Executor, Future

import numpy as np
import pytest
from clihelpers import refusal

from ball import Ball, SineLaw
from racket import CATALOG, Swing, impact, paper_ball, paper_racket
from studies.face.maps import face_map
from studies.scale import (
    MIN_TASK_IMPACTS,
    TASK_IMPACTS,
    Impacts,
    _task,
    _tasks,
    check_scheduler,
    check_workers,
    executor_for,
    run_calls,
)
from studies.sweeps import compare, sweep
from studies.tables import impact_columns


class Recording(Executor):
    """Runs each task at once in this process, after a pickling round trip (as a worker
    would get it), and records what it was given."""

    def __init__(self):
        self.calls = []

    def submit(self, fn, *args, **kwargs):
        self.calls.append((fn.__name__, len(pickle.dumps(args))))
        fn, args = pickle.loads(pickle.dumps((fn, args)))
        future = Future()
        future.set_result(fn(*args, **kwargs))
        return future


def test_tasks_cover_every_point_once_in_order():
    racket, other = paper_racket(), paper_racket("clamped-head")
    counts = [3, 2 * TASK_IMPACTS + 5, 40, 7]
    calls = [
        Impacts(r, paper_ball(), np.arange(n, dtype=float), 10.0, np.arange(n) * 0.5, 1.0 + n)
        for r, n in zip([racket, other, racket, other], counts, strict=True)
    ]
    tasks, index = _tasks(calls)
    for call, pieces in zip(calls, index, strict=True):
        x = np.concatenate([tasks[t][k].position for t, k in pieces])
        assert np.array_equal(x, call.position)
        y = np.concatenate([tasks[t][k].offset for t, k in pieces])
        assert np.array_equal(y, call.offset)
    for task in tasks:
        assert sum(p.position.size for p in task) <= TASK_IMPACTS
        assert len({id(p.racket) for p in task}) == 1  # one racket's caches per task
    assert len(tasks) >= 4


def test_small_studies_are_cut_for_the_workers_too():
    calls = [Impacts(paper_racket(), paper_ball(), np.zeros(1000), 10.0)]
    tasks, _ = _tasks(calls)
    assert len(tasks) == -(-1000 // MIN_TASK_IMPACTS)


def test_a_racket_pickles_with_the_caches_it_has_computed():
    racket = CATALOG["pure-drive-2021"].racket()
    cold = len(pickle.dumps(racket))
    x, y = np.linspace(0.1, 0.2, 5), np.linspace(-0.02, 0.02, 5)
    first = impact_columns(impact(racket, paper_ball(), x, 20.0, offset=y))
    warm = pickle.loads(pickle.dumps(racket))
    assert len(pickle.dumps(racket)) > 5 * cold
    for name in ("system", "face_system"):
        assert name in warm.__dict__
    for name in ("modes", "_flexibility", "roll_modes"):
        assert name in warm.beam.__dict__
    again = impact_columns(impact(warm, paper_ball(), x, 20.0, offset=y))
    for name, values in first.items():
        assert np.array_equal(values, again[name], equal_nan=True), name


def test_a_racket_of_several_tasks_is_warmed_once_and_sent_warm():
    racket = paper_racket()
    x = np.linspace(0.0, 0.32, 3 * MIN_TASK_IMPACTS)
    serial = sweep(racket, paper_ball(), x, [10.0, 20.0], f1=[100.0, 130.0], progress=False)
    pool = Recording()
    parallel = sweep(racket, paper_ball(), x, [10.0, 20.0], f1=[100.0, 130.0], executor=pool)
    assert parallel.equals(serial)
    warmed = [size for name, size in pool.calls if name == "_warmed"]
    tasks = [size for name, size in pool.calls if name == "_task"]
    assert len(warmed) == 2  # one per f1 variant, each in several tasks
    assert len(tasks) >= 4
    assert min(tasks) > 10 * max(warmed)  # the tasks carry the caches the warm-up made


def test_the_tasks_warnings_are_said_here():
    unhappy = Ball(0.057, SineLaw(4e4))
    x = np.linspace(0.0, 0.32, 40)
    with pytest.warns(UserWarning, match="no self-consistent Xo"):
        serial = sweep(paper_racket(), unhappy, x, 10.0, progress=False)
    with pytest.warns(UserWarning, match="no self-consistent Xo"):
        parallel = sweep(paper_racket(), unhappy, x, 10.0, executor=Recording())
    assert parallel.equals(serial)


def _threads_in_a_worker():
    from numba import config

    _task(("k", 0), ("elsewhere", -1), impact_columns, [])
    return config.NUMBA_NUM_THREADS, os.environ["NUMBA_NUM_THREADS"]


def test_a_process_pool_is_bit_identical_and_one_thread_per_worker():
    racket = CATALOG["pure-drive-2021"].racket()
    x = np.linspace(0.08, 0.26, 300)
    kwargs = dict(offset=0.01, tension=[200.0, 260.0], progress=False)
    serial = sweep(racket, paper_ball(), x, [10.0, 25.0, 10.0], **kwargs)
    swing = Swing(30.0)
    rackets = {"paper": paper_racket(), "pure drive": racket}
    compared = compare(rackets, paper_ball(), 0.0, 200, swing=swing, equal_effort=True)
    face = face_map(racket, paper_ball(), swing=swing, grid=(21, 11))
    with executor_for(workers=2) as pool:
        assert pool.submit(_threads_in_a_worker).result() == (1, "1")
        parallel = sweep(racket, paper_ball(), x, [10.0, 25.0, 10.0], executor=pool, **kwargs)
        compared_parallel = compare(
            rackets, paper_ball(), 0.0, 200, swing=swing, equal_effort=True, executor=pool
        )
        face_parallel = face_map(racket, paper_ball(), swing=swing, grid=(21, 11), executor=pool)
    assert parallel.equals(serial)
    assert compared_parallel.equals(compared)
    for name, value in vars(face).items():
        if isinstance(value, np.ndarray):
            assert np.array_equal(value, getattr(face_parallel, name), equal_nan=True), name
        elif isinstance(value, float):
            assert value == getattr(face_parallel, name) or np.isnan(value), name


def test_a_dask_cluster_is_bit_identical_repeated_points_included():
    distributed = pytest.importorskip("distributed")
    racket = paper_racket()
    x = np.linspace(0.0, 0.32, 500)
    # The same grid point twice (speed 10 twice): with the client's default pure=True, equal
    # arguments would share one task; each task's own key keeps them apart.
    grid = dict(string_stiffness=[3e4, 4e4], swing=None, progress=False)
    serial = sweep(racket, paper_ball(), x, [10.0, 20.0, 10.0], **grid)
    with (
        distributed.LocalCluster(
            host="127.0.0.1", n_workers=2, threads_per_worker=1, processes=True,
            dashboard_address=None,
        ) as cluster,
        distributed.Client(cluster) as client,
    ):  # fmt: skip
        parallel = sweep(
            racket, paper_ball(), x, [10.0, 20.0, 10.0], executor=client.get_executor(), **grid
        )
        with executor_for(scheduler=cluster.scheduler_address) as dask:
            again = sweep(racket, paper_ball(), x, [10.0, 20.0, 10.0], executor=dask, **grid)
    assert parallel.equals(serial)
    assert again.equals(serial)


@pytest.mark.parametrize("workers", [0, -1, 2.5, True, "2", 10_000])
def test_bad_workers_are_refused(workers):
    with pytest.raises(ValueError, match="workers must be"):
        check_workers(workers)


@pytest.mark.parametrize(
    "address", ["", "localhost", "tcp://", "tcp://host:0", "http://host:8786", "host:99999"]
)
def test_bad_scheduler_addresses_are_refused(address):
    with pytest.raises(ValueError, match="scheduler must be a Dask scheduler's address"):
        check_scheduler(address)


@pytest.mark.parametrize("address", ["127.0.0.1:8786", "tcp://10.0.0.5:8786", "tls://h:1"])
def test_scheduler_addresses(address):
    assert check_scheduler(address) == address


def test_run_impacts_in_this_process_keeps_each_call_whole():
    calls = [Impacts(paper_racket(), paper_ball(), np.linspace(0.1, 0.2, n), 10.0) for n in (3, 5)]
    out = run_calls(calls, impact_columns)
    assert [part["e"].size for part in out] == [3, 5]


def _cli(*words):
    return subprocess.run(
        [sys.executable, "-m", "studies.cli", *words], capture_output=True, text=True
    )


def test_the_command_line_on_workers_prints_what_it_prints_alone(tmp_path):
    words = ["sweep", "--points", "300", "--speed", "10", "20"]
    alone = _cli(*words, "--out", str(tmp_path / "alone.csv"))
    pooled = _cli(*words, "--workers", "2", "--out", str(tmp_path / "pooled.csv"))
    assert alone.returncode == pooled.returncode == 0, pooled.stderr
    assert pooled.stdout == alone.stdout
    assert (tmp_path / "pooled.csv").read_text() == (tmp_path / "alone.csv").read_text()


@pytest.mark.parametrize(
    ("words", "message"),
    [
        (["--workers", "0"], "--workers must be in [1, 1024]"),
        (["--workers", "2", "--scheduler", "127.0.0.1:8786"], "not allowed with argument"),
        (["--scheduler", "nowhere"], "--scheduler must be a Dask scheduler's address"),
    ],
)
def test_the_command_line_refuses_bad_scale_options_in_one_line(words, message, tmp_path):
    # run in this process (as tests/test_bad_inputs.py runs its refusals): status 2, one
    # line, nothing on stdout, nothing written in tmp_path (no table, no sidecar)
    for command in ("sweep", "map", "compare"):
        out = tmp_path / f"{command}.csv"
        assert message in refusal([command, *words, "--out", str(out)], folder=tmp_path)
        assert not out.exists()


def test_the_command_line_on_a_dask_scheduler_prints_what_it_prints_alone(tmp_path):
    distributed = pytest.importorskip("distributed")
    words = ["compare", "--points", "150", "--speed", "20"]
    alone = _cli(*words, "--out", str(tmp_path / "alone.csv"))
    with distributed.LocalCluster(
        host="127.0.0.1", n_workers=2, threads_per_worker=1, processes=True,
        dashboard_address=None,
    ) as cluster:  # fmt: skip
        on_dask = _cli(*words, "--scheduler", cluster.scheduler_address,
                       "--out", str(tmp_path / "dask.csv"))  # fmt: skip
    assert alone.returncode == on_dask.returncode == 0, on_dask.stderr
    assert on_dask.stdout == alone.stdout
    assert (tmp_path / "dask.csv").read_text() == (tmp_path / "alone.csv").read_text()
    # its rerun, the cluster gone, runs here: the same table, a sidecar without the address
    (tmp_path / "dask.csv").unlink()
    again = _cli("rerun", str(tmp_path / "dask.csv.meta.json"))
    assert again.returncode == 0, again.stderr
    assert (tmp_path / "dask.csv").read_text() == (tmp_path / "alone.csv").read_text()
    assert "--scheduler" not in (tmp_path / "dask.csv.meta.json").read_text()


def test_a_scheduler_that_does_not_answer_is_refused_in_one_line():
    pytest.importorskip("distributed")
    import socket

    with socket.socket() as free:  # a port nothing listens on
        free.bind(("127.0.0.1", 0))
        port = free.getsockname()[1]
    with pytest.raises(ValueError, match=f"no Dask scheduler answers at 127.0.0.1:{port}") as err:
        with executor_for(scheduler=f"127.0.0.1:{port}", timeout=1.0):
            pass
    assert "\n" not in str(err.value)
