"""Analytic bending modes of a uniform free-free Euler-Bernoulli beam.

The free-free beam's bending modes satisfy cos(bL) cosh(bL) = 1, with roots
bL = 4.7300, 7.8532, 10.9956, ... (-> (n + 1/2) pi), and shapes

    Phi(x) = cosh(bx) + cos(bx) - s (sinh(bx) + sin(bx)),
    s = (cosh(bL) - cos(bL)) / (sinh(bL) - sin(bL)),

normalised so that (1/L) int_0^L Phi**2 dx = 1.  For bL beyond ~20 the hyperbolic terms
cancel catastrophically in floating point, so the shape is evaluated with the growing
exponential written relative to the far end.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


def free_free_roots(n: int) -> np.ndarray:
    """The first ``n`` roots bL of cos(bL) cosh(bL) = 1, bL > 0.

    Newton's method on cos(x) - 1/cosh(x), which has one root near each (k + 1/2) pi,
    k = 1, 2, ... (and is well scaled there, unlike cos cosh - 1), from that start; it
    converges to round-off in a few iterations (numpy only: no scipy import on the way
    to a uniform beam's modes).

    Parameters
    ----------
    n : int
        Number of roots wanted.
    """
    x = (np.arange(1, n + 1) + 0.5) * np.pi
    for _ in range(50):
        step = (np.cos(x) - 1.0 / np.cosh(x)) / (-np.sin(x) + np.tanh(x) / np.cosh(x))
        x = x - step
        if np.all(np.abs(step) <= 4 * np.finfo(float).eps * x):
            break
    return x


def shapes(beta_l: np.ndarray, xi) -> np.ndarray:
    """Normalised shapes Phi_n at fractional positions ``xi`` = x / L (from either end).

    Returns an array of shape (len(beta_l), len(xi)) with (1/L) int Phi**2 dx = 1.

    Parameters
    ----------
    beta_l : ndarray
        Roots bL [-] of the modes wanted (see :func:`free_free_roots`).
    xi : float or array_like
        Fractional positions x / L along the beam [-], in [0, 1].
    """
    bl = np.asarray(beta_l, dtype=float)[:, None]
    u = bl * np.atleast_1d(np.asarray(xi, dtype=float))[None, :]
    # s = (cosh bL - cos bL) / (sinh bL - sin bL); 1 - s is tiny for large bL, so the
    # growing part (1 - s) e^u / 2 of cosh u - s sinh u is written with e^(u - bL) <= 1.
    e_l = np.exp(-bl)
    s = (np.cosh(bl) - np.cos(bl)) / (np.sinh(bl) - np.sin(bl))
    grow = (
        0.5
        * (np.cos(bl) - np.sin(bl) - e_l)
        * np.exp(u - bl)
        / (0.5 * (1.0 - e_l**2) - np.sin(bl) * e_l)
    )
    return grow + 0.5 * (1.0 + s) * np.exp(-u) + np.cos(u) - s * np.sin(u)


@dataclass(frozen=True, eq=False)
class UniformShapes:
    """Mass-normalised bending shapes [1/sqrt(kg)] of a uniform free-free beam as a
    picklable callable of positions x [m from the tip] (a beam's modes can then be sent to
    other processes).

    Parameters
    ----------
    beta_l : ndarray
        Roots bL [-] of the modes kept.
    length : float
        Beam length [m].
    scale : float
        1 / sqrt(beam mass) [1/sqrt(kg)].
    """

    beta_l: np.ndarray
    length: float
    scale: float

    def __call__(self, x) -> np.ndarray:
        """The shapes at ``x`` [m from the tip] (see the class docstring)."""
        return self.scale * shapes(self.beta_l, np.asarray(x) / self.length)
