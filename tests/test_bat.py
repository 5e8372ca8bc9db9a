"""Bats (issue 37): a beam struck on its own surface, free, pivoted as in the certification
rig or held, swung as a batter swings it.

Closed forms from the rigid-body collision, against the simulation of a bat stiff enough not
to vibrate: the pivoted bat's BBCOR from its collision efficiency (angular momentum about the
pivot), and the swung free bat's exit speed (N2000 eq. 16, Eq. 22's generalisation).
"""

import numpy as np
import pytest

from ball import Ball, PowerLawHysteresis, SineLaw
from bat import BATS, Bat, BatSwing
from bat import certification as cert
from bat.presets import (
    R161_DIAMETERS_MM,
    R161_LENGTH,
    WOOD_DENSITY,
    alloy_wall,
    r161_beam,
)
from racket import impact
from racket.solver.dispatch import lockstep_from

E0 = 0.5
"""Nathan's high-speed e0 (N2000 p. 986)."""

NATHAN = Ball(0.145, PowerLawHysteresis.with_cor(6.53e7, 1.84, E0), 0.0366)
"""Nathan's ball (k1, alpha: N2000 Fig. 2 caption; the mass an assumption, data/bats.md)."""

STIFF = 1e10
"""EI and kappa G A times this: the bending modes ring 1e5 times faster than the R161's,
far above a 1 ms contact (a bat that does not vibrate)."""

FINE = 3000
"""Time steps per contact for the closed-form comparisons (error about dt**2: 4e-7 here,
4e-5 at the default 300)."""


@pytest.fixture(scope="module")
def stiff_beam():
    return r161_beam(n_modes=4).stiffened(STIFF)


def test_the_r161_is_built_from_its_profile():
    """Mass and centre of mass of the 84 slices (data/bats.md 1.2: 0.8694 kg, 0.5609 m from
    the knob with slices centred at z - 0.5 cm) from the diameters, by the formula."""
    beam = r161_beam()
    d = 1e-3 * np.asarray(R161_DIAMETERS_MM)
    slices = WOOD_DENSITY * np.pi * d**2 / 4 * 0.01
    z = np.arange(d.size) * 0.01 + 0.005  # centres [m from the knob]
    assert beam.length == R161_LENGTH
    assert beam.mass == pytest.approx(slices.sum(), rel=1e-12)
    assert beam.length - beam.center_of_mass == pytest.approx(slices @ z / slices.sum(), rel=1e-12)
    assert beam.mass == pytest.approx(0.8694, abs=5e-5)


def test_the_pivoted_bbcor_is_the_closed_form_from_e_a(stiff_beam):
    """A rigid pivoted bat at rest: e (the relative speeds) equals e_A (1 + r) + r with
    r = m d**2 / I_pivot, to 1e-6 (the issue's target), at every position."""
    bat = Bat(stiff_beam, "pivoted")
    x = np.linspace(0.0, bat.pivot - 0.05, 9)
    r = impact(bat, NATHAN, x, 60.0, steps_per_contact=FINE)
    ratio = cert.mass_ratio(NATHAN.mass, bat.pivot - x, bat.inertia_pivot)
    assert np.abs(r.e - cert.bbcor(r.e_A, ratio)).max() < 1e-6
    assert np.abs(r.e - E0).max() < 1e-5  # and the rigid bat's e is the ball's e0
    assert np.abs(r.energy_residual / r.energy_initial).max() < 1e-8


def test_a_flexible_pivoted_bat_keeps_its_clamps_still_and_its_angular_momentum():
    """The rig's clamps (their mean deflection) do not move, during the contact or after,
    and angular momentum about the pivot is the ball's impulse's moment: I_pivot omega =
    m (v_in + v_out) d (the constraint's force acts at the pivot)."""
    from racket.feel import driven_motion

    bat = BATS["r161"]("pivoted")
    x = bat.beam.length - 0.68
    r = impact(bat, NATHAN, x, 40.0, histories=True)
    moment = NATHAN.mass * (40.0 + r.ball_rebound) * (bat.pivot - x)
    assert bat.inertia_pivot * r.omega == pytest.approx(moment, rel=1e-9)
    force = np.nan_to_num(r.force)
    motion = driven_motion(bat, x, force, r.t[1] - r.t[0])
    clamps = bat.beam.modes.shape(bat.clamps).mean(axis=1)
    assert np.abs(motion.q @ clamps).max() < 1e-12
    assert np.abs(motion.qd @ clamps).max() < 1e-10
    assert abs(r.energy_residual / r.energy_initial) < 1e-5


def test_a_swung_bat_that_does_not_vibrate_gives_the_rigid_exit_speed(stiff_beam):
    """N2000 eq. 16 with the bat's own R_0: v_f = (e0 - R0) / (1 + R0) v_ball + (1 + e0) /
    (1 + R0) v_bat, to 1e-6 at every position (Nathan's swing: 24 m/s, 51 rad/s)."""
    bat = Bat(stiff_beam)
    swing = BatSwing(51.0, cm_speed=24.0)
    x = np.linspace(0.0, bat.beam.length - 0.45, 12)
    kwargs = swing.impact_kwargs(bat, x)
    r = impact(bat, NATHAN, x, 40.0, steps_per_contact=FINE, **kwargs)
    beam = stiff_beam
    r0 = (
        NATHAN.mass / beam.mass * (1 + (x - beam.center_of_mass) ** 2 * beam.mass / beam.inertia_cm)
    )
    v_bat = kwargs["swing_speed"]
    rigid = (E0 - r0) / (1 + r0) * 40.0 + (1 + E0) / (1 + r0) * v_bat
    assert np.abs(r.ball_rebound / rigid - 1.0).max() < 1e-6


@pytest.mark.parametrize("support", ["free", "pivoted", "hand-held"])
def test_the_two_kernels_agree_bit_for_bit_on_a_bat(support):
    bat = BATS["r161"](support)
    x = np.linspace(0.02, 0.3, 40)
    with lockstep_from(0):
        fast = impact(bat, NATHAN, x, 40.0)
    with lockstep_from(10**9):
        slow = impact(bat, NATHAN, x, 40.0)
    for name in ("e", "e_A", "ball_rebound", "contact_time", "vibration_energy"):
        np.testing.assert_array_equal(getattr(fast, name), getattr(slow, name))


def test_the_free_bats_budget_closes_and_e_a_falls_off_the_sweet_spot():
    bat = BATS["r161"]()
    z = np.array([0.45, 0.6, 0.7, 0.83])  # from the knob [m]
    r = impact(bat, NATHAN, bat.beam.length - z, 40.0)
    assert np.abs(r.energy_residual / r.energy_initial).max() < 1e-5
    assert np.all((r.e > 0) & (r.e < 1))  # (above e0 near a node: the bat gives back)
    assert r.e_A[2] > max(r.e_A[0], r.e_A[3])  # the sweet zone beats handle and end


def test_a_thick_beams_rotary_inertia_counts_in_its_moment_of_inertia():
    beam = r161_beam()
    own = np.asarray(beam.rotary_inertia_per_length) @ np.diff(beam.stations)
    thin = r161_beam().__class__.__mro__[1].inertia_about(beam, 0.3)
    assert beam.inertia_about(0.3) == pytest.approx(thin + own, rel=1e-14)
    assert own > 0


def test_the_alloy_what_if_weighs_its_target():
    bat = BATS["alloy"]()
    assert bat.beam.mass == pytest.approx(0.850, rel=1e-9)
    assert 0.0 < alloy_wall() < 0.5e-3 * min(R161_DIAMETERS_MM)


@pytest.mark.parametrize(
    ("bat", "kwargs", "says"),
    [
        ("free", {"position": 0.9}, "position must be on the bat"),
        ("pivoted", {"position": 0.7}, "short of the clamps"),
        ("free", {"position": 0.2, "offset": 0.01}, "offset must be None for a bat"),
        ("hand-held", {"position": 0.2, "swing_speed": 10.0, "pivot": 0.75}, "hand-held bat"),
        ("pivoted", {"position": 0.2, "swing_speed": 10.0, "pivot": 0.75}, "turns about its"),
    ],
)
def test_a_bat_refuses_what_it_cannot_do(bat, kwargs, says):
    speed = kwargs.pop("speed", 40.0)
    with pytest.raises(ValueError, match=says):
        impact(BATS["r161"](bat), NATHAN, speed=speed, **kwargs)


def test_the_unhappy_ball_is_for_rackets():
    with pytest.raises(ValueError, match="for rackets"):
        impact(BATS["r161"](), Ball(0.0103, SineLaw(2e4)), 0.2, 5.0)


def test_a_bat_swing_names_one_of_its_two_ways():
    with pytest.raises(ValueError, match="one of cm_speed"):
        BatSwing(51.0, cm_speed=24.0, pivot_from_knob=0.1)
    bat = BATS["r161"]()
    swing = BatSwing(51.0, cm_speed=24.0)
    assert bat.beam.length - swing.pivot(bat) == pytest.approx(
        bat.beam.balance - 24.0 / 51.0, rel=1e-12
    )
    with pytest.raises(ValueError, match="beyond it"):
        swing.impact_kwargs(bat, bat.beam.length - 0.05)


def _nathan_discrete(diameters, dz, split):
    """Nathan's discrete bat (ACOR's symmetric form, data/bats.md 1.3), each slice cut into
    ``split``: frequencies [Hz] and slice positions [m from the knob] with the first four
    bending modes' deflections.  A link between slices takes their mean area and the
    harmonic mean of their I (Nathan's takes the knob-side slice's: first order in dz)."""
    from scipy.linalg import eigh

    from bat.presets import WOOD_DENSITY, WOOD_SHEAR_MODULUS, WOOD_YOUNGS_MODULUS

    d, dz = np.repeat(diameters, split), dz / split
    n = d.size
    area, second = np.pi * d**2 / 4, np.pi * d**4 / 64
    k = np.zeros((2 * n, 2 * n))
    shear = np.array([-1 / dz, 1 / dz, 0.5 / dz, 0.5 / dz])
    bend = np.array([-1 / dz**2, 1 / dz**2])
    for i in range(n - 1):  # strain energy of link i + 1/2: shear, then bending
        # each a rank-one term on the link's own degrees of freedom (the rest of the
        # outer product is zero): added as its 4x4 and 2x2 blocks
        sheared, bent = [i, i + 1, n + i, n + i + 1], [n + i, n + i + 1]
        a = 0.5 * (area[i] + area[i + 1])
        j = 2.0 / (1.0 / second[i] + 1.0 / second[i + 1])
        k[np.ix_(sheared, sheared)] += WOOD_SHEAR_MODULUS * a * dz * np.outer(shear, shear)
        k[np.ix_(bent, bent)] += WOOD_YOUNGS_MODULUS * j * dz * np.outer(bend, bend)
    mass = np.r_[WOOD_DENSITY * area * dz, WOOD_DENSITY * second / dz]
    w2, v = eigh(k, np.diag(mass), subset_by_index=[0, 5])
    return np.sqrt(w2[2:]) / (2 * np.pi), (np.arange(n) + 0.5) * dz, v[:n, 2:]


def test_the_r161_is_nathans_discrete_bat_converged():
    """Nathan's own equations, built here independently from the same inputs and refined
    (each 1-cm slice cut in 8), give the finite elements' first four frequencies to 1e-4 and
    their nodes to 2 mm: the same bat, the same way round."""
    beam = r161_beam(n_modes=4)
    f, z, shapes = _nathan_discrete(1e-3 * np.asarray(R161_DIAMETERS_MM), 0.01, 8)
    assert f == pytest.approx(beam.modes.frequencies, rel=1e-4)
    for mode in range(1, 5):
        s = shapes[:, mode - 1]
        cross = np.nonzero(np.sign(s[:-1]) != np.sign(s[1:]))[0]
        nodes = z[cross] - s[cross] * (z[cross + 1] - z[cross]) / (s[cross + 1] - s[cross])
        ours = np.sort(beam.length - beam.modes.nodes(mode))
        assert nodes == pytest.approx(ours, abs=2e-3)
