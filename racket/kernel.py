"""The compiled time-stepper that advances every impact of a sweep together.

Scheme
------
Between two steps the contact force is taken to vary linearly (first-order hold).  For a
force of that shape the racket, a linear system in real 2x2 blocks (each free mode, a
damped oscillator q'' + 2 zeta omega q' + omega**2 q = phi(b) F, is one block; a hand-held
racket's coupled modes are brought to such blocks by :mod:`racket.system`), is advanced
*exactly* by precomputed 2x2 transition matrices (:func:`racket.system.block_steps`), and
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
continuous function of Xo that :func:`racket.solver.impact` drives to zero (the
self-consistent Xo of :mod:`ball.unhappy`).

Outcome at separation
---------------------
After the force first returns to zero the stepping goes on, so that a vibrating frame can
catch the ball again, until the dc motion has separated the two by more than the reach of
the remaining vibration (and then ``extra_steps`` more).  The outcome (ball and racket
states, energies) is the state at the step where the force last returned to zero: the
moment the ball finally left.  For a hand-held racket the hand keeps pushing after that,
and the racket's momentum keeps changing, so any later moment would give another e.

Law codes: 0 linear hysteresis (k, e), 1 power law (k, a, b), 2 sine law (k0).
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit, prange

from racket.layout import (
    DAMPING_LOSS,
    ENDED,
    F_PEAK,
    H_BALL_COMP,
    H_BALL_VEL,
    H_FORCE,
    H_POINT_VEL,
    H_POINT_VEL_DC,
    H_STRING,
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


@njit(cache=True)
def _power_compression(f, f_max, k, a, b):
    """Compression of a power-law ball at force f after largest force f_max."""
    if f <= 0.0:
        return 0.0
    if f >= f_max:
        return (f / k) ** (1.0 / a)
    return (f_max / k) ** (1.0 / a) * (f / f_max) ** (1.0 / b)


@njit(cache=True)
def ball_compression(code, p0, p1, p2, f, f_max):
    """Compression of a monotone ball law at force f after largest force f_max."""
    if code == LINEAR:
        if f >= f_max:
            return f / p0
        return (f_max * (1.0 - p1 * p1) + p1 * p1 * f) / p0
    return _power_compression(f, f_max, p0, p1, p2)


@njit(cache=True)
def _power_force(target, c, f_lo, f_hi, f_max, k, a, b):
    """Solve g(F) + c F = target for F in [f_lo, f_hi] (g the power law), by safeguarded
    Newton: g + c F rises with F, and the bracket holds the root."""
    f = 0.5 * (f_lo + f_hi)
    for _ in range(100):
        g = _power_compression(f, f_max, k, a, b)
        resid = g + c * f - target
        if resid < 0.0:
            f_lo = f
        else:
            f_hi = f
        expo = a if f >= f_max else b
        slope = g / (expo * f) + c if f > 0.0 else math.inf
        f_new = f - resid / slope
        if not (f_lo < f_new < f_hi):
            f_new = 0.5 * (f_lo + f_hi)
        if abs(f_new - f) <= 1e-15 * f_new:
            return f_new
        f = f_new
    return f


@njit(cache=True)
def monotone_force(code, p0, p1, p2, a, z_pred, f_max):
    """Force solving g_ball(F) + a F = z_pred (a = 1/k_s + c), 0 if the contact is open."""
    if code == LINEAR:
        f = z_pred / (1.0 / p0 + a)  # loading line
        if f >= f_max:
            return f
        e2 = p1 * p1
        f = (z_pred - f_max * (1.0 - e2) / p0) / (e2 / p0 + a)  # unloading line
        return max(f, 0.0)
    switch = _power_compression(f_max, f_max, p0, p1, p2) + a * f_max
    if z_pred >= switch:
        return _power_force(z_pred, a, f_max, z_pred / a, f_max, p0, p1, p2)
    if z_pred <= 0.0:
        return 0.0
    return _power_force(z_pred, a, 0.0, f_max, f_max, p0, p1, p2)


@njit(cache=True)
def _sine_root(target, c, k0, x_o, lo, hi):
    """X in [lo, hi] with X + c k0 Xo sin(pi X / Xo) = target, the left side monotone there."""
    x = 0.5 * (lo + hi)
    rising = (lo + c * k0 * x_o * math.sin(math.pi * lo / x_o)) < target
    for _ in range(200):
        s = math.sin(math.pi * x / x_o)
        resid = x + c * k0 * x_o * s - target
        below = resid < 0.0
        if below == rising:
            lo = x
        else:
            hi = x
        slope = 1.0 + c * k0 * math.pi * math.cos(math.pi * x / x_o)
        x_new = x - resid / slope if slope != 0.0 else 0.5 * (lo + hi)
        if not (min(lo, hi) < x_new < max(lo, hi)):
            x_new = 0.5 * (lo + hi)
        if abs(x_new - x) <= 1e-15 * x_o:
            return x_new
        x = x_new
    return x


@njit(cache=True)
def sine_step(k0, x_o, a, z_pred, x_n, cross_tol):
    """One return-mapping step of the unhappy ball.

    Returns (force, new X, residual): ``residual`` > 0 is a snap (the overshoot past the
    fold's maximum, or the push on a spent ball, over Xo), otherwise minus the gap left to
    the fold's maximum over Xo while the ball flows along the rising branch (-inf
    elsewhere).  ``a`` = 1/k_s + c is the compliance in series with the ball, ``x_n`` its
    compression so far.
    """
    if x_n >= x_o:  # spent: the force came back to zero at X = Xo
        if z_pred > x_n:
            return 0.0, x_n, (z_pred - x_n) / x_o
        return 0.0, x_n, -math.inf

    ck = a * k0 * math.pi
    x_fold = x_o / math.pi * math.acos(-1.0 / ck) if ck > 1.0 else x_o
    h_n = x_n + a * k0 * x_o * math.sin(math.pi * x_n / x_o)  # X + a F_sine(X)
    h_fold = x_fold + a * k0 * x_o * math.sin(math.pi * x_fold / x_o)
    if x_n < x_fold:
        if z_pred >= h_n:
            if z_pred <= h_fold:
                x = _sine_root(z_pred, a, k0, x_o, x_n, x_fold)
                return k0 * x_o * math.sin(math.pi * x / x_o), x, (z_pred - h_fold) / x_o
            return 0.0, x_n, (z_pred - h_fold) / x_o  # past the fold's maximum: a snap
        if h_fold - h_n > cross_tol * x_o or x_fold >= x_o:
            return max((z_pred - x_n) / a, 0.0), x_n, -math.inf  # lock
        # At the fold and relaxing: cross onto the falling branch.
        if z_pred >= x_o:
            x = _sine_root(z_pred, a, k0, x_o, x_fold, x_o)
            return k0 * x_o * math.sin(math.pi * x / x_o), x, -math.inf
        return 0.0, x_o, -math.inf
    if z_pred > h_n:
        # Pushed again on the falling branch (the frame's vibration): the ball holds its
        # compression, like any loaded material reloaded below its previous peak.
        return (z_pred - x_n) / a, x_n, -math.inf
    if z_pred >= x_o:
        x = _sine_root(z_pred, a, k0, x_o, x_n, x_o)
        return k0 * x_o * math.sin(math.pi * x / x_o), x, -math.inf
    return 0.0, x_o, -math.inf  # force back to zero at X = Xo: the contact opens


@njit(cache=True, parallel=True)
def run_impacts(
    trans,
    gin0,
    gin1,
    out_d,
    out_v,
    out_dc,
    reach_w,
    metric,
    damp_blocks,
    damp_rows,
    ball_trans,
    ball_g0,
    ball_g1,
    inv_ks,
    code,
    p0,
    p1,
    p2,
    ball_velocity,
    state0,
    x_o,
    cross_tol,
    dt,
    max_steps,
    extra_steps,
    force_tol,
    stop_on_snap,
    record,
    out_ball,
    out_state,
    summary,
    history,
):
    """Advance P impacts from first touch until the ball has left for good.

    The racket is a linear system in real 2x2 blocks (:mod:`racket.system`).  The outputs
    are the states at the final separation (see the module docstring).

    Parameters
    ----------
    trans : (nb, 2, 2)
        Exact step of each block: s_next = trans s + gin0 F_start + gin1 F_end.
    gin0, gin1 : (P, nb, 2)
        Each block's response to a unit contact force at each impact point, varying
        linearly over the step (force at the step's start and end).
    out_d, out_v, out_dc : (P, nb, 2)
        Rows giving the impact point's displacement, velocity and dc (rigid-body) velocity
        from the block states.
    reach_w : (P, nb)
        Size of each block's contribution to the point's displacement (0 for dc blocks).
    metric : (nb, 2)
        sqrt(metric . s**2) bounds a block's future amplitude.
    damp_blocks, damp_rows : (R, K) int, (R, K, 2)
        Dissipated power = sum_r (sum_k damp_rows[r, k] . s[damp_blocks[r, k]])**2 (the K
        blocks of each row that can be non-zero: one for a free racket's diagonal damping).
    ball_trans, ball_g0, ball_g1 : (2, 2), (2,), (2,)
        The same for the ball (force -F on it).
    inv_ks : float
        1 / string-bed stiffness [m/N].
    code, p0, p1, p2 :
        Ball law (see the module docstring).
    ball_velocity : (P,)
        Ball velocity at first touch [m/s] (towards the racket positive).
    state0 : (P, nb, 2)
        Block states at first touch (a swung racket's rigid-body motion).
    x_o : (P,)
        Sine law's Xo per impact [m] (ignored by other laws).
    cross_tol : float
        A sine-law ball closer than this times Xo to its fold's maximum may cross the fold.
    dt : float
        Time step [s].
    max_steps, extra_steps : int
        Most steps in all; steps to go on after the ball has left for good.
    force_tol : float
        A sine-law contact approaching a common speed without a fold ends when its force
        has fallen to this fraction of its peak, and the relative speed to this fraction of
        the closing speed.
    stop_on_snap : bool
        Stop an impact at its first snap (an Xo search needs no more).
    record : bool
        Fill ``history`` (as far as it reaches).
    out_ball : (P, 2), out_state : (P, nb, 2), summary : (P, N_SUMMARY),
    history : (N_HISTORY, P, T)
        Outputs: ball and block states at the final separation, summary numbers,
        histories of the first T steps (if record).
    """
    n_points, nb = reach_w.shape
    for p in prange(n_points):
        s = state0[p].copy()
        u, ud = 0.0, ball_velocity[p]
        c = -ball_g1[0]  # ball displacement per unit force at the step end, sign flipped
        for j in range(nb):
            c += out_d[p, j, 0] * gin1[p, j, 0] + out_d[p, j, 1] * gin1[p, j, 1]
        a = inv_ks + c
        # The point's displacement after a force-free step: dT . s + c0 F (F the force at
        # the step's start).
        d_t = np.empty((nb, 2))
        c0 = 0.0
        for j in range(nb):
            d_t[j, 0] = out_d[p, j, 0] * trans[j, 0, 0] + out_d[p, j, 1] * trans[j, 1, 0]
            d_t[j, 1] = out_d[p, j, 0] * trans[j, 0, 1] + out_d[p, j, 1] * trans[j, 1, 1]
            c0 += out_d[p, j, 0] * gin0[p, j, 0] + out_d[p, j, 1] * gin0[p, j, 1]
        force, f_peak, x_ball, snapped = 0.0, 0.0, 0.0, False
        residual = -math.inf
        damping_loss = 0.0
        sine_work = 0.0
        power_prev = _power(damp_blocks, damp_rows, s)
        stop_at = -1  # step at which to stop, once the ball has left for good
        recontacts = -1  # contacts after the first
        # The state when the ball last left (force back to zero).
        sep_step, sep_u, sep_ud, sep_x = 0, u, ud, 0.0
        sep_damping, sep_work, sep_contact = 0.0, 0.0, 0.0
        sep_s = s.copy()
        step = 0
        closing = ud - _dot(out_v, p, s, nb)
        if record:
            history[H_BALL_VEL, p, 0] = ud
            history[H_POINT_VEL, p, 0] = _dot(out_v, p, s, nb)
            history[H_POINT_VEL_DC, p, 0] = _dot(out_dc, p, s, nb)
        while step < max_steps and step != stop_at:
            # Free prediction (no force at the step end).
            u_p = ball_trans[0, 0] * u + ball_trans[0, 1] * ud + ball_g0[0] * force
            ud_p = ball_trans[1, 0] * u + ball_trans[1, 1] * ud + ball_g0[1] * force
            z_pred = u_p - c0 * force
            for j in range(nb):
                z_pred -= d_t[j, 0] * s[j, 0] + d_t[j, 1] * s[j, 1]
            if code == SINE:
                x_before = x_ball
                f_new, x_ball, step_residual = sine_step(p0, x_o[p], a, z_pred, x_ball, cross_tol)
                sine_work += 0.5 * (force + f_new) * (x_ball - x_before)
                if step_residual > 0.0 and not snapped:
                    snapped = True
                    residual = step_residual
                    if stop_on_snap:
                        break
                elif not snapped:
                    residual = max(residual, step_residual)
            else:
                f_new = monotone_force(code, p0, p1, p2, a, z_pred, f_peak)
            # Advance everything with the force varying from `force` to `f_new`.
            u_new = u_p + ball_g1[0] * f_new
            ud_new = ud_p + ball_g1[1] * f_new
            for j in range(nb):
                s0 = (
                    trans[j, 0, 0] * s[j, 0]
                    + trans[j, 0, 1] * s[j, 1]
                    + gin0[p, j, 0] * force
                    + gin1[p, j, 0] * f_new
                )
                s1 = (
                    trans[j, 1, 0] * s[j, 0]
                    + trans[j, 1, 1] * s[j, 1]
                    + gin0[p, j, 1] * force
                    + gin1[p, j, 1] * f_new
                )
                s[j, 0] = s0
                s[j, 1] = s1
            power = _power(damp_blocks, damp_rows, s)
            damping_loss += 0.5 * (power + power_prev) * dt
            power_prev = power
            w_dot = _dot(out_v, p, s, nb)
            w_dot_dc = _dot(out_dc, p, s, nb)
            z_now = u_new - _dot(out_d, p, s, nb)
            u, ud = u_new, ud_new
            if f_new > 0.0 and force == 0.0:
                recontacts += 1
                stop_at = -1  # caught again: not over yet
            left = f_new == 0.0 and force > 0.0
            force = f_new
            f_peak = max(f_peak, force)
            step += 1
            if record and step < history.shape[2]:
                history[H_FORCE, p, step] = force
                if code == SINE:
                    history[H_BALL_COMP, p, step] = x_ball
                else:
                    history[H_BALL_COMP, p, step] = ball_compression(
                        code, p0, p1, p2, force, f_peak
                    )
                history[H_STRING, p, step] = force * inv_ks
                history[H_BALL_VEL, p, step] = ud
                history[H_POINT_VEL, p, step] = w_dot
                history[H_POINT_VEL_DC, p, step] = w_dot_dc
            asymptotic = (
                code == SINE
                and 0.0 < force < force_tol * f_peak
                and abs(ud - w_dot) < force_tol * closing
            )
            if left or asymptotic:
                sep_step, sep_u, sep_ud, sep_x = step, u, ud, x_ball
                sep_damping, sep_work = damping_loss, sine_work
                sep_contact = (step - 1) * dt if left else step * dt
                for j in range(nb):
                    sep_s[j, 0] = s[j, 0]
                    sep_s[j, 1] = s[j, 1]
            if asymptotic:
                stop_at = step  # common speed approached asymptotically (no fold)
                break
            if stop_at < 0 and force == 0.0 and w_dot_dc > ud:
                # Open and separating in the dc motion: over for good once the gap exceeds
                # the largest deflection the remaining vibration can bring to the point.
                if code == SINE:
                    z_open = x_ball
                else:
                    z_open = ball_compression(code, p0, p1, p2, 0.0, f_peak)
                reach = 0.0
                for j in range(nb):
                    if reach_w[p, j] > 0.0:
                        reach += reach_w[p, j] * math.sqrt(
                            metric[j, 0] * s[j, 0] ** 2 + metric[j, 1] * s[j, 1] ** 2
                        )
                if z_open - z_now >= reach:
                    stop_at = step + extra_steps
        out_ball[p, 0] = sep_u
        out_ball[p, 1] = sep_ud
        for j in range(nb):
            out_state[p, j, 0] = sep_s[j, 0]
            out_state[p, j, 1] = sep_s[j, 1]
        summary[p, T_END] = sep_step * dt
        summary[p, T_CONTACT] = sep_contact
        summary[p, F_PEAK] = f_peak
        summary[p, SINE_WORK] = sep_work
        summary[p, DAMPING_LOSS] = sep_damping
        summary[p, SNAPPED] = 1.0 if snapped else 0.0
        summary[p, ENDED] = 1.0 if step == stop_at else 0.0
        summary[p, SNAP_RESIDUAL] = residual
        summary[p, X_END] = sep_x
        summary[p, RECONTACTS] = max(recontacts, 0)


@njit(cache=True)
def _dot(rows, p, s, nb):
    """rows[p] . s over all blocks."""
    total = 0.0
    for j in range(nb):
        total += rows[p, j, 0] * s[j, 0] + rows[p, j, 1] * s[j, 1]
    return total


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
    """a @ b by loops (numba's @ calls BLAS)."""
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
