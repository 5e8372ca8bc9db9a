"""The analytic solution (Eqs. 12-15) against Eqs. 8-11 and against the integration."""

import numpy as np
import pytest
from scipy.integrate import cumulative_simpson

from ball import Ball, LinearHysteresis, LinearSpring, SineLaw, collide, unhappy_solution
from ball.unhappy import _fold_phases, _Path, _work_phases

M1, M2, K0, V1 = 0.0103, 0.0207, 2e4, 4.0


@pytest.mark.parametrize("k2", [5e3, 2e4, 5e4])
def test_eqs_12_15_satisfy_eqs_8_11(k2):
    """For k2 < pi k0 the analytic solution satisfies the equations of motion exactly."""
    sol0 = unhappy_solution(0.0, M1, M2, K0, k2, V1)
    t = np.linspace(0, np.pi / sol0.omega, 2001)
    s = unhappy_solution(t, M1, M2, K0, k2, V1)
    dt = t[1] - t[0]
    acc_x = np.gradient(np.gradient(s.x, dt), dt)
    acc_y = np.gradient(np.gradient(s.y, dt), dt)
    inner = slice(5, -5)
    scale = s.f_o / M1
    assert np.allclose(acc_x[inner], -s.force[inner] / M1, atol=1e-4 * scale)  # Eq. 8
    assert np.allclose(acc_y[inner], s.force[inner] / M2, atol=1e-4 * scale)  # Eq. 9
    assert np.allclose(
        s.x - s.y, s.compression_unhappy + s.compression_happy, atol=1e-12
    )  # Eq. 10 with D = 0
    sine = K0 * s.x_o * np.sin(np.pi * s.compression_unhappy / s.x_o)
    assert np.allclose(s.force, sine) and np.allclose(s.force, k2 * s.compression_happy)  # 11
    assert np.gradient(s.x, dt)[0] == pytest.approx(V1, rel=1e-3)


@pytest.mark.parametrize("k2", [5e3, 2e4, 5e4])
def test_integration_reproduces_analytic_histories(k2):
    r = collide(Ball(M1, SineLaw(K0)), Ball(M2, LinearSpring(k2)), V1)
    s = unhappy_solution(r.history.t, M1, M2, K0, k2, V1)
    assert r.x_o == pytest.approx(s.x_o, rel=1e-9)
    assert r.contact_time == pytest.approx(np.pi / s.omega, rel=1e-6)
    assert np.allclose(r.history.force, s.force, atol=1e-5 * s.f_o)
    assert np.allclose(r.history.position_a, s.x, atol=1e-5 * s.x_o)
    assert np.allclose(r.history.position_b, s.y, atol=1e-5 * s.x_o)


@pytest.mark.parametrize("partner", [None, LinearSpring(2e4), LinearHysteresis(4e4, 0.75)])
def test_the_kept_phase_grids_give_the_fresh_grids_bits(partner):
    """The unhappy ball's phase grids are kept with their sines and cosines (the same grid
    for every Xo Brent's method tries): the path on a kept grid is the path on the bare
    phases, bit for bit, and a kept work grid is the one made afresh."""
    path = _Path(SineLaw(2e4), partner, 0.004)
    kept = _fold_phases()
    for on_kept, on_bare in zip(path.state(kept), path.state(kept.theta), strict=True):
        assert np.array_equal(on_kept, on_bare)
    fresh = _work_phases.__wrapped__(0.0, 0.9 * np.pi)
    assert np.array_equal(_work_phases(0.0, 0.9 * np.pi).theta, fresh.theta)
    assert path.work(0.0, 0.9 * np.pi) == float(
        cumulative_simpson(path.power(fresh.theta), x=fresh.theta)[-1]
    )
