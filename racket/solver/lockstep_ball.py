"""The lockstep kernel's force of a power-law ball on the paper's bed (:mod:`racket.solver.
lockstep`): the safeguarded Newton iteration of :func:`racket.solver.ball_kernel.
branch_force` run over the whole tile at once, with the same numbers.

Each step picks every impact's branch and bracket impact by impact (:func:`_brackets`: the
loading curve, the unloading one with its exponent, or no contact); each iteration is then
three passes over the tile, as :mod:`racket.solver.lockstep_massed` makes them: where the
ball's law is at the iterates and its closed forms (:func:`_branches`), the powers it needs
one impact at a time (:func:`_powers`), and the Newton step with its bracket
(:func:`_newton_step`), vectorised by LLVM.  Every impact keeps its own stopping rule (a
zero residual, or a step within :data:`racket.solver.ball_kernel.NEWTON_SETTLED` of the
force), and the passes end when no impact iterates, so that each goes through the scalar
kernel's floating-point operations in the same order, and gets the same bits.
"""

from __future__ import annotations

import math

from numba import njit

from racket.solver import tile_layout as tl
from racket.solver.ball_kernel import NEWTON_STEPS, _loading, bracketed_newton, unloading_exponent
from racket.solver.layout import STIFFENING

# Rows of the tile's scratch (``lanes``).
F, LO, HI, B, TOP, RUN, POWERED, G, DG, POWER = range(10)
BALL_ROWS = 10
"""F the force iterated, LO and HI its bracket, B the branch's unloading exponent (1 on the
loading curve), TOP the ball's compression at its largest force, RUN 1 while the impact
iterates, POWERED 1 where the ball's law needs a power at the iterate (POWER), G and DG
the ball's compression and its d/dF there."""


@njit(cache=True)
def ball_pass(law, params, v, memo, lanes, picks, n):
    """The ball's force at the step's end for the tile's ``n`` impacts, a power law (POWER,
    GROWING or STIFFENING) on the paper's bed, as
    :func:`racket.solver.ball_kernel.monotone_force` gives it (into the row F_NEW of ``v``,
    from its rows A, Z (the force-free compression), F_PEAK_, FORCE and F_BEFORE).

    Parameters
    ----------
    law, params : int, ndarray
        The ball's law and its numbers.
    v, memo : ndarray
        The tile's scalars and contact memos (:mod:`racket.solver.tile_layout`); the memo's
        rows 0 and 4 keep each impact's unloading exponent and the largest force it is for.
    lanes, picks : ndarray (>= BALL_ROWS, TILE), ndarray (TILE,) of int
        Scratch.
    """
    _brackets(law, params, v, memo, lanes, n)
    # The rows the iteration works on, viewed once a step, not once an iteration (each view
    # costs an atomic increment and decrement of its array's reference count).
    f_max, a, target = v[tl.F_PEAK_], v[tl.A], v[tl.Z]
    f, lo, hi, run, powered, g, dg = (lanes[F], lanes[LO], lanes[HI], lanes[RUN],
                                      lanes[POWERED], lanes[G], lanes[DG])  # fmt: skip
    for _ in range(NEWTON_STEPS):
        _branches(law, params, f_max, f, run, powered, g, dg, n)
        if not _powers(params, f_max, lanes, picks, n):
            break
        _newton_step(a, target, f, lo, hi, g, dg, run, n)
    for i in range(n):
        v[tl.F_NEW, i] = lanes[F, i]


@njit(cache=True)
def _brackets(law, params, v, memo, lanes, n):
    """Each impact's branch, bracket and first iterate, as
    :func:`racket.solver.ball_kernel.branch_force` chooses them (the unloading exponent
    kept in the memo for the largest force it is for: the same number, worked out once);
    an impact out of contact gets its force, 0, and does not iterate.
    """
    for i in range(n):
        a, z, f_max = v[tl.A, i], v[tl.Z, i], v[tl.F_PEAK_, i]
        guess = 2.0 * v[tl.FORCE, i] - v[tl.F_BEFORE, i]
        top = _loading(law, params, f_max)[0] if f_max > 0.0 else 0.0
        lanes[TOP, i], lanes[RUN, i] = top, 1.0
        if z >= top + a * f_max:  # loading: b plays no part
            lo, hi, lanes[B, i] = f_max, z / a, 1.0
        elif z <= 0.0:
            lo, hi, lanes[RUN, i], lanes[F, i] = 0.0, 0.0, 0.0, 0.0
        else:
            if memo[0, i] != f_max:
                memo[0, i], memo[4, i] = f_max, unloading_exponent(law, params, f_max)
            lo, hi, lanes[B, i] = 0.0, f_max, memo[4, i]
        if lanes[RUN, i] != 0.0:
            lanes[F, i] = guess if lo < guess < hi else 0.5 * (lo + hi)
        lanes[LO, i], lanes[HI, i] = lo, hi


@njit(cache=True, error_model="numpy")
def _branches(law, params, f_max, f, run, powered, g, dg, n):
    """Where the ball's law is at the iterates (:func:`racket.solver.ball_kernel._branch`):
    no force (compression 0, d/dF infinite), the stiffening law's loading hyperbola (both
    into ``g`` and ``dg``), or a power (``powered``: a power law's loading curve, an
    unloading curve).
    """
    x_lim, f_c = params[1], params[0] * params[1]
    for i in range(n):
        f_i, going, g_i, dg_i = f[i], run[i] != 0.0, g[i], dg[i]
        hyperbola = law == STIFFENING and f_i >= f_max[i]
        if going and f_i <= 0.0:
            g_i, dg_i = 0.0, math.inf
        elif going and hyperbola:
            g_i, dg_i = x_lim * f_i / (f_i + f_c), x_lim * f_c / ((f_i + f_c) * (f_i + f_c))
        powered[i] = 1.0 if going and f_i > 0.0 and not hyperbola else 0.0
        g[i], dg[i] = g_i, dg_i


@njit(cache=True)
def _powers(params, f_max, lanes, picks, n):
    """The ball's compression and its d/dF at the iterates marked POWERED, one impact at a
    time, as :func:`racket.solver.ball_kernel._branch` takes them: (F / k) ** (1 / a) on a
    power law's loading curve, X_max (F / F_max) ** (1 / b) on an unloading curve.  Returns
    whether any impact is still iterating.
    """
    live, m = False, 0
    for i in range(n):  # the impacts to power, in order (no branch to mispredict)
        picks[m] = i
        m += 1 if lanes[POWERED, i] != 0.0 else 0
        live = live or lanes[RUN, i] != 0.0
    for t in range(m):
        i = picks[t]
        f = lanes[F, i]
        if f >= f_max[i]:
            x = (f / params[0]) ** (1.0 / params[1])
            lanes[G, i], lanes[DG, i] = x, x / (params[1] * f)
        else:
            b = lanes[B, i]
            x = lanes[TOP, i] * (f / f_max[i]) ** (1.0 / b)
            lanes[G, i], lanes[DG, i] = x, x / (b * f)
    return live


@njit(cache=True, error_model="numpy")
def _newton_step(a, target, f, lo, hi, g, dg, run, n):
    """One safeguarded Newton step of g(F) + a F = target in the bracket [lo, hi]
    (:func:`racket.solver.ball_kernel._branch_force`) for the impacts still iterating; one
    whose residual is zero, or whose step settles, stops.
    """
    for i in range(n):
        # (every load and store for every impact: see racket.solver.lockstep_massed)
        f_i, lo_i, hi_i, going, a_i = f[i], lo[i], hi[i], run[i] != 0.0, a[i]
        g_i, dg_i, target_i = g[i], dg[i], target[i]
        still = 0.0
        if going:
            resid = g_i + a_i * f_i - target_i
            if resid != 0.0:  # (zero: the bracket would close on f, Newton's step leave it)
                f_i, lo_i, hi_i, settled = bracketed_newton(f_i, resid, dg_i + a_i, lo_i, hi_i)
                still = 0.0 if settled else 1.0
        f[i], lo[i], hi[i], run[i] = f_i, lo_i, hi_i, still
