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
from functools import cached_property

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
    return _shapes_from(shape_terms(beta_l), xi)


def _shapes_from(terms: tuple, xi) -> np.ndarray:
    """:func:`shapes` from the modes' :func:`shape_terms` ``terms`` (made once for many
    calls), at fractional positions ``xi`` [-].
    """
    bl, grow, grow_scale, fall, s = terms
    u = bl * np.atleast_1d(np.asarray(xi, dtype=float))[None, :]
    # s = (cosh bL - cos bL) / (sinh bL - sin bL); 1 - s is tiny for large bL, so the
    # growing part (1 - s) e^u / 2 of cosh u - s sinh u is written with e^(u - bL) <= 1.
    return grow * np.exp(u - bl) / grow_scale + fall * np.exp(-u) + np.cos(u) - s * np.sin(u)


def shape_terms(beta_l: np.ndarray) -> tuple:
    """The parts of :func:`shapes` that do not depend on the position, (len(beta_l), 1)
    each [-]: bL, the growing part's factor and its scale, the falling part's factor and s.

    Parameters
    ----------
    beta_l : ndarray
        Roots bL [-] of the modes wanted (see :func:`free_free_roots`).
    """
    bl = np.asarray(beta_l, dtype=float)[:, None]
    e_l = np.exp(-bl)
    s = (np.cosh(bl) - np.cos(bl)) / (np.sinh(bl) - np.sin(bl))
    grow = 0.5 * (np.cos(bl) - np.sin(bl) - e_l)
    return bl, grow, 0.5 * (1.0 - e_l**2) - np.sin(bl) * e_l, 0.5 * (1.0 + s), s


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

    @cached_property
    def _terms(self) -> tuple:
        """:func:`shape_terms` of the modes, computed once (the shapes are frozen)."""
        return shape_terms(self.beta_l)

    def __call__(self, x) -> np.ndarray:
        """The shapes at ``x`` [m from the tip] (see the class docstring)."""
        return self.scale * _shapes_from(self._terms, np.asarray(x) / self.length)
