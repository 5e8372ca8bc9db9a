"""Free-free beam: analytic modes, finite elements, mass properties, Eq. 20."""

import numpy as np
import pytest

from beam import Beam

BETA_L = [4.7300408, 7.8532046, 10.9956078, 14.1371655, 17.2787597]


@pytest.fixture(scope="module")
def uniform():
    return Beam.uniform(length=0.68, mass=0.34, f1=120.0)


def test_uniform_frequencies_follow_the_free_free_roots(uniform):
    f = uniform.modes.frequencies
    assert f[0] == pytest.approx(120.0, rel=1e-12)
    assert f[:5] / f[0] == pytest.approx((np.array(BETA_L) / BETA_L[0]) ** 2, rel=1e-7)


def test_analytic_shapes_are_mass_normalised_and_orthogonal(uniform):
    x = np.linspace(0, uniform.length, 20001)
    phi = uniform.modes.shape(x)
    rho = uniform.mass / uniform.length
    gram = rho * np.trapezoid(phi[:, None, :] * phi[None, :, :], x, axis=-1)
    assert gram == pytest.approx(np.eye(phi.shape[0]), abs=1e-6)


def test_analytic_shapes_satisfy_the_beam_equation(uniform):
    """EI phi'''' = rho omega**2 phi inside, phi'' = phi''' = 0 at the free ends."""
    modes = uniform.modes
    rho, ei = uniform.mass_per_length[0], uniform.bending_stiffness[0]
    h = 1e-3
    x = np.linspace(0.1, 0.58, 7)
    phi = lambda s: modes.shape(s)[2:5]  # noqa: E731
    d4 = (phi(x - 2 * h) - 4 * phi(x - h) + 6 * phi(x) - 4 * phi(x + h) + phi(x + 2 * h)) / h**4
    expected = rho * modes.omega[2:5, None] ** 2 / ei * phi(x)
    assert d4 == pytest.approx(expected, rel=1e-3, abs=1e-3 * np.abs(expected).max())
    ends = np.array([0.0, uniform.length])
    inside = np.array([h, uniform.length - h])
    curvature = (phi(ends + np.array([2 * h, -2 * h])) - 2 * phi(inside) + phi(ends)) / h**2
    assert np.abs(curvature).max() < 1e-3 * np.abs(d4).max() * h


def test_fem_matches_analytic_on_a_uniform_profile(uniform):
    fem = uniform.compute_modes("fem")
    exact = uniform.modes
    # 1e-8 on the fundamental (the eigen-solver's round-off), 2e-8 on the fifth (h**4).
    assert fem.frequencies[:5] == pytest.approx(exact.frequencies[:5], rel=5e-8)
    x = np.linspace(0, uniform.length, 41)
    assert fem.shape(x)[:7] == pytest.approx(exact.shape(x)[:7], abs=1e-4)


def test_fem_converges_with_mesh():
    beam = Beam((0.0, 0.3, 0.5, 0.68), (0.7, 0.3, 0.45), (60.0, 120.0, 80.0), n_modes=4)
    f = [
        Beam(
            beam.stations, beam.mass_per_length, beam.bending_stiffness, n_modes=4, elements=n
        ).modes.frequencies
        for n in (30, 60, 120)
    ]
    err1, err2 = np.abs(f[0] - f[2]), np.abs(f[1] - f[2])
    assert np.all(err2[1:] < err1[1:] / 8)  # cubic Hermite: h**4 convergence
    # The order, fitted over three meshes against a much finer one (as scikit-fem does), on
    # modes 3 and 4 (modes 1 and 2 reach the eigen-solver's round-off too early to fit).
    levels = (20, 40, 80)
    ref = Beam(
        beam.stations, beam.mass_per_length, beam.bending_stiffness, n_modes=4, elements=960
    ).modes.frequencies
    coarse = [
        Beam(
            beam.stations, beam.mass_per_length, beam.bending_stiffness, n_modes=4, elements=n
        ).modes.frequencies
        for n in levels
    ]
    errors = np.abs(np.array(coarse) - ref)[:, 2:]
    orders = np.polyfit(np.log(1.0 / np.array(levels)), np.log(errors), 1)[0]
    print(f"\nmesh order of modes 3-4: {np.round(orders, 2)}")  # measured 4.01, 3.93
    assert orders == pytest.approx([4.0, 4.0], abs=0.3)
    # Mode 1 has already converged to the eigen-solver's round-off (~1e-8).
    assert err2[0] < 1e-7 * f[2][0]


def test_mode_one_nodes_at_0224_length(uniform):
    nodes = uniform.modes.nodes(1)
    assert nodes / uniform.length == pytest.approx([0.2242, 1 - 0.2242], abs=2e-4)
    assert len(uniform.modes.nodes(2)) == 3


def test_mass_properties_and_swingweight(uniform):
    m, length = 0.34, 0.68
    assert uniform.mass == pytest.approx(m)
    assert uniform.center_of_mass == pytest.approx(length / 2)
    assert uniform.inertia_cm == pytest.approx(m * length**2 / 12)
    sw = m * length**2 / 12 + m * (length / 2 - 0.10) ** 2
    assert uniform.swingweight == pytest.approx(sw)
    assert uniform.swingweight_kgcm2 == pytest.approx(sw * 1e4)


def test_effective_mass_eq20(uniform):
    m2 = uniform.effective_mass(uniform.center_of_mass)
    assert m2 == pytest.approx(uniform.mass)
    b = 0.2
    assert uniform.effective_mass(uniform.center_of_mass - b) == pytest.approx(
        1 / (1 / uniform.mass + b**2 / uniform.inertia_cm)
    )


def test_point_mass_parallel_axis_and_fem():
    base = Beam.uniform(0.68, 0.34, 120.0)
    taped = Beam(
        base.stations, base.mass_per_length, base.bending_stiffness, point_masses=((0.05, 0.01),)
    )
    d = base.length - 0.10 - 0.05
    assert taped.swingweight - base.swingweight == pytest.approx(0.01 * d**2)
    assert taped.mass == pytest.approx(0.35)
    assert not taped.is_uniform
    assert taped.modes.frequencies[0] < base.modes.frequencies[0]


@pytest.mark.parametrize("where", [0.3, 0.68])
def test_a_point_mass_a_rounding_error_off_a_station_is_at_the_station(where):
    """Lead tape placed at a station computed another way (the head's middle, the butt) is
    a rounding error off it; the beam must not grow an element of that length."""
    profile = Beam((0.0, 0.3, 0.68), (0.6, 0.4), (120.0, 60.0))
    exact, off = (
        profile.with_point_masses((x, 0.005), (x, 0.005, 0.1))
        for x in (where, where - 4 * np.spacing(where))
    )
    assert where - 4 * np.spacing(where) != where
    assert off.modes.frequencies == pytest.approx(exact.modes.frequencies, rel=1e-9)
    assert off.length == exact.length


@pytest.mark.parametrize(
    "kwargs, name",
    [
        (
            dict(stations=(0.0, 0.68), mass_per_length=(0.0,), bending_stiffness=(10.0,)),
            "mass_per_length",
        ),
        (
            dict(stations=(0.0, 0.68), mass_per_length=(0.5,), bending_stiffness=(-1.0,)),
            "bending_stiffness",
        ),
        (
            dict(stations=(0.0, 0.68), mass_per_length=(np.nan,), bending_stiffness=(1.0,)),
            "mass_per_length",
        ),
        (dict(stations=(0.1, 0.68), mass_per_length=(0.5,), bending_stiffness=(1.0,)), "stations"),
        (
            dict(stations=(0.0, 0.68), mass_per_length=(0.5,), bending_stiffness=(1.0,), n_modes=0),
            "n_modes",
        ),
        (
            dict(
                stations=(0.0, 0.68), mass_per_length=(0.5,), bending_stiffness=(1.0,), damping=1.5
            ),
            "damping",
        ),
        (
            dict(stations=(0.0, 0.68), mass_per_length=(0.5, 0.4), bending_stiffness=(1.0,)),
            "mass_per_length",
        ),
    ],
)
def test_bad_profiles_raise(kwargs, name):
    with pytest.raises(ValueError, match=name):
        Beam(**kwargs)


def test_uniform_rejects_bad_numbers():
    with pytest.raises(ValueError, match="f1"):
        Beam.uniform(0.68, 0.34, -120.0)
    with pytest.raises(ValueError, match="mass"):
        Beam.uniform(0.68, 0.0, 120.0)


def test_every_mode_has_one_node_more_than_its_number():
    # Mode k of a free-free beam has k + 1 nodes; an antisymmetric mode's node at L/2 falls
    # exactly on the search grid and must not be lost (mode 14 of 20 once listed 14).
    modes = Beam.uniform(0.68, 0.34, 120.0, n_modes=20).modes
    assert [modes.nodes(k).size for k in range(1, 21)] == list(range(2, 22))
    assert 0.34 in np.round(modes.nodes(14), 12)


def test_static_flexibility_is_the_sum_over_every_mode():
    # The finite-element flexibility under inertia relief equals sum phi**2 / omega**2 over
    # the bending modes (200 analytic ones: the rest add < 1e-7 of it).
    beam = Beam.uniform(0.68, 0.34, 120.0, n_modes=200)
    x = np.linspace(0.0, 0.68, 13)
    phi = beam.modes.shape(x)[2:]
    modal = np.sum(phi**2 / beam.modes.omega[2:, None] ** 2, axis=0)
    assert beam.static_flexibility(x) == pytest.approx(modal, rel=1e-6)
    # ... and the residual is what the modes kept leave out: zero at 200 modes, not at 8.
    few = Beam.uniform(0.68, 0.34, 120.0)
    assert np.all(few.residual_flexibility(x) > 1e-4 * few.static_flexibility(x))
    assert np.all(beam.residual_flexibility(x) < 1e-6 * beam.static_flexibility(x))


def test_with_f1_scales_modes_and_flexibility_without_recomputing():
    beam = Beam((0.0, 0.3, 0.68), (0.6, 0.4), (150.0, 90.0), point_masses=((0.05, 0.004),))
    x = np.linspace(0.0, 0.68, 9)
    beam.residual_flexibility(x)
    scaled = beam.with_f1(160.0)
    fresh = Beam(
        scaled.stations, scaled.mass_per_length, scaled.bending_stiffness, scaled.point_masses
    )
    assert scaled.modes.frequencies[0] == pytest.approx(160.0, rel=1e-12)
    # The fresh solve's frequencies carry the eigensolver's error, eps times the finite
    # elements' spread of stiffness to mass: 1.4e-9 of the fundamental on one of this
    # project's machines (its LAPACK), under 1e-9 on another; the scaled ones are exact.
    assert scaled.modes.omega == pytest.approx(fresh.modes.omega, rel=1e-8)
    assert scaled.modes.shape(x) == pytest.approx(fresh.modes.shape(x), rel=1e-7, abs=1e-9)
    assert scaled.static_flexibility(x) == pytest.approx(fresh.static_flexibility(x), rel=1e-7)


def test_one_points_element_shapes_are_the_arrays_bit_for_bit():
    # element_shapes takes one point in Python's numbers, and the element without shear in
    # fewer steps than the Timoshenko one at Phi = 0: the same bits, signs of zero included.
    from beam import fem

    rng = np.random.default_rng(0)
    nodes = fem.mesh(np.array([0.0, 0.3, 0.68]), np.array([0.05]), 240)
    x = np.concatenate([0.68 * rng.random(300), nodes, [-0.0, 0.68]])
    e, shapes = fem.element_shapes(nodes, x)
    for i in range(x.size):
        e_i, shapes_i = fem.element_shapes(nodes, x[i : i + 1])
        assert e_i.dtype == e.dtype and e_i[0] == e[i]
        assert np.array_equal(shapes_i[:, 0], shapes[:, i])
        assert np.array_equal(np.signbit(shapes_i[:, 0]), np.signbit(shapes[:, i]))
    s = np.concatenate([rng.random(1000), 2.0 * rng.random(1000) - 0.5, [0.0, -0.0, 1.0]])
    length = 1e-3 + 1e-3 * rng.random(s.size)
    plain, timoshenko = fem.hermite(s, length), fem.hermite(s, length, 0.0)
    assert np.array_equal(plain, timoshenko)
    assert np.array_equal(np.signbit(plain), np.signbit(timoshenko))


def test_one_points_flexibility_and_effective_mass_are_the_arrays_bit_for_bit():
    # One point's static flexibility (an impact's) is summed in Python's numbers, and its
    # effective mass worked out in them: the same bits as numpy's einsum and ufuncs on many
    # points, for a uniform frame, a spec-sheet one with point masses, and a point at a node.
    from racket import CATALOG, default_racket

    rng = np.random.default_rng(1)
    for beam in (Beam.uniform(0.68, 0.34, 120.0), default_racket().beam,
                 CATALOG["pure-drive-2021"].racket().beam):  # fmt: skip
        flexibility = beam._flexibility
        x = np.concatenate([beam.length * rng.random(400), flexibility.nodes[::7], [0.0]])
        many_flexibility, many_mass = beam.static_flexibility(x), beam.effective_mass(x)
        for i in range(x.size):
            one = x[i : i + 1]
            assert beam.static_flexibility(one).tolist() == [many_flexibility[i]]
            assert beam.effective_mass(one).tolist() == [many_mass[i]]
        for size in (2, 3, 5):  # short sweeps (einsum's own path) give the same bits too
            assert beam.static_flexibility(x[:size]).tolist() == many_flexibility[:size].tolist()
