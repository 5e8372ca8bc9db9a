"""The kernel's pieces: each law's kernel parameters and compiled formulas against the law
objects, the chunking of large calls, and the contact's opening placed within its step."""

import warnings

import numpy as np
import pytest

from ball import Ball
from ball.laws import GrowingHysteresis, LinearHysteresis, LinearSpring, PowerLawHysteresis, SineLaw
from ball.stiffening import StiffeningHysteresis
from racket import impact, paper_ball, paper_racket
from racket.solver import ball_kernel as kernel
from racket.solver import driver as solver

LAWS = [
    LinearSpring(4e4),
    LinearHysteresis(4e4, 0.75),
    PowerLawHysteresis(2e6, 1.5, 3.0),
    GrowingHysteresis(1e6, 1.4, 0.82, 8.0),
    StiffeningHysteresis(3.75e4, 0.0335, 0.8, 7.3),
]


@pytest.mark.parametrize("law", LAWS, ids=lambda law: type(law).__name__)
def test_kernel_formulas_agree_with_the_law_objects(law):
    # The compiled kernel's compression and force solve are the laws of ball/laws.py.
    code, params = law.kernel_law
    params = np.array(params, dtype=float)
    rng = np.random.default_rng(1)
    for f_max, frac in zip(rng.uniform(10, 3000, 50), rng.uniform(0, 1.2, 50), strict=True):
        f = frac * f_max
        peak = max(f, f_max)
        x = kernel.ball_compression(code, params, f, peak)
        assert x == pytest.approx(float(law.compression(f, peak)), rel=1e-12)
        # The force solve inverts g(F) + a F = z on the branch the ball is on.
        a = 2.5e-5
        coef = kernel.force_coefficients(code, params, a)
        z = x + a * f
        for guess in (0.0, f, 0.5 * f, 3.0 * peak):  # wherever Newton starts
            assert kernel.monotone_force(code, params, coef, a, z, peak, guess) == pytest.approx(
                f, rel=1e-9, abs=1e-9
            )


def test_every_law_names_its_kernel_code():
    codes = {type(law).__name__: law.kernel_law[0] for law in [*LAWS, SineLaw(2e4)]}
    assert len(set(codes.values())) == 5  # linear (two laws), power, sine, growing, stiffening
    assert codes["SineLaw"] not in (codes["LinearSpring"], codes["PowerLawHysteresis"])


def test_a_large_call_runs_in_chunks_with_the_same_results(monkeypatch):
    x = np.linspace(0.0, 0.32, 23)
    whole = impact(paper_racket(), paper_ball(), x, 10.0)
    monkeypatch.setattr(solver, "CHUNK_POINTS", 5)
    chunked = impact(paper_racket(), paper_ball(), x, 10.0)
    for name in ("e", "e_A", "contact_time", "vibration_energy", "energy_residual"):
        assert getattr(chunked, name) == pytest.approx(getattr(whole, name), rel=1e-13, abs=1e-15)


def test_unhappy_warning_is_said_once_for_all_chunks(monkeypatch):
    monkeypatch.setattr(solver, "CHUNK_POINTS", 4)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        impact(paper_racket(), Ball(0.057, SineLaw(4e4)), np.linspace(0.0, 0.02, 9), 10.0)
    said = [w for w in caught if "self-consistent" in str(w.message)]
    assert len(said) == 1


def test_contact_time_is_second_order_in_the_step():
    # The opening is placed within its step, so the contact time converges as dt**2 (it
    # was first order when the contact ended at a step's end).
    at = {
        n: impact(paper_racket(), paper_ball(), 0.1, 10.0, steps_per_contact=n).contact_time
        for n in (100, 200, 400, 6400)
    }
    errors = [abs(at[n] - at[6400]) for n in (100, 200, 400)]
    order = np.polyfit(np.log([1 / 100, 1 / 200, 1 / 400]), np.log(errors), 1)[0]
    print(f"\ncontact-time order: {order:.2f} (errors {errors})")
    assert order == pytest.approx(2.0, abs=0.2)
