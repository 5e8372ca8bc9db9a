"""The lockstep time-stepper: a batch of impacts advanced together, step by step.

The same scheme and the same numbers as :func:`racket.solver.kernel.run_impacts` (see
:mod:`racket.solver.kernel`), laid out for the machine: the impacts of a tile (``TILE`` of
them) sit side by side along arrays, so that each pass of a step (the free step of every
block, the force of a linear ball, the force's response and, with a free racket's modal
damping, the dissipated power with it, the bookkeeping) is a loop over the impacts that LLVM
vectorises (on a free racket the blocks' passes read one row an impact and block, the
point's displacement, from which each mode's inputs are made, rather than five:
:func:`_modal`); the test that an open contact has left for good is one pass over the tile's
open contacts (:mod:`racket.solver.lockstep_watch`). A power-law ball's Newton iteration, on
the paper's bed (:mod:`racket.solver.lockstep_ball`) or on a bed with a mass
(:mod:`racket.solver.lockstep_massed`), runs over the tile too, a pass an iteration, each
impact stopping by its own rule. What happens rarely, or per impact only, is fixed up impact
by impact with the scalar kernel's own functions: the force on a massless bed that stiffens
or loses energy, the unhappy ball's return mapping, the contact opening within its step, the
moment the ball leaves, the histories. An impact that has ended leaves the tile (the last
one takes its place), so the passes run over the impacts still in contact or watched.

The results are bit-identical to the scalar kernel's: every impact goes through the same
floating-point operations in the same order (numba compiles without fast-math, so LLVM
neither reassociates nor contracts to FMA, and vectorising a loop over independent impacts
changes neither); ``tests/test_lockstep.py`` compares the two bit for bit.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from racket.solver import lockstep_slot as slot
from racket.solver import lockstep_watch as watch
from racket.solver import tile_layout as tl
from racket.solver.bed_kernel import bed_active
from racket.solver.bed_mass_kernel import BED_MEMO_ROWS, bed_mass_coupling
from racket.solver.contact_kernel import MEMO_ROWS, contact_force
from racket.solver.kernel import _power, damping_diagonal
from racket.solver.layout import H_FORCE, LINEAR, SINE
from racket.solver.lockstep_ball import BALL_ROWS, ball_pass
from racket.solver.lockstep_massed import LANE_ROWS, massed_pass


@njit(cache=True, nogil=True)
def run_lockstep(frame, points, ball, controls, out, start, stop, step):
    """Advance impacts ``start`` to ``stop`` (by ``step``) of P, ``TILE`` at a time in
    lockstep; the same arguments and outputs as :func:`racket.solver.kernel.run_impacts`.
    """
    nb = frame.trans.shape[0]
    w = np.empty((tl.N_ROWS, nb, tl.TILE))
    v = np.empty((tl.N_SCALARS, tl.TILE))
    memo = np.empty((max(MEMO_ROWS, BED_MEMO_ROWS), tl.TILE))  # the contacts' memos
    flags = np.empty((tl.N_FLAGS, tl.TILE), dtype=np.int64)
    scratch = np.empty((nb, 2))
    ids = np.arange(start, stop, step)
    tiles = -(-ids.size // tl.TILE)
    size = -(-ids.size // max(tiles, 1))  # tiles of even size: no narrow last one
    # the force iterations' scratch (racket.solver.lockstep_massed, lockstep_ball)
    lanes = np.empty((max(LANE_ROWS, BALL_ROWS), tl.TILE))
    picks = np.empty(tl.TILE, dtype=np.int64)
    for first in range(0, ids.size, size):
        _tile(frame, points, ball, controls, out, ids[first : first + size], w, v, flags, scratch,
              memo, lanes, picks)  # fmt: skip


@njit(cache=True)
def _tile(frame, points, ball, controls, out, ids, w, v, flags, scratch, memo, lanes, picks):
    """Impacts ``ids`` (at most TILE) from first touch until each has left for good."""
    n = ids.size
    nb = frame.trans.shape[0]
    law, params, sine = ball.law, ball.params, ball.law == SINE
    bed, plain = ball.bed, not bed_active(ball.bed)
    massed = bed[2] > 0.0 and not sine
    record = controls.record and out.history.shape[2] > 1
    full = record and out.history.shape[0] > 1  # every history, or the force's alone
    dt = controls.dt
    h = bed_mass_coupling(dt, bed[2]) if massed else 0.0
    for i in range(n):
        slot.start_slot(frame, points, ball, out, ids[i], i, w, v, flags, record, h)
        memo[0, i] = -1.0
        memo[3, i], memo[4, i] = 0.0, -1.0
        for r in range(7, memo.shape[0]):
            memo[r, i] = 0.0
    step = 0
    t00, t01, t10, t11 = ball.trans[0, 0], ball.trans[0, 1], ball.trans[1, 0], ball.trans[1, 1]
    g00, g01, g10, g11 = ball.g0[0], ball.g0[1], ball.g1[0], ball.g1[1]
    tol = controls.force_tol if sine else 0.0
    # Views made once (making one in the loop costs two atomic reference counts).
    s0, s1, out_d0, out_d1, trans = w[tl.S0], w[tl.S1], w[tl.OUT_D0], w[tl.OUT_D1], frame.trans
    damp_blocks, damp_rows = frame.damp_blocks, frame.damp_rows
    diagonal = damping_diagonal(damp_blocks)  # the power then summed in the response
    summed = damp_blocks if diagonal else np.empty((0, 1), dtype=np.int64)
    shapes = np.empty((nb, 4))
    modal = _modal(frame.g0, frame.g1, w, shapes, n)
    gin0_0, gin0_1, gin1_0, gin1_1 = w[tl.GIN0_0], w[tl.GIN0_1], w[tl.GIN1_0], w[tl.GIN1_1]
    u, ud, u_p, ud_p, z, tau = v[tl.U], v[tl.UD], v[tl.U_P], v[tl.UD_P], v[tl.Z], v[tl.TAU]
    force, f_new, f_before, f_peak = v[tl.FORCE], v[tl.F_NEW], v[tl.F_BEFORE], v[tl.F_PEAK_]
    power, power_prev, damping, need, row = (
        v[tl.POWER],
        v[tl.POWER_PREV],
        v[tl.DAMPING],
        v[tl.NEED],
        v[tl.ROW],
    )
    c0, c1, c2, stop_at, recontacts = (
        v[tl.C0],
        v[tl.C1],
        v[tl.C2],
        flags[tl.STOP_AT],
        flags[tl.RECONTACT],
    )
    f_frame, f_frame_new = (v[tl.F2], v[tl.F2_NEW]) if massed else (force, f_new)  # on the frame
    # (and the points' arrays taken out of their tuple once: see lockstep_watch)
    out_dc, out_d, out_v, reach_w = points.out_dc, points.out_d, points.out_v, points.reach_w
    series, inv_ks_rows, metric = points.series, points.inv_ks, frame.metric
    while n > 0 and step < controls.max_steps:
        # The free step (the force going from `force` to 0): ball, blocks, the point.
        _ball_free(t00, t01, t10, t11, g00, g01, u, ud, force, u_p, ud_p, z, n)
        _free_blocks(trans, shapes, modal, s0, s1, gin0_0, gin0_1, out_d0, out_d1, f_frame, z, n)
        # The force at the step's end.
        if massed:
            massed_pass(law, params, bed, v, memo, lanes, picks, dt, h, n)
        elif law == LINEAR and plain:
            _linear_force(u_p, z, c0, c1, c2, f_peak, f_new, n)
        else:
            for i in range(n):
                z[i] = u_p[i] - z[i]  # z_pred
            if plain and not sine:  # a power law on the paper's bed
                ball_pass(law, params, v, memo, lanes, picks, n)
            else:
                for i in range(n):
                    if sine:
                        slot.sine_force(params[0], controls, out, v, flags, i, step)
                    else:
                        coef = (c0[i], c1[i], c2[i])
                        guess = 2.0 * force[i] - f_before[i]
                        inv_ks = points.inv_ks[flags[tl.IMPACT, i]]
                        f_new[i] = contact_force(law, params, coef, bed, inv_ks, v[tl.A, i],
                                                 z[i], f_peak[i], guess, memo, i)  # fmt: skip
        # The response to the force at the step's end.
        _ball_force(g10, g11, u_p, ud_p, f_new, u, ud, tau, n)
        _force_blocks(shapes, modal, s0, s1, gin1_0, gin1_1, out_d0, f_frame_new, summed,
                      damp_rows, power, n)  # fmt: skip
        if massed:
            for i in range(n):  # the ball left the bed within the step: placed there
                if f_new[i] == 0.0 and force[i] > 0.0:
                    slot.massed_opening(ball, law, params, v, i, dt, h)
                v[tl.F2_BEFORE, i], v[tl.F2, i] = v[tl.F2, i], v[tl.F2_NEW, i]
                v[tl.F2_PEAK, i] = max(v[tl.F2_PEAK, i], v[tl.F2, i])
        elif not sine:
            for i in range(n):  # the contact opened within the step: placed there
                if f_new[i] == 0.0 and force[i] > 0.0:
                    slot.opening(ball, law, params, points, flags[tl.IMPACT, i], w, v, i, nb)
                    if diagonal:  # its power anew
                        slot.gather(w, i, scratch)
                        power[i] = _power(damp_blocks, damp_rows, scratch)
        if not diagonal:
            _powers(damp_blocks, damp_rows, s0, s1, power, row, n)
        _bookkeep(power, power_prev, damping, force, f_new, f_before, f_peak, need, stop_at,
                  recontacts, dt, tol, n)  # fmt: skip
        step += 1
        if record and not full and step < out.history.shape[2]:
            for i in range(n):
                if not flags[tl.DONE, i]:
                    out.history[H_FORCE, flags[tl.IMPACT, i], step] = force[i]
        for i in range(n):  # the histories, the ball leaving, a sine law's end
            if (full or need[i] != 0.0) and not flags[tl.DONE, i]:
                left = force[i] == 0.0 and f_before[i] > 0.0
                if full or left or sine:
                    slot.after_step(frame, points, ball, controls, out, w, v, flags, scratch, i,
                                    step, left, memo)  # fmt: skip
        for i in range(n):  # what the test needs, made anew where a largest force changed
            if sine or force[i] != 0.0 or stop_at[i] >= 0 or flags[tl.DONE, i]:
                continue
            if v[tl.Z_REST_FOR, i] != f_peak[i] or (massed and memo[0, i] != v[tl.F2_PEAK, i]):
                watch.rest(law, params, bed, massed, inv_ks_rows, v, flags, memo, i)
        watch.watch_tile(massed, sine, bed[0], bed[2], out_dc, out_d, out_v, reach_w, series,
                         inv_ks_rows, metric, s0, s1, v, flags, memo, step, controls.extra_steps,
                         n)  # fmt: skip
        # Impacts that have ended leave the tile; the last takes each one's place.
        i = 0
        while i < n:
            if flags[tl.DONE, i] or step == flags[tl.STOP_AT, i] or step >= controls.max_steps:
                if not flags[tl.DONE, i]:
                    slot.finish(out, v, flags, i, step)
                n -= 1
                slot.move_slot(w, v, flags, memo, n, i, nb)
            else:
                i += 1
    for i in range(n):  # (only if the budget allowed no step at all)
        slot.finish(out, v, flags, i, step)


@njit(cache=True)
def _ball_free(t00, t01, t10, t11, g00, g01, u, ud, force, u_p, ud_p, z, n):
    """The ball's free step for the tile (and the point's displacement zeroed)."""
    for i in range(n):
        u_p[i] = t00 * u[i] + t01 * ud[i] + g00 * force[i]
        ud_p[i] = t10 * u[i] + t11 * ud[i] + g01 * force[i]
        z[i] = 0.0


@njit(cache=True)
def _modal(g0, g1, w, shapes, n):
    """Whether each block's input from the force is, for every impact of the tile, a number
    of the block's times the point's displacement row, to the bit, and that row's velocity
    half zero (a free racket's modes: the force moves a mode's velocity by its shape at the
    point, which is the point's displacement from that mode); the numbers into ``shapes``
    (nb, 4): the inputs' second columns, g0's and g1's.  Then the blocks' passes read that
    row alone, not five (:func:`_free_blocks`, :func:`_force_blocks`), with the same bits:
    the same products, and the zero half's terms are +-0 added to a point's displacement
    that starts at +0 (so never -0: it stays itself), for finite states.
    """
    for j in range(shapes.shape[0]):
        shapes[j, 0], shapes[j, 1] = g0[j, 0, 1], g0[j, 1, 1]
        shapes[j, 2], shapes[j, 3] = g1[j, 0, 1], g1[j, 1, 1]
        for i in range(n):
            p = w[tl.OUT_D0, j, i]
            if w[tl.OUT_D1, j, i] != 0.0:
                return False
            for k in range(4):
                stored, made = w[tl.GIN0_0 + k, j, i], shapes[j, k] * p
                if stored != made or math.copysign(1.0, stored) != math.copysign(1.0, made):
                    return False
    return True


@njit(cache=True)
def _free_blocks(trans, shapes, modal, s0, s1, gin0_0, gin0_1, out_d0, out_d1, force, z, n):
    """The blocks' free step for the tile, and the point's displacement into ``z`` (summed
    over the blocks in order, as :func:`racket.solver.kernel._free_step`); ``modal``: the
    inputs made from ``shapes`` and ``out_d0`` (:func:`_modal`).
    """
    for j in range(trans.shape[0]):
        t00, t01, t10, t11 = trans[j, 0, 0], trans[j, 0, 1], trans[j, 1, 0], trans[j, 1, 1]
        if modal:
            c0, c1 = shapes[j, 0], shapes[j, 1]
            for i in range(n):
                p = out_d0[j, i]
                a0 = t00 * s0[j, i] + t01 * s1[j, i] + (c0 * p) * force[i]
                a1 = t10 * s0[j, i] + t11 * s1[j, i] + (c1 * p) * force[i]
                s0[j, i] = a0
                s1[j, i] = a1
                z[i] += p * a0
        else:
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
def _force_blocks(shapes, modal, s0, s1, gin1_0, gin1_1, out_d0, f_new, damp_blocks, damp_rows,
                  power, n):  # fmt: skip
    """The blocks' response to the force at the step's end, for the tile (``modal``: see
    :func:`_free_blocks`), and the dissipated power of damping rows of one block each, in the
    blocks' order (:func:`racket.solver.kernel.damping_diagonal`), as :func:`_powers` sums it,
    block by block as each is updated; ``damp_blocks`` with no rows: the response alone (the
    power zeroed, for :func:`_powers`).
    """
    for i in range(n):
        power[i] = 0.0
    r = 0
    for j in range(s0.shape[0]):
        damped = r < damp_blocks.shape[0] and damp_blocks[r, 0] == j
        d0, d1 = (damp_rows[r, 0, 0], damp_rows[r, 0, 1]) if damped else (0.0, 0.0)
        r += 1 if damped else 0
        c0, c1 = shapes[j, 2], shapes[j, 3]
        # (four loops of two shapes: a branch within a loop would stop LLVM vectorising it,
        # and the power summed in a loop of its own after the response cost a free racket 4 %)
        if damped and modal:
            for i in range(n):
                p = out_d0[j, i]
                a0 = s0[j, i] + (c0 * p) * f_new[i]
                a1 = s1[j, i] + (c1 * p) * f_new[i]
                s0[j, i] = a0
                s1[j, i] = a1
                row = 0.0 + (d0 * a0 + d1 * a1)
                power[i] += row * row
        elif damped:
            for i in range(n):
                a0 = s0[j, i] + gin1_0[j, i] * f_new[i]
                a1 = s1[j, i] + gin1_1[j, i] * f_new[i]
                s0[j, i] = a0
                s1[j, i] = a1
                row = 0.0 + (d0 * a0 + d1 * a1)
                power[i] += row * row
        elif modal:
            for i in range(n):
                p = out_d0[j, i]
                s0[j, i] += (c0 * p) * f_new[i]
                s1[j, i] += (c1 * p) * f_new[i]
        else:
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
