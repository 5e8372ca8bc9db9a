"""Bending modes of a non-uniform free-free beam by Hermite finite elements.

Each element carries a constant mass per length and bending stiffness and the standard
cubic Hermite shape functions (deflection and slope at both ends), with the consistent
mass matrix; point masses add to the deflection entries of the mass matrix.  The free-free
generalised eigenproblem K v = omega**2 M v gives two zero modes (rigid-body motion, which
:class:`~beam.Modes` writes down exactly instead) and the bending modes above them.
Cubic Hermite elements converge in frequency as h**4, so a few hundred elements give the
first modes of a racket to better than 1e-6.
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass

import numpy as np


def hermite(s: np.ndarray, length: np.ndarray, shear=None) -> np.ndarray:
    """Cubic Hermite shape functions of the deflection at local coordinate s in [0, 1]:
    array (4, len(s)).  With a shear parameter the Timoshenko element's
    (:mod:`beam.timoshenko`), whose second and fourth degrees of freedom are the sections'
    rotations; None gives the Euler-Bernoulli element's.

    Parameters
    ----------
    s : ndarray
        Local coordinate [-] along each element, 0 at its start and 1 at its end.
    length : ndarray
        Length of the element at each ``s`` [m] (scales the slope functions).
    shear : float or ndarray or None
        The element's shear parameter Phi = 12 EI / (kappa G A l**2) [-] at each ``s``.
    """
    s2, s3 = s**2, s**3
    if shear is None:
        return np.array(_euler_bernoulli(s, s2, s3, length))
    p = shear
    half = 0.5 * p * (s - s2)
    return np.array(
        [
            1 - 3 * s2 + 2 * s3 + p * (1 - s),
            length * (s - 2 * s2 + s3 + half),
            3 * s2 - 2 * s3 + p * s,
            length * (-s2 + s3 - half),
        ]
    ) / (1.0 + p)


def _euler_bernoulli(s, s2, s3, length) -> list:
    """:func:`hermite`'s four functions without shear, from s, its square and its cube
    (arrays, or numbers: IEEE's operations either way, the same bits): the Timoshenko
    element's at Phi = 0, with fewer steps.  Its terms Phi (1 - s) and Phi s add +-0.0 to
    sums that are never -0.0, and dividing by 1 + Phi = 1 changes nothing; ``half`` stays
    (it turns a -0.0 at s = -0.0 into +0.0).
    """
    half = 0.0 * (s - s2)
    return [
        1 - 3 * s2 + 2 * s3,
        length * (s - 2 * s2 + s3 + half),
        3 * s2 - 2 * s3,
        length * (-s2 + s3 - half),
    ]


def element_shapes(nodes: np.ndarray, x, shear=None):
    """The element holding each x [m from the tip] and its shape functions there:
    (element index (len(x),), values (4, len(x))).

    Parameters
    ----------
    nodes : ndarray
        Mesh nodes [m from the tip], increasing.
    x : float or array_like
        Positions to evaluate at [m from the tip].
    shear : ndarray or None
        Each element's shear parameter [-] (:func:`hermite`); None for Euler-Bernoulli.
    """
    x = np.asarray(x, dtype=float)
    if shear is None and x.shape == (1,):  # one point (an impact's): in numbers
        return _point_shapes(nodes, x)
    # (the element's own length, not np.diff of the whole mesh: the same subtraction, and
    # np.minimum/np.maximum rather than np.clip: a few points cost little)
    e = np.minimum(np.maximum(nodes.searchsorted(x, side="right") - 1, 0), nodes.size - 2)
    start = nodes[e]
    length = nodes[e + 1] - start
    return e, hermite((x - start) / length, length, None if shear is None else shear[e])


def _point_shapes(nodes: np.ndarray, x: np.ndarray):
    """:func:`element_shapes` of one point ``x`` (1,) [m from the tip] without shear, in
    Python's numbers (IEEE's operations, the same bits as numpy's on arrays, at a fraction
    of their cost): all but s**3, whose numpy power (SIMD) differs from the C library's in
    the last bit for one number in twenty.
    """
    e, rows = _point_rows(nodes, x)
    return np.array([e]), np.array(rows).reshape(4, 1)


def _point_rows(nodes: np.ndarray, x: np.ndarray):
    """:func:`_point_shapes` of one point ``x`` (1,) [m from the tip] as numbers: the element
    (an int) and its four shape functions (a list of floats [-, m, -, m]).
    """
    e = min(max(int(nodes.searchsorted(x[0], side="right")) - 1, 0), nodes.size - 2)
    start = float(nodes[e])
    length = float(nodes[e + 1]) - start
    s = (x - start) / length
    t = s.item()  # (its square t * t as numpy's s**2, np.square; Python's t**2 is C's pow)
    return e, _euler_bernoulli(t, t * t, (s**3).item(), length)


def mesh(stations: np.ndarray, extra_points: np.ndarray, elements: int) -> np.ndarray:
    """Node positions: every station and extra point, elements of about L / ``elements``.

    Points closer than 1e-9 L to the one before are merged with it: an element of rounding
    length would make the stiffness matrix singular (a point mass placed at a station
    computed another way lands there).

    Parameters
    ----------
    stations : ndarray
        Segment boundaries [m from the tip].
    extra_points : ndarray
        Further positions that must be nodes, e.g. point masses [m from the tip].
    elements : int
        About how many elements along the beam.
    """
    knots = np.unique(np.concatenate([stations, extra_points]))
    tol = 1e-9 * (stations[-1] - stations[0])
    keep = np.r_[True, np.diff(knots) > tol]
    keep[-1] = True  # the beam's ends stay where they are
    knots = knots[keep]
    if knots.size > 2 and knots[-1] - knots[-2] <= tol:
        knots = np.delete(knots, -2)
    target = (stations[-1] - stations[0]) / elements
    pieces = [
        np.linspace(a, b, max(1, int(np.ceil((b - a) / target))) + 1)[:-1]
        for a, b in itertools.pairwise(knots)
    ]
    return np.concatenate([*pieces, knots[-1:]])


def element_properties(stations, mass_per_length, bending_stiffness, nodes):
    """Length, mass per length and EI of each element between ``nodes``.

    Parameters
    ----------
    stations : array (S + 1,)
        Segment boundaries [m from the tip].
    mass_per_length, bending_stiffness : array (S,)
        Per segment [kg/m] and [N m^2].
    nodes : ndarray
        Mesh nodes [m from the tip].
    """
    lengths = np.diff(nodes)
    mid = 0.5 * (nodes[:-1] + nodes[1:])
    seg = np.clip(np.searchsorted(stations, mid) - 1, 0, len(mass_per_length) - 1)
    return lengths, np.asarray(mass_per_length)[seg], np.asarray(bending_stiffness)[seg]


def assemble(stations, mass_per_length, bending_stiffness, point_masses, elements: int):
    """Node positions and the global stiffness and mass matrices of the beam.

    Parameters
    ----------
    stations, mass_per_length, bending_stiffness
        As in :func:`element_properties`.
    point_masses : array (P, 2)
        Rows (position [m from the tip], mass [kg]).
    elements : int
        About how many elements along the beam.

    Returns
    -------
    nodes : (N,) [m from the tip]; k, m : (2N, 2N), degrees of freedom (deflection, slope)
    at each node in turn.
    """
    point_masses = np.asarray(point_masses, dtype=float).reshape(-1, 2)
    nodes = mesh(stations, point_masses[:, 0], elements)
    l, rho, ei = element_properties(stations, mass_per_length, bending_stiffness, nodes)  # noqa: E741

    o = np.ones_like(l)
    k_e = (ei / l**3)[:, None, None] * np.array(
        [
            [12 * o, 6 * l, -12 * o, 6 * l],
            [6 * l, 4 * l**2, -6 * l, 2 * l**2],
            [-12 * o, -6 * l, 12 * o, -6 * l],
            [6 * l, 2 * l**2, -6 * l, 4 * l**2],
        ]
    ).transpose(2, 0, 1)
    m_e = (rho * l / 420.0)[:, None, None] * np.array(
        [
            [156 * o, 22 * l, 54 * o, -13 * l],
            [22 * l, 4 * l**2, 13 * l, -3 * l**2],
            [54 * o, 13 * l, 156 * o, -22 * l],
            [-13 * l, -3 * l**2, -22 * l, 4 * l**2],
        ]
    ).transpose(2, 0, 1)
    k, m = scatter(nodes, k_e, m_e, point_masses)
    return nodes, k, m


def scatter(nodes: np.ndarray, k_e: np.ndarray, m_e: np.ndarray, point_masses):
    """The global stiffness and mass matrices (2N, 2N) from the elements' (E, 4, 4), degrees
    of freedom (deflection, slope or rotation) at each node in turn, with the point masses on
    the deflections of their nearest nodes.

    Parameters
    ----------
    nodes : ndarray (N,)
        Mesh nodes [m from the tip].
    k_e, m_e : ndarray (N - 1, 4, 4)
        Each element's stiffness and mass matrices [SI].
    point_masses : array (P, 2)
        Rows (position [m from the tip], mass [kg]).
    """
    n_dof = 2 * nodes.size
    dofs = 2 * np.arange(nodes.size - 1)[:, None] + np.arange(4)[None, :]
    rows = np.repeat(dofs, 4, axis=1).ravel()
    cols = np.tile(dofs, (1, 4)).ravel()
    # Sum the element matrices into the global ones (bincount: np.add.at is ten times slower).
    flat = rows * n_dof + cols
    k = np.bincount(flat, k_e.ravel(), n_dof * n_dof).reshape(n_dof, n_dof)
    m = np.bincount(flat, m_e.ravel(), n_dof * n_dof).reshape(n_dof, n_dof)
    for x_p, m_p in point_masses:
        i = 2 * int(np.argmin(np.abs(nodes - x_p)))
        m[i, i] += m_p
    return k, m


def bending_modes(
    stations, mass_per_length, bending_stiffness, point_masses, n_modes: int, elements: int
):
    """Angular frequencies [rad/s] and a shape evaluator of the first ``n_modes`` bending modes
    (arguments as in :func:`assemble`).

    Parameters
    ----------
    stations, mass_per_length, bending_stiffness, point_masses, elements
        As in :func:`assemble`.
    n_modes : int
        Bending modes to keep.
    """
    nodes, k, m = assemble(stations, mass_per_length, bending_stiffness, point_masses, elements)
    _, rho, ei = element_properties(stations, mass_per_length, bending_stiffness, nodes)
    return modes_of(nodes, k, m, rho, ei, n_modes)


def modes_of(nodes, k, m, rho, ei, n_modes: int, shear=None):
    """Angular frequencies [rad/s] and shapes (:class:`FemShapes`) of the first ``n_modes``
    bending modes of an assembled free-free beam.

    Parameters
    ----------
    nodes : ndarray (N,)
        Mesh nodes [m from the tip].
    k, m : ndarray (2N, 2N)
        Stiffness and mass matrices [SI].
    rho, ei : ndarray (N - 1,)
        Each element's mass per length [kg/m] and EI [N m^2] (for the solver's shift).
    n_modes : int
        Bending modes to keep.
    shear : ndarray or None
        Each element's shear parameter [-] (:func:`hermite`); None for Euler-Bernoulli.
    """
    from scipy.linalg import eigh  # scipy loads on first use (import time)

    n_dof = k.shape[0]
    lengths = np.diff(nodes)
    # Solve the shifted, inverted problem m v = mu (k + s m) v, mu = 1 / (omega**2 + s): a
    # dense solver's eigenvalue errors are about eps times the largest eigenvalue, which for
    # k v = omega**2 m v is the mesh's highest frequency squared (1e-4 relative error on the
    # fundamental of a fine mesh); inverted, the largest eigenvalues are the wanted ones.
    # The shift: the fundamental of a uniform beam of the mean EI and mass per length
    # (beta L = 4.730), so that mu of the wanted modes is within a small factor of 1 / s.
    span = nodes[-1] - nodes[0]
    shift = 4.730**4 * (ei @ lengths) / (rho @ lengths) / span**4
    mu, v = eigh(m, k + shift * m, subset_by_index=[n_dof - n_modes - 2, n_dof - 3])
    mu, v = mu[::-1], v[:, ::-1]
    w2 = 1.0 / mu - shift
    v = v / np.sqrt(np.einsum("im,ij,jm->m", v, m, v))  # mass-normalised
    v = v * np.sign(v[0])  # deflection at the tip positive
    omega = np.sqrt(np.maximum(w2, 0.0))

    return omega, FemShapes(nodes, v, shear)


@dataclass(frozen=True, eq=False)
class FemShapes:
    """Bending shapes [1/sqrt(kg)] interpolated from the finite-element eigenvectors, as a
    picklable callable of positions x [m from the tip].

    Parameters
    ----------
    nodes : ndarray
        Mesh nodes [m from the tip].
    vectors : ndarray
        (2 nodes, modes) mass-normalised eigenvectors (deflection [1/sqrt(kg)],
        slope [1/(sqrt(kg) m)] per node).
    shear : ndarray or None
        Each element's shear parameter [-] (:func:`hermite`; the second degree of freedom
        is then the section's rotation); None for Euler-Bernoulli.
    """

    nodes: np.ndarray
    vectors: np.ndarray
    shear: np.ndarray | None = None

    def __call__(self, x) -> np.ndarray:
        """Values at ``x`` [m from the tip] (see the class docstring)."""
        e, n = element_shapes(self.nodes, x, self.shear)
        dof = 2 * e[None, :] + np.arange(4)[:, None]  # (4, len(x))
        return np.einsum("kx,mkx->mx", n, self.vectors[dof].transpose(2, 0, 1))


def static_flexibility(stations, mass_per_length, bending_stiffness, point_masses, elements: int):
    """The beam's elastic flexibility under inertia relief, as a callable of positions.

    A free beam pushed at a point b by a force F accelerates as a rigid body and bends; the
    bending part, F times ``sum over every bending mode of phi_k(b)**2 / omega_k**2``, is
    what a static load balanced by the beam's own inertia (d'Alembert) deflects.  It is
    computed from the finite-element model without its eigenvectors: the load minus its
    rigid-body part (M R R^T f, R the mass-normalised rigid-body modes) is applied to the
    beam propped at both ends, and the rigid-body part of that deflection is removed again:

        A = (I - R R^T M) K_c^-1 (I - M R R^T),

    K_c^-1 the propped beam's flexibility (A is the same for any statically determinate
    props).  Arguments as in :func:`assemble`.

    Parameters
    ----------
    stations, mass_per_length, bending_stiffness, point_masses, elements
        As in :func:`assemble`.
    """
    nodes, k, m = assemble(stations, mass_per_length, bending_stiffness, point_masses, elements)
    return flexibility_of(nodes, k, m)


def flexibility_of(nodes, k, m, shear=None):
    """:func:`static_flexibility` of an assembled free-free beam (arguments as in
    :func:`modes_of`).

    Parameters
    ----------
    nodes, k, m, shear
        As in :func:`modes_of`.
    """
    n_dof = k.shape[0]
    rigid = np.zeros((n_dof, 2))
    rigid[0::2, 0] = 1.0  # translation: deflection 1, slope 0
    rigid[0::2, 1] = nodes - nodes.mean()  # rotation: deflection x, slope 1
    rigid[1::2, 1] = 1.0
    rigid[:, 1] -= rigid[:, 0] * (rigid[:, 0] @ m @ rigid[:, 1]) / (rigid[:, 0] @ m @ rigid[:, 0])
    rigid /= np.sqrt(np.einsum("im,ij,jm->m", rigid, m, rigid))  # mass-normalised, orthogonal
    free = np.ones(n_dof, dtype=bool)
    free[[0, n_dof - 2]] = False  # deflection propped at both ends
    propped = np.zeros((n_dof, n_dof))
    propped[np.ix_(free, free)] = np.linalg.inv(k[np.ix_(free, free)])
    relief = np.eye(n_dof) - rigid @ (rigid.T @ m)
    flexibility = relief @ propped @ relief.T
    dof = 2 * np.arange(nodes.size - 1)[:, None] + np.arange(4)  # (E, 4) per element
    return FemFlexibility(nodes, flexibility[dof[:, :, None], dof[:, None, :]], shear)


@dataclass(frozen=True, eq=False)
class FemFlexibility:
    """The flexibility [m/N] of the beam at x [m from the tip] to a force at x (see
    :func:`static_flexibility`), picklable.

    Parameters
    ----------
    nodes : ndarray
        Mesh nodes [m from the tip].
    blocks : ndarray
        (elements, 4, 4) the flexibility matrix's block between each element's degrees of
        freedom (deflection and slope at both ends) [SI], all that a point inside it needs.
    shear : ndarray or None
        Each element's shear parameter [-] (:func:`hermite`); None for Euler-Bernoulli.
    """

    nodes: np.ndarray
    blocks: np.ndarray
    shear: np.ndarray | None = None

    def __call__(self, x) -> np.ndarray:
        """Values at ``x`` [m from the tip] (see the class docstring)."""
        x = np.asarray(x, dtype=float)
        if self.shear is None and x.shape == (1,):  # one point (an impact's): in numbers
            return np.array([self._at_point(x)])
        e, n = element_shapes(self.nodes, x, self.shear)
        return np.einsum("ix,xij,jx->x", n, self.blocks[e], n)

    def _at_point(self, x: np.ndarray) -> float:
        """The value [m/N] at one point ``x`` (1,) [m from the tip] without shear, in Python's
        numbers: n^T B n summed term by term in the order numpy's einsum takes (row by row,
        each term n_i B_ij n_j multiplied left to right), so the same bits as
        :meth:`__call__` on many points (``tests/test_beam.py`` holds it), without einsum's
        set-up: one point's call 8.5 -> 6.4 us (measured alone).
        """
        e, n = _point_rows(self.nodes, x)
        value = 0.0
        for n_i, row in zip(n, self.blocks[e].tolist(), strict=True):
            for b_ij, n_j in zip(row, n, strict=True):
                value += n_i * b_ij * n_j
        return value
