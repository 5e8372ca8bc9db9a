"""The compiled time-stepper that advances every impact of a sweep together.

Scheme
------
Between two steps the contact force is taken to vary linearly (first-order hold).  For a
force of that shape the racket, a linear system in real 2x2 blocks (each free mode, a
damped oscillator q'' + 2 zeta omega q' + omega**2 q = phi(b) F, is one block; a hand-held
racket's coupled modes are brought to such blocks by :mod:`racket.system`), is advanced
*exactly* by precomputed 2x2 transition matrices (:func:`racket.solver.steps.block_steps`), and
so is the ball (u'' = -F / m1).  Only the force
at the end of the step is unknown; the compression of the ball plus strings then depends
on it linearly through the step's compliance c, so the step reduces to one scalar equation

    g_ball(F) + F / k_s + c F = z_pred,

z_pred being the contact compression the step would give without force.  The left side
rises with F on every branch of a monotone law, so the force is unique: closed form for
linear laws, a safeguarded Newton iteration for power laws.  The step length is set by the
contact (about 1/600 of it by default), not by the highest mode.

The unhappy ball (sine law) uses a return mapping in its compression X, which never
decreases: the ball flows along the sine (X + c' F_sine(X) = z_pred) when the contact
pushes it, and locks (X frozen, F below the sine) when the contact relaxes.  Only a ball
that has reached the fold (the maximum of X + c' F_sine(X)) to within ``cross_tol`` Xo
crosses it, onto the falling branch, so X never jumps.  Pushed again on the falling branch
(by the frame's vibration) it holds its compression until the force falls back to the
sine.  If the contact would push the ball past the fold's maximum, or push a spent ball
(X = Xo, force back to zero) again, Xo was not the ball's largest compression: the step
flags a *snap*, and the summary's ``SNAP_RESIDUAL`` says by how much (the overshoot, > 0)
or how close the contact came to it (minus the smallest gap to the fold, <= 0), a
continuous function of Xo that :func:`racket.solver.driver` drives to zero (the
self-consistent Xo of :mod:`ball.unhappy`).

Outcome at separation
---------------------
After the force first returns to zero the stepping goes on, so that a vibrating frame can
catch the ball again, until the dc motion has separated the two by more than the reach of
the remaining vibration (and then ``extra_steps`` more).  The outcome (ball and racket
states, energies) is the state at the step where the force last returned to zero: the
moment the ball finally left.  For a hand-held racket the hand keeps pushing after that,
and the racket's momentum keeps changing, so any later moment would give another e.

This module advances one impact at a time (:func:`run_impacts`); :mod:`racket.solver.lockstep`
advances a batch together, with the same numbers.  The laws' force solves are in
:mod:`racket.solver.ball_kernel`, the blocks' exponentials in :mod:`racket.solver.expm`.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from racket.solver.ball_kernel import ball_compression, force_coefficients, sine_step
from racket.solver.bed_kernel import bed_active, bed_extra
from racket.solver.bed_mass_kernel import (
    BED_MEMO_ROWS,
    EARLY_OVER_LATE,
    bed_deflection,
    bed_elastic,
    bed_gap,
    bed_mass_coupling,
    massed_forces,
    opening_fraction,
)
from racket.solver.contact_kernel import MEMO_ROWS, contact_compression, contact_force
from racket.solver.expm import step_back
from racket.solver.layout import (
    BED_ELASTIC,
    BED_PEAK,
    BED_VEL,
    DAMPING_LOSS,
    ENDED,
    F_PEAK,
    H_BALL_COMP,
    H_BALL_VEL,
    H_FORCE,
    H_FRAME_FORCE,
    H_POINT_VEL,
    H_POINT_VEL_DC,
    H_STRING,
    RECONTACTS,
    SINE,
    SINE_WORK,
    SNAP_RESIDUAL,
    SNAPPED,
    T_CONTACT,
    T_END,
    X_END,
)


@njit(cache=True, nogil=True)
def run_impacts(frame, points, ball, controls, out, start, stop, step):
    """Advance impacts ``start`` to ``stop`` of P from first touch until the ball has left for good.

    The racket is a linear system in real 2x2 blocks (:mod:`racket.system`).  The outputs
    are the states at the final separation (see the module docstring).

    Parameters
    ----------
    frame : racket.solver.layout.Frame
        The racket's blocks, the same for every impact.
    points : racket.solver.layout.Points
        What differs between the P impacts (the impact point, the ball's speed, Xo).
    ball : racket.solver.layout.BallModel
        The ball: its free step and its law.
    controls : racket.solver.layout.Controls
        Time step, step budget, tolerances, whether to stop at a snap or record.
    out : racket.solver.layout.Outputs
        Filled: ball and block states at the final separation, summary numbers and
        histories of the first T steps (if recorded).
    start, stop, step : int
        The slice of the P impacts to run (compiled with ``nogil``, so that threads can run
        slices at once: :func:`racket.solver.dispatch._run_on_threads`).
    """
    for p in range(start, stop, step):
        _one_impact(frame, points, ball, controls, out, p)


@njit(cache=True)
def _one_impact(frame, points, ball, controls, out, p):
    """Impact ``p`` of :func:`run_impacts`."""
    trans, out_d = frame.trans, points.out_d[p]
    nb = trans.shape[0]
    # Each block's response over a step to a unit force at the point, varying linearly
    # from the step's start (gin0) or to its end (gin1).
    gin0, gin1 = np.empty((nb, 2)), np.empty((nb, 2))
    for j in range(nb):
        for r in range(2):
            gin0[j, r] = (
                frame.g0[j, r, 0] * points.unit[p, j, 0] + frame.g0[j, r, 1] * points.unit[p, j, 1]
            )
            gin1[j, r] = (
                frame.g1[j, r, 0] * points.unit[p, j, 0] + frame.g1[j, r, 1] * points.unit[p, j, 1]
            )
    dt, law, params, sine = controls.dt, ball.law, ball.params, ball.law == SINE
    bed, inv_ks = ball.bed, points.inv_ks[p]
    memo = np.full((max(MEMO_ROWS, BED_MEMO_ROWS), 1), -1.0)  # the contact's memo
    record = controls.record and out.history.shape[2] > 1
    s = points.state0[p].copy()
    u, ud = 0.0, points.ball_velocity[p]
    x_o = points.x_o[p]
    # Compression change per unit force at the step's end (ball and point), and the
    # compliance the force solve sees: the series compliance plus that.
    c = -ball.g1[0]
    for j in range(nb):
        c += out_d[j, 0] * gin1[j, 0] + out_d[j, 1] * gin1[j, 1]
    a = points.series[p] + c
    coef = force_coefficients(law, params, a)
    # A bed with a mass (racket.solver.bed_mass_kernel): the ball's own compliance, the
    # bed's series one (the frame's step and the modes left out) and the coupling h.
    massed = bed[2] > 0.0 and not sine
    q, qd, f2, f2_before, f2_peak = 0.0, 0.0, 0.0, 0.0, 0.0
    h, a1, comp, k_bed, coef1 = 0.0, a, 0.0, 0.0, coef
    if massed:
        h = bed_mass_coupling(dt, bed[2])
        a1 = -ball.g1[0] + h
        coef1 = force_coefficients(law, params, a1)
        comp = h + (points.series[p] - inv_ks) + _dot(out_d, gin1)
        k_bed = 1.0 / inv_ks
        q, qd = _dot(out_d, s), _dot(points.out_v[p], s)  # the bed moves with the frame
        memo[3, 0], memo[7:, 0] = 0.0, 0.0
    force, f_before, f_peak, x_ball, snapped = 0.0, 0.0, 0.0, 0.0, False
    residual = -math.inf
    damping_loss, sine_work = 0.0, 0.0
    damp_blocks, damp_rows = frame.damp_blocks, frame.damp_rows
    diagonal = damping_diagonal(damp_blocks)  # the power then summed in the response
    power_prev = _power(damp_blocks, damp_rows, s)
    out_dc, rest_for, rest = points.out_dc[p], math.nan, 0.0
    stop_at = -1  # step at which to stop, once the ball has left for good
    recontacts = -1  # contacts after the first
    # The state when the ball last left (force back to zero).
    sep_step, sep_u, sep_ud, sep_x = 0, u, ud, 0.0
    sep_damping, sep_work, sep_contact = 0.0, 0.0, 0.0
    sep_bed_vel, sep_elastic, sep_f2_peak = qd, 0.0, 0.0
    sep_s = s.copy()
    closing = ud - _dot(points.out_v[p], s)
    if record:
        _record(out.history, points, p, 0, 0.0, 0.0, 0.0, ud, s, 0.0)
    step = 0
    while step < controls.max_steps and step != stop_at:
        # Free step (force going from `force` to 0), then the force at the step's end.
        u_p = ball.trans[0, 0] * u + ball.trans[0, 1] * ud + ball.g0[0] * force
        ud_p = ball.trans[1, 0] * u + ball.trans[1, 1] * ud + ball.g0[1] * force
        f_new, f2_new = 0.0, 0.0
        if massed:
            y_p = _free_step(trans, gin0, out_d, s, f2)
            q_p = q + dt * qd + EARLY_OVER_LATE * h * (force - f2)
            qd_p = qd + 0.5 * dt * (force - f2) / bed[2]
            z_pred = u_p - q_p
            f_new, f2_new, f_peak = massed_forces(law, params, coef1, a1, bed, k_bed, comp, h,
                                                  z_pred, q_p - y_p, f_peak, f2_peak, f_before,
                                                  force, 2.0 * f2 - f2_before, memo, 0)  # fmt: skip
            z_pred += h * (2.0 * f2 - f2_before)  # the ball's, with no force of its own
            q = q_p + h * (f_new - f2_new)
            qd = qd_p + 0.5 * dt * (f_new - f2_new) / bed[2]
        else:
            z_pred = u_p - _free_step(trans, gin0, out_d, s, force)
        if sine:
            x_before = x_ball
            f_new, x_ball, step_residual = sine_step(
                params[0], x_o, a, z_pred, x_ball, controls.cross_tol
            )
            sine_work += 0.5 * (force + f_new) * (x_ball - x_before)
            if step_residual > 0.0 and not snapped:
                snapped = True
                residual = step_residual
                if controls.stop_on_snap:
                    break
            elif not snapped:
                residual = max(residual, step_residual)
        elif not massed:
            guess = 2.0 * force - f_before
            f_new = contact_force(law, params, coef, bed, inv_ks, a, z_pred, f_peak, guess, memo, 0)
        # Add the response to the force at the step's end.
        u = u_p + ball.g1[0] * f_new
        ud = ud_p + ball.g1[1] * f_new
        f_frame = f2_new if massed else f_new
        power, r = 0.0, 0
        for j in range(nb):
            s[j, 0] += gin1[j, 0] * f_frame
            s[j, 1] += gin1[j, 1] * f_frame
            if diagonal and r < damp_blocks.shape[0] and damp_blocks[r, 0] == j:
                row = 0.0 + (damp_rows[r, 0, 0] * s[j, 0] + damp_rows[r, 0, 1] * s[j, 1])
                power += row * row  # (as _power sums it)
                r += 1
        tau = 1.0  # fraction of the step at which the contact opened
        if f_new == 0.0 and force > 0.0 and massed:
            tau = opening_fraction(law, params, force, f_peak, z_pred)
            d0 = force * tau * (2.0 - tau) - force
            d1 = -force * tau * (1.0 - tau)
            u += ball.g0[0] * d0 + ball.g1[0] * d1
            ud += ball.g0[1] * d0 + ball.g1[1] * d1
            # the bed mass felt the ball's force alone (its force and deflection stay the
            # step's end's: the difference is of the order of h times the force, 4e-8 J)
            q += EARLY_OVER_LATE * h * d0 + h * d1
            qd += 0.5 * dt * (d0 + d1) / bed[2]
        elif f_new == 0.0 and force > 0.0 and not sine:
            tau = _opening_fraction(law, params, bed, inv_ks, points.series[p], force, f_peak,
                                    z_pred)  # fmt: skip
            # The force reached zero at tau dt, not at the step's end: replace the hold
            # (force -> 0 over the step) by the one with the same impulse and first moment
            # as force -> 0 over tau dt then nothing, by superposition.
            d0 = force * tau * (2.0 - tau) - force
            d1 = -force * tau * (1.0 - tau)
            u += ball.g0[0] * d0 + ball.g1[0] * d1
            ud += ball.g0[1] * d0 + ball.g1[1] * d1
            for j in range(nb):
                s[j, 0] += gin0[j, 0] * d0 + gin1[j, 0] * d1
                s[j, 1] += gin0[j, 1] * d0 + gin1[j, 1] * d1
            if diagonal:  # the state moved after its power was summed
                power = _power(damp_blocks, damp_rows, s)
        if not diagonal:
            power = _power(damp_blocks, damp_rows, s)
        damping_loss += 0.5 * (power + power_prev) * dt
        power_prev = power
        if f_new > 0.0 and force == 0.0:
            recontacts += 1
            stop_at = -1  # caught again: not over yet
        left = f_new == 0.0 and force > 0.0
        f_before, force = force, f_new
        f_peak = max(f_peak, force)
        f2_before, f2 = f2, f2_new
        f2_peak = max(f2_peak, f2)
        step += 1
        if record and step < out.history.shape[2] and out.history.shape[0] == 1:
            out.history[H_FORCE, p, step] = force  # the force's history alone
        elif record and step < out.history.shape[2]:
            x_now = x_ball if sine else ball_compression(law, params, force, f_peak)
            if massed:
                string = bed_deflection(bed, k_bed, memo, 0, f2, f2_peak)
            else:
                string = string_deflection(bed, inv_ks, force, f_peak)
            _record(out.history, points, p, step, force, x_now, string, ud, s,
                    f2 if massed else force)  # fmt: skip
        asymptotic = (
            sine
            and 0.0 < force < controls.force_tol * f_peak
            and abs(ud - _dot(points.out_v[p], s)) < controls.force_tol * closing
        )
        if left or asymptotic:
            # The state when the ball left, tau dt into the step (force-free since then).
            back = (1.0 - tau) * dt
            sep_step, sep_u, sep_ud, sep_x = step, u - back * ud, ud, x_ball
            sep_damping, sep_work = damping_loss - back * power, sine_work
            sep_contact = (step - 1 + tau) * dt if left and not sine else (step - 1) * dt
            if asymptotic:
                sep_contact = step * dt
            step_back(frame.blocks, s, back, sep_s)
            if massed:  # the bed mass at the step's end: see racket.solver.bed_mass_kernel
                sep_bed_vel, sep_f2_peak = qd, f2_peak
                sep_elastic = (
                    bed_elastic(bed, k_bed, memo, 0, f2, f2_peak)
                    + 0.5 * (points.series[p] - inv_ks) * f2 * f2
                )  # and the modes left out (fmt: skip)
        if asymptotic:
            stop_at = step  # common speed approached asymptotically (no fold)
            break
        if stop_at < 0 and force == 0.0 and _dot(out_dc, s) > ud:
            # Open and separating in the dc motion: over for good once the gap exceeds
            # the largest deflection the remaining vibration can bring to the point.
            if massed:
                z_open = bed_gap(law, params, bed, k_bed, points.series[p] - inv_ks, memo, 0,
                                 f_peak, f2, f2_peak, qd - _dot(points.out_v[p], s))  # fmt: skip
            elif sine:
                z_open = x_ball
            else:
                if rest_for != f_peak:  # made again only where the largest force has changed
                    rest, rest_for = (
                        contact_compression(law, params, bed, inv_ks, 0.0, f_peak),
                        f_peak,
                    )
                z_open = rest
            gap = z_open - (u - _dot(out_d, s))
            if gap >= _reach(points.reach_w, p, frame.metric, s, gap):
                stop_at = step + controls.extra_steps
    out.ball[p, 0] = sep_u
    out.ball[p, 1] = sep_ud
    for j in range(nb):  # element by element: a slice copy compiles numba's shape check
        out.state[p, j, 0] = sep_s[j, 0]
        out.state[p, j, 1] = sep_s[j, 1]
    summary = out.summary[p]
    summary[T_END] = sep_step * dt
    summary[T_CONTACT] = sep_contact
    summary[F_PEAK] = f_peak
    summary[SINE_WORK] = sep_work
    summary[DAMPING_LOSS] = sep_damping
    summary[SNAPPED] = 1.0 if snapped else 0.0
    summary[ENDED] = 1.0 if step == stop_at else 0.0
    summary[SNAP_RESIDUAL] = residual
    summary[X_END] = sep_x
    summary[RECONTACTS] = max(recontacts, 0)
    summary[BED_VEL] = sep_bed_vel
    summary[BED_ELASTIC] = sep_elastic
    summary[BED_PEAK] = sep_f2_peak


@njit(cache=True)
def _opening_fraction(law, params, bed, inv_ks, series, force, f_peak, z_pred):
    """Fraction of the step at which a monotone-law contact opened: where the approach
    beyond the residual compression of the ball and bed, d = z - g(0), went through zero,
    from ``force`` at the step's start (d = g(force) - g(0) + series force) to the
    force-free prediction ``z_pred`` at its end, linearly.
    """
    rest = contact_compression(law, params, bed, inv_ks, 0.0, f_peak)
    d_start = contact_compression(law, params, bed, inv_ks, force, f_peak) - rest + series * force
    d_end = z_pred - rest
    if d_start - d_end <= 0.0:
        return 1.0
    return min(max(d_start / (d_start - d_end), 0.0), 1.0)


@njit(cache=True)
def _free_step(trans, gin0, out_d, s, force):
    """Advance the block states ``s`` in place over a step with the force going from
    ``force`` to zero; returns the impact point's displacement then.
    """
    z = 0.0
    for j in range(trans.shape[0]):
        s0 = trans[j, 0, 0] * s[j, 0] + trans[j, 0, 1] * s[j, 1] + gin0[j, 0] * force
        s1 = trans[j, 1, 0] * s[j, 0] + trans[j, 1, 1] * s[j, 1] + gin0[j, 1] * force
        s[j, 0] = s0
        s[j, 1] = s1
        z += out_d[j, 0] * s0 + out_d[j, 1] * s1
    return z


@njit(cache=True)
def _reach(reach_w, p, metric, s, gap):
    """The largest displacement the blocks' remaining vibration can bring to point ``p``
    (its row of ``reach_w`` read in place: a view costs two atomic reference counts), or
    its sum so far once that passes ``gap``: a sum of terms none negative only grows, so
    ``gap >= _reach(...)`` is decided as with the whole sum, most steps after a few blocks.
    """
    reach = 0.0
    for j in range(reach_w.shape[1]):
        if reach_w[p, j] > 0.0:
            reach += reach_w[p, j] * math.sqrt(
                metric[j, 0] * s[j, 0] ** 2 + metric[j, 1] * s[j, 1] ** 2
            )
            if reach > gap:
                break
    return reach


@njit(cache=True)
def string_deflection(bed, inv_ks, force, f_peak):
    """The string bed's deflection [m] at ``force`` after the largest ``f_peak`` [N]."""
    string = force * inv_ks
    if bed_active(bed):
        string += bed_extra(bed, inv_ks, force, f_peak)[0]
    return string


@njit(cache=True)
def _record(history, points, p, step, force, compression, string, ball_velocity, s,
            frame_force):  # fmt: skip
    """Write one step of impact ``p``'s histories: the force, the ball's compression, the
    strings' deflection, the ball's velocity, the point's (all and dc) from the block
    states ``s``, and the force on the frame (the bed's, with a mass; the ball's without);
    the force alone into a history of one row.
    """
    history[H_FORCE, p, step] = force
    if history.shape[0] == 1:
        return
    history[H_BALL_COMP, p, step] = compression
    history[H_STRING, p, step] = string
    history[H_BALL_VEL, p, step] = ball_velocity
    history[H_POINT_VEL, p, step] = _dot(points.out_v[p], s)
    history[H_POINT_VEL_DC, p, step] = _dot(points.out_dc[p], s)
    history[H_FRAME_FORCE, p, step] = frame_force


@njit(cache=True)
def _dot(rows, s):
    """Rows . s over all blocks."""
    total = 0.0
    for j in range(s.shape[0]):
        total += rows[j, 0] * s[j, 0] + rows[j, 1] * s[j, 1]
    return total


@njit(cache=True)
def damping_diagonal(damp_blocks):
    """Whether each row of the dissipated power is one block's, the rows in the blocks'
    order (a free racket's modal damping): the kernels then sum the power block by block as
    each block takes the force's response, in the order :func:`_power` sums it.
    """
    if damp_blocks.shape[1] != 1:
        return False
    for r in range(1, damp_blocks.shape[0]):
        if damp_blocks[r, 0] <= damp_blocks[r - 1, 0]:
            return False
    return True


@njit(cache=True)
def _power(damp_blocks, damp_rows, s):
    """Dissipated power (see ``damp_blocks`` in :func:`run_impacts`)."""
    total = 0.0
    for r in range(damp_rows.shape[0]):
        v = 0.0
        for k in range(damp_rows.shape[1]):
            j = damp_blocks[r, k]
            v += damp_rows[r, k, 0] * s[j, 0] + damp_rows[r, k, 1] * s[j, 1]
        total += v * v
    return total
