"""The relative motion of a two-body contact, as both contact solvers return it."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class RelativeContact:
    """History of one contact in the relative coordinate z = X_a + X_b (Eq. 10).

    Attributes
    ----------
    t : ndarray
        Time since first touch [s].
    force : ndarray
        Contact force [N].
    compression_a, compression_b : ndarray
        Compression of each body's spring [m] (zero for the wall).
    closing_speed : ndarray
        dz/dt [m/s]: positive while the bodies approach, negative as they separate.
    dissipated_a, dissipated_b : float
        Energy lost in each body's spring [J].
    x_o : float or None
        Largest compression of the unhappy ball (the self-consistent Xo of Eq. 7) [m].
    """

    t: np.ndarray
    force: np.ndarray
    compression_a: np.ndarray
    compression_b: np.ndarray
    closing_speed: np.ndarray
    dissipated_a: float
    dissipated_b: float
    x_o: float | None = None
