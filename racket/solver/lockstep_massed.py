"""The lockstep kernel's forces on a bed with a mass (:mod:`racket.solver.lockstep`): the
two-unknown Newton iteration of :func:`racket.solver.bed_mass_kernel.massed_forces` run over
the whole tile at once, with the same numbers.

Each iteration is four passes over the tile's impacts: which still iterate and where the
ball's law is at their iterates (:func:`_branches`, or :func:`_lines` for a linear law),
the powers the law needs there (an unloading curve, a power law's loading curve:
:func:`_powers`, one impact at a time, as there is no vectorised ``pow`` that gives the C
library's bits; the memo's unloading exponents made first, where missing), the ball's
compression from them (:func:`_powered`), and the Newton step with the bed's law and the
stiffening law's loading hyperbola (:func:`_newton_step`).  All but the powers are loops that LLVM
vectorises (AVX2 here).  Every impact keeps its own stopping rule: one that settles, or
whose ball's force is not positive, stops iterating, one that has not settled after
``_FUSED_STEPS`` goes to the scalar solves (:func:`racket.solver.bed_mass_kernel.
_ball_force` and :func:`racket.solver.bed_mass_kernel.bed_force`, impact by impact), and
the passes end when no impact iterates.  Every impact so goes through the floating-point
operations of the scalar kernel's iteration, in the same order, and gets the same bits.

What makes the passes vectorise: numpy's error model (a division by zero gives inf or NaN
instead of raising: Python's model tests every divisor, a branch out of the loop; the
iteration's divisions give the same bits in either), each pass's rows passed as arrays of
their own (LLVM checks at run time that the arrays a loop writes overlap no other, and
gives up beyond a few checks), and every impact's loads and stores made whether or not it
iterates (the arithmetic of those that do not is discarded: a store on a condition is a
masked store, slow on AMD's processors).

What keeps numba's reference counts out of the iteration: the rows are viewed once a step,
before it (each view costs an atomic increment and decrement), and the passes call nothing
(a pass that calls, or that branches into loops of its own, keeps the counts of its array
arguments, two atomic operations each a call; one that does not has them cancelled at
compile time).
"""

from __future__ import annotations

import math

from numba import njit

from racket.solver import tile_layout as tl
from racket.solver.ball_kernel import NEWTON_SETTLED
from racket.solver.bed_kernel import stored
from racket.solver.bed_mass_kernel import (
    _FUSED_STEPS,
    EARLY_OVER_LATE,
    _ball_force,
    _remember,
    bed_force,
    bed_residual,
    massed_solve,
    peak_top,
    unloading_memo,
)
from racket.solver.layout import LINEAR, STIFFENING

# Rows of the tile's scratch for the iteration (``lanes``, LANE_ROWS x TILE).
(
    F1, U, RUN, HYPERBOLA, POWERED, UNLOADING, DEN, POWER, G, DG, X0, R0, Q_P, QD_P, F2_GUESS,
    U_GUESS, RATE,
) = range(17)  # fmt: skip
LANE_ROWS = 17
"""F1 and U the unknowns (the ball's force and the bed's loading-curve deflection), RUN 1
while the impact iterates; HYPERBOLA 1 where the ball's law is on the stiffening law's
loading hyperbola at the iterate, POWERED 1 where it needs a power there, UNLOADING 1 on
an unloading curve, POWER the power and DEN its exponent's inverse; G and DG the ball's
compression and its d/dF at the iterate; X0 and R0 the ball's compression and the bed's
deflection with neither force at the step's end, Q_P and QD_P the bed mass's predicted
displacement and velocity, F2_GUESS and U_GUESS the bed's force and deflection
extrapolated, RATE the set-back curve's delta / F_max."""


@njit(cache=True)
def massed_pass(law, params, bed, v, memo, lanes, picks, dt, h, n):
    """The ball's and the bed's forces at the step's end for the tile's ``n`` impacts on a
    bed with a mass, and the bed mass's step, as :func:`racket.solver.kernel._one_impact`
    does them (into the rows F_NEW, F2_NEW, Z, Q and QD of ``v``).

    Parameters
    ----------
    law, params : int, ndarray
        The ball's law and its numbers.
    bed : ndarray (3,)
        The bed's stretch [1/m^2], loss [-] and moving mass [kg].
    v, memo : ndarray
        The tile's scalars and contact memos (:mod:`racket.solver.tile_layout`,
        :data:`racket.solver.bed_mass_kernel.BED_MEMO_ROWS`).
    lanes, picks : ndarray (LANE_ROWS, TILE), ndarray (TILE,) of int
        Scratch.
    dt, h : float
        The step [s] and the bed mass's coupling h (bed_mass_coupling) [m/N].
    """
    _predict(v[tl.FORCE], v[tl.F2], v[tl.F2_BEFORE], v[tl.Q], v[tl.QD],
             v[tl.U_P], v[tl.Z], lanes[Q_P], lanes[QD_P], lanes[F2_GUESS], lanes[X0], lanes[R0],
             dt, h, bed[2], n)  # fmt: skip
    k = v[tl.K_BED]
    for i in range(n):  # the memo is the last step's but where the bed's peak has moved
        if memo[0, i] != v[tl.F2_PEAK, i]:  # (a call only then)
            _remember(k[i], bed[0], bed[1], v[tl.F2_PEAK, i], memo, i)
    _extrapolate(memo[2], memo[3], memo[7], memo[11], memo[8], memo[9], memo[10],
                 v[tl.F2_PEAK], lanes[RATE], lanes[U_GUESS], lanes[F1], lanes[U], lanes[RUN],
                 n)  # fmt: skip
    # The rows the iteration works on, viewed once a step, not once an iteration (see the
    # module docstring).
    f1_max, comp, a1, top, u_max, delta = (v[tl.F_PEAK_], v[tl.COMP], v[tl.A1], memo[5],
                                           memo[1], memo[2])  # fmt: skip
    f1, u, run, hyperbola, powered, unloading = (lanes[F1], lanes[U], lanes[RUN],
                                                 lanes[HYPERBOLA], lanes[POWERED],
                                                 lanes[UNLOADING])  # fmt: skip
    den, power, g, dg, rate, x0, r0 = (lanes[DEN], lanes[POWER], lanes[G], lanes[DG],
                                       lanes[RATE], lanes[X0], lanes[R0])  # fmt: skip
    exponent, x_lim, f_c = memo[6], params[1], params[0] * params[1]
    for _ in range(_FUSED_STEPS):
        if law == LINEAR:
            _lines(params, f1_max, f1, run, hyperbola, powered, g, dg, n)
        else:
            _branches(law, f1_max, f1, run, hyperbola, powered, unloading, n)
        m, live = _picks(run, powered, picks, n)
        if not live:
            break
        for t in range(m):  # (here: a pass that calls keeps its arrays' reference counts)
            i = picks[t]
            if unloading[i] != 0.0 and (memo[4, i] != f1_max[i] or math.isnan(memo[6, i])):
                unloading_memo(law, params, f1_max[i], memo, i)  # made for another force
        _powers(params, f1_max, exponent, f1, unloading, den, power, picks, m)
        _powered(f1, powered, unloading, top, power, den, g, dg, n)
        _newton_step(x_lim, f_c, bed[0], h, comp, a1, u_max, delta, rate, k, x0, r0, hyperbola,
                     g, dg, f1, u, run, n)  # fmt: skip
    for i in range(n):  # the scalar solves where the iteration gave no positive force
        if lanes[RUN, i] != 0.0:
            lanes[F1, i] = 0.0  # (not settled)
        if not lanes[F1, i] > 0.0:
            coef = (v[tl.C1_0, i], v[tl.C1_1, i], v[tl.C1_2, i])
            f1 = _ball_force(law, params, coef, v[tl.A1, i], lanes[X0, i] + h * lanes[F2_GUESS, i],
                             v[tl.F_PEAK_, i], 2.0 * v[tl.FORCE, i] - v[tl.F_BEFORE, i], memo,
                             i)  # fmt: skip
            lanes[F1, i] = f1
            lanes[U, i] = bed_force(k[i], bed[0], bed[1], v[tl.COMP, i], lanes[R0, i] + h * f1,
                                    v[tl.F2_PEAK, i], lanes[U_GUESS, i], memo, i)[1]  # fmt: skip
    for i in range(n):  # the ball's peak within the step, as massed_forces
        guess = 2.0 * v[tl.FORCE, i] - v[tl.F_BEFORE, i]
        top = peak_top(memo[10, i], v[tl.F_BEFORE, i], v[tl.FORCE, i], lanes[F1, i],
                       v[tl.F_PEAK_, i])  # fmt: skip
        if top > v[tl.F_PEAK_, i]:
            v[tl.F_PEAK_, i] = top
            coef = (v[tl.C1_0, i], v[tl.C1_1, i], v[tl.C1_2, i])
            lanes[F1, i], lanes[U, i] = massed_solve(law, params, coef, v[tl.A1, i], bed, k[i],
                                                     v[tl.COMP, i], h, lanes[X0, i],
                                                     lanes[R0, i], top, v[tl.F2_PEAK, i], guess,
                                                     lanes[F2_GUESS, i], memo, i)  # fmt: skip
    _store(bed[0], bed[1], bed[2], dt, h, k, lanes[F1], lanes[U], lanes[X0],
           lanes[F2_GUESS], lanes[Q_P], lanes[QD_P], v[tl.F2_PEAK], memo[0], memo[1], memo[2],
           memo[3], memo[7], memo[11], memo[8], memo[9], memo[10], v[tl.Z], v[tl.Q], v[tl.QD],
           v[tl.F_NEW], v[tl.F2_NEW], n)  # fmt: skip


@njit(cache=True, error_model="numpy")
def _predict(force, f2, f2_before, q, qd, u_p, y_p, q_p, qd_p, f2_guess, x0, r0, dt,
             h, mass, n):  # fmt: skip
    """The bed mass's free step and what the two equations need from it, for the tile (the
    frame's point's displacement ``y_p`` as the free blocks' pass left it).
    """
    for i in range(n):
        q_p[i] = q[i] + dt * qd[i] + EARLY_OVER_LATE * h * (force[i] - f2[i])
        qd_p[i] = qd[i] + 0.5 * dt * (force[i] - f2[i]) / mass
        f2_guess[i] = 2.0 * f2[i] - f2_before[i]  # the bed's force extrapolated
        x0[i] = u_p[i] - q_p[i]
        r0[i] = q_p[i] - y_p[i]


@njit(cache=True, error_model="numpy")
def _extrapolate(delta, u_last, u_1, u_2, f_last, f_1, f_2, f2_max, rate, u_guess, f1, u, run,
                 n):  # fmt: skip
    """The unknowns' first guesses, extrapolated quadratically from the last three steps (the
    memo's rows: the bed's u and the ball's force, the last first), and the set-back curve's
    delta / F_max; every impact set iterating.
    """
    for i in range(n):
        rate[i] = delta[i] / f2_max[i] if f2_max[i] > 0.0 else 0.0
        u_guess[i] = 3.0 * (u_last[i] - u_1[i]) + u_2[i]
        f1[i] = 3.0 * (f_last[i] - f_1[i]) + f_2[i]
        u[i] = u_guess[i]
        run[i] = 1.0


@njit(cache=True, error_model="numpy")
def _lines(params, f1_max, f1, run, hyperbola, powered, g, dg, n):
    """Which impacts still iterate (``run``; an impact whose ball's force is not positive
    stops), and a linear law's compression and d/dF at their iterates, on its loading line or
    its unloading one (into ``g`` and ``dg``; as :func:`racket.solver.bed_mass_kernel.
    _ball_at`).
    """
    k, e2 = params[0], params[1] * params[1]
    for i in range(n):
        f, f_max, g_i, dg_i = f1[i], f1_max[i], g[i], dg[i]
        going = run[i] != 0.0 and f > 0.0
        if going and f >= f_max:
            g_i, dg_i = f / k, 1.0 / k
        elif going:
            g_i, dg_i = (f_max * (1.0 - e2) + e2 * f) / k, e2 / k
        run[i], g[i], dg[i] = (1.0 if going else 0.0), g_i, dg_i
        hyperbola[i] = powered[i] = 0.0


@njit(cache=True, error_model="numpy")
def _branches(law, f1_max, f1, run, hyperbola, powered, unloading, n):
    """Which impacts still iterate (``run``; an impact whose ball's force is not positive
    stops), and where a law other than the linear one (:func:`_lines`) is at their iterates
    (as :func:`racket.solver.bed_mass_kernel._ball_at`): on the stiffening law's loading
    hyperbola (``hyperbola``, for :func:`_newton_step`), or on a power (``powered``: a power
    law's loading curve, or an ``unloading`` curve, for :func:`_powers`).

    (A pass of its own for the linear law: one pass with a loop for each kept its arrays'
    reference counts, see the module docstring.)
    """
    for i in range(n):
        f, f_max = f1[i], f1_max[i]
        going = run[i] != 0.0 and f > 0.0
        loading = law == STIFFENING and f >= f_max
        run[i] = 1.0 if going else 0.0
        hyperbola[i] = 1.0 if going and loading else 0.0
        powered[i] = 1.0 if going and not loading else 0.0
        unloading[i] = 1.0 if f < f_max else 0.0


@njit(cache=True)
def _picks(run, powered, picks, n):
    """The impacts marked ``powered`` into ``picks``, in order (no branch to mispredict);
    returns how many, and whether any impact is still iterating.
    """
    live, m = False, 0
    for i in range(n):
        picks[m] = i
        m += 1 if powered[i] != 0.0 else 0
        live = live or run[i] != 0.0
    return m, live


@njit(cache=True)
def _powers(params, f1_max, exponent, f1, unloading, den, power, picks, m):
    """The powers of the ``m`` impacts in ``picks``, one impact at a time, as
    :func:`racket.solver.bed_mass_kernel._ball_at` takes them: (F / F_max) ** (1 / b) on an
    unloading curve (its exponent b, the memo's ``exponent``, into ``den``), (F / k) ** (1 / a)
    on a power law's loading curve.
    """
    for t in range(m):
        i = picks[t]
        if unloading[i] != 0.0:
            den[i] = exponent[i]
            power[i] = (f1[i] / f1_max[i]) ** (1.0 / den[i])
        else:
            den[i] = params[1]
            power[i] = (f1[i] / params[0]) ** (1.0 / params[1])


@njit(cache=True, error_model="numpy")
def _powered(f1, powered, unloading, top, power, den, g, dg, n):
    """The ball's compression and its d/dF at the iterates from their powers: X_max
    (F / F_max)**(1 / b) unloading (X_max the memo's ``top``), (F / k)**(1 / a) loading.
    """
    for i in range(n):
        g_i, dg_i = g[i], dg[i]
        if powered[i] != 0.0:
            g_i = top[i] * power[i] if unloading[i] != 0.0 else power[i]
            dg_i = g_i / (den[i] * f1[i])
        g[i], dg[i] = g_i, dg_i


@njit(cache=True, error_model="numpy")
def _newton_step(x_lim, f_c, s, h, comp, a1, u_max, delta, rate, k, x0, r0, hyperbola, g_at,
                 dg_at, f1, u, run, n):  # fmt: skip
    """One Newton step in the two unknowns (:func:`racket.solver.bed_mass_kernel.
    massed_forces`) for the impacts still iterating, the ball's compression and its d/dF at
    the iterate in ``g_at`` and ``dg_at`` or on the stiffening law's loading hyperbola
    (X_lim, F_c = k X_lim); an impact whose step settles stops.
    """
    for i in range(n):
        # (every load and store for every impact: see the module docstring)
        f, x, going = f1[i], u[i], run[i] != 0.0
        k_i, c_i, a1_i, u_max_i, delta_i, rate_i = k[i], comp[i], a1[i], u_max[i], delta[i], rate[i]
        x0_i, r0_i, g, dg = x0[i], r0[i], g_at[i], dg_at[i]
        still = 0.0
        if going:
            if hyperbola[i] != 0.0:
                g, dg = x_lim * f / (f + f_c), x_lim * f_c / ((f + f_c) * (f + f_c))
            f2, df2, r2, d2 = bed_residual(k_i, s, x, delta_i, u_max_i, rate_i, c_i, r0_i, h, f)
            r1, d1 = g + a1_i * f - x0_i - h * f2, dg + a1_i
            step1 = -(r1 * d2 + h * df2 * r2) / (d1 * d2 - h * h * df2)
            step2 = (h * step1 - r2) / d2
            f += step1
            x += step2
            settled = abs(step1) <= NEWTON_SETTLED * f and abs(step2) <= NEWTON_SETTLED * (
                abs(x) + u_max_i
            )
            still = 0.0 if settled else 1.0
        f1[i], u[i], run[i] = f, x, still


@njit(cache=True, error_model="numpy")
def _store(s, loss, mass, dt, h, k, f1, u, x0, f2_guess, q_p, qd_p, f2_max, m_force, m_u, m_delta,
           u_last, u_1, u_2, f_last, f_1, f_2, z, q, qd, f_new, f2_new, n):  # fmt: skip
    """The forces, the memo's history of the unknowns (and its numbers for the bed's new
    largest force, while loading), the ball's compression with no force of its own, and the
    bed mass's state at the step's end, for the tile (in loops of few arrays each, which LLVM
    vectorises: it checks at run time that the arrays a loop writes overlap no other).
    """
    for i in range(n):
        u_2[i], u_1[i], u_last[i] = u_1[i], u_last[i], u[i]
    for i in range(n):
        f_2[i], f_1[i], f_last[i] = f_1[i], f_last[i], f1[i]
    for i in range(n):
        x = u[i]
        f2 = k[i] * x * (1.0 + s * x * x)
        f2_new[i] = f2
        if f2 > f2_max[i]:  # loading: the memo made for the largest force this sets
            m_force[i], m_u[i], m_delta[i] = f2, x, 2.0 * loss * stored(k[i], s, x) / f2
    for i in range(n):
        f, f2 = f1[i], f2_new[i]
        z[i] = x0[i] + h * f2_guess[i]
        q[i] = q_p[i] + h * (f - f2)
        qd[i] = qd_p[i] + 0.5 * dt * (f - f2) / mass
        f_new[i] = f
