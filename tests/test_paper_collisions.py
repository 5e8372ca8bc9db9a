"""The paper's unhappy-ball results (Figs. 2-4, Sec. VI) from the time integration."""

import numpy as np
import pytest

from ball import WALL, Ball, LinearSpring, SineLaw, collide, unhappy_cor

UNHAPPY = Ball(0.0103, SineLaw(k0=2e4))


def happy(k2, mass=0.0103):
    return Ball(mass, LinearSpring(k2))


def test_fig2_unhappy_ball_on_rigid_wall():
    r = collide(UNHAPPY, WALL, 4.0)
    assert abs(r.v_a_after) < 1e-3
    t_peak = r.history.t[np.argmax(r.history.force)]
    assert t_peak == pytest.approx(0.36e-3, abs=0.02e-3)
    f_o, x_o = r.peak_force, r.x_o
    assert f_o == pytest.approx(2e4 * x_o, rel=1e-9)  # Fo = k0 Xo
    assert r.energy_lost == pytest.approx(2 * f_o * x_o / np.pi, rel=1e-6)
    assert r.energy_lost == pytest.approx(r.energy_initial, rel=1e-6)
    # The ball's velocity falls monotonically to zero (paper, Sec. IV).
    assert np.all(np.diff(r.history.velocity_a) <= 1e-12)
    # The force follows Eq. 7 along the whole history.
    sine = UNHAPPY.law.force(r.history.compression_a, r.x_o)
    assert np.allclose(r.history.force, sine, atol=1e-9 * f_o)


def test_fig3_soft_happy_ball():
    r = collide(UNHAPPY, happy(2e4), 4.0)
    assert r.v_b_after == pytest.approx(3.034, abs=0.002)
    assert r.v_a_after == pytest.approx(0.966, abs=0.002)
    assert r.e == pytest.approx(0.517, abs=0.002)


def test_fig4_stiff_happy_ball():
    r = collide(UNHAPPY, happy(1e5), 4.0)
    assert 0.0 <= r.e <= 0.005
    assert r.v_a_after == pytest.approx(2.0, abs=0.01)
    assert r.v_b_after == pytest.approx(2.0, abs=0.01)


def test_centre_of_mass_frame_and_swapped_roles():
    cm = collide(UNHAPPY, happy(2e4), 2.0, -2.0)
    assert cm.energy_lost_fraction == pytest.approx(1 - cm.e**2, abs=1e-9)  # Eq. 4
    assert cm.v_a_after == pytest.approx(-1.034, abs=0.002)
    assert cm.v_b_after == pytest.approx(1.034, abs=0.002)
    swapped = collide(happy(2e4), UNHAPPY, 4.0)
    assert swapped.v_b_after == pytest.approx(3.034, abs=0.002)


@pytest.mark.parametrize("ratio", [0.05, 0.1, 0.3, 0.5, 1.0, 1.5, 2.0, 2.5, 3.0])
def test_cor_matches_eq16(ratio):
    r = collide(UNHAPPY, happy(ratio * 2e4), 4.0)
    assert r.e == pytest.approx(unhappy_cor(2e4, ratio * 2e4), abs=0.01)


@pytest.mark.parametrize("ratio", [3.2, 5.0, 20.0, 100.0])
def test_cor_never_negative_for_stiff_partner(ratio):
    r = collide(UNHAPPY, happy(ratio * 2e4), 4.0)
    assert 0.0 <= r.e < 1e-3


@pytest.mark.parametrize("ratio", [0.3, 1.0, 2.5, 5.0])
def test_cor_independent_of_masses_and_speed(ratio):
    ref = collide(UNHAPPY, happy(ratio * 2e4), 4.0).e
    for m1, m2 in [(0.0103, 0.00103), (0.00103, 0.0103), (0.103, 0.0103), (0.0103, 0.103)]:
        r = collide(Ball(m1, SineLaw(2e4)), happy(ratio * 2e4, m2), 4.0)
        assert r.e == pytest.approx(ref, abs=0.005)
    for speed in [0.5, 1.0, 10.0, 40.0]:
        assert collide(UNHAPPY, happy(ratio * 2e4), speed).e == pytest.approx(ref, abs=0.005)


@pytest.mark.parametrize("k2", [None, 2e4, 1e5])
def test_the_kept_figure_collisions_are_fresh_ones_and_read_only(k2):
    """``racket-impact paper`` computes Figs. 2-4's collisions once for its claims and its
    figures: each is the collision made afresh, and no reader can change its histories."""
    from studies.paper import figure_collision

    kept = figure_collision(k2)
    fresh = collide(UNHAPPY, WALL if k2 is None else happy(k2), 4.0)
    assert kept.e == fresh.e and kept.v_b_after == fresh.v_b_after
    assert np.array_equal(kept.history.force, fresh.history.force)
    with pytest.raises(ValueError, match="read-only"):
        kept.history.force[0] = 0.0


def test_the_kept_free_racket_is_the_papers():
    """``racket-impact paper``'s claims and figures share one free racket: the paper's,
    giving the impacts a racket made afresh gives."""
    from racket import impact, paper_ball, paper_racket
    from studies.paper import free_racket

    assert free_racket() is free_racket()
    kept, fresh = (
        impact(r, paper_ball(), [0.05, 0.2], 10.0) for r in [free_racket(), paper_racket()]
    )
    assert np.array_equal(kept.e, fresh.e) and np.array_equal(kept.peak_force, fresh.peak_force)
