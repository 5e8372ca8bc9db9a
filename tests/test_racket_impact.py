"""Impacts on the flexible racket (paper Sec. VII): conservation, Eq. 21, convergence,
the rigid and clamped limits, and the paper's numbers for its default racket."""

import dataclasses

import numpy as np
import pytest

from ball import (
    Ball,
    LinearHysteresis,
    LinearSpring,
    PowerLawHysteresis,
    SineLaw,
    collide,
    series_cor,
    serve_speed,
    unhappy_cor,
)
from beam import Beam
from racket import Racket, StringBed, impact, paper_ball, paper_racket
from racket.solver import DEFAULT_STEPS_PER_CONTACT

BALL = paper_ball()
POSITIONS = np.linspace(0.0, 0.32, 17)


@pytest.fixture(scope="module")
def sweep():
    return impact(paper_racket(), BALL, np.linspace(0.0, 0.32, 321), 10.0)


def test_momentum_and_angular_momentum_conserved(sweep):
    r, beam, m1 = sweep, paper_racket().beam, BALL.mass
    p_after = m1 * -r.ball_rebound + beam.mass * r.v_cm
    assert p_after == pytest.approx(m1 * 10.0, rel=1e-9)
    arm = beam.center_of_mass - r.position  # lever arm of the ball about the centre of mass
    l_after = beam.inertia_cm * r.omega + arm * m1 * -r.ball_rebound
    assert l_after == pytest.approx(arm * m1 * 10.0, rel=1e-9, abs=1e-12)


def test_eq21_links_e_and_e_A(sweep):
    m1, m2 = BALL.mass, sweep.effective_mass
    assert sweep.e == pytest.approx(sweep.e_A + (1 + sweep.e_A) * m1 / m2, abs=1e-6)
    # the rigid body's point velocity from momentum alone: impulse / effective mass (Eq. 20)
    impulse = m1 * (10.0 + sweep.ball_rebound)
    assert sweep.point_velocity_dc == pytest.approx(impulse / m2, rel=1e-9)


def test_energy_budget_closes_without_damping():
    racket = Racket(Beam.uniform(0.68, 0.34, 120.0, damping=0.0), paper_racket().strings)
    levels = (600, 1200, 2400)
    residuals = [
        np.abs(
            impact(racket, BALL, POSITIONS, 10.0, steps_per_contact=n).energy_residual
            / 0.5
            / BALL.mass
            / 100
        ).max()
        for n in levels
    ]
    assert residuals[-1] < 1e-6
    order = -np.polyfit(np.log(levels), np.log(residuals), 1)[0]
    assert order == pytest.approx(2.0, abs=0.2)  # second order in the time step
    damped = impact(paper_racket(), BALL, POSITIONS, 10.0, steps_per_contact=2400)
    assert np.all(damped.damping_loss > 0)
    assert np.abs(damped.energy_residual / damped.energy_initial).max() < 1e-6


def test_default_is_within_2e5_of_a_64_mode_fine_step_solution_everywhere():
    # The default (12 modes with the static correction, 300 steps per contact) against 64
    # modes and 16x the steps, at every point of the paper racket's strings, free and held.
    x = np.linspace(0.0, 0.32, 65)
    for support in ("free", "hand-held"):
        fine = Racket(Beam.uniform(0.68, 0.34, 120.0, n_modes=64), paper_racket().strings, support)
        ref = impact(fine, BALL, x, 10.0, steps_per_contact=16 * DEFAULT_STEPS_PER_CONTACT)
        default = impact(paper_racket(support), BALL, x, 10.0)
        print(f"\n{support}: max |de| {np.abs(default.e - ref.e).max():.2e} against 64 modes")
        assert np.abs(default.e - ref.e).max() < 2e-5
        assert np.abs(default.e_A - ref.e_A).max() < 2e-5


def test_static_correction_leaves_4_modes_better_than_8_were_without_it():
    # Without the residual flexibility of the modes left out, the error in e falls as
    # n_modes**-4 and is 2.6e-4 at 8 modes; with it, 4 modes already do better than that.
    x = np.linspace(0.0, 0.32, 33)
    strings = paper_racket().strings
    ref = impact(Racket(Beam.uniform(0.68, 0.34, 120.0, n_modes=64), strings), BALL, x, 10.0)
    four = impact(Racket(Beam.uniform(0.68, 0.34, 120.0, n_modes=4), strings), BALL, x, 10.0)
    assert np.abs(four.e - ref.e).max() < 5e-5


def test_time_step_convergence_is_second_order():
    # The error in e against a 32x finer step, fitted over three step sizes (as scikit-fem
    # does), has slope 2 on a log-log plot (measured 2.01).
    steps = (150, 300, 600)
    e_at = {
        n: impact(paper_racket(), BALL, POSITIONS, 10.0, steps_per_contact=n).e
        for n in (*steps, 4800)
    }
    errors = [np.abs(e_at[n] - e_at[4800]).max() for n in steps]
    order = np.polyfit(np.log([1 / n for n in steps]), np.log(errors), 1)[0]
    print(f"\ntime-step order of e: {order:.2f} (errors {errors})")
    assert 1.8 < order < 2.2


def test_rigid_racket_gives_eq6_everywhere():
    rigid = Racket(Beam.uniform(0.68, 0.34, 2e5), paper_racket().strings)
    r = impact(rigid, BALL, POSITIONS, 10.0)
    assert r.e == pytest.approx(series_cor(0.75, 4e4, 4e4), abs=1e-3)
    assert r.vibration_energy.max() < 1e-5 * r.energy_initial[0]


def test_clamped_head_at_the_node_equals_the_free_racket():
    node = paper_racket().beam.modes.nodes(1)[0]
    free = impact(paper_racket(), BALL, node, 10.0)
    clamped = impact(paper_racket("clamped-head"), BALL, node, 10.0)
    assert clamped.e == pytest.approx(series_cor(0.75, 4e4, 4e4), abs=1e-4)
    assert clamped.e == pytest.approx(clamped.e_A)
    assert free.e == pytest.approx(clamped.e, abs=0.01)


def test_paper_numbers_for_the_default_racket(sweep):
    node = paper_racket().beam.modes.nodes(1)[0]
    i_max = int(np.argmax(sweep.e))
    assert abs(sweep.position[i_max] - node) < 0.01
    assert sweep.e[i_max] == pytest.approx(0.86, abs=0.03)
    at = lambda x: float(np.interp(x, sweep.position, sweep.e))  # noqa: E731
    assert at(0.01) == pytest.approx(0.54, abs=0.04)
    assert at(0.30) == pytest.approx(0.71, abs=0.03)
    # e_A peaks nearer the throat than e does (paper Sec. VII).
    assert sweep.position[np.argmax(sweep.e_A)] > sweep.position[i_max] + 0.02
    centre = paper_racket().strings.center
    m2 = float(np.interp(centre, sweep.position, sweep.effective_mass))
    assert m2 / BALL.mass == pytest.approx(3.0, abs=0.35)
    # Van Zandt's e counts vibration as rebound: it differs where vibration is excited.
    assert np.abs(sweep.e_van_zandt - sweep.e).max() > 0.01


def test_unhappy_ball_on_strings():
    u = Ball(0.057, SineLaw(k0=4e4))
    clamped = impact(paper_racket("clamped-head"), u, 0.15, 10.0)
    assert clamped.e == pytest.approx(unhappy_cor(4e4, 4e4), abs=1e-3)
    assert clamped.e == pytest.approx(0.517, abs=0.01)
    node = paper_racket().beam.modes.nodes(1)[0]
    free = impact(paper_racket(), u, node, 10.0)
    assert free.e == pytest.approx(clamped.e, abs=0.02)
    assert abs(free.energy_residual) < 1e-5 * free.energy_initial


def test_swung_racket_on_a_ball_at_rest_matches_eq22_in_translation():
    rest = impact(paper_racket(), BALL, 0.16, 10.0)
    swung = impact(paper_racket(), BALL, 0.16, 0.0, swing_speed=10.0)
    expected = serve_speed(rest.e, BALL.mass, rest.effective_mass, 10.0)
    assert swung.ball_rebound == pytest.approx(expected, rel=1e-6)
    assert swung.e_A == pytest.approx(rest.e_A, abs=1e-12)  # in the swing's frame
    pivoted = impact(paper_racket(), BALL, 0.16, 0.0, swing_speed=10.0, pivot=0.6)
    assert pivoted.e == pytest.approx(swung.e, abs=0.02)
    assert pivoted.ball_rebound > 10.0


def test_histories_split_dc_and_ac():
    r = impact(paper_racket(), BALL, 0.02, 10.0, histories=True)
    assert r.force.shape == r.t.shape
    assert np.nanmax(r.force) == pytest.approx(r.peak_force)
    ac = r.point_velocity_ac_history
    assert np.nanmax(np.abs(ac)) > 0.1  # an impact near the tip rings the frame
    assert r.point_velocity_dc_history[-1] == pytest.approx(r.point_velocity_dc)
    assert r.mode_energy.sum() == pytest.approx(r.vibration_energy)
    assert r.t.size == round(r.contact_time / r.t[1]) + 2  # sized to the steps used


def test_histories_only_on_demand_and_the_outcome_is_the_same():
    x = np.array([0.0, 0.16, 0.3])
    plain = impact(paper_racket(), BALL, x, 10.0)
    assert plain.force is None and plain.t is None and plain.point_velocity_ac_history is None
    recorded = impact(paper_racket(), BALL, x, 10.0, histories=True)
    assert np.array_equal(plain.e, recorded.e)
    assert recorded.force.shape == (3, recorded.t.size)


@pytest.mark.parametrize(
    "kwargs, needle",
    [
        (dict(position=0.40, speed=10.0), "position"),
        (dict(position=-0.01, speed=10.0), "position"),
        (dict(position=[0.1, np.nan], speed=10.0), "position"),
        (dict(position=0.1, speed=-3.0), "speed"),
        (dict(position=0.1, speed=0.0), "speed"),
        (dict(position=0.1, speed=np.nan), "speed"),
        (dict(position=0.1, speed=10.0, swing_speed=-1.0), "swing_speed"),
        (dict(position=0.1, speed=10.0, swing_speed=5.0, pivot=0.05), "pivot"),
        (dict(position=0.1, speed=10.0, steps_per_contact=10), "steps_per_contact"),
    ],
)
def test_bad_impact_input(kwargs, needle):
    with pytest.raises(ValueError, match=needle):
        impact(paper_racket(), BALL, **kwargs)


@pytest.mark.parametrize(
    "make, needle",
    [
        (lambda: StringBed(-4e4, (0.0, 0.32)), "stiffness"),
        (lambda: StringBed(4e4, (0.3, 0.1)), "extent"),
        (lambda: StringBed(4e4, (0.0, np.nan)), "extent"),
        (lambda: Racket(Beam.uniform(0.68, 0.34, 120), StringBed(4e4, (0, 0.9))), "extent"),
        (
            lambda: Racket(Beam.uniform(0.68, 0.34, 120), StringBed(4e4, (0, 0.3)), "held"),
            "support",
        ),
    ],
)
def test_bad_racket_input(make, needle):
    with pytest.raises(ValueError, match=needle):
        make()


def test_ball_law_with_clamped_swing_rejected():
    with pytest.raises(ValueError, match="swing_speed"):
        impact(paper_racket("clamped-head"), BALL, 0.1, 10.0, swing_speed=3.0)


def test_a_law_is_not_a_ball():
    with pytest.raises(ValueError, match="ball"):
        impact(paper_racket(), LinearHysteresis(4e4, 0.75), 0.1, 10.0)


@pytest.mark.parametrize(
    "law",
    [
        LinearHysteresis(4e4, 0.75),
        PowerLawHysteresis.with_cor(k=3e6, a=1.5, e=0.75),
        PowerLawHysteresis(k=1e5, a=1.0, b=1.0),
    ],
)
def test_clamped_head_equals_the_two_body_collision(law):
    """On the clamped head the ball meets immovable strings: ball.collide's problem."""
    ball = Ball(0.057, law)
    r = impact(paper_racket("clamped-head"), ball, 0.1, 20.0, steps_per_contact=2400)
    two_body = collide(ball, Ball(1e15, LinearSpring(4e4)), 20.0)
    assert r.e == pytest.approx(two_body.e, abs=1e-5)
    assert r.contact_time == pytest.approx(two_body.contact_time, rel=2e-3)
    assert r.peak_force == pytest.approx(two_body.peak_force, rel=1e-4)


def test_first_compilation_is_announced_on_stderr(capsys):
    import time
    from types import SimpleNamespace

    from racket.solver import driver as solver

    with solver._compile_notice(SimpleNamespace(signatures=[]), after=0.05):
        time.sleep(0.3)  # a compilation in progress
    assert "compiling the solver (once, about" in capsys.readouterr().err
    with solver._compile_notice(SimpleNamespace(signatures=["compiled"]), after=0.05):
        time.sleep(0.2)
    assert capsys.readouterr().err == ""


@pytest.mark.parametrize("threads", [2, 3])
def test_threads_share_the_points_and_change_no_number(monkeypatch, threads):
    # T threads take points t, t + T, ... (racket.solver.dispatch._run_on_threads): every point
    # once, each with the same numbers as on one thread.
    from numba import config

    x = np.linspace(0.0, 0.32, 53)
    monkeypatch.setattr(config, "NUMBA_NUM_THREADS", 1)
    one = impact(paper_racket("hand-held"), paper_ball(), x, 20.0)
    monkeypatch.setattr(config, "NUMBA_NUM_THREADS", threads)
    many = impact(paper_racket("hand-held"), paper_ball(), x, 20.0)
    for name in ("e", "e_A", "contact_time", "peak_force", "vibration_energy"):
        assert np.array_equal(getattr(one, name), getattr(many, name)), name


@pytest.mark.parametrize("support", ["free", "hand-held", "clamped-head"])
def test_one_position_is_its_one_element_array_bit_for_bit(support):
    # A number takes its own route through impact (its checks and its set-up in Python's
    # numbers where they give numpy's bits): every field must be the array's, as a number.
    racket = paper_racket(support)
    for position in (0.003, 0.16, 0.3):
        one, array = impact(racket, BALL, position, 10.0), impact(racket, BALL, [position], 10.0)
        for name in (f.name for f in dataclasses.fields(one)):
            number, values = getattr(one, name), getattr(array, name)
            if values is None or name == "speed":
                assert number == values, name
            else:
                assert np.ndim(number) == np.ndim(values) - 1, name
                assert np.array_equal(number, values[0], equal_nan=True), name
