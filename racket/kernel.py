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

Law codes (:data:`ball.laws.LINEAR` ...): 0 linear hysteresis (k, e), 1 power law (k, a, b),
2 sine law (k0), 3 growing hysteresis (k, a, e0, slope), 4 stiffening hysteresis (k, X_lim,
e0, slope), each from the law's ``kernel_law``.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from ball.laws import COR_FLOOR
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
    POWER,
    RECONTACTS,
    SINE,
    SINE_WORK,
    SNAP_RESIDUAL,
    SNAPPED,
    STIFFENING,
    T_CONTACT,
    T_END,
    X_END,
)


@njit(cache=True)
def _loading(law, params, f):
    """Compression on a monotone ball law's loading curve at force f > 0, and its
    d(compression)/d(force): k X**a (POWER, GROWING: params k, a) or the hyperbola
    X = X_lim F / (F + k X_lim) (STIFFENING: params k, X_lim).
    """
    if law == STIFFENING:
        f_c = params[0] * params[1]
        return params[1] * f / (f + f_c), params[1] * f_c / ((f + f_c) * (f + f_c))
    x = (f / params[0]) ** (1.0 / params[1])
    return x, x / (params[1] * f)


@njit(cache=True)
def _branch(law, params, f, f_max, b):
    """Compression of a power-unloading ball at force f after largest force f_max, and its
    d(compression)/d(force) on the branch it is on (unloading X_max (f / f_max)**(1 / b)).
    """
    if f <= 0.0:
        return 0.0, math.inf
    if f >= f_max:
        return _loading(law, params, f)
    x = _loading(law, params, f_max)[0] * (f / f_max) ** (1.0 / b)
    return x, x / (b * f)


@njit(cache=True)
def _stored_over_r2(r):
    """(ln(1 + r) - r / (1 + r)) / r**2, as in :mod:`ball.stiffening` (its series below 1e-3)."""
    if r < 1e-3:
        return 0.5 - r * (2.0 / 3.0 - r * (0.75 - r * (0.8 - r * 5.0 / 6.0)))
    return (math.log1p(r) - r / (1.0 + r)) / (r * r)


@njit(cache=True)
def unloading_exponent(law, params, f_max):
    """Exponent b of a ball's unloading curve from the largest force f_max: fixed (POWER:
    params k, a, b), or set by the largest compression so that the unloading returns
    e**2 of the energy stored, e = max(e0 - slope X_max, COR_FLOOR) (GROWING: params k, a,
    e0, slope, b = (a + 1) / e**2 - 1; STIFFENING: params k, X_lim, e0, slope,
    b = F_max X_max / (e**2 W) - 1 with W the stored energy).
    """
    if law == POWER:
        return params[2]
    x_max = _loading(law, params, f_max)[0] if f_max > 0.0 else 0.0
    e = max(params[2] - params[3] * x_max, COR_FLOOR)
    if law == STIFFENING:
        r = f_max / (params[0] * params[1])
        return 1.0 / ((1.0 + r) * _stored_over_r2(r) * e * e) - 1.0
    return (params[1] + 1.0) / (e * e) - 1.0


@njit(cache=True)
def ball_compression(law, params, f, f_max):
    """Compression of a monotone ball law (code ``law``, numbers ``params``) at force f
    after largest force f_max.
    """
    if law == LINEAR:
        k, e = params[0], params[1]
        if f >= f_max:
            return f / k
        return (f_max * (1.0 - e * e) + e * e * f) / k
    return _branch(law, params, f, f_max, unloading_exponent(law, params, f_max))[0]


@njit(cache=True)
def _branch_force(target, c, f_lo, f_hi, f_max, law, params, b, guess):
    """Solve g(F) + c F = target for F in [f_lo, f_hi] (g the ball's branch, :func:`_branch`),
    by safeguarded Newton from ``guess`` (the bracket's middle if outside it): g + c F rises
    with F, and the bracket holds the root.
    """
    f = guess if f_lo < guess < f_hi else 0.5 * (f_lo + f_hi)
    for _ in range(100):
        g, dg = _branch(law, params, f, f_max, b)
        resid = g + c * f - target
        if resid == 0.0:  # (the bracket would close on f, and Newton's step leave it)
            return f
        if resid < 0.0:
            f_lo = f
        else:
            f_hi = f
        f_new = f - resid / (dg + c)
        if not (f_lo < f_new < f_hi):
            f_new = 0.5 * (f_lo + f_hi)
        if abs(f_new - f) <= 1e-15 * f_new:
            return f_new
        f = f_new
    return f


@njit(cache=True)
def force_coefficients(law, params, a):
    """Numbers of the force solve that stay the same over an impact (``a`` = the series
    compliance plus the step's): for a linear law, 1 / (1/k + a) and 1 / (e**2/k + a),
    the slopes of force against z_pred on loading and unloading, and (1 - e**2) / k, the
    residual compression per unit of the largest force.
    """
    if law == LINEAR:
        k, e2 = params[0], params[1] * params[1]
        return 1.0 / (1.0 / k + a), 1.0 / (e2 / k + a), (1.0 - e2) / k
    return 0.0, 0.0, 0.0


@njit(cache=True)
def monotone_force(law, params, coef, a, z_pred, f_max, guess):
    """Force solving g_ball(F) + a F = z_pred (a = 1/k_s + c), 0 if the contact is open;
    ``coef`` from :func:`force_coefficients`; a non-linear law's Newton iteration starts from
    ``guess`` (the force extrapolated from the last two steps).
    """
    if law == LINEAR:
        f = z_pred * coef[0]  # loading line
        if f >= f_max:
            return f
        return max((z_pred - f_max * coef[2]) * coef[1], 0.0)  # unloading line
    switch = (_loading(law, params, f_max)[0] if f_max > 0.0 else 0.0) + a * f_max
    if z_pred >= switch:  # loading: b plays no part
        return _branch_force(z_pred, a, f_max, z_pred / a, f_max, law, params, 1.0, guess)
    if z_pred <= 0.0:
        return 0.0
    b = unloading_exponent(law, params, f_max)
    return _branch_force(z_pred, a, 0.0, f_max, f_max, law, params, b, guess)


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


@njit(cache=True, nogil=True)
def run_impacts(frame, points, ball, controls, out, start, stop, step):
    """Advance impacts ``start`` to ``stop`` of P from first touch until the ball has left for good.

    The racket is a linear system in real 2x2 blocks (:mod:`racket.system`).  The outputs
    are the states at the final separation (see the module docstring).

    Parameters
    ----------
    frame : racket.layout.Frame
        The racket's blocks, the same for every impact.
    points : racket.layout.Points
        What differs between the P impacts (the impact point, the ball's speed, Xo).
    ball : racket.layout.BallModel
        The ball: its free step and its law.
    controls : racket.layout.Controls
        Time step, step budget, tolerances, whether to stop at a snap or record.
    out : racket.layout.Outputs
        Filled: ball and block states at the final separation, summary numbers and
        histories of the first T steps (if recorded).
    start, stop, step : int
        The slice of the P impacts to run (compiled with ``nogil``, so that threads can run
        slices at once: :func:`racket.solver._run_on_threads`).
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
    force, f_before, f_peak, x_ball, snapped = 0.0, 0.0, 0.0, 0.0, False
    residual = -math.inf
    damping_loss, sine_work = 0.0, 0.0
    power_prev = _power(frame.damp_blocks, frame.damp_rows, s)
    stop_at = -1  # step at which to stop, once the ball has left for good
    recontacts = -1  # contacts after the first
    # The state when the ball last left (force back to zero).
    sep_step, sep_u, sep_ud, sep_x = 0, u, ud, 0.0
    sep_damping, sep_work, sep_contact = 0.0, 0.0, 0.0
    sep_s = s.copy()
    closing = ud - _dot(points.out_v[p], s)
    if record:
        _record(
            out.history,
            p,
            0,
            0.0,
            0.0,
            0.0,
            ud,
            _dot(points.out_v[p], s),
            _dot(points.out_dc[p], s),
        )
    step = 0
    while step < controls.max_steps and step != stop_at:
        # Free step (force going from `force` to 0), then the force at the step's end.
        u_p = ball.trans[0, 0] * u + ball.trans[0, 1] * ud + ball.g0[0] * force
        ud_p = ball.trans[1, 0] * u + ball.trans[1, 1] * ud + ball.g0[1] * force
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
        else:
            f_new = monotone_force(law, params, coef, a, z_pred, f_peak, 2.0 * force - f_before)
        # Add the response to the force at the step's end.
        u = u_p + ball.g1[0] * f_new
        ud = ud_p + ball.g1[1] * f_new
        for j in range(nb):
            s[j, 0] += gin1[j, 0] * f_new
            s[j, 1] += gin1[j, 1] * f_new
        tau = 1.0  # fraction of the step at which the contact opened
        if f_new == 0.0 and force > 0.0 and not sine:
            tau = _opening_fraction(law, params, points.series[p], force, f_peak, z_pred)
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
        power = _power(frame.damp_blocks, frame.damp_rows, s)
        damping_loss += 0.5 * (power + power_prev) * dt
        power_prev = power
        if f_new > 0.0 and force == 0.0:
            recontacts += 1
            stop_at = -1  # caught again: not over yet
        left = f_new == 0.0 and force > 0.0
        f_before, force = force, f_new
        f_peak = max(f_peak, force)
        step += 1
        if record and step < out.history.shape[2]:
            x_now = x_ball if sine else ball_compression(law, params, force, f_peak)
            _record(
                out.history,
                p,
                step,
                force,
                x_now,
                force * points.inv_ks[p],
                ud,
                _dot(points.out_v[p], s),
                _dot(points.out_dc[p], s),
            )
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
            _step_back(frame.blocks, s, back, sep_s)
        if asymptotic:
            stop_at = step  # common speed approached asymptotically (no fold)
            break
        if stop_at < 0 and force == 0.0 and _dot(points.out_dc[p], s) > ud:
            # Open and separating in the dc motion: over for good once the gap exceeds
            # the largest deflection the remaining vibration can bring to the point.
            z_open = x_ball if sine else ball_compression(law, params, 0.0, f_peak)
            gap = z_open - (u - _dot(out_d, s))
            if gap >= _reach(points.reach_w[p], frame.metric, s):
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


@njit(cache=True)
def _opening_fraction(law, params, series, force, f_peak, z_pred):
    """Fraction of the step at which a monotone-law contact opened: where the approach
    beyond the ball's residual compression, d = z - g(0), went through zero, from ``force``
    at the step's start (d = g(force) - g(0) + series force) to the force-free prediction
    ``z_pred`` at its end, linearly.
    """
    rest = ball_compression(law, params, 0.0, f_peak)
    d_start = ball_compression(law, params, force, f_peak) - rest + series * force
    d_end = z_pred - rest
    if d_start - d_end <= 0.0:
        return 1.0
    return min(max(d_start / (d_start - d_end), 0.0), 1.0)


@njit(cache=True)
def _step_back(blocks, s, back, out):
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
def _reach(reach_w, metric, s):
    """The largest displacement the blocks' remaining vibration can bring to the point."""
    reach = 0.0
    for j in range(reach_w.size):
        if reach_w[j] > 0.0:
            reach += reach_w[j] * math.sqrt(
                metric[j, 0] * s[j, 0] ** 2 + metric[j, 1] * s[j, 1] ** 2
            )
    return reach


@njit(cache=True)
def _record(history, p, step, force, compression, string, ball_velocity, velocity, velocity_dc):
    """Write one step of impact ``p``'s histories."""
    history[H_FORCE, p, step] = force
    history[H_BALL_COMP, p, step] = compression
    history[H_STRING, p, step] = string
    history[H_BALL_VEL, p, step] = ball_velocity
    history[H_POINT_VEL, p, step] = velocity
    history[H_POINT_VEL_DC, p, step] = velocity_dc


@njit(cache=True)
def _dot(rows, s):
    """Rows . s over all blocks."""
    total = 0.0
    for j in range(s.shape[0]):
        total += rows[j, 0] * s[j, 0] + rows[j, 1] * s[j, 1]
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
