"""The Timoshenko beam (:class:`beam.ThickBeam`) against the exact free-free frequencies.

The reference is the closed-form frequency equation of a uniform free-free Timoshenko beam
(T. C. Huang, "The effect of rotatory inertia and of shear deformation on the frequency and
normal mode equations of uniform beams with simple end conditions", J. Appl. Mech. 28,
579-584 (1961); also S. M. Han, H. Benaroya and T. Wei, J. Sound Vib. 225, 935-988 (1999)),
here derived again from the equations.  With b**2 = rho A omega**2 L**4 / EI,
r**2 = I / (A L**2) (rotary inertia) and s**2 = EI / (kappa G A L**2) (shear), the
characteristic roots of the Timoshenko equations are S = +-b alpha and S = +-i b beta,

    alpha**2, beta**2 = (-+(r**2 + s**2) + sqrt((r**2 - s**2)**2 + 4 / b**2)) / 2,

and free ends (EI psi' = 0 and kappa G A (w' - psi) = 0 at both) give

    2 - 2 cosh(b alpha) cos(b beta)
      + [b**2 r**2 (r**2 - s**2)**2 + 3 r**2 - s**2] sinh(b alpha) sin(b beta) / (alpha beta) = 0.

Above the cut-off b**2 r**2 s**2 = 1 (omega_c = sqrt(kappa G A / rho I)) alpha**2 < 0: with
alpha = i a, cosh(b alpha) = cos(b a) and sinh(b alpha) / alpha = sin(b a) / a, so the
function below, written in alpha**2, is real and continuous across it (both spectra).  It
was checked against the 4x4 boundary matrix built from the equations directly (singular
to round-off at its roots, both sides of the cut-off: :func:`test_reference_both_spectra`);
with r, s -> 0 it gives cos(bL) cosh(bL) = 1 (:func:`test_reference_euler_bernoulli_limit`).
"""

import itertools

import numpy as np
import pytest
from scipy.optimize import brentq

from beam import Beam, ThickBeam

NU = 0.3
KAPPA = 6 * (1 + NU) / (7 + 6 * NU)  # solid circle (Cowper 1966), 0.886
E, G, RHO, LENGTH = 2.0e11, 2.0e11 / (2 * (1 + NU)), 7800.0, 1.0  # steel [Pa, Pa, kg/m^3, m]
EB_ROOTS = np.array([4.730040745, 7.853204624, 10.99560784, 14.13716549, 17.27875966, 20.42035225])


def huang(b, r2, s2):
    """Huang's free-free frequency function at b [-], divided by max(1, cosh(b alpha)).

    Parameters
    ----------
    b : ndarray
        Frequency parameter sqrt(rho A / EI) omega L**2 [-], > 0.
    r2, s2 : float
        Rotary-inertia and shear parameters I / (A L**2) and EI / (kappa G A L**2) [-].
    """
    root = np.sqrt((r2 - s2) ** 2 + 4.0 / b**2)
    a2, beta = 0.5 * (root - r2 - s2), np.sqrt(0.5 * (root + r2 + s2))  # a2 < 0 above cut-off
    u = b * np.sqrt(np.abs(a2))
    up = np.where(a2 > 0, u, 0.0)  # below the cut-off: cosh, sinh / alpha over cosh
    ch = np.where(a2 > 0, 1.0, np.cos(u))
    sh = np.where(a2 > 0, np.tanh(up) / np.where(up > 0, up, 1.0), np.sinc(u / np.pi)) * b
    bracket = b**2 * r2 * (r2 - s2) ** 2 + 3.0 * r2 - s2
    return 2.0 / np.cosh(up) - 2.0 * ch * np.cos(b * beta) + bracket * sh * np.sin(b * beta) / beta


def exact_b(r2, s2, n=6):
    """The first ``n`` roots b [-] of :func:`huang`: sign changes on a fine grid, brentq."""
    grid = np.linspace(1.0, 1.25 * EB_ROOTS[-1] ** 2 * (n / 6.0) ** 2, 40_000)
    value = huang(grid, r2, s2)
    cross = np.nonzero(np.sign(value[:-1]) * np.sign(value[1:]) < 0)[0][:n]
    assert cross.size == n, "the scan found too few roots"
    return np.array([brentq(huang, grid[i], grid[i + 1], (r2, s2), xtol=1e-14) for i in cross])


def round_bar(slenderness, shear=1.0, rotary=1.0):
    """Profile of a solid round steel bar L / r_g = ``slenderness`` (r_g = d / 4), its shear
    stiffness times ``shear`` and rotary inertia times ``rotary``: (rho A [kg/m],
    EI [N m^2], kappa G A [N], rho I [kg m]).
    """
    r_g = LENGTH / slenderness
    area = np.pi * (2 * r_g) ** 2
    inertia = area * r_g**2
    return RHO * area, E * inertia, shear * KAPPA * G * area, rotary * RHO * inertia


def exact_hz(rho_a, ei, kga, rho_i, n=6):
    """The first ``n`` exact free-free frequencies [Hz] of a uniform Timoshenko beam."""
    b = exact_b(rho_i / (rho_a * LENGTH**2), ei / (kga * LENGTH**2), n)
    return b * np.sqrt(ei / (rho_a * LENGTH**4)) / (2 * np.pi)


def thick(rho_a, ei, kga, rho_i, elements, n_modes=6):
    """A uniform :class:`ThickBeam` [SI profile] of length :data:`LENGTH` [m]."""
    return ThickBeam(stations=(0.0, LENGTH), mass_per_length=(rho_a,), bending_stiffness=(ei,),
                     shear_stiffness=(kga,), rotary_inertia_per_length=(rho_i,),
                     n_modes=n_modes, elements=elements)  # fmt: skip


def test_reference_euler_bernoulli_limit():
    """Without shear and rotary inertia the closed form gives cos(bL) cosh(bL) = 1."""
    b = exact_b(1e-14, 1e-14)
    np.testing.assert_allclose(np.sqrt(b), EB_ROOTS, rtol=2e-9)


def test_reference_both_spectra():
    """The closed form is continuous across the cut-off: at L / r_g = 10 its roots, five of
    the eight above omega_c, make the 4x4 boundary matrix built straight from the equations
    (w = sum of exp(S x / L), psi from the first equation) singular.
    """
    rho_a, ei, kga, rho_i = round_bar(10.0)
    r2, s2 = rho_i / (rho_a * LENGTH**2), ei / (kga * LENGTH**2)
    b = exact_b(r2, s2, 8)
    assert b[-1] ** 2 * r2 * s2 > 1.0  # some roots lie above the cut-off
    for b_k in b:
        p, q = b_k**2 * (r2 + s2), -(b_k**2) * (1.0 - b_k**2 * r2 * s2)
        s_sq = -p / 2 + np.array([1, -1]) * np.sqrt(p**2 / 4 - q + 0j)
        s = np.concatenate([np.sqrt(s_sq), -np.sqrt(s_sq)])
        k = (s**2 + b_k**2 * s2) / s  # psi / w of each root (L = 1)
        ends = [np.exp(s * xi - np.maximum(s.real, 0)) for xi in (0.0, 1.0)]
        m = np.array([row for e in ends for row in (k * s * e, (s - k) * e)])
        m /= np.linalg.norm(m, axis=0)
        sv = np.linalg.svd(m, compute_uv=False)
        assert sv[-1] < 1e-9 * sv[0]


# How far shear and rotary inertia move the free-free frequencies (modes 1..6, measured):
# L / r_g = 20 (L / d = 5) 8.9 % .. 53 % below Euler-Bernoulli, L / r_g = 50 1.7 % .. 21 %.
@pytest.mark.parametrize("slenderness", [20.0, 50.0])
def test_frequencies_match_closed_form(slenderness):
    """Test A: the first 6 frequencies [Hz] of a uniform ThickBeam within 1e-4 of the exact
    ones, and above them (consistent mass: a Rayleigh-Ritz upper bound).  Measured with 500
    elements: 4.8e-7 .. 3.8e-5 (L / r_g = 20), 9.3e-8 .. 2.0e-5 (L / r_g = 50); the error
    goes as h**2 (:func:`test_convergence_order_thick`), so 200 would miss 1e-4 at L / r_g = 20.
    """
    profile = round_bar(slenderness)
    modes = thick(*profile, elements=500).modes
    error = modes.frequencies / exact_hz(*profile) - 1.0
    assert modes.omega.shape == (8,) and np.all(modes.omega[:2] == 0.0)
    assert np.all(error > 0.0) and np.all(error < 1e-4), error


def fitted_order(profile, meshes=(20, 40, 80, 160)):
    """Least-squares slope of log(error) against log(h) of each mode, and the errors [-]."""
    exact = exact_hz(*profile)
    error = np.array([thick(*profile, n).modes.frequencies / exact - 1.0 for n in meshes])
    slope = np.polyfit(np.log(1.0 / np.asarray(meshes)), np.log(np.abs(error)), 1)[0]
    return slope, error


def test_convergence_order_thick():
    """Test B: with shear the frequencies converge as h**2, not h**4 (measured 1.99-2.00 at
    L / r_g = 20, modes 1-6, meshes 20-160).  This is the element's, not a defect: its shear
    strain w' - psi is constant in each element (exact for end loads only), while a mode's
    shear force varies along it under the inertia load rho A omega**2 w; the energy of that
    O(h) misfit raises omega by about rho A omega**2 h**2 / (24 kappa G A).  The fundamental's
    error matches that estimate (measured 0.94 of it); a wrong mass matrix would not.
    """
    profile = round_bar(20.0)
    slope, error = fitted_order(profile)
    assert np.all((slope > 1.9) & (slope < 2.1)), slope
    rho_a, _, kga, _ = profile
    omega = 2 * np.pi * exact_hz(*profile)[0]
    estimate = rho_a * omega**2 * (LENGTH / 160) ** 2 / (24 * kga)
    assert 0.85 < error[-1, 0] / estimate < 1.05, error[-1, 0] / estimate


def test_convergence_order_euler_bernoulli_limit():
    """Test B: with shear stiffness x1e6 and no rotary inertia the element is the cubic
    Hermite one and converges as h**4 (measured 3.96-4.00, meshes 20-80; finer meshes reach
    the eigensolver's round-off on the fundamental).
    """
    slope, _ = fitted_order(round_bar(50.0, shear=1e6, rotary=0.0), meshes=(20, 40, 80))
    assert np.all(slope > 3.5), slope


def test_euler_bernoulli_limit():
    """Test C: as kappa G A grows and rho I shrinks (x and / by 10, 100, 1e4, 1e6) the
    frequencies [Hz] fall toward Beam's analytic ones: the largest gap of modes 1-6 shrinks
    about as 1/factor (measured 3.1e-2, 3.3e-3, 3.3e-5, 3.2e-7), every one below them up to
    x1e4 (at x1e6 the fundamental's 1.7e-8 is within the eigensolver's round-off).
    """
    rho_a, ei, _, _ = round_bar(50.0)
    euler = Beam((0.0, LENGTH), (rho_a,), (ei,), n_modes=6).modes.frequencies
    factors = (10.0, 100.0, 1e4, 1e6)
    gaps = [thick(*round_bar(50.0, f, 1 / f), elements=400).modes.frequencies / euler - 1.0
            for f in factors]  # fmt: skip
    largest = [np.max(np.abs(g)) for g in gaps]
    assert all(np.all(g < 0.0) for g in gaps[:3]), gaps
    assert all(b < 0.2 * a for a, b in itertools.pairwise(largest)), largest
    assert largest[-1] < 1e-6, largest


def test_mass_properties_and_orthogonality():
    """Mass [kg] and centre of mass [m from the tip] as Beam's; the moment of inertia adds
    the sections' own (rho I L).  Without rotary inertia the deflection shapes (8 modes, the
    rigid ones included) are rho A-orthonormal (measured to 5e-13, a 4-point Gauss rule on
    each of 2000 pieces; the shapes must use the shear interpolation the mass matrix does).
    """
    rho_a, ei, kga, rho_i = round_bar(20.0)
    euler = Beam((0.0, LENGTH), (rho_a,), (ei,), n_modes=6)
    beam = thick(rho_a, ei, kga, rho_i, elements=200)
    assert beam.mass == pytest.approx(euler.mass, rel=1e-14)
    assert beam.center_of_mass == pytest.approx(euler.center_of_mass, rel=1e-14)
    assert beam.inertia_cm == pytest.approx(euler.inertia_cm + rho_i * LENGTH, rel=1e-12)
    node, weight = np.polynomial.legendre.leggauss(4)
    edges = np.linspace(0.0, LENGTH, 2001)
    half = 0.5 * np.diff(edges)[:, None]
    x = (edges[:-1, None] + half * (node + 1.0)).ravel()
    phi = thick(rho_a, ei, kga, 0.0, elements=200).modes.shape(x)
    gram = (phi * (rho_a * (half * weight).ravel())) @ phi.T
    np.testing.assert_allclose(gram, np.eye(8), atol=1e-9)
