"""Mode sets: rigid-body plus bending modes of a free-free beam, mass-normalised."""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from functools import cached_property

import numpy as np


@dataclass(frozen=True)
class Modes:
    """The modes of a free-free beam: two rigid-body modes, then ``n`` bending modes.

    Every mode is mass-normalised (int m(x) phi_i phi_j dx + sum of point masses = delta_ij).
    Mode 0 is translation, phi_0 = 1 / sqrt(M); mode 1 is rotation about the centre of mass,
    phi_1(x) = (x_cm - x) / sqrt(I_cm), so that the velocity of the point at x is
    V_cm + (x_cm - x) omega with omega = q_1' / sqrt(I_cm) (Fig. 5).

    Attributes
    ----------
    omega : ndarray
        Angular frequency of each mode [rad/s] (0 for the two rigid-body modes).
    damping : ndarray
        Modal damping ratio [-] of each mode (0 for the rigid-body modes).
    mass, center_of_mass, inertia_cm : float
        Total mass [kg], centre of mass [m from the tip], moment of inertia about it [kg m^2].
    length : float
        Beam length [m].
    bending_shapes : callable
        Maps positions x [m from the tip] to the bending-mode shapes there, array
        (count - 2, len(x)) [1/sqrt(kg)].
    """

    omega: np.ndarray
    damping: np.ndarray
    mass: float
    center_of_mass: float
    inertia_cm: float
    length: float
    bending_shapes: Callable[[np.ndarray], np.ndarray]

    @property
    def count(self) -> int:
        """Number of modes, rigid-body modes included."""
        return self.omega.size

    @cached_property
    def bending_omega_squared(self) -> np.ndarray:
        """(count - 2, 1) the bending modes' omega**2 [rad^2/s^2], a column; computed once
        (the modes are frozen).
        """
        return self.omega[2:, None] ** 2

    @property
    def frequencies(self) -> np.ndarray:
        """Bending-mode frequencies [Hz] (the rigid-body modes left out)."""
        return self.omega[2:] / (2.0 * np.pi)

    def shape(self, x) -> np.ndarray:
        """Mode shapes at ``x`` [m from the tip]: array (count, len(x)) [1/sqrt(kg)].

        Parameters
        ----------
        x : float or array_like
            Positions [m from the tip].
        """
        x = np.atleast_1d(np.asarray(x, dtype=float))
        shapes = np.empty((self.count, x.size))  # (filled row by row: cheaper than stacking)
        shapes[0] = 1.0 / math.sqrt(self.mass)  # (math's: numpy's costs more on a number)
        shapes[1] = (self.center_of_mass - x) / math.sqrt(self.inertia_cm)
        shapes[2:] = self.bending_shapes(x)
        return shapes

    def nodes(self, mode: int = 1) -> np.ndarray:
        """Zeros [m from the tip] of bending mode ``mode`` (1 = fundamental) on the beam.

        Parameters
        ----------
        mode : int, optional
            The bending mode, 1 (the fundamental) to ``count - 2``.
        """
        from scipy.optimize import brentq  # scipy loads on first use (import time)

        if not 1 <= mode <= self.count - 2:
            raise ValueError(f"mode must be in [1, {self.count - 2}], got {mode!r}")
        x = np.linspace(0.0, self.length, 4001)
        phi = self.bending_shapes(x)[mode - 1]
        f = lambda s: float(self.bending_shapes(np.array([s]))[mode - 1, 0])  # noqa: E731
        sign = np.sign(phi)
        cross = np.nonzero(sign[:-1] * sign[1:] < 0)[0]
        roots = [brentq(f, x[i], x[i + 1], xtol=1e-13) for i in cross]
        # A node exactly on a grid point (antisymmetric modes of a uniform beam at L/2).
        on_grid = np.nonzero((sign[1:-1] == 0) & (sign[:-2] * sign[2:] < 0))[0] + 1
        return np.sort(np.concatenate([roots, x[on_grid]]))
