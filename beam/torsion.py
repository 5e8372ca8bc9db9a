"""Twisting of a free-free beam about its long axis: the rigid roll and the torsion modes.

The frame twists by an angle theta(x, t) about its long axis.  With a torsional stiffness
GJ(x) [N m^2] and a roll inertia per length J(x) [kg m] (plus point masses m at lateral
offsets y, adding m y**2 at their position), the free-free shaft obeys
(GJ theta')' = J theta'' (Saint-Venant torsion, warping neglected), solved here by linear
finite elements with the consistent mass matrix (frequencies converge as h**2).  One zero
mode is the rigid roll, theta_0 = 1 / sqrt(I_roll); the others are the torsion modes.
A normal force at (x, y) on the string plane drives mode k through y theta_k(x), so the
modal shape a ball sees is y theta_k(x) (:meth:`RollModes.shape`).

For a frame symmetric about its long axis (every profile of this package: lead tape goes
on both sides, see :meth:`racket.strings.head.Hoop.clock`) bending out of the string plane is
symmetric in y and twisting antisymmetric, so the two are uncoupled and add.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from beam import fem


@dataclass(frozen=True)
class RollModes:
    """The rigid roll and the torsion modes of a free-free beam, mass-normalised
    (int J theta_i theta_j dx + sum m y**2 theta_i theta_j = delta_ij).

    Attributes
    ----------
    omega : ndarray
        Angular frequency of each mode [rad/s]: 0 for the rigid roll, then the torsion modes.
    damping : ndarray
        Modal damping ratio [-] of each mode (0 for the rigid roll).
    roll_inertia : float
        Moment of inertia about the long axis [kg m^2].
    nodes : ndarray
        Finite-element nodes [m from the tip].
    vectors : ndarray
        Nodal twist of each kept mode (count, nodes) [1/sqrt(kg m^2)].
    residual : ndarray
        (nodes, nodes) sum over the torsion modes not kept of theta theta^T / omega**2
        [1/(N m)]: the static twist per unit torque they add (the static correction).
    element_flexibility : ndarray
        h / GJ of each element [1/(N m)] (0 for a torsionally rigid frame): the twist that
        a torque inside an element adds beyond what its two nodes carry
        (:meth:`residual_flexibility`).
    """

    omega: np.ndarray
    damping: np.ndarray
    roll_inertia: float
    nodes: np.ndarray
    vectors: np.ndarray
    residual: np.ndarray
    element_flexibility: np.ndarray

    @property
    def count(self) -> int:
        """Number of modes, the rigid roll included."""
        return self.omega.size

    @property
    def frequencies(self) -> np.ndarray:
        """Torsion-mode frequencies [Hz] (the rigid roll left out)."""
        return self.omega[1:] / (2.0 * np.pi)

    def _interpolation(self, x):
        x = np.atleast_1d(np.asarray(x, dtype=float))
        e = np.clip(np.searchsorted(self.nodes, x, side="right") - 1, 0, self.nodes.size - 2)
        s = (x - self.nodes[e]) / (self.nodes[e + 1] - self.nodes[e])
        return e, s

    def twist(self, x) -> np.ndarray:
        """Twist shapes theta_k at ``x`` [m from the tip]: (count, len(x)) [1/sqrt(kg m^2)]."""
        e, s = self._interpolation(x)
        return self.vectors[:, e] * (1.0 - s) + self.vectors[:, e + 1] * s

    def shape(self, x, y) -> np.ndarray:
        """Modal shapes y theta_k(x) of the string plane's normal motion at (``x`` [m from
        the tip], ``y`` [m from the long axis]): (count, P) [1/sqrt(kg)].
        """
        return np.asarray(y, dtype=float) * self.twist(x)

    def residual_flexibility(self, x, y) -> np.ndarray:
        """Normal deflection per unit normal force [m/N] at (x, y) from the torsion modes
        not kept (the static correction).

        Two parts, y**2 (theta^T R theta + s (1 - s) h / GJ):

        * the modes of the mesh not kept, R = :attr:`residual`, for the torque shared
          between the two nodes of the element holding x (linear shapes);
        * the twist a linear element cannot carry: a torque T at a fraction s of an element
          of length h twists that point by T s (1 - s) h / GJ more than the element's
          nodes say (the Green's function of the element held at its nodes, exact for a
          uniform element: with it the static twist at x is the exact one wherever x is,
          not only on a node).
        """
        e, s = self._interpolation(x)
        r = self.residual
        twist2 = (
            (1.0 - s) ** 2 * r[e, e] + 2.0 * s * (1.0 - s) * r[e, e + 1] + s**2 * r[e + 1, e + 1]
        )
        inside = s * (1.0 - s) * self.element_flexibility[e]
        return np.asarray(y, dtype=float) ** 2 * (np.maximum(twist2, 0.0) + inside)


def roll_modes(
    stations,
    roll_inertia_per_length,
    torsional_stiffness,
    point_masses,
    n_modes: int,
    damping: float,
    elements: int,
) -> RollModes:
    """The rigid roll and the first ``n_modes`` torsion modes of a free-free shaft.

    Parameters
    ----------
    stations : array (S + 1,)
        Segment boundaries [m from the tip].
    roll_inertia_per_length : array (S,)
        Roll inertia per length of each segment [kg m].
    torsional_stiffness : array (S,) or None
        GJ of each segment [N m^2]; None for a torsionally rigid frame (the rigid roll only).
    point_masses : array (P, 3)
        Rows (position [m from the tip], mass [kg], lateral offset [m]).
    n_modes : int
        Torsion modes to keep (beyond the rigid roll).
    damping : float
        Modal damping ratio [-] of every torsion mode.
    elements : int
        Elements along the beam (about).
    """
    stations = np.asarray(stations, dtype=float)
    points = np.asarray(point_masses, dtype=float).reshape(-1, 3)
    nodes = fem.mesh(stations, points[:, 0], elements)
    n = nodes.size
    h, j, gj = fem.element_properties(
        stations,
        roll_inertia_per_length,
        np.ones(len(roll_inertia_per_length))
        if torsional_stiffness is None
        else torsional_stiffness,
        nodes,
    )
    mass = np.zeros((n, n))
    stiff = np.zeros((n, n))
    i = np.arange(n - 1)
    for a, b, m_ab, k_ab in ((0, 0, 2, 1), (1, 1, 2, 1), (0, 1, 1, -1), (1, 0, 1, -1)):
        np.add.at(mass, (i + a, i + b), m_ab * j * h / 6.0)
        np.add.at(stiff, (i + a, i + b), k_ab * gj / h)
    at = np.clip(np.searchsorted(nodes, points[:, 0] - 1e-9 * nodes[-1]), 0, n - 1)
    np.add.at(mass, (at, at), points[:, 1] * points[:, 2] ** 2)
    roll_inertia = float(mass.sum())
    rigid = np.full((1, n), 1.0 / np.sqrt(roll_inertia))
    if torsional_stiffness is None:
        return RollModes(
            np.zeros(1), np.zeros(1), roll_inertia, nodes, rigid, np.zeros((n, n)), np.zeros(n - 1)
        )
    from scipy.linalg import eigh  # scipy loads on first use (import time)

    w2, vec = eigh(stiff, mass)
    w2, vec = w2[1:], vec[:, 1:]  # the first is the rigid roll, written down exactly above
    vec *= np.where(vec[0] < 0.0, -1.0, 1.0)  # a fixed sign: + twist at the tip
    kept = min(n_modes, w2.size)
    rest = vec[:, kept:]
    return RollModes(
        omega=np.concatenate([[0.0], np.sqrt(w2[:kept])]),
        damping=np.concatenate([[0.0], np.full(kept, float(damping))]),
        roll_inertia=roll_inertia,
        nodes=nodes,
        vectors=np.vstack([rigid, vec[:, :kept].T]),
        residual=(rest / w2[kept:]) @ rest.T,
        element_flexibility=h / gj,
    )
