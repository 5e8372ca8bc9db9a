"""Collisions of linear and nonlinear hysteretic balls: Eq. 6, rigid-surface COR, energy."""

import numpy as np
import pytest

from ball import (
    WALL,
    Ball,
    LinearHysteresis,
    LinearSpring,
    PowerLawHysteresis,
    collide,
    series_cor,
)
from studies.tables import history_table

TENNIS = Ball(0.057, LinearHysteresis(k=4e4, e=0.75))


def test_tennis_ball_on_strings_matches_eq6():
    """An immovable lossless partner of 4e4 N/m: e = 0.88 (paper Sec. III)."""
    strings = Ball(1e12, LinearSpring(4e4))
    r = collide(TENNIS, strings, 10.0)
    assert r.e == pytest.approx(series_cor(0.75, 4e4, 4e4), abs=1e-3)
    assert r.e == pytest.approx(0.88, abs=0.005)


@pytest.mark.parametrize("e", [0.0, 0.3, 0.75, 1.0])
@pytest.mark.parametrize("speed", [1.0, 30.0])
def test_hysteretic_ball_on_wall_returns_its_own_e(e, speed):
    r = collide(Ball(0.057, LinearHysteresis(4e4, e)), WALL, speed)
    assert r.e == pytest.approx(e, abs=1e-9)
    # the wall is the limit of a partner of huge mass and stiffness
    block = collide(Ball(0.057, LinearHysteresis(4e4, e)), Ball(1e9, LinearSpring(1e14)), speed)
    assert r.v_a_after == pytest.approx(block.v_a_after, abs=1e-4 * speed)


@pytest.mark.parametrize("a,e", [(1.0, 0.5), (1.5, 0.75), (2.0, 0.9), (0.8, 0.6)])
def test_power_law_ball_on_wall_returns_its_own_e(a, e):
    law = PowerLawHysteresis.with_cor(k=1e6, a=a, e=e)
    assert law.rigid_cor == pytest.approx(e)
    r = collide(Ball(0.057, law), WALL, 20.0)
    assert r.e == pytest.approx(e, abs=1e-7)


def test_power_law_contact_shortens_with_speed():
    """A stiffening ball (a > 1) has a shorter contact at higher speed (paper Sec. III)."""
    ball = Ball(0.057, PowerLawHysteresis.with_cor(k=5e6, a=1.5, e=0.75))
    slow, fast = collide(ball, WALL, 5.0), collide(ball, WALL, 40.0)
    # Hertzian scaling: contact time ~ v**(-1/5).
    assert fast.contact_time / slow.contact_time == pytest.approx(8 ** (-0.2), rel=1e-3)


def test_elastic_pair_conserves_energy_and_lasts_half_a_period():
    a, b = Ball(0.0103, LinearSpring(3e4)), Ball(0.02, LinearSpring(5e4))
    r = collide(a, b, 3.0, -1.0)
    assert abs(r.energy_final - r.energy_initial) <= 1e-9 * r.energy_initial
    mu = a.mass * b.mass / (a.mass + b.mass)
    k = 1 / (1 / 3e4 + 1 / 5e4)
    assert r.contact_time == pytest.approx(np.pi * np.sqrt(mu / k), rel=1e-9)
    assert r.e == pytest.approx(1.0, abs=1e-9)


def test_two_lossy_balls_budget():
    a = Ball(0.05, LinearHysteresis(3e4, 0.6))
    b = Ball(0.08, PowerLawHysteresis.with_cor(2e6, 1.5, 0.8))
    r = collide(a, b, 5.0, -2.0)
    lost = r.energy_dissipated_a + r.energy_dissipated_b
    assert r.energy_lost == pytest.approx(lost, rel=1e-8)
    assert 0 < r.e < 1


def test_history_is_consistent():
    r = collide(TENNIS, Ball(0.2, LinearSpring(4e4)), 10.0)
    h = r.history
    assert h.t[0] == 0.0 and h.t[-1] == pytest.approx(r.contact_time)
    assert np.allclose(h.position_a - h.position_b, h.total_compression, atol=1e-12)
    assert np.max(h.force) == pytest.approx(r.peak_force)
    frame = history_table(h)
    assert list(frame.columns)[:2] == ["t_s", "force_N"] and len(frame) == h.t.size


@pytest.mark.parametrize("e_a, e_b", [(1e-6, 1e-4), (0.0, 1e-5), (1e-3, 1e-3), (0.01, 0.0)])
def test_nearly_vertical_unloading(e_a, e_b):
    """Tiny e: the contact opens within ~e**2 of the largest compression."""
    k_a, k_b = 5.9e5, 6.6e5
    a, b = Ball(0.9, LinearHysteresis(k_a, e_a)), Ball(0.088, LinearHysteresis(k_b, e_b))
    r = collide(a, b, 0.9, -21.5)
    # Energy returned / stored = e**2, with each ball's share of the stored energy.
    e2 = (e_a**2 / k_a + e_b**2 / k_b) / (1 / k_a + 1 / k_b)
    assert r.e == pytest.approx(np.sqrt(e2), rel=1e-6, abs=1e-9)
    assert r.energy_lost == pytest.approx(r.energy_dissipated_a + r.energy_dissipated_b, rel=1e-9)
