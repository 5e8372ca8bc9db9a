"""The lockstep kernel's work on one impact (slot) of its tile (:mod:`racket.solver.lockstep`):
setting a slot up, what happens rarely or per impact only (the unhappy ball's return mapping,
the contact opening within its step, a bed with a mass's forces, the moment the ball leaves,
the test that it has left for good, the histories), and moving a slot, each as
:func:`racket.solver.kernel._one_impact` does it, with the same numbers.
"""

from __future__ import annotations

import numpy as np
from numba import njit

from racket.solver.ball_kernel import ball_compression, force_coefficients, sine_step
from racket.solver.bed_mass_kernel import (
    bed_deflection,
    bed_elastic,
    bed_gap,
    massed_forces,
    opening_fraction,
)
from racket.solver.contact_kernel import contact_compression
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
    BED_ELASTIC,
    BED_PEAK,
    BED_VEL,
    DAMPING_LOSS,
    ENDED,
    F_PEAK,
    H_FORCE,
    RECONTACTS,
    SINE,
    SINE_WORK,
    SNAP_RESIDUAL,
    SNAPPED,
    T_CONTACT,
    T_END,
    X_END,
)
from racket.solver.tile_layout import (
    A1,
    C0,
    C1,
    C1_0,
    C1_1,
    C1_2,
    C2,
    CLOSING,
    COMP,
    DAMPING,
    DONE,
    F2,
    F2_BEFORE,
    F2_NEW,
    F2_PEAK,
    F_BEFORE,
    F_NEW,
    F_PEAK_,
    FORCE,
    GIN0_0,
    GIN0_1,
    GIN1_0,
    GIN1_1,
    IMPACT,
    N_FLAGS,
    N_ROWS,
    N_SCALARS,
    OUT_D0,
    POWER,
    POWER_PREV,
    QD,
    RECONTACT,
    RESIDUAL,
    S0,
    S1,
    SNAP,
    STOP_AT,
    TAU,
    U_P,
    UD,
    WORK,
    X_BALL,
    X_O,
    A,
    Q,
    U,
    Z,
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
    v[Q, i], v[QD, i], v[F2, i], v[F2_NEW, i], v[F2_PEAK, i] = 0.0, 0.0, 0.0, 0.0, 0.0
    v[F2_BEFORE, i] = 0.0
    if h > 0.0:  # a bed with a mass, as the scalar kernel sets it up
        a1 = -ball.g1[0] + h
        coef1 = force_coefficients(ball.law, ball.params, a1)
        v[A1, i], v[C1_0, i], v[C1_1, i], v[C1_2, i] = a1, coef1[0], coef1[1], coef1[2]
        v[COMP, i] = (
            h + (points.series[p] - points.inv_ks[p]) + _dot(out_d, w[GIN1_0 : GIN1_1 + 1, :, i].T)
        )
        v[Q, i], v[QD, i] = _dot(out_d, s), _dot(points.out_v[p], s)
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
    summary[BED_VEL], summary[BED_ELASTIC], summary[BED_PEAK] = v[QD, i], 0.0, 0.0
    if record:
        _record(out.history, points, p, 0, 0.0, 0.0, 0.0, ud, s, 0.0)


@njit(cache=True)
def sine_force(k0, controls, out, v, flags, i, step):
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
            finish(out, v, flags, i, step)
    elif not flags[SNAP, i]:
        v[RESIDUAL, i] = max(v[RESIDUAL, i], step_residual)


@njit(cache=True)
def opening(ball, law, params, points, p, w, v, i, nb):
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
def after_step(frame, points, ball, controls, out, w, v, flags, scratch, i, step, left, memo):
    """Slot ``i`` after the step: its histories, the state when the ball left, and whether
    it has left for good (as :func:`racket.solver.kernel._one_impact`).
    """
    p = flags[IMPACT, i]
    law, params, sine = ball.law, ball.params, ball.law == SINE
    bed = ball.bed
    massed = bed[2] > 0.0 and not sine
    force, ud = v[FORCE, i], v[UD, i]
    record = controls.record and out.history.shape[2] > 1
    gathered = False
    if record and step < out.history.shape[2] and out.history.shape[0] == 1:
        out.history[H_FORCE, p, step] = force  # the force's history alone
    elif record and step < out.history.shape[2]:
        gather(w, i, scratch)
        gathered = True
        x_now = v[X_BALL, i] if sine else ball_compression(law, params, force, v[F_PEAK_, i])
        if massed:
            string = bed_deflection(bed, 1.0 / points.inv_ks[p], memo, i, v[F2, i],
                                    v[F2_PEAK, i])  # fmt: skip
        else:
            string = string_deflection(bed, points.inv_ks[p], force, v[F_PEAK_, i])
        _record(out.history, points, p, step, force, x_now, string, ud, scratch,
                v[F2, i] if massed else force)  # fmt: skip
    f_peak = v[F_PEAK_, i]
    asymptotic = False
    if sine and 0.0 < force < controls.force_tol * f_peak:
        if not gathered:
            gather(w, i, scratch)
            gathered = True
        asymptotic = abs(ud - _dot(points.out_v[p], scratch)) < controls.force_tol * v[CLOSING, i]
    dt = controls.dt
    if left or asymptotic:
        if not gathered:
            gather(w, i, scratch)
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
        if massed:  # the bed still pushes the frame: the step's end for all but the ball
            summary[DAMPING_LOSS] = v[DAMPING, i]
            out.state[p] = scratch
            summary[BED_VEL], summary[BED_PEAK] = v[QD, i], v[F2_PEAK, i]
            f2 = v[F2, i]
            summary[BED_ELASTIC] = bed_elastic(bed, 1.0 / points.inv_ks[p], memo, i, f2,
                                               v[F2_PEAK, i]) + 0.5 * (
                points.series[p] - points.inv_ks[p]) * f2 * f2  # fmt: skip
        else:
            step_back(frame.blocks, scratch, back, out.state[p])
    if asymptotic:
        flags[STOP_AT, i] = step  # common speed approached asymptotically (no fold)
        return
    if flags[STOP_AT, i] < 0 and force == 0.0:
        if not gathered:
            gather(w, i, scratch)
        if _dot(points.out_dc[p], scratch) > ud:
            # Open and separating in the dc motion: over for good once the gap exceeds the
            # largest deflection the remaining vibration can bring to the point.
            if massed:
                residual = points.series[p] - points.inv_ks[p]
                z_open = bed_gap(law, params, bed, 1.0 / points.inv_ks[p], residual, memo, i,
                                 f_peak, v[F2, i], v[F2_PEAK, i],
                                 v[QD, i] - _dot(points.out_v[p], scratch))  # fmt: skip
            elif sine:
                z_open = v[X_BALL, i]
            else:
                z_open = contact_compression(law, params, bed, points.inv_ks[p], 0.0, f_peak)
            gap = z_open - (v[U, i] - _dot(points.out_d[p], scratch))
            if gap >= _reach(points.reach_w[p], frame.metric, scratch):
                flags[STOP_AT, i] = step + controls.extra_steps


@njit(cache=True)
def gather(w, i, scratch):
    """Slot ``i``'s block states as (nb, 2), as the scalar kernel holds them."""
    for j in range(scratch.shape[0]):
        scratch[j, 0] = w[S0, j, i]
        scratch[j, 1] = w[S1, j, i]


@njit(cache=True)
def finish(out, v, flags, i, step):
    """Slot ``i``'s summary once it has ended at ``step``."""
    summary = out.summary[flags[IMPACT, i]]
    summary[F_PEAK] = v[F_PEAK_, i]
    summary[SNAPPED] = 1.0 if flags[SNAP, i] else 0.0
    summary[ENDED] = 1.0 if step == flags[STOP_AT, i] else 0.0
    summary[SNAP_RESIDUAL] = v[RESIDUAL, i]
    summary[RECONTACTS] = max(flags[RECONTACT, i], 0)
    flags[DONE, i] = 1


@njit(cache=True)
def move_slot(w, v, flags, memo, src, dst, nb):
    """Slot ``src``'s impact into slot ``dst``."""
    for r in range(memo.shape[0]):
        memo[r, dst] = memo[r, src]
    for r in range(N_ROWS):
        for j in range(nb):
            w[r, j, dst] = w[r, j, src]
    for r in range(N_SCALARS):
        v[r, dst] = v[r, src]
    for r in range(N_FLAGS):
        flags[r, dst] = flags[r, src]


@njit(cache=True)
def massed_force(law, params, bed, k_bed, v, i, dt, h, memo):
    """Slot ``i``'s forces on a bed with a mass, the ball's and the bed's (as
    :func:`racket.solver.kernel._one_impact`), and the bed mass's step.
    """
    force, f2 = v[FORCE, i], v[F2, i]
    q_p = v[Q, i] + dt * v[QD, i] + 2.0 * h * (force - f2)
    qd_p = v[QD, i] + 0.5 * dt * (force - f2) / bed[2]
    f2_guess = 2.0 * f2 - v[F2_BEFORE, i]  # the bed's force extrapolated
    z_pred = v[U_P, i] - q_p
    coef = (v[C1_0, i], v[C1_1, i], v[C1_2, i])
    f_new, f2_new = massed_forces(law, params, coef, v[A1, i], bed, k_bed,
                                  v[COMP, i], h, z_pred, q_p - v[Z, i], v[F_PEAK_, i],
                                  v[F2_PEAK, i], 2.0 * force - v[F_BEFORE, i], f2_guess, memo,
                                  i)  # fmt: skip
    v[Z, i] = z_pred + h * f2_guess
    v[Q, i] = q_p + h * (f_new - f2_new)
    v[QD, i] = qd_p + 0.5 * dt * (f_new - f2_new) / bed[2]
    v[F_NEW, i] = f_new
    v[F2_NEW, i] = f2_new


@njit(cache=True)
def massed_opening(ball, law, params, v, i, dt, h):
    """The ball of slot ``i`` left a bed with a mass within the step: the ball's and the
    bed mass's hold replaced by force -> 0 over tau dt (as the scalar kernel).
    """
    force = v[FORCE, i]
    tau = opening_fraction(law, params, force, v[F_PEAK_, i], v[Z, i])
    d0 = force * tau * (2.0 - tau) - force
    d1 = -force * tau * (1.0 - tau)
    v[U, i] += ball.g0[0] * d0 + ball.g1[0] * d1
    v[UD, i] += ball.g0[1] * d0 + ball.g1[1] * d1
    v[Q, i] += 2.0 * h * d0 + h * d1
    v[QD, i] += 0.5 * dt * (d0 + d1) / ball.bed[2]
    v[TAU, i] = tau
