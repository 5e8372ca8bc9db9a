"""Bending modes of a non-uniform free-free Timoshenko beam by finite elements.

A thick beam (a baseball bat: 6.4 cm across and 84 cm long) shears as it bends, and its
sections' rotary inertia counts: the Timoshenko theory keeps both (A. M. Nathan, Am. J.
Phys. 68, 979 (2000), Sec. II A and App. B).  Each element carries a constant mass per
length rho A, rotary inertia per length rho I, bending stiffness EI and shear stiffness
kappa G A, with degrees of freedom (deflection, section rotation) at both ends.

The element is the two-node "interdependent interpolation" element of D. Friedman and
J. B. Kosmatka, "An improved two-node Timoshenko beam finite element", Comput. Struct. 47,
473-481 (1993): cubic deflection and quadratic rotation tied together by the shear
parameter Phi = 12 EI / (kappa G A l**2), exact for a static end load, with the consistent
mass matrices of translation and rotary inertia (J. S. Przemieniecki, Theory of Matrix
Structural Analysis, McGraw-Hill (1968), Sec. 11.7).  Phi = 0 and rho I = 0 give the
Euler-Bernoulli element of :mod:`beam.fem`.  The shapes of the deflection it interpolates
are :func:`beam.fem.hermite` with the element's Phi.

Its frequencies converge as h**2 where the beam shears (the shear strain is constant within
an element while a mode's shear force varies along it: the frequency is high by about
rho A omega**2 h**2 / (24 kappa G A)), measured 2.0 against the closed form of a uniform
beam (``tests/test_timoshenko.py``), and as h**4 in the thin limit.  A bat's 252 elements
put its first mode within about 1e-6 and its sixth within about 1e-4.
"""

from __future__ import annotations

import numpy as np

from beam import fem


def element_properties(stations, values, nodes):
    """Each element's value of the per-segment ``values`` (a tuple of arrays (S,)).

    Parameters
    ----------
    stations : array (S + 1,)
        Segment boundaries [m from the tip].
    values : tuple of array (S,)
        Per-segment properties [SI].
    nodes : ndarray
        Mesh nodes [m from the tip].
    """
    mid = 0.5 * (nodes[:-1] + nodes[1:])
    seg = np.clip(np.searchsorted(stations, mid) - 1, 0, len(stations) - 2)
    return tuple(np.asarray(v, dtype=float)[seg] for v in values)


def element_matrices(l, rho_a, rho_i, ei, kga):  # noqa: E741
    """Stiffness and consistent mass matrices (E, 4, 4) of each element, degrees of freedom
    (w1, psi1, w2, psi2), and each element's shear parameter Phi (E,).

    Parameters
    ----------
    l : ndarray (E,)
        Element lengths [m].
    rho_a, rho_i : ndarray (E,)
        Mass per length [kg/m] and rotary inertia per length [kg m].
    ei, kga : ndarray (E,)
        Bending stiffness [N m^2] and shear stiffness kappa G A [N].
    """
    p = 12.0 * ei / (kga * l**2)
    o = np.ones_like(l)
    k_e = (ei / (l**3 * (1.0 + p)))[:, None, None] * np.array(
        [
            [12 * o, 6 * l, -12 * o, 6 * l],
            [6 * l, (4 + p) * l**2, -6 * l, (2 - p) * l**2],
            [-12 * o, -6 * l, 12 * o, -6 * l],
            [6 * l, (2 - p) * l**2, -6 * l, (4 + p) * l**2],
        ]
    ).transpose(2, 0, 1)
    a, b = 70 * p**2 + 147 * p + 78, (35 * p**2 + 77 * p + 44) * l / 4
    c, d = 35 * p**2 + 63 * p + 27, (35 * p**2 + 63 * p + 26) * l / 4
    f, g = (7 * p**2 + 14 * p + 8) * l**2 / 4, (7 * p**2 + 14 * p + 6) * l**2 / 4
    m_t = (rho_a * l / (210.0 * (1.0 + p) ** 2))[:, None, None] * np.array(
        [[a, b, c, -d], [b, f, d, -g], [c, d, a, -b], [-d, -g, -b, f]]
    ).transpose(2, 0, 1)
    h, r, s = (3 - 15 * p) * l, (10 * p**2 + 5 * p + 4) * l**2, (5 * p**2 - 5 * p - 1) * l**2
    m_r = (rho_i / (30.0 * (1.0 + p) ** 2 * l))[:, None, None] * np.array(
        [[36 * o, h, -36 * o, h], [h, r, -h, s], [-36 * o, -h, 36 * o, -h], [h, s, -h, r]]
    ).transpose(2, 0, 1)
    return k_e, m_t + m_r, p


def assemble(stations, profile, point_masses, elements: int):
    """Node positions, the global stiffness and mass matrices and each element's Phi.

    Parameters
    ----------
    stations, point_masses, elements
        As in :func:`beam.fem.assemble`.
    profile : tuple of 4 arrays (S,)
        Per segment: mass per length [kg/m], rotary inertia per length [kg m], bending
        stiffness EI [N m^2] and shear stiffness kappa G A [N].

    Returns
    -------
    nodes : (N,) [m from the tip]; k, m : (2N, 2N), degrees of freedom (deflection,
    rotation) at each node in turn; shear : (N - 1,) each element's Phi [-];
    rho_a, ei : (N - 1,) each element's mass per length and EI.
    """
    point_masses = np.asarray(point_masses, dtype=float).reshape(-1, 2)
    nodes = fem.mesh(stations, point_masses[:, 0], elements)
    rho_a, rho_i, ei, kga = element_properties(stations, profile, nodes)
    k_e, m_e, shear = element_matrices(np.diff(nodes), rho_a, rho_i, ei, kga)
    k, m = fem.scatter(nodes, k_e, m_e, point_masses)
    return nodes, k, m, shear, rho_a, ei


def bending_modes(stations, profile, point_masses, n_modes: int, elements: int):
    """Angular frequencies [rad/s] and shapes (:class:`beam.fem.FemShapes`) of the first
    ``n_modes`` bending modes (arguments as in :func:`assemble`).

    Parameters
    ----------
    stations, point_masses, elements
        As in :func:`assemble`.
    profile : tuple of 4 arrays (S,)
        As in :func:`assemble` [SI].
    n_modes : int
        Bending modes to keep.
    """
    nodes, k, m, shear, rho_a, ei = assemble(stations, profile, point_masses, elements)
    return fem.modes_of(nodes, k, m, rho_a, ei, n_modes, shear)


def static_flexibility(stations, profile, point_masses, elements: int):
    """The free beam's elastic flexibility under inertia relief (:func:`beam.fem.
    static_flexibility`, shear included), as a callable of positions [m from the tip].

    Parameters
    ----------
    stations, profile, point_masses, elements
        As in :func:`bending_modes`.
    """
    nodes, k, m, shear, _, _ = assemble(stations, profile, point_masses, elements)
    return fem.flexibility_of(nodes, k, m, shear)
