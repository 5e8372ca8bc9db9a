"""The closed forms: the paper's worked numbers (Secs. III and VIII)."""

import pytest

from ball import (
    energy_loss_fraction,
    energy_loss_fraction_lab,
    series_cor,
    serve_speed,
    unhappy_cor,
)


def test_eq4():
    assert energy_loss_fraction(0.6) == pytest.approx(0.64)


def test_eq6_tennis_estimate():
    assert series_cor(0.75, 4e4, 4e4) == pytest.approx(0.88, abs=0.005)
    assert series_cor(0.0, 1.0, 1e-9) == pytest.approx(1.0, abs=1e-6)


def test_eq16():
    assert unhappy_cor(2e4, 2e4) == pytest.approx(0.517, abs=5e-4)
    assert unhappy_cor(1.0, 3.141592653589793) == pytest.approx(0.0, abs=1e-12)


def test_eq22_serve_numbers():
    m1 = 0.057
    # 0.75 * 1.86 = 1.395, which the paper quotes as 1.39.
    assert serve_speed(0.86, m1, 3 * m1, 1.0) == pytest.approx(1.39, abs=0.01)
    assert serve_speed(0.5, m1, 3 * m1, 1.0) == pytest.approx(1.12, abs=0.005)
    assert serve_speed(1.0, m1, 3 * m1, 1.0) == pytest.approx(1.5)
    reduction = 1 - serve_speed(0.5, m1, 3 * m1, 1) / serve_speed(0.86, m1, 3 * m1, 1)
    assert reduction == pytest.approx(0.19, abs=0.005)


def test_eq23_energy_fractions():
    m1 = 0.057
    assert energy_loss_fraction_lab(0.0, m1, 3 * m1, 0.0, 1.0) == pytest.approx(0.25)
    assert energy_loss_fraction_lab(0.0, m1, 3 * m1, 1.0, 1.0) == pytest.approx(0.75)
    # Reduces to Eq. 4 in the centre-of-mass frame (m1 v1 = m2 v2).
    assert energy_loss_fraction_lab(0.7, m1, 3 * m1, 3.0, 1.0) == pytest.approx(1 - 0.49)
