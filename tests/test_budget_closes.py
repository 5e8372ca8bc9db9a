"""No impossible answer leaves the solver (issue 46): at any speed the commands accept, an
impact on every implement with every ball either closes its energy budget with e <= 1, or is
refused in one line saying up to what speed this racket and ball are answered."""

import functools
import re
import warnings

import numpy as np
import pytest
from helpers import examples
from hypothesis import given, settings
from hypothesis import strategies as st

import racket
from ball import BALL_PRESETS, BASEBALL_PRESETS
from bat import BATS
from common.checks import SPEED_RANGE
from racket.solver.closure import BUDGET_TOL, REFINE, REFINEMENTS

REFUSED = re.compile(
    r"^at [\d.]+ m/s \(the ball's speed plus the swing's\) the impact at [\d.]+ m from the tip "
    r"gives e = \S+ and does not settle even with \d+ times the steps.*; "
    r"racket-impact answers this racket and ball up to about ([\d.]+) m/s$"
)


@functools.cache
def implement(name):
    if name.startswith("bat "):
        return BATS[name[4:].split()[0]](name.split()[-1])
    if name == "paper":
        return racket.paper_racket()
    return racket.default_racket(name)


def balls(name):
    if name.startswith("bat "):
        return [p.ball() for p in BASEBALL_PRESETS.values()]
    return [p.ball() for p in BALL_PRESETS.values()] + [racket.paper_ball()]


IMPLEMENTS = ["free", "hand-held", "paper", "bat r161 free", "bat r161 pivoted", "bat alloy free"]


def check(result):
    e = np.atleast_1d(result.e)
    residual = np.abs(np.atleast_1d(result.energy_residual))
    assert np.all(e <= 1.0 + BUDGET_TOL), e
    assert np.all(residual <= BUDGET_TOL * np.atleast_1d(result.energy_initial)), residual


@settings(max_examples=examples(30), deadline=None)
@given(
    name=st.sampled_from(IMPLEMENTS),
    which=st.integers(0, 50),
    speed=st.floats(1.0, SPEED_RANGE[1]),
    along=st.floats(0.0, 1.0),
    across=st.floats(-1.0, 1.0),
)
def test_every_answer_closes_its_budget_or_is_refused(name, which, speed, along, across):
    body = implement(name)
    ball = balls(name)[which % len(balls(name))]
    position, offset = _point(body, along, across)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # squashed-ball and plausibility warnings
        try:
            result = racket.impact(body, ball, position, speed, offset=offset)
        except ValueError as err:
            refusal = REFUSED.match(str(err))
            assert refusal, str(err)
            assert "\n" not in str(err)
            assert float(refusal.group(1)) < speed
            return
    check(result)


def _point(body, along, across):
    """An impact point on ``body``: a fraction ``along`` of its hitting range, and for a
    racket ``across`` its half-width (0: on the axis)."""
    if isinstance(body, racket.Racket):
        low, high = body.strings.extent
        position = low + (0.05 + 0.9 * along) * (high - low)
        if body.beam.roll_inertia is None:
            return position, None
        half = 0.5 * body.strings.full_width * np.sqrt(max(1.0 - body.strings.rho2(position), 0))
        return position, across * 0.8 * half
    return 0.05 + along * 0.25, None


@pytest.mark.parametrize("speed", [120.0, 150.0])
def test_fast_impacts_are_stepped_finer_until_their_budget_closes(speed):
    """At 120 and 150 m/s the default step leaves the stiffening ball's peak unresolved (e
    off by 6e-3 and 1e-2 before issue 46, and far above 1 at 200 m/s); the answer now
    closes, and agrees with the one at 64 times the steps to 5e-3."""
    body, ball = racket.default_racket(), racket.default_ball()
    x = np.array([0.1, 0.16, 0.2])
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        result = racket.impact(body, ball, x, speed)
        fine = racket.impact(body, ball, x, speed, steps_per_contact=300 * 64)
    check(result)
    assert np.allclose(result.e, fine.e, atol=5e-3)


def test_beyond_its_limit_an_impact_is_refused_naming_the_limit():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        with pytest.raises(ValueError) as err:
            racket.impact(racket.default_racket(), racket.default_ball(), 0.16, 300.0)
        limit = float(REFUSED.match(str(err.value)).group(1))
        assert 150.0 < limit < 300.0
        check(racket.impact(racket.default_racket(), racket.default_ball(), 0.16, limit))


@pytest.mark.parametrize("name", ["free", "paper", "bat r161 free"])
def test_at_sixteen_times_the_steps_the_budget_closes_to_a_millionth(name):
    """The budget's residual is the integration error: at the accuracy reference (16 times
    the default steps) it is below 1e-6 of the energy in, at play speeds."""
    body = implement(name)
    for ball in balls(name)[:3]:
        for speed in (10.0, 40.0, 70.0):
            position, offset = _point(body, 0.5, 0.3)
            result = racket.impact(body, ball, position, speed, offset=offset,
                                   steps_per_contact=300 * REFINE**REFINEMENTS)  # fmt: skip
            assert abs(result.energy_residual) <= 1e-6 * result.energy_initial
            assert result.e <= 1.0


def test_the_command_line_refuses_in_the_unit_typed(capsys, workdir):
    from studies.cli import main

    assert main(["sweep", "--speed-mph", "600", "--points", "3"]) == 2
    said = capsys.readouterr().err.strip().splitlines()[-1]
    assert said.startswith("racket-impact sweep: error: at 600 mph (the ball's speed plus")
    assert re.search(r"answers this racket and ball up to about [\d.]+ mph$", said)


def test_one_impacts_check_is_the_arrays():
    # unclosed takes one impact in Python's numbers (no NaN warning to silence): the same
    # verdicts as on many, for each way an answer can break what a passive impact allows.
    from racket.solver.closure import STIFF_FRACTION, unclosed

    stiff = racket.default_ball()
    limit = stiff.law.x_lim * STIFF_FRACTION
    nan, edge = np.nan, 1.0 + BUDGET_TOL  # (each case's flaw alone; the last three on edges)
    e = [0.8, 1.0 + 2 * BUDGET_TOL, 0.8, 0.8, nan, 0.8, 0.8, 0.8, 0.8, edge, 0.8, 0.8]
    residual = [0.0, 0.0, 1e-3, -1e-3, 0.0, nan, 0.0, 0.0, 0.0, 0.0, -BUDGET_TOL, 0.0]
    fields = {
        "e": np.array(e),
        "energy_residual": np.array(residual),
        "energy_initial": np.array([1.0] * 7 + [nan] + [1.0] * 4),
        "compression": np.array([0.0] * 6 + [1.01 * limit, 0.0, nan, 0.0, 0.0, limit]),
    }
    for ball, squashed in ((stiff, True), (racket.paper_ball(), False)):  # (no limit: linear)
        many = unclosed(fields, ball)
        flags = [False, True, True, True, True, True, squashed, True, True, False, False, False]
        assert many.tolist() == flags
        for i in range(many.size):
            alone = unclosed({k: v[i : i + 1] for k, v in fields.items()}, ball)
            assert alone.dtype == bool and alone.tolist() == [many[i]]
