"""The lockstep time-stepper: a batch of impacts advanced together, step by step.

The same scheme and the same numbers as :func:`racket.solver.kernel.run_impacts` (see
:mod:`racket.solver.kernel`), laid out for the machine: the impacts of a tile (``TILE`` of them) sit
side by side along arrays, so that each pass of a step (the free step of every block, the
force of a linear ball, the force's response, the dissipated power, the bookkeeping) is a
loop over the impacts that LLVM vectorises.  What happens rarely, or per impact only, is
fixed up impact by impact with the scalar kernel's own functions: a non-linear law's Newton
iteration and the unhappy ball's return mapping, the contact opening within its step, the
moment the ball leaves, the test that it has left for good, the histories.  An impact that
has ended leaves the tile (the last one takes its place), so the passes run over the impacts
still in contact or watched.

The results are bit-identical to the scalar kernel's: every impact goes through the same
floating-point operations in the same order (numba compiles without fast-math, so LLVM
neither reassociates nor contracts to FMA, and vectorising a loop over independent impacts
changes neither); ``tests/test_lockstep.py`` compares the two bit for bit.
"""

from __future__ import annotations

import numpy as np
from numba import njit

from racket.solver.ball_kernel import ball_compression, force_coefficients, sine_step
from racket.solver.bed_kernel import bed_active
from racket.solver.contact_kernel import MEMO_ROWS, contact_compression, contact_force
from racket.solver.expm import step_back
from racket.solver.kernel import (
    _dot,
    _opening_fraction,
    _power,
    _reach,
    _record,
    string_deflection,
)
from racket.solver.layout import (
    DAMPING_LOSS,
    ENDED,
    F_PEAK,
    LINEAR,
    RECONTACTS,
    SINE,
    SINE_WORK,
    SNAP_RESIDUAL,
    SNAPPED,
    T_CONTACT,
    T_END,
    X_END,
)

TILE = 64
"""Impacts advanced together, at most: their per-block arrays (8 of nb x TILE) stay in the
L1 and L2 caches, and a pass over them is long enough to pay for its start (on the paper
racket 16 took a third longer than 64; 32 and 128 no less time than 64)."""

# Rows of the per-impact scalars (``v`` in :func:`_tile`).
(
    U, UD, FORCE, F_BEFORE, F_PEAK_, A, C0, C1, C2, X_O, X_BALL, RESIDUAL, DAMPING, WORK,
    POWER_PREV, CLOSING, TAU, U_P, UD_P, Z, F_NEW, POWER, ROW, NEED,
) = range(24)  # fmt: skip
N_SCALARS = 24

# Rows of the per-impact integers (``flags``).
IMPACT, STOP_AT, RECONTACT, SNAP, DONE = range(5)
N_FLAGS = 5

# Rows of the per-block arrays (``w``, nb x TILE each).
S0, S1, GIN0_0, GIN0_1, GIN1_0, GIN1_1, OUT_D0, OUT_D1 = range(8)
N_ROWS = 8


@njit(cache=True, nogil=True)
def run_lockstep(frame, points, ball, controls, out, start, stop, step):
    """Advance impacts ``start`` to ``stop`` (by ``step``) of P, ``TILE`` at a time in
    lockstep; the same arguments and outputs as :func:`racket.solver.kernel.run_impacts`.
    """
    nb = frame.trans.shape[0]
    w = np.empty((N_ROWS, nb, TILE))
    v = np.empty((N_SCALARS, TILE))
    memo = np.empty((MEMO_ROWS, TILE))  # the contacts' memos (contact_force)
    flags = np.empty((N_FLAGS, TILE), dtype=np.int64)
    scratch = np.empty((nb, 2))
    ids = np.arange(start, stop, step)
    tiles = -(-ids.size // TILE)
    size = -(-ids.size // max(tiles, 1))  # tiles of even size: no narrow last one
    for first in range(0, ids.size, size):
        _tile(frame, points, ball, controls, out, ids[first : first + size], w, v, flags, scratch,
              memo)  # fmt: skip


@njit(cache=True)
def _tile(frame, points, ball, controls, out, ids, w, v, flags, scratch, memo):
    """Impacts ``ids`` (at most TILE) from first touch until each has left for good."""
    n = ids.size
    nb = frame.trans.shape[0]
    law, params, sine = ball.law, ball.params, ball.law == SINE
    bed, plain = ball.bed, not bed_active(ball.bed)
    record = controls.record and out.history.shape[2] > 1
    for i in range(n):
        _start(frame, points, ball, out, ids[i], i, w, v, flags, record)
        memo[0, i] = -1.0
    step = 0
    t00, t01, t10, t11 = ball.trans[0, 0], ball.trans[0, 1], ball.trans[1, 0], ball.trans[1, 1]
    g00, g01, g10, g11 = ball.g0[0], ball.g0[1], ball.g1[0], ball.g1[1]
    dt, tol = controls.dt, controls.force_tol if sine else 0.0
    # Views made once (making one in the loop costs two atomic reference counts).
    s0, s1, out_d0, out_d1, trans = w[S0], w[S1], w[OUT_D0], w[OUT_D1], frame.trans
    gin0_0, gin0_1, gin1_0, gin1_1 = w[GIN0_0], w[GIN0_1], w[GIN1_0], w[GIN1_1]
    u, ud, u_p, ud_p, z, tau = v[U], v[UD], v[U_P], v[UD_P], v[Z], v[TAU]
    force, f_new, f_before, f_peak = v[FORCE], v[F_NEW], v[F_BEFORE], v[F_PEAK_]
    power, power_prev, damping, need, row = v[POWER], v[POWER_PREV], v[DAMPING], v[NEED], v[ROW]
    c0, c1, c2, stop_at, recontacts = v[C0], v[C1], v[C2], flags[STOP_AT], flags[RECONTACT]
    while n > 0 and step < controls.max_steps:
        # The free step (the force going from `force` to 0): ball, blocks, the point.
        _ball_free(t00, t01, t10, t11, g00, g01, u, ud, force, u_p, ud_p, z, n)
        _free_blocks(trans, s0, s1, gin0_0, gin0_1, out_d0, out_d1, force, z, n)
        # The force at the step's end.
        if law == LINEAR and plain:
            _linear_force(u_p, z, c0, c1, c2, f_peak, f_new, n)
        else:
            for i in range(n):
                z[i] = u_p[i] - z[i]  # z_pred
            for i in range(n):
                if sine:
                    _sine_force(params[0], controls, out, v, flags, i, step)
                else:
                    coef = (c0[i], c1[i], c2[i])
                    guess = 2.0 * force[i] - f_before[i]
                    inv_ks = points.inv_ks[flags[IMPACT, i]]
                    f_new[i] = contact_force(law, params, coef, bed, inv_ks, v[A, i], z[i],
                                             f_peak[i], guess, memo, i)  # fmt: skip
        # The response to the force at the step's end.
        _ball_force(g10, g11, u_p, ud_p, f_new, u, ud, tau, n)
        _force_blocks(s0, s1, gin1_0, gin1_1, f_new, n)
        if not sine:
            for i in range(n):  # the contact opened within the step: placed there
                if f_new[i] == 0.0 and force[i] > 0.0:
                    _opening(ball, law, params, points, flags[IMPACT, i], w, v, i, nb)
        _powers(frame.damp_blocks, frame.damp_rows, s0, s1, power, row, n)
        _bookkeep(power, power_prev, damping, force, f_new, f_before, f_peak, need, stop_at,
                  recontacts, dt, tol, n)  # fmt: skip
        step += 1
        for i in range(n):
            if (record or need[i] != 0.0) and not flags[DONE, i]:
                left = force[i] == 0.0 and f_before[i] > 0.0
                _after_step(frame, points, ball, controls, out, w, v, flags, scratch, i, step, left)
        # Impacts that have ended leave the tile; the last takes each one's place.
        i = 0
        while i < n:
            if flags[DONE, i] or step == flags[STOP_AT, i] or step >= controls.max_steps:
                if not flags[DONE, i]:
                    _finish(out, v, flags, i, step)
                n -= 1
                _move(w, v, flags, memo, n, i, nb)
            else:
                i += 1
    for i in range(n):  # (only if the budget allowed no step at all)
        _finish(out, v, flags, i, step)


@njit(cache=True)
def _start(frame, points, ball, out, p, i, w, v, flags, record):
    """Impact ``p`` into slot ``i``: its inputs, first state and outputs as if it never left
    (as :func:`racket.solver.kernel._one_impact` sets them up).
    """
    nb = frame.trans.shape[0]
    out_d = points.out_d[p]
    c = -ball.g1[0]
    for j in range(nb):
        for r in range(2):
            g0 = frame.g0[j, r, 0] * points.unit[p, j, 0] + frame.g0[j, r, 1] * points.unit[p, j, 1]
            g1 = frame.g1[j, r, 0] * points.unit[p, j, 0] + frame.g1[j, r, 1] * points.unit[p, j, 1]
            w[GIN0_0 + r, j, i] = g0
            w[GIN1_0 + r, j, i] = g1
            w[OUT_D0 + r, j, i] = out_d[j, r]
            w[S0 + r, j, i] = points.state0[p, j, r]
            out.state[p, j, r] = points.state0[p, j, r]
    for j in range(nb):
        c += out_d[j, 0] * w[GIN1_0, j, i] + out_d[j, 1] * w[GIN1_1, j, i]
    a = points.series[p] + c
    coef = force_coefficients(ball.law, ball.params, a)
    s = points.state0[p]
    ud = points.ball_velocity[p]
    v[U, i], v[UD, i], v[FORCE, i], v[F_BEFORE, i], v[F_PEAK_, i] = 0.0, ud, 0.0, 0.0, 0.0
    v[A, i], v[C0, i], v[C1, i], v[C2, i] = a, coef[0], coef[1], coef[2]
    v[X_O, i], v[X_BALL, i], v[RESIDUAL, i] = points.x_o[p], 0.0, -np.inf
    v[DAMPING, i], v[WORK, i] = 0.0, 0.0
    v[POWER_PREV, i] = _power(frame.damp_blocks, frame.damp_rows, s)
    v[CLOSING, i] = ud - _dot(points.out_v[p], s)
    flags[IMPACT, i], flags[STOP_AT, i], flags[RECONTACT, i] = p, -1, -1
    flags[SNAP, i], flags[DONE, i] = 0, 0
    out.ball[p, 0], out.ball[p, 1] = 0.0, ud
    summary = out.summary[p]
    summary[T_END] = summary[T_CONTACT] = summary[SINE_WORK] = 0.0
    summary[DAMPING_LOSS] = summary[X_END] = 0.0
    if record:
        _record(out.history, points, p, 0, 0.0, 0.0, 0.0, ud, s)


@njit(cache=True)
def _ball_free(t00, t01, t10, t11, g00, g01, u, ud, force, u_p, ud_p, z, n):
    """The ball's free step for the tile (and the point's displacement zeroed)."""
    for i in range(n):
        u_p[i] = t00 * u[i] + t01 * ud[i] + g00 * force[i]
        ud_p[i] = t10 * u[i] + t11 * ud[i] + g01 * force[i]
        z[i] = 0.0


@njit(cache=True)
def _free_blocks(trans, s0, s1, gin0_0, gin0_1, out_d0, out_d1, force, z, n):
    """The blocks' free step for the tile, and the point's displacement into ``z`` (summed
    over the blocks in order, as :func:`racket.solver.kernel._free_step`).
    """
    for j in range(trans.shape[0]):
        t00, t01, t10, t11 = trans[j, 0, 0], trans[j, 0, 1], trans[j, 1, 0], trans[j, 1, 1]
        for i in range(n):
            a0 = t00 * s0[j, i] + t01 * s1[j, i] + gin0_0[j, i] * force[i]
            a1 = t10 * s0[j, i] + t11 * s1[j, i] + gin0_1[j, i] * force[i]
            s0[j, i] = a0
            s1[j, i] = a1
            z[i] += out_d0[j, i] * a0 + out_d1[j, i] * a1


@njit(cache=True)
def _linear_force(u_p, z, c0, c1, c2, f_peak, f_new, n):
    """z_pred = u_p - z into ``z``, and a linear ball's force, as
    :func:`racket.solver.ball_kernel.monotone_force`: on the loading line, else the unloading one.
    """
    for i in range(n):
        z_pred = u_p[i] - z[i]
        z[i] = z_pred
        f = z_pred * c0[i]
        if not f >= f_peak[i]:
            f = max((z_pred - f_peak[i] * c2[i]) * c1[i], 0.0)
        f_new[i] = f


@njit(cache=True)
def _ball_force(g10, g11, u_p, ud_p, f_new, u, ud, tau, n):
    """The ball's response to the force at the step's end, for the tile (and the opening's
    fraction of the step reset to 1).
    """
    for i in range(n):
        u[i] = u_p[i] + g10 * f_new[i]
        ud[i] = ud_p[i] + g11 * f_new[i]
        tau[i] = 1.0


@njit(cache=True)
def _force_blocks(s0, s1, gin1_0, gin1_1, f_new, n):
    """The blocks' response to the force at the step's end, for the tile."""
    for j in range(s0.shape[0]):
        for i in range(n):
            s0[j, i] += gin1_0[j, i] * f_new[i]
            s1[j, i] += gin1_1[j, i] * f_new[i]


@njit(cache=True)
def _powers(damp_blocks, damp_rows, s0, s1, power, row, n):
    """Dissipated power of each impact of the tile, as :func:`racket.solver.kernel._power`
    (``row`` a scratch row).
    """
    for i in range(n):
        power[i] = 0.0
    for r in range(damp_rows.shape[0]):
        for i in range(n):
            row[i] = 0.0
        for k in range(damp_rows.shape[1]):
            j = damp_blocks[r, k]
            c0, c1 = damp_rows[r, k, 0], damp_rows[r, k, 1]
            for i in range(n):
                row[i] += c0 * s0[j, i] + c1 * s1[j, i]
        for i in range(n):
            power[i] += row[i] * row[i]


@njit(cache=True)
def _bookkeep(
    power, power_prev, damping, force, f_new, f_before, f_peak, need, stop_at, recontacts, dt,
    tol, n,
):  # fmt: skip
    """The step's damping loss, re-contacts, forces and peak, for the tile; ``need`` marks
    the impacts whose contact has just opened, or is open and not yet over, or whose force
    has fallen below ``tol`` of its peak (an unhappy ball's asymptotic end; tol = 0 for the
    other laws).
    """
    for i in range(n):
        damping[i] += 0.5 * (power[i] + power_prev[i]) * dt
        power_prev[i] = power[i]
        old, new = force[i], f_new[i]
        caught = new > 0.0 and old == 0.0
        recontacts[i] += 1 if caught else 0
        stop_at[i] = -1 if caught else stop_at[i]  # caught again: not over yet
        left = new == 0.0 and old > 0.0
        need[i] = 1.0 if left or (new == 0.0 and stop_at[i] < 0) else 0.0
        f_before[i] = old
        force[i] = new
        f_peak[i] = max(f_peak[i], new)
        need[i] = 1.0 if 0.0 < new < tol * f_peak[i] else need[i]


@njit(cache=True)
def _sine_force(k0, controls, out, v, flags, i, step):
    """The unhappy ball's return mapping for slot ``i`` (as the scalar kernel); a snap ends
    the impact there, at ``step``, when the run stops at snaps.
    """
    x_before = v[X_BALL, i]
    f_new, x_ball, step_residual = sine_step(
        k0, v[X_O, i], v[A, i], v[Z, i], x_before, controls.cross_tol
    )
    v[X_BALL, i] = x_ball
    v[F_NEW, i] = f_new
    v[WORK, i] += 0.5 * (v[FORCE, i] + f_new) * (x_ball - x_before)
    if step_residual > 0.0 and not flags[SNAP, i]:
        flags[SNAP, i] = 1
        v[RESIDUAL, i] = step_residual
        if controls.stop_on_snap:
            _finish(out, v, flags, i, step)
    elif not flags[SNAP, i]:
        v[RESIDUAL, i] = max(v[RESIDUAL, i], step_residual)


@njit(cache=True)
def _opening(ball, law, params, points, p, w, v, i, nb):
    """The contact of impact ``p`` (slot ``i``) opened within the step: the hold replaced
    by force -> 0 over tau dt (as :func:`racket.solver.kernel._one_impact`).
    """
    force = v[FORCE, i]
    tau = _opening_fraction(law, params, ball.bed, points.inv_ks[p], points.series[p], force,
                            v[F_PEAK_, i], v[Z, i])  # fmt: skip
    d0 = force * tau * (2.0 - tau) - force
    d1 = -force * tau * (1.0 - tau)
    v[U, i] += ball.g0[0] * d0 + ball.g1[0] * d1
    v[UD, i] += ball.g0[1] * d0 + ball.g1[1] * d1
    for j in range(nb):
        w[S0, j, i] += w[GIN0_0, j, i] * d0 + w[GIN1_0, j, i] * d1
        w[S1, j, i] += w[GIN0_1, j, i] * d0 + w[GIN1_1, j, i] * d1
    v[TAU, i] = tau


@njit(cache=True)
def _after_step(frame, points, ball, controls, out, w, v, flags, scratch, i, step, left):
    """Slot ``i`` after the step: its histories, the state when the ball left, and whether
    it has left for good (as :func:`racket.solver.kernel._one_impact`).
    """
    p = flags[IMPACT, i]
    law, params, sine = ball.law, ball.params, ball.law == SINE
    force, ud = v[FORCE, i], v[UD, i]
    record = controls.record and out.history.shape[2] > 1
    gathered = False
    if record and step < out.history.shape[2]:
        _gather(w, i, scratch)
        gathered = True
        x_now = v[X_BALL, i] if sine else ball_compression(law, params, force, v[F_PEAK_, i])
        string = string_deflection(ball.bed, points.inv_ks[p], force, v[F_PEAK_, i])
        _record(out.history, points, p, step, force, x_now, string, ud, scratch)
    f_peak = v[F_PEAK_, i]
    asymptotic = False
    if sine and 0.0 < force < controls.force_tol * f_peak:
        if not gathered:
            _gather(w, i, scratch)
            gathered = True
        asymptotic = abs(ud - _dot(points.out_v[p], scratch)) < controls.force_tol * v[CLOSING, i]
    dt = controls.dt
    if left or asymptotic:
        if not gathered:
            _gather(w, i, scratch)
            gathered = True
        tau = v[TAU, i]
        back = (1.0 - tau) * dt
        out.ball[p, 0] = v[U, i] - back * ud
        out.ball[p, 1] = ud
        summary = out.summary[p]
        summary[T_END] = step * dt
        summary[X_END] = v[X_BALL, i]
        summary[DAMPING_LOSS] = v[DAMPING, i] - back * v[POWER, i]
        summary[SINE_WORK] = v[WORK, i]
        contact = (step - 1 + tau) * dt if left and not sine else (step - 1) * dt
        summary[T_CONTACT] = step * dt if asymptotic else contact
        step_back(frame.blocks, scratch, back, out.state[p])
    if asymptotic:
        flags[STOP_AT, i] = step  # common speed approached asymptotically (no fold)
        return
    if flags[STOP_AT, i] < 0 and force == 0.0:
        if not gathered:
            _gather(w, i, scratch)
        if _dot(points.out_dc[p], scratch) > ud:
            # Open and separating in the dc motion: over for good once the gap exceeds the
            # largest deflection the remaining vibration can bring to the point.
            z_open = (
                v[X_BALL, i]
                if sine
                else contact_compression(law, params, ball.bed, points.inv_ks[p], 0.0, f_peak)
            )
            gap = z_open - (v[U, i] - _dot(points.out_d[p], scratch))
            if gap >= _reach(points.reach_w[p], frame.metric, scratch):
                flags[STOP_AT, i] = step + controls.extra_steps


@njit(cache=True)
def _gather(w, i, scratch):
    """Slot ``i``'s block states as (nb, 2), as the scalar kernel holds them."""
    for j in range(scratch.shape[0]):
        scratch[j, 0] = w[S0, j, i]
        scratch[j, 1] = w[S1, j, i]


@njit(cache=True)
def _finish(out, v, flags, i, step):
    """Slot ``i``'s summary once it has ended at ``step``."""
    summary = out.summary[flags[IMPACT, i]]
    summary[F_PEAK] = v[F_PEAK_, i]
    summary[SNAPPED] = 1.0 if flags[SNAP, i] else 0.0
    summary[ENDED] = 1.0 if step == flags[STOP_AT, i] else 0.0
    summary[SNAP_RESIDUAL] = v[RESIDUAL, i]
    summary[RECONTACTS] = max(flags[RECONTACT, i], 0)
    flags[DONE, i] = 1


@njit(cache=True)
def _move(w, v, flags, memo, src, dst, nb):
    """Slot ``src``'s impact into slot ``dst``."""
    for r in range(MEMO_ROWS):
        memo[r, dst] = memo[r, src]
    for r in range(N_ROWS):
        for j in range(nb):
            w[r, j, dst] = w[r, j, src]
    for r in range(N_SCALARS):
        v[r, dst] = v[r, src]
    for r in range(N_FLAGS):
        flags[r, dst] = flags[r, src]
