"""The tangential contact (ball.grip) against closed forms: a ball that slides throughout, one
that grips on a stiff spring and leaves rolling, the budget, the order of the stepping, and
nothing at all without a tangential speed or spin (issue 36)."""

import numpy as np
import pytest

from ball import BALL_PRESETS, DEFAULT_BALL, WALL, Ball, LinearHysteresis, LinearSpring, collide
from ball.grip import Layer, slide
from ball.spin import BallSpin

MASS = 0.057
DT = 1e-5
LAW = LinearHysteresis(3e4, 0.8)
"""The ball's own law (the histories' below): the tangential stiffness follows it."""


def _history(normal_speed, e=0.8, k=3e4, dt=DT):
    """The normal force [N] of a linear hysteretic ball on a wall, every ``dt`` [s], and
    its normal impulse [N s] (exact: m v (1 + e))."""
    c = collide(Ball(MASS, LinearHysteresis(k, e)), WALL, normal_speed, samples=4000)
    t = np.arange(0.0, c.history.t[-1] + 3 * dt, dt)
    return np.interp(t, c.history.t, c.history.force, right=0.0), MASS * normal_speed * (1 + e)


def test_a_ball_that_slides_throughout_changes_as_friction_times_the_normal_impulse():
    force, _ = _history(2.0)
    impulse = force.sum() * DT  # the sampled history's own impulse (trapezoid, ends zero)
    spin = BallSpin(offset_ratio=0.0)
    g = slide(force, DT, MASS, spin, 0.1, [5.0, 0.0], [0.0, 0.0, 0.0], law=LAW)
    assert g.slid_throughout[0]
    assert g.velocity[0, 0] == pytest.approx(5.0 - 0.1 * impulse / MASS, rel=1e-9)
    rolling = 0.1 * impulse * spin.radius / spin.inertia(MASS)
    assert g.spin[0, 1] == pytest.approx(rolling, rel=1e-9)
    assert g.spin[0, 0] == 0.0 and g.velocity[0, 1] == 0.0


def test_the_offset_adds_d_n_to_the_spin_of_a_sliding_ball():
    force, _ = _history(2.0)
    impulse = force.sum() * DT
    spin = BallSpin()
    g = slide(force, DT, MASS, spin, 0.1, [5.0, 0.0], [0.0, 0.0, 0.0], law=LAW)
    expected = (0.1 * spin.radius + spin.offset) * impulse / spin.inertia(MASS)
    assert g.spin[0, 1] == pytest.approx(expected, rel=1e-9)


def test_a_stiff_gripping_ball_leaves_rolling():
    force, _ = _history(3.0)
    spin = BallSpin(tangential_stiffness=1e8, offset_ratio=0.0)
    g = slide(force, DT, MASS, spin, 1.5, [2.0, 0.0], [0.0, 0.0, 0.0], substeps=16, law=LAW)
    # the rigid ball's rolling state: v = R w, with m v + I w / R kept about the contact
    rolling = 2.0 / (1.0 + spin.inertia(MASS) / (MASS * spin.radius**2))
    assert g.velocity[0, 0] == pytest.approx(rolling, rel=0.02)
    assert g.velocity[0, 0] == pytest.approx(spin.radius * g.spin[0, 1], rel=0.02)


ITF_LAW = BALL_PRESETS[DEFAULT_BALL].ball().law
"""A stiffening law: the tangential stiffness then changes with the force (issue 44)."""


@pytest.mark.parametrize("form", ["secant", "incremental"])
@pytest.mark.parametrize("law", [LAW, ITF_LAW], ids=["linear", "stiffening"])
@pytest.mark.parametrize("across", [0.0, 1.5])
@pytest.mark.parametrize("layer", [None, Layer(3e4, 1e-3, 0.1)])
def test_the_budget_closes_to_round_off(across, layer, law, form):
    """In + the stiffness's work = out + losses, in both forms of the patch's spring."""
    force, _ = _history(8.0)
    inv = np.array([[1 / 0.3 + 1.0, 0.5], [0.5, 1 / 0.3 + 3.0]])
    g = slide(force, DT, MASS, BallSpin(form=form), 0.45, [6.0, across], [10.0, -300.0, 50.0],
              inv_mass=inv, layer=layer, law=law)  # fmt: skip
    if law is ITF_LAW:
        assert g.stiffness_work[0] != 0.0  # the spring's stiffness changed with the force
    # round-off without the layer; with it, the layer's ringing at the end, (h k_l s)^2 /
    # 8 m_l, second order in the step (tests/test_oblique.py fits the order)
    assert abs(g.residual[0]) < (1e-12 if layer is None else 1e-7) * g.energy_in[0]
    assert g.slip_loss[0] > 0.0
    assert g.layer_loss[0] >= 0.0


def test_spin_about_the_normal_is_untouched_and_no_slip_means_nothing_happens():
    force, _ = _history(8.0)
    g = slide(force, DT, MASS, BallSpin(), 0.45, [0.0, 0.0], [0.0, 0.0, 70.0], law=LAW)
    assert np.all(g.velocity == 0.0) and np.all(g.spin[0, :2] == 0.0)
    assert g.spin[0, 2] == 70.0


@pytest.mark.parametrize("layer", [None, Layer(3e4, 1e-3, 0.1)])
def test_momentum_goes_to_the_surface(layer):
    force, _ = _history(8.0)
    g = slide(force, DT, MASS, BallSpin(), 0.45, [6.0, 1.0], [0.0, 0.0, 0.0],
              inv_mass=np.eye(2) / 0.3, layer=layer, law=LAW)  # fmt: skip
    lost = MASS * (g.velocity[0] - [6.0, 1.0]) + g.impulse[0]
    # what is missing is the layer's, still ringing on its spring when the ball has left
    ringing = 0.0 if layer is None else np.sqrt(2.0 * layer.mass * g.layer_energy[0])
    assert np.hypot(*lost) <= ringing + 1e-12


def test_the_outcome_converges_with_the_step():
    """Spin after against the step: the stick-slip switches are located to the step, so
    the error falls about as the step, not smoothly (nor always); 4 sub-steps of a 1e-5 s
    step are within 1e-3 of the converged change of spin.
    """
    spins = {}
    for dt, sub in ((1e-5, 4), (2e-6, 4), (5e-7, 4), (2.5e-7, 4)):
        force, _ = _history(6.0, dt=dt)
        g = slide(
            force, dt, MASS, BallSpin(), 0.6, [4.0, 0.0], [0.0, -100.0, 0.0], substeps=sub, law=LAW
        )
        spins[dt] = g.spin[0, 1]
    converged = spins[2.5e-7]
    change = abs(converged + 100.0)  # the spin's change [rad/s]
    assert abs(spins[5e-7] - converged) < 1e-4 * change
    assert abs(spins[1e-5] - converged) < 1e-3 * change
    assert abs(spins[2e-6] - converged) < 1e-3 * change


def test_bad_inputs_name_themselves():
    force, _ = _history(2.0)
    with pytest.raises(ValueError, match="friction must be in"):
        slide(force, DT, MASS, BallSpin(), 3.0, [1.0, 0.0], [0.0, 0.0, 0.0], law=LAW)
    with pytest.raises(ValueError, match="tangential_stiffness"):
        BallSpin(tangential_stiffness=10.0)


def test_the_tangential_stiffness_follows_the_balls_own_normal_stiffness():
    """Issue 44: k_t = kappa k_n(N), k_n the loading law's dF/dX at N, so the ratio stays fixed
    as the force grows (a stiffening ball: stiffer at a stroke's 850 N than at 100 N); a fixed
    stiffness stays fixed; without the law, a refusal that says what to give."""
    force = np.array([[0.0, 100.0, 850.0, 300.0, 0.0]])
    spin = BallSpin()
    k_t = spin.stiffness(ITF_LAW, force)
    k_n = 1.0 / ITF_LAW.compliance(force, force)
    pressed = force > 0.0
    assert np.allclose(k_t[pressed] / k_n[pressed], spin.stiffness_ratio, rtol=1e-12)
    assert k_t[0, 2] > 2.0 * k_t[0, 1]
    assert np.all(BallSpin(tangential_stiffness=5e4).stiffness(None, force) == 5e4)
    with pytest.raises(ValueError, match="needs the ball's law"):
        spin.stiffness(None, force)
    with pytest.raises(ValueError, match="form must be one of"):
        BallSpin(form="tangent")


@pytest.mark.parametrize("e", [0.5, 0.8, 0.95])
def test_the_dashpot_returns_the_balls_own_cor(e):
    """The patch's damping ratio is the one with which a spring-dashpot bouncing off a wall
    returns the ball's own COR: simulated, a half period of the damped oscillator."""
    from scipy.integrate import solve_ivp

    zeta = BallSpin().damping(LinearSpring(1.0) if e == 1.0 else LinearHysteresis(3e4, e))
    omega = 1.0
    sol = solve_ivp(lambda _t, s: [s[1], -(omega**2) * s[0] - 2 * zeta * omega * s[1]],
                    (0.0, 10.0), [0.0, 1.0], events=lambda _t, s: s[0] if _t > 0 else 1.0,
                    rtol=1e-12, atol=1e-14)  # fmt: skip
    assert -sol.y_events[0][0][1] == pytest.approx(e, rel=1e-6)  # back through 0, once


def test_the_substeps_need_a_stiffness():
    """A BallSpin whose stiffness follows the force has none of its own: stable_substeps
    says what to give instead of failing on None."""
    from ball.grip import stable_substeps

    with pytest.raises(ValueError, match="stiffness history"):
        stable_substeps(BallSpin(), MASS, DT)
    assert stable_substeps(BallSpin(), MASS, DT, stiffness=[0.0, 6e4]) >= 1


def test_each_family_of_strings_moves_only_across_its_own_length():
    """Issue 44: slip across the mains drives the mains, not the crosses: a purely across
    slip gives the same outcome bit for bit whatever the crosses' spring and mass, and
    another with the mains'; with the whole grip on the crosses (share 0), which lie across
    and are held there by the frame, it is a surface without a layer."""
    force, _ = _history(8.0)

    def across(layer):
        return slide(force, DT, MASS, BallSpin(), 0.45, [0.0, 6.0], [300.0, 0.0, 0.0],
                     layer=layer, law=LAW, substeps=8)  # fmt: skip

    base = across(Layer((3e4, 3e4), (1e-3, 1e-3), 0.1, 0.08, 20.0))
    crosses = across(Layer((9e4, 3e4), (5e-3, 1e-3), 0.1, 0.08, 20.0))
    mains = across(Layer((3e4, 9e4), (1e-3, 5e-3), 0.1, 0.08, 20.0))
    assert np.array_equal(base.spin, crosses.spin) and np.array_equal(
        base.velocity, crosses.velocity
    )
    assert not np.allclose(base.spin, mains.spin, rtol=1e-6, atol=0.0)
    assert np.all(base.velocity[:, 0] == 0.0) and np.all(base.spin[:, 1] == 0.0)
    bare = across(None)
    on_crosses = across(Layer(3e4, 1e-3, 0.1, share=0.0))
    assert np.allclose(on_crosses.spin, bare.spin, rtol=1e-12, atol=1e-9)
    assert on_crosses.layer_peak[0] == 0.0


def test_kinetic_friction_above_static_is_refused():
    force, _ = _history(2.0)
    with pytest.raises(ValueError, match="layer kinetic friction must be in"):
        slide(force, DT, MASS, BallSpin(), 0.45, [1.0, 0.0], [0.0, 0.0, 0.0],
              layer=Layer(3e4, 1e-3, 0.1, kinetic=0.2), law=LAW)  # fmt: skip
