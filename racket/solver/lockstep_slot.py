"""The lockstep kernel's work on one impact (slot) of its tile (:mod:`racket.solver.lockstep`):
setting a slot up, what happens rarely or per impact only (the unhappy ball's return mapping,
the contact opening within its step, the ball leaving a bed with a mass, the moment it leaves,
the test that it has left for good, the histories), and moving a slot, each as
:func:`racket.solver.kernel._one_impact` does it, with the same numbers.
"""

from __future__ import annotations

import numpy as np
from numba import njit

from racket.solver import layout
from racket.solver import tile_layout as tl
from racket.solver.ball_kernel import ball_compression, force_coefficients, sine_step
from racket.solver.bed_mass_kernel import (
    EARLY_OVER_LATE,
    bed_deflection,
    bed_elastic,
    opening_fraction,
)
from racket.solver.expm import step_back
from racket.solver.kernel import (
    _dot,
    _opening_fraction,
    _power,
    _record,
    string_deflection,
)


@njit(cache=True)
def start_slot(frame, points, ball, out, p, i, w, v, flags, record, h):
    """Impact ``p`` into slot ``i``: its inputs, first state and outputs as if it never left
    (as :func:`racket.solver.kernel._one_impact` sets them up); ``h`` the coupling of a bed
    with a mass (0 without).
    """
    nb = frame.trans.shape[0]
    out_d = points.out_d[p]
    c = -ball.g1[0]
    for j in range(nb):
        for r in range(2):
            g0 = frame.g0[j, r, 0] * points.unit[p, j, 0] + frame.g0[j, r, 1] * points.unit[p, j, 1]
            g1 = frame.g1[j, r, 0] * points.unit[p, j, 0] + frame.g1[j, r, 1] * points.unit[p, j, 1]
            w[tl.GIN0_0 + r, j, i] = g0
            w[tl.GIN1_0 + r, j, i] = g1
            w[tl.OUT_D0 + r, j, i] = out_d[j, r]
            w[tl.S0 + r, j, i] = points.state0[p, j, r]
            out.state[p, j, r] = points.state0[p, j, r]
    for j in range(nb):
        c += out_d[j, 0] * w[tl.GIN1_0, j, i] + out_d[j, 1] * w[tl.GIN1_1, j, i]
    a = points.series[p] + c
    coef = force_coefficients(ball.law, ball.params, a)
    s = points.state0[p]
    ud = points.ball_velocity[p]
    v[tl.Q, i], v[tl.QD, i], v[tl.F2, i], v[tl.F2_NEW, i], v[tl.F2_PEAK, i] = (
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
    )
    v[tl.F2_BEFORE, i] = 0.0
    if h > 0.0:  # a bed with a mass, as the scalar kernel sets it up
        a1 = -ball.g1[0] + h
        coef1 = force_coefficients(ball.law, ball.params, a1)
        v[tl.A1, i], v[tl.C1_0, i], v[tl.C1_1, i], v[tl.C1_2, i] = a1, coef1[0], coef1[1], coef1[2]
        v[tl.K_BED, i] = 1.0 / points.inv_ks[p]
        v[tl.COMP, i] = (
            h
            + (points.series[p] - points.inv_ks[p])
            + _dot(out_d, w[tl.GIN1_0 : tl.GIN1_1 + 1, :, i].T)
        )
        v[tl.Q, i], v[tl.QD, i] = _dot(out_d, s), _dot(points.out_v[p], s)
    v[tl.U, i], v[tl.UD, i], v[tl.FORCE, i], v[tl.F_BEFORE, i], v[tl.F_PEAK_, i] = (
        0.0,
        ud,
        0.0,
        0.0,
        0.0,
    )
    v[tl.A, i], v[tl.C0, i], v[tl.C1, i], v[tl.C2, i] = a, coef[0], coef[1], coef[2]
    v[tl.X_O, i], v[tl.X_BALL, i], v[tl.RESIDUAL, i] = points.x_o[p], 0.0, -np.inf
    v[tl.Z_REST_FOR, i] = np.nan  # (made when the contact first opens)
    v[tl.DAMPING, i], v[tl.WORK, i] = 0.0, 0.0
    v[tl.POWER_PREV, i] = _power(frame.damp_blocks, frame.damp_rows, s)
    v[tl.CLOSING, i] = ud - _dot(points.out_v[p], s)
    flags[tl.IMPACT, i], flags[tl.STOP_AT, i], flags[tl.RECONTACT, i] = p, -1, -1
    flags[tl.SNAP, i], flags[tl.DONE, i] = 0, 0
    out.ball[p, 0], out.ball[p, 1] = 0.0, ud
    summary = out.summary[p]
    summary[layout.T_END] = summary[layout.T_CONTACT] = summary[layout.SINE_WORK] = 0.0
    summary[layout.DAMPING_LOSS] = summary[layout.X_END] = 0.0
    summary[layout.BED_VEL], summary[layout.BED_ELASTIC], summary[layout.BED_PEAK] = (
        v[tl.QD, i],
        0.0,
        0.0,
    )
    if record:
        _record(out.history, points, p, 0, 0.0, 0.0, 0.0, ud, s, 0.0)


@njit(cache=True)
def sine_force(k0, controls, out, v, flags, i, step):
    """The unhappy ball's return mapping for slot ``i`` (as the scalar kernel); a snap ends
    the impact there, at ``step``, when the run stops at snaps.
    """
    x_before = v[tl.X_BALL, i]
    f_new, x_ball, step_residual = sine_step(
        k0, v[tl.X_O, i], v[tl.A, i], v[tl.Z, i], x_before, controls.cross_tol
    )
    v[tl.X_BALL, i] = x_ball
    v[tl.F_NEW, i] = f_new
    v[tl.WORK, i] += 0.5 * (v[tl.FORCE, i] + f_new) * (x_ball - x_before)
    if step_residual > 0.0 and not flags[tl.SNAP, i]:
        flags[tl.SNAP, i] = 1
        v[tl.RESIDUAL, i] = step_residual
        if controls.stop_on_snap:
            finish(out, v, flags, i, step)
    elif not flags[tl.SNAP, i]:
        v[tl.RESIDUAL, i] = max(v[tl.RESIDUAL, i], step_residual)


@njit(cache=True)
def opening(ball, law, params, points, p, w, v, i, nb):
    """The contact of impact ``p`` (slot ``i``) opened within the step: the hold replaced
    by force -> 0 over tau dt (as :func:`racket.solver.kernel._one_impact`).
    """
    force = v[tl.FORCE, i]
    tau = _opening_fraction(law, params, ball.bed, points.inv_ks[p], points.series[p], force,
                            v[tl.F_PEAK_, i], v[tl.Z, i])  # fmt: skip
    d0 = force * tau * (2.0 - tau) - force
    d1 = -force * tau * (1.0 - tau)
    v[tl.U, i] += ball.g0[0] * d0 + ball.g1[0] * d1
    v[tl.UD, i] += ball.g0[1] * d0 + ball.g1[1] * d1
    for j in range(nb):
        w[tl.S0, j, i] += w[tl.GIN0_0, j, i] * d0 + w[tl.GIN1_0, j, i] * d1
        w[tl.S1, j, i] += w[tl.GIN0_1, j, i] * d0 + w[tl.GIN1_1, j, i] * d1
    v[tl.TAU, i] = tau


@njit(cache=True)
def after_step(frame, points, ball, controls, out, w, v, flags, scratch, i, step, left, memo):
    """Slot ``i`` after the step: its histories, the state when the ball left, and an
    unhappy ball's asymptotic end (as :func:`racket.solver.kernel._one_impact`; whether an
    open contact is over for good: :func:`racket.solver.lockstep_watch.watch_tile`).
    """
    p = flags[tl.IMPACT, i]
    law, params, sine = ball.law, ball.params, ball.law == layout.SINE
    bed = ball.bed
    massed = bed[2] > 0.0 and not sine
    force, ud = v[tl.FORCE, i], v[tl.UD, i]
    record = controls.record and out.history.shape[2] > 1
    gathered = False
    if record and step < out.history.shape[2] and out.history.shape[0] == 1:
        out.history[layout.H_FORCE, p, step] = force  # the force's history alone
    elif record and step < out.history.shape[2]:
        gather(w, i, scratch)
        gathered = True
        x_now = v[tl.X_BALL, i] if sine else ball_compression(law, params, force, v[tl.F_PEAK_, i])
        if massed:
            string = bed_deflection(bed, 1.0 / points.inv_ks[p], memo, i, v[tl.F2, i],
                                    v[tl.F2_PEAK, i])  # fmt: skip
        else:
            string = string_deflection(bed, points.inv_ks[p], force, v[tl.F_PEAK_, i])
        _record(out.history, points, p, step, force, x_now, string, ud, scratch,
                v[tl.F2, i] if massed else force)  # fmt: skip
    f_peak = v[tl.F_PEAK_, i]
    asymptotic = False
    if sine and 0.0 < force < controls.force_tol * f_peak:
        if not gathered:
            gather(w, i, scratch)
            gathered = True
        asymptotic = (
            abs(ud - _dot(points.out_v[p], scratch)) < controls.force_tol * v[tl.CLOSING, i]
        )
    dt = controls.dt
    if left or asymptotic:
        if not gathered:
            gather(w, i, scratch)
        tau = v[tl.TAU, i]
        back = (1.0 - tau) * dt
        out.ball[p, 0] = v[tl.U, i] - back * ud
        out.ball[p, 1] = ud
        summary = out.summary[p]
        summary[layout.T_END] = step * dt
        summary[layout.X_END] = v[tl.X_BALL, i]
        summary[layout.DAMPING_LOSS] = v[tl.DAMPING, i] - back * v[tl.POWER, i]
        summary[layout.SINE_WORK] = v[tl.WORK, i]
        contact = (step - 1 + tau) * dt if left and not sine else (step - 1) * dt
        summary[layout.T_CONTACT] = step * dt if asymptotic else contact
        step_back(frame.blocks, scratch, back, out.state[p])
        if massed:  # the bed mass at the step's end: see racket.solver.bed_mass_kernel
            summary[layout.BED_VEL], summary[layout.BED_PEAK] = v[tl.QD, i], v[tl.F2_PEAK, i]
            f2 = v[tl.F2, i]
            summary[layout.BED_ELASTIC] = bed_elastic(bed, 1.0 / points.inv_ks[p], memo, i, f2,
                                               v[tl.F2_PEAK, i]) + 0.5 * (
                points.series[p] - points.inv_ks[p]) * f2 * f2  # fmt: skip
    if asymptotic:
        flags[tl.STOP_AT, i] = step  # common speed approached asymptotically (no fold)


@njit(cache=True)
def gather(w, i, scratch):
    """Slot ``i``'s block states as (nb, 2), as the scalar kernel holds them."""
    for j in range(scratch.shape[0]):
        scratch[j, 0] = w[tl.S0, j, i]
        scratch[j, 1] = w[tl.S1, j, i]


@njit(cache=True)
def finish(out, v, flags, i, step):
    """Slot ``i``'s summary once it has ended at ``step``."""
    summary = out.summary[flags[tl.IMPACT, i]]
    summary[layout.F_PEAK] = v[tl.F_PEAK_, i]
    summary[layout.SNAPPED] = 1.0 if flags[tl.SNAP, i] else 0.0
    summary[layout.ENDED] = 1.0 if step == flags[tl.STOP_AT, i] else 0.0
    summary[layout.SNAP_RESIDUAL] = v[tl.RESIDUAL, i]
    summary[layout.RECONTACTS] = max(flags[tl.RECONTACT, i], 0)
    flags[tl.DONE, i] = 1


@njit(cache=True)
def move_slot(w, v, flags, memo, src, dst, nb):
    """Slot ``src``'s impact into slot ``dst``."""
    for r in range(memo.shape[0]):
        memo[r, dst] = memo[r, src]
    for r in range(tl.N_ROWS):
        for j in range(nb):
            w[r, j, dst] = w[r, j, src]
    for r in range(tl.N_SCALARS):
        v[r, dst] = v[r, src]
    for r in range(tl.N_FLAGS):
        flags[r, dst] = flags[r, src]


@njit(cache=True)
def massed_opening(ball, law, params, v, i, dt, h):
    """The ball of slot ``i`` left a bed with a mass within the step: the ball's and the
    bed mass's hold replaced by force -> 0 over tau dt (as the scalar kernel).
    """
    force = v[tl.FORCE, i]
    tau = opening_fraction(law, params, force, v[tl.F_PEAK_, i], v[tl.Z, i])
    d0 = force * tau * (2.0 - tau) - force
    d1 = -force * tau * (1.0 - tau)
    v[tl.U, i] += ball.g0[0] * d0 + ball.g1[0] * d1
    v[tl.UD, i] += ball.g0[1] * d0 + ball.g1[1] * d1
    v[tl.Q, i] += EARLY_OVER_LATE * h * d0 + h * d1
    v[tl.QD, i] += 0.5 * dt * (d0 + d1) / ball.bed[2]
    v[tl.TAU, i] = tau
