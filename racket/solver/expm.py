"""Matrix exponentials for the time-steppers, compiled and without BLAS: the exact step of
each 2x2 block over a time step (:func:`augmented_steps`, for
:func:`racket.solver.steps.block_steps`), and a block state stepped back in time
(:func:`step_back`, to the moment the ball left within its step).
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit


@njit(cache=True)
def step_back(blocks, s, back, out):
    """Block states ``back`` seconds before ``s`` with no force acting, exp(-A back) s,
    into ``out``.
    """
    for j in range(s.shape[0]):
        m00, m01, m10, m11 = _expm2(
            -back * blocks[j, 0, 0],
            -back * blocks[j, 0, 1],
            -back * blocks[j, 1, 0],
            -back * blocks[j, 1, 1],
        )
        out[j, 0] = m00 * s[j, 0] + m01 * s[j, 1]
        out[j, 1] = m10 * s[j, 0] + m11 * s[j, 1]


@njit(cache=True)
def _expm2(a, b, c, d):
    """Exp of the 2x2 matrix [[a, b], [c, d]] in closed form: with t the half trace and
    N = M - t I, N**2 = delta I, so exp(M) = e**t (C I + S N), C = cosh(sqrt(delta)) and
    S = sinh(sqrt(delta)) / sqrt(delta) (cos and sin for delta < 0).
    """
    t = 0.5 * (a + d)
    h = 0.5 * (a - d)
    delta = h * h + b * c
    if delta > 0.0:
        q = math.sqrt(delta)
        cc, ss = math.cosh(q), math.sinh(q) / q
    elif delta < 0.0:
        q = math.sqrt(-delta)
        cc, ss = math.cos(q), math.sin(q) / q
    else:
        cc, ss = 1.0, 1.0
    g = math.exp(t)
    return g * (cc + ss * h), g * ss * b, g * ss * c, g * (cc - ss * h)


@njit(cache=True)
def _expm(m):
    """exp(m) of a small square matrix: balancing, then scaling and squaring of a Taylor
    series.

    The matrix is first balanced by a diagonal similarity of powers of two (exact in
    floating point; as LAPACK's gebal, Parlett and Reinsch), since a block's state (q, q')
    mixes units; then it is scaled by 2**-s until its norm is below 1/4, where 18 terms of
    the series leave a truncation error below 1e-27 of the result, and squared s times back.
    """
    n = m.shape[0]
    d = np.ones(n)
    a = m.copy()
    for _ in range(20):
        changed = False
        for i in range(n):
            col, row = 0.0, 0.0
            for j in range(n):
                if j != i:
                    col += abs(a[j, i])
                    row += abs(a[i, j])
            if col == 0.0 or row == 0.0:
                continue
            f = 1.0
            while col < row / 2.0:
                col *= 2.0
                row /= 2.0
                f *= 2.0
            while col >= row * 2.0:
                col /= 2.0
                row *= 2.0
                f /= 2.0
            if f != 1.0:
                changed = True
                d[i] *= f
                for j in range(n):
                    a[i, j] /= f
                    a[j, i] *= f
        if not changed:
            break
    norm = 0.0
    for i in range(n):
        row = 0.0
        for j in range(n):
            row += abs(a[i, j])
        norm = max(norm, row)
    s = 0
    while norm > 0.25:
        norm *= 0.5
        s += 1
    a *= 0.5**s
    result = np.eye(n)
    term = np.eye(n)
    for k in range(1, 19):
        term = _matmul(term, a) / k
        result += term
    for _ in range(s):
        result = _matmul(result, result)
    for i in range(n):  # undo the balancing: exp(m) = D exp(D^-1 m D) D^-1
        for j in range(n):
            result[i, j] *= d[i] / d[j]
    return result


@njit(cache=True)
def _matmul(a, b):
    """A @ b by loops (numba's @ calls BLAS)."""
    n, m, p = a.shape[0], a.shape[1], b.shape[1]
    out = np.zeros((n, p))
    for i in range(n):
        for k in range(m):
            aik = a[i, k]
            for j in range(p):
                out[i, j] += aik * b[k, j]
    return out


@njit(cache=True)
def augmented_steps(blocks, dt, trans, g0, g1):
    """Fill T, G0, G1 of each block from exp of [[A, I, 0], [0, 0, I], [0, 0, 0]] dt."""
    aug = np.zeros((6, 6))
    for i in range(blocks.shape[0]):
        aug[:] = 0.0
        for r in range(2):
            for c in range(2):
                aug[r, c] = blocks[i, r, c] * dt
            aug[r, 2 + r] = dt
            aug[2 + r, 4 + r] = dt
        e = _expm(aug)
        for r in range(2):
            for c in range(2):
                g1[i, r, c] = e[r, 4 + c] / dt
                g0[i, r, c] = e[r, 2 + c] - g1[i, r, c]
                trans[i, r, c] = e[r, c]
