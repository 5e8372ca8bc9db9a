"""The lockstep kernel (racket.solver.lockstep) against the scalar one
(racket.solver.kernel): the same numbers bit for bit, for every support, law, offset and
swing; and the batch switch (racket.solver.dispatch.run_kernel) choosing each of them."""

from dataclasses import replace
from functools import cache

import numpy as np
import pytest
from helpers import drawn_law, examples, run_uncompiled
from hypothesis import given, settings
from hypothesis import strategies as st

from ball import Ball
from ball.laws import GrowingHysteresis, LinearHysteresis, LinearSpring, PowerLawHysteresis, SineLaw
from ball.stiffening import StiffeningHysteresis
from racket import CATALOG, Hand, impact, paper_ball, paper_racket
from racket.solver import dispatch, kernel, layout, lockstep, one_blas_thread, tile_layout
from racket.solver.stepper import Stepper


@cache
def _racket(name):
    """Rackets of every support (built once: their modes take a while)."""
    face = CATALOG["pure-drive-2021"].racket()  # roll inertia modelled: offsets allowed
    return {
        "free": lambda: paper_racket(),
        "clamped": lambda: paper_racket("clamped-head"),
        "held": lambda: paper_racket("hand-held"),
        "held, hand's mass": lambda: replace(paper_racket("hand-held"), hand=Hand(mass=0.45)),
        "face free": lambda: face,
        "face held": lambda: replace(face, support="hand-held"),
        "face, rolling grip": lambda: replace(
            face, support="hand-held", hand=Hand(resists_twist=False)
        ),
    }[name]()


RACKETS = [
    "free",
    "clamped",
    "held",
    "held, hand's mass",
    "face free",
    "face held",
    "face, rolling grip",
]

LAWS = st.one_of(
    drawn_law(LinearHysteresis, (2e4, 8e4), (0.4, 0.95)),
    drawn_law(LinearSpring, (2e4, 8e4)),
    drawn_law(PowerLawHysteresis, (1e6, 4e6), (1.2, 1.8), (2.0, 4.0)),
    drawn_law(GrowingHysteresis, (5e5, 2e6), (1.2, 1.6), (0.7, 0.9), (0.0, 10.0)),
    drawn_law(StiffeningHysteresis, (2.5e4, 5e4), (0.025, 0.045), (0.7, 0.9), (0.0, 8.0)),
    drawn_law(SineLaw, (2e4, 6e4)),
)


def _bits(x):
    """An array's bytes: +0 and -0, and NaNs' payloads, told apart (np.array_equal does not)."""
    return np.ascontiguousarray(x).tobytes()


def _assert_same(a, b):
    for name, x, y in zip(a._fields, a, b, strict=True):
        assert np.asarray(x).shape == np.asarray(y).shape and _bits(x) == _bits(y), name


@settings(max_examples=examples(40), deadline=None)
@given(
    name=st.sampled_from(RACKETS),
    law=LAWS,
    mass=st.floats(0.03, 0.07),
    speed=st.floats(5.0, 40.0),
    count=st.integers(1, 40),
    spread=st.floats(0.0, 1.0),
    offset=st.floats(-1.0, 1.0),
    swing=st.sampled_from([0.0, 0.0, 8.0, 25.0]),
    pivot=st.sampled_from([None, 0.73]),
    steps=st.integers(50, 150),
    history=st.sampled_from([0, 0, 60]),
    x_o=st.floats(2e-3, 1.5e-2),
    stop_on_snap=st.booleans(),
    watch=st.sampled_from([0, 0, 25]),
)
def test_lockstep_equals_the_scalar_kernel_bit_for_bit(
    name, law, mass, speed, count, spread, offset, swing, pivot, steps, history, x_o,
    stop_on_snap, watch,
):  # fmt: skip
    racket = _racket(name)
    start, stop = racket.strings.extent
    middle = 0.5 * (start + stop)
    x = middle + spread * (np.linspace(start, stop, count) - middle)
    y = None
    if name.startswith("face"):  # within the bed's width near its middle
        x = middle + 0.6 * spread * (np.linspace(start, stop, count) - middle)
        y = np.full(count, 0.03 * offset)
    swing = swing if racket.support == "free" else 0.0
    stepper = Stepper(racket, Ball(mass, law), x, y, speed, swing, pivot, steps)
    x_o = np.full(count, x_o if stepper.code == layout.SINE else np.nan)
    runs = {}
    for which, threshold in (("scalar", 10**9), ("lockstep", 0)):
        with dispatch.lockstep_from(threshold):
            runs[which] = stepper.run(
                x_o, stop_on_snap=stop_on_snap, extra_steps=watch, history_steps=history
            )
    _assert_same(runs["scalar"], runs["lockstep"])


@pytest.mark.filterwarnings("ignore:.*self-consistent")
@pytest.mark.parametrize(
    "name, ball, count",
    [
        ("free", paper_ball(), 40),
        ("held, hand's mass", Ball(0.057, PowerLawHysteresis(2e6, 1.5, 3.0)), 40),
        ("face held", Ball(0.057, StiffeningHysteresis(3.75e4, 0.0335, 0.8, 7.3)), 40),
        ("free", Ball(0.057, SineLaw(4e4)), 40),  # the Xo search runs in lockstep too
        # several tiles (tile_layout.TILE = 64) and a ragged last one, with offsets
        ("face free", paper_ball(), 2 * tile_layout.TILE + 22),
        ("face held", paper_ball(), 2 * tile_layout.TILE + 22),
    ],
)
def test_whole_impacts_come_out_the_same(name, ball, count):
    racket = _racket(name)
    start, stop = racket.strings.extent
    x = np.linspace(start, stop, count)
    y = None
    if name.startswith("face"):  # within the bed's width near its middle
        x = np.linspace(0.8 * start + 0.2 * stop, 0.2 * start + 0.8 * stop, count)
        y = np.linspace(-0.02, 0.02, count)
    results = {}
    for which, threshold in (("scalar", 10**9), ("lockstep", 0)):
        with dispatch.lockstep_from(threshold):
            results[which] = impact(racket, ball, x, 20.0, offset=y)
    for name_, value in vars(results["scalar"]).items():
        if value is not None:
            other = getattr(results["lockstep"], name_)
            assert np.shape(value) == np.shape(other) and _bits(value) == _bits(other), name_


def test_the_batch_switch_chooses_each_kernel(monkeypatch):
    ran = []

    def spy(which, run):
        def call(*args):
            ran.append(which)
            return run(*args)

        return call

    monkeypatch.setattr(kernel, "run_impacts", spy("scalar", kernel.run_impacts))
    monkeypatch.setattr(lockstep, "run_lockstep", spy("lockstep", lockstep.run_lockstep))
    racket, ball = paper_racket(), paper_ball()
    impact(racket, ball, 0.1, 10.0)
    assert set(ran) == {"scalar"}
    ran.clear()
    many = 4 * dispatch.LOCKSTEP_MIN * dispatch.pool_size()
    impact(racket, ball, np.linspace(0.0, 0.32, many), 10.0)
    assert set(ran) == {"lockstep"}
    ran.clear()
    impact(racket, ball, np.linspace(0.0, 0.32, dispatch.LOCKSTEP_MIN - 1), 10.0)
    assert set(ran) == {"scalar"}


SCRIPT = """
import json
import numpy as np
from racket import impact, paper_ball, paper_racket
from racket.solver import dispatch, one_blas_thread
dispatch.LOCKSTEP_MIN = 0
with one_blas_thread():
    r = impact(paper_racket("hand-held"), paper_ball(), [0.02, 0.16, 0.3], 10.0,
               steps_per_contact=60)
print(json.dumps([*r.e.tolist(), *r.vibration_energy.tolist(), *r.contact_time.tolist()]))
"""


def test_the_lockstep_kernel_runs_uncompiled_with_the_same_numbers():
    """Both sides on one BLAS thread; modes cached earlier in the process on several BLAS
    threads may differ in their last bits (e by up to 1e-9, ``one_blas_thread``), which the
    tolerance allows (as tests/test_kernel_uncompiled.py): compilation would differ far more.
    """
    uncompiled = run_uncompiled(SCRIPT)
    with dispatch.lockstep_from(0), one_blas_thread():
        r = impact(paper_racket("hand-held"), paper_ball(), [0.02, 0.16, 0.3], 10.0,
                   steps_per_contact=60)  # fmt: skip
    compiled = [*r.e, *r.vibration_energy, *r.contact_time]
    assert np.allclose(compiled, uncompiled, rtol=1e-8, atol=0.0)
