"""Sweeps, serve what-ifs and the paper table."""

import numpy as np
import pytest

from beam.beam import DEFAULT_MODES
from racket import impact, paper_ball, paper_racket
from studies.paper import paper_table
from studies.serve import serve_table, serve_what_if
from studies.sweeps import COLUMNS, sweep


def test_sweep_columns_and_values_match_impact():
    x = np.linspace(0.0, 0.32, 11)
    table = sweep(paper_racket(), paper_ball(), x, 10.0, progress=False)
    assert list(table.columns) == list(COLUMNS)
    direct = impact(paper_racket(), paper_ball(), x, 10.0)
    assert table["e"].to_numpy() == pytest.approx(direct.e)
    assert table["position_from_tip_m"].to_numpy() == pytest.approx(x)


def test_sweep_grid_adds_one_column_per_varying_parameter():
    table = sweep(
        paper_racket(),
        {"normal": paper_ball()},
        np.linspace(0.05, 0.3, 4),
        speed=[10.0, 30.0],
        string_stiffness=[3e4, 5e4],
        f1=[100.0, 150.0],
        progress=False,
    )
    assert len(table) == 4 * 2 * 2 * 2
    assert list(table.columns[len(COLUMNS) :]) == ["speed_m_s", "string_stiffness_N_m", "f1_Hz"]
    assert set(table["f1_Hz"].round(6)) == {100.0, 150.0}
    # Softer strings lose less in the ball (paper, Sec. IX): higher e near the node.
    near_node = table[np.isclose(table.position_from_tip_m, 0.05 + 0.25 / 3)]
    e_by_k = near_node.groupby("string_stiffness_N_m")["e"].mean()
    assert e_by_k.loc[3e4] > e_by_k.loc[5e4]


def test_with_f1_scales_frequencies_and_keeps_shapes():
    beam = paper_racket().beam
    stiff = beam.with_f1(180.0)
    assert stiff.modes.frequencies[0] == pytest.approx(180.0)
    assert stiff.modes.frequencies[1] / stiff.modes.frequencies[0] == pytest.approx(
        beam.modes.frequencies[1] / beam.modes.frequencies[0]
    )


def test_serve_two_ways_and_paper_numbers():
    table = serve_table(paper_racket(), paper_ball(), racket_speed=40.0)
    # The dc collision depends only on the relative motion: Eq. 22 with the simulated e and
    # m2 is the swung racket's answer.
    assert table["serve_simulated_m_s"].to_numpy() == pytest.approx(
        table["serve_eq22_m_s"].to_numpy(), rel=1e-6
    )
    assert table.loc["normal", "ratio_simulated"] == pytest.approx(1.39, abs=0.07)
    assert table.loc["zero-COR", "ratio_simulated"] == pytest.approx(1.12, abs=0.07)
    assert table.loc["zero-COR", "reduction_simulated_percent"] == pytest.approx(19, abs=4)


def test_serve_what_if_stiffer_strings_cost_more():
    table = serve_what_if(
        paper_racket(), paper_ball(), string_stiffness=[2e4, 4e4, 8e4], ball_stiffness=[3e4, 6e4]
    )
    strings = table[table.varied == "strings"]["reduction_simulated_percent"]
    assert np.all(np.diff(strings.to_numpy()) > 0)  # paper: higher tension, larger reduction
    balls = table[table.varied == "ball"]["reduction_simulated_percent"]
    assert np.all(np.diff(balls.to_numpy()) < 0)


def test_every_paper_claim_within_tolerance():
    table = paper_table()
    assert len(table) >= 20
    failed = table[~table["ok"]]
    assert failed.empty, failed.to_string()


def test_sweep_on_a_process_pool_matches_the_serial_sweep(monkeypatch):
    import multiprocessing
    import pickle
    from concurrent.futures import ProcessPoolExecutor

    from numba import config

    monkeypatch.setattr(config, "NUMBA_NUM_THREADS", 2)  # threads even on a one-core runner

    racket = paper_racket()
    assert racket.beam.modes.count == 2 + DEFAULT_MODES  # computed modes travel with the racket
    assert pickle.loads(pickle.dumps(racket)).beam.modes.frequencies[0] == pytest.approx(120.0)
    # 40 points: the serial sweep runs the kernel on threads before the pool forks.
    x = np.linspace(0.0, 0.32, 40)
    kwargs = dict(f1=[120.0, 150.0], string_stiffness=[3e4, 4e4], progress=False)
    serial = sweep(racket, paper_ball(), x, [10.0, 20.0], **kwargs)
    # "fork" (Linux's default before Python 3.14): the kernel's threads end with each call,
    # so a forked worker starts clean (numba's own parallel threads did not survive a fork).
    fork = multiprocessing.get_context("fork")
    with ProcessPoolExecutor(max_workers=2, mp_context=fork) as pool:
        parallel = sweep(racket, paper_ball(), x, [10.0, 20.0], executor=pool, **kwargs)
    assert parallel.equals(serial)
