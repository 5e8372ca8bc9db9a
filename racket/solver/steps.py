"""The exact step of a racket's linear system over a time step: the transition matrices
the time-steppers advance its 2x2 blocks with (:mod:`racket.solver.kernel`) and the feel's
hand force is computed with (:mod:`racket.feel`).
"""

from __future__ import annotations

import numpy as np

STEPS_KEPT = 8
"""Time steps whose matrices a system keeps (a linear ball has the same step at every
speed, so a sweep asks again and again for the same few)."""


def system_steps(system, dt: float):
    """Exact step of every block of ``system`` for an input varying linearly over ``dt``.

    Returns T, G0, G1, each (nb, 2, 2): s1 = T s0 + G0 u0 + G1 u1 for the block input u (a
    2-vector) going linearly from u0 to u1.  The last :data:`STEPS_KEPT` are kept in the
    system's ``step_memo``.

    Parameters
    ----------
    system : racket.system.BlockSystem
        The racket's linear system, in real 2x2 blocks.
    dt : float
        Time step [s].
    """
    memo = system.step_memo
    if dt not in memo:
        if len(memo) >= STEPS_KEPT:
            memo.pop(next(iter(memo)))
        memo[dt] = block_steps(system.blocks, dt)
    return memo[dt]


def block_steps(blocks: np.ndarray, dt: float):
    """T, G0, G1 (n, 2, 2) of :func:`system_steps` for any 2x2 blocks (n, 2, 2).

    From the exponential of the augmented system (state, input, input rate), compiled
    (:func:`racket.solver.expm.augmented_steps`): no BLAS call, so no BLAS worker thread
    competes with the time-stepper's threads for the cores.

    Parameters
    ----------
    blocks : ndarray (n, 2, 2)
        The 2x2 blocks of s' = blocks s [1/s].
    dt : float
        Time step [s].
    """
    from racket.solver.expm import augmented_steps  # numba loads on first use (import time)

    blocks = np.ascontiguousarray(blocks, dtype=float).reshape(-1, 2, 2)
    trans = np.empty_like(blocks)
    g0 = np.empty_like(blocks)
    g1 = np.empty_like(blocks)
    augmented_steps(blocks, float(dt), trans, g0, g1)
    return trans, g0, g1
