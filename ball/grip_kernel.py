"""The compiled tangential contact of :mod:`ball.grip` (numba loads it on first use, not on
``import ball``): velocity Verlet on the history's sub-steps, the two patches' Jenkins
elements and their return mapping, the offset's torque and the woven layer's implicit
friction (the model and its stepping are described in :mod:`ball.grip`).

One impact's state lives in local numbers, not an array (a third of the time: nothing to
reload after each store): the ball's velocity (v0, v1) and spin (w0, w1), the surface
point's velocity (u0, u1) and the impulse it received (p0, p1), the layer's offsets (s0, s1)
and velocities (l0, l1) (its strings that move along, across), and each patch's spring
(xa, xb: the displacement xi, or the elastic force, per unit share), force per unit share
(fa, fb) and whether it slides.
"""

from __future__ import annotations

import math

from numba import njit

from ball.grip_layout import (
    ENERGY_IN,
    ENERGY_OUT,
    GRIP_TIME,
    LAYER_ENERGY,
    LAYER_KINETIC,
    LAYER_LOSS,
    LAYER_MASS,
    LAYER_PEAK,
    LAYER_PRELOAD,
    LAYER_PRESS,
    LAYER_SHARE,
    LAYER_STATIC,
    LAYER_STIFFNESS,
    OFFSET_WORK,
    P_ACROSS,
    P_ALONG,
    REVERSALS,
    SLIP_LOSS,
    STIFFNESS_WORK,
    SURFACE_ENERGY,
    U_ACROSS,
    U_ALONG,
    V_ACROSS,
    V_ALONG,
    W_ACROSS,
    W_ALONG,
    W_NORMAL,
)  # fmt: skip


@njit(cache=True, inline="always", error_model="numpy")
def _stored(x0, x1, k, secant) -> float:
    """Energy [J] per unit share in a patch's spring (x0, x1) at stiffness ``k`` [N/m]."""
    if secant:
        return 0.5 * k * (x0 * x0 + x1 * x1)
    return 0.5 * (x0 * x0 + x1 * x1) / k if k > 0.0 else 0.0


@njit(cache=True, inline="always", error_model="numpy")
def _patch(x0, x1, f0, f1, c0, c1, k_a, k_b, h, secant, damp, limit):
    """A patch moved by the drift (c0, c1) [m/s] over ``h`` [s] as its stiffness goes from
    ``k_a`` to ``k_b`` [N/m] (per unit share), its spring (x0, x1) and last force (f0, f1):
    its spring and dashpot ``damp`` [N s/m] while it grips, cut back to friction's ``limit``
    [N] when they would beat it.  Returns the new spring, the new force, whether it slides,
    the work the stiffness change did on the spring at the start's state (:data:`STIFFNESS_WORK`:
    the normal motion's), and the work the patch took in the drift less what its spring kept
    (:data:`SLIP_LOSS`), both per unit share.
    """
    if secant:
        held = 0.5 * (x0 * x0 + x1 * x1)
        before, stored = k_a * held, k_b * held
    else:
        before, stored = _stored(x0, x1, k_a, secant), _stored(x0, x1, k_b, secant)
    if secant:  # the spring holds the displacement xi
        x0 += h * c0
        x1 += h * c1
        g0, g1 = k_b * x0, k_b * x1
    else:  # it holds the elastic force
        x0 += k_b * h * c0
        x1 += k_b * h * c1
        g0, g1 = x0, x1
    g0, g1 = g0 + damp * c0, g1 + damp * c1  # the dashpot, while it grips
    trial = g0 * g0 + g1 * g1  # squared
    slides = trial > limit * limit
    if slides:  # it slides: the spring carries the friction force
        cut = limit / math.sqrt(trial)
        g0 *= cut
        g1 *= cut
        if not secant:
            x0, x1 = g0, g1
        elif k_b > 0.0:
            x0, x1 = g0 / k_b, g1 / k_b
    taken = 0.5 * h * ((f0 + g0) * c0 + (f1 + g1) * c1)
    lost = taken - (_stored(x0, x1, k_b, secant) - stored)
    return x0, x1, g0, g1, slides, stored - before, lost


@njit(cache=True, inline="always", error_model="numpy")
def _offset_torque(w0, w1, normal, h, inertia, offset, sa, fa0, fa1, on_a, sb, fb0, fb1, on_b):
    """While a patch slides (``on_a``, ``on_b``), its share (``sa``, ``sb``) of the normal
    force's offset adds d N to its friction's torque: the spin after, and the work taken
    from it [J].
    """
    if normal <= 0.0 or not (on_a or on_b):
        return w0, w1, 0.0
    before = w0 * w0 + w1 * w1
    if on_a and sa > 0.0:
        scale = sa * offset * normal / math.sqrt(fa0 * fa0 + fa1 * fa1) * h / inertia
        w0 += scale * fa1
        w1 -= scale * fa0
    if on_b and sb > 0.0:
        scale = sb * offset * normal / math.sqrt(fb0 * fb0 + fb1 * fb1) * h / inertia
        w0 += scale * fb1
        w1 -= scale * fb0
    return w0, w1, 0.5 * inertia * (before - w0 * w0 - w1 * w1)


@njit(cache=True, inline="always", error_model="numpy")
def _half_kick(v0, v1, w0, w1, l0, l1, p0, p1, u0, u1, s0, s1, fa0, fa1, fb0, fb1, normal,
               layer_slides, row):  # fmt: skip
    """The forces' half kick (``row``: the impact's constants, as :func:`grip_kernel` packs
    them; the half step ``half`` [s], the ball's half kick per newton ``hm``, ``hr``, the
    layer's ``hc``, ``hmm``): the patches' forces on the ball and
    on what they sit on (patch a on the frame along and on the strings that move across,
    the mains; patch b on the strings that move along, the crosses, and on the frame
    across; without a layer, patch a on the surface), then the layer's friction at the
    crossings, an implicit impulse J (as RATTLE enforces a constraint): the one that stops
    the strings on the surface if within static friction's limit (kinetic friction's once
    they slide: no chatter at the step's rate), else that limit; its loss
    -J . (r0 + r_end) / 2.  Returns the state after, whether the strings slide, and that
    loss [J].
    """
    (sa, sb, half, hm, hr, hc, hmm, woven, k_c, k_m, i_c, i_m, press_ratio, preload, mu_s,
     mu_k, w00, w01, w11, a00, a11, det) = row  # fmt: skip
    r0, r1 = l0 - u0, l1 - u1  # the layer's slip, at the start
    f0, f1 = sa * fa0 + sb * fb0, sa * fa1 + sb * fb1
    v0 += f0 * hm
    v1 += f1 * hm
    w0 += f1 * hr
    w1 -= f0 * hr
    if not woven:
        p0 -= f0 * half
        p1 -= f1 * half
        return v0, v1, w0, w1, l0, l1, p0, p1, w00 * p0 + w01 * p1, w01 * p0 + w11 * p1, False, 0.0
    l0 -= (sb * fb0 + k_c * s0) * hc
    l1 -= (sa * fa1 + k_m * s1) * hmm
    p0 += (k_c * s0 - sa * fa0) * half
    p1 += (k_m * s1 - sb * fb1) * half
    u0, u1 = w00 * p0 + w01 * p1, w01 * p0 + w11 * p1
    press = (press_ratio * normal + preload) * half
    t0, t1 = l0 - u0, l1 - u1
    j0 = -(a11 * t0 - w01 * t1) * det
    j1 = -(a00 * t1 - w01 * t0) * det
    held = (mu_k if layer_slides else mu_s) * press
    layer_slides = j0 * j0 + j1 * j1 > held * held
    if layer_slides:
        limit = mu_k * press
        r = math.sqrt(t0 * t0 + t1 * t1)
        j0, j1 = -limit * t0 / r, -limit * t1 / r
    l0 += j0 * i_c
    l1 += j1 * i_m
    p0 -= j0
    p1 -= j1
    u0, u1 = w00 * p0 + w01 * p1, w01 * p0 + w11 * p1
    lost = -0.5 * (j0 * (r0 + l0 - u0) + j1 * (r1 + l1 - u1))
    return v0, v1, w0, w1, l0, l1, p0, p1, u0, u1, layer_slides, lost


@njit(cache=True, nogil=True, error_model="numpy")
def grip_kernel(force, dt, substeps, m, radius, inertia, k_t, offset, zeta, secant, mu, inv_mass,
                layer, v, w, out, start, stop, stride):  # fmt: skip
    """The tangential contact of impacts ``start``, ``start + stride``, ... before ``stop``
    (rows) along each one's normal force history, into ``out`` (it releases the GIL: threads
    may share the rows).

    Each sub-step is a half kick, a drift, a half kick.  A half kick: the offset's torque
    while a patch slides, outside the forces' kick (before it in the first half kick, after
    it in the second: the step stays symmetric, and the budget second order); the patches'
    forces on the ball and on what they sit on (patch a on the frame along and on the
    strings that move across, the mains; patch b on the strings that move along, the
    crosses, and on the frame across; without a layer, patch a on the surface); the layer's
    friction at the crossings, an implicit impulse after the forces (as RATTLE enforces a
    constraint): the one that stops the strings on the surface if it is within static
    friction's limit (kinetic friction's once they slide: no chatter at the step's rate),
    else that limit, its loss -J . (r0 + r_end) / 2.

    Parameters
    ----------
    force : ndarray
        (n, T) normal force [N] at times 0, dt, ... (T samples).
    dt : float
        Step [s] of the history.
    substeps : int
        Sub-steps per step.
    m, radius, inertia, offset : float
        Ball mass [kg], radius [m], moment of inertia [kg m^2], normal force's offset [m].
    k_t : ndarray
        (n, T) tangential stiffness [N/m] at the history's times (linear between them).
    zeta : float
        Damping ratio [-] of the patches' dashpot, c = 2 zeta sqrt(k_t m_t) (m_t the ball's
        tangential effective mass) at the history's times, linear between them, while they
        grip.
    secant : bool
        True: the patches' springs are secant, F = k_t xi (the stored force rescaled as k_t
        changes); False: incremental, dF = k_t dxi.
    mu : ndarray
        (n,) ball-surface friction coefficient [-].
    inv_mass : ndarray
        (n, 2, 2) the surface point's in-plane inverse mass [1/kg].
    layer : ndarray
        (n, N_LAYER) the woven layer's row (:mod:`ball.grip_layout`); its masses 0: none.
    v, w : ndarray
        (n, 2) ball's tangential velocity relative to the surface [m/s]; (n, 3) its spin
        [rad/s].
    out : ndarray
        (n, N_OUT) zeros, for the outcome, columns as named in :mod:`ball.grip_layout`.
    start, stop, stride : int
        The rows to run.
    """
    steps = force.shape[1]
    h = dt / substeps
    half = 0.5 * h
    fraction = 1.0 / substeps
    hm, hr = half / m, radius * half / inertia  # the ball's half kick per newton
    m_t = m * inertia / (inertia + m * radius * radius)  # the ball's tangential mass
    for i in range(start, stop, stride):
        o = out[i]
        k_c, k_m = layer[i, LAYER_STIFFNESS], layer[i, LAYER_STIFFNESS + 1]
        m_c, m_m = layer[i, LAYER_MASS], layer[i, LAYER_MASS + 1]
        woven = m_c > 0.0
        sa, sb = (layer[i, LAYER_SHARE], 1.0 - layer[i, LAYER_SHARE]) if woven else (1.0, 0.0)
        mu_s, mu_k, mu_i = layer[i, LAYER_STATIC], layer[i, LAYER_KINETIC], mu[i]
        press_ratio, preload = layer[i, LAYER_PRESS], layer[i, LAYER_PRELOAD]
        w00, w01, w11 = inv_mass[i, 0, 0], inv_mass[i, 0, 1], inv_mass[i, 1, 1]
        # the crossings' friction, (1/m + W) J = -slip: its matrix and 1 / its determinant
        a00 = a11 = det = 1.0
        hc = hmm = i_c = i_m = 0.0  # the layer's half kick per newton, its inverse masses
        if woven:
            i_c, i_m = 1.0 / m_c, 1.0 / m_m
            a00, a11 = i_c + w00, i_m + w11
            det = 1.0 / (a00 * a11 - w01 * w01)
            hc, hmm = half * i_c, half * i_m
        # the ball has left after the last positive force: nothing moves it after the step
        # that ends there (the strings may ring on, pressed by the weave alone)
        last = steps - 1
        while last > 0 and force[i, last] <= 0.0 and force[i, last - 1] <= 0.0:
            last -= 1
        row = (sa, sb, half, hm, hr, hc, hmm, woven, k_c, k_m, i_c, i_m, press_ratio, preload,
               mu_s, mu_k, w00, w01, w11, a00, a11, det)  # fmt: skip
        v0, v1, w0, w1 = v[i, 0], v[i, 1], w[i, 0], w[i, 1]
        o[ENERGY_IN] = 0.5 * m * (v0 * v0 + v1 * v1) + 0.5 * inertia * (w0 * w0 + w1 * w1)
        slip0, slip1 = v0 - radius * w1, v1 + radius * w0
        size = math.sqrt(slip0 * slip0 + slip1 * slip1)
        d0, d1 = (slip0 / size, slip1 / size) if size > 0.0 else (1.0, 0.0)
        u0 = u1 = p0 = p1 = s0 = s1 = l0 = l1 = 0.0
        xa0 = xa1 = xb0 = xb1 = fa0 = fa1 = fb0 = fb1 = 0.0
        on_a = on_b = layer_slides = False
        slip_loss = layer_loss = offset_work = stiffness_work = grip_time = reversals = 0.0
        sign = peak = 0.0
        n_b = k_b = 0.0
        for j in range(last):
            n_j, dn = force[i, j], force[i, j + 1] - force[i, j]
            k_j, dk = k_t[i, j], k_t[i, j + 1] - k_t[i, j]
            n_b, k_b = n_j, max(k_j, 0.0)
            # the dashpot c = 2 zeta sqrt(k_t m_t), linear over the step as k_t is
            c_j = 2.0 * zeta * math.sqrt(k_b * m_t)
            dc = 2.0 * zeta * math.sqrt(max(k_t[i, j + 1], 0.0) * m_t) - c_j
            for k in range(substeps):
                # N and k_t linear over the step (k_t >= 0: falling to 0 it may round to
                # -1 ulp of its last value)
                n_a, k_a = n_b, k_b
                n_b = n_j + dn * ((k + 1) * fraction)
                k_b = max(k_j + dk * ((k + 1) * fraction), 0.0)
                w0, w1, work = _offset_torque(w0, w1, n_a, half, inertia, offset, sa, fa0, fa1,
                                              on_a, sb, fb0, fb1, on_b)  # fmt: skip
                offset_work += work
                v0, v1, w0, w1, l0, l1, p0, p1, u0, u1, layer_slides, lost = _half_kick(
                    v0, v1, w0, w1, l0, l1, p0, p1, u0, u1, s0, s1, fa0, fa1, fb0, fb1, n_a,
                    layer_slides, row)  # fmt: skip
                layer_loss += lost
                # the drift: each patch follows what it sits on while it grips
                b0, b1 = v0 - radius * w1, v1 + radius * w0  # the ball's contact point
                if woven:
                    s0 += h * (l0 - u0)
                    s1 += h * (l1 - u1)
                    peak = max(peak, s0 * s0 + s1 * s1)  # squared
                gripped = n_b > 0.0
                damp = c_j + dc * ((k + 1) * fraction)
                limit = mu_i * max(n_b, 0.0)
                if sa > 0.0:
                    ca0, ca1 = u0 - b0, (l1 if woven else u1) - b1
                    xa0, xa1, fa0, fa1, slides, work, lost = _patch(
                        xa0, xa1, fa0, fa1, ca0, ca1, k_a, k_b, h, secant, damp, limit
                    )
                    stiffness_work += sa * work
                    slip_loss += sa * lost
                    on_a = slides and limit > 0.0
                    gripped = gripped and not slides
                if sb > 0.0:
                    xb0, xb1, fb0, fb1, slides, work, lost = _patch(
                        xb0, xb1, fb0, fb1, l0 - b0, u1 - b1, k_a, k_b, h, secant, damp, limit
                    )
                    stiffness_work += sb * work
                    slip_loss += sb * lost
                    on_b = slides and limit > 0.0
                    gripped = gripped and not slides
                if gripped:
                    grip_time += h
                along = (sa * fa0 + sb * fb0) * d0 + (sa * fa1 + sb * fb1) * d1
                if along != 0.0:
                    if sign != 0.0 and along * sign < 0.0:
                        reversals += 1.0
                    sign = along
                v0, v1, w0, w1, l0, l1, p0, p1, u0, u1, layer_slides, lost = _half_kick(
                    v0, v1, w0, w1, l0, l1, p0, p1, u0, u1, s0, s1, fa0, fa1, fb0, fb1, n_b,
                    layer_slides, row)  # fmt: skip
                layer_loss += lost
                w0, w1, work = _offset_torque(w0, w1, n_b, half, inertia, offset, sa, fa0, fa1,
                                              on_a, sb, fb0, fb1, on_b)  # fmt: skip
                offset_work += work
        o[SLIP_LOSS], o[LAYER_LOSS], o[OFFSET_WORK] = slip_loss, layer_loss, offset_work
        o[STIFFNESS_WORK], o[GRIP_TIME], o[REVERSALS] = stiffness_work, grip_time, reversals
        o[V_ALONG], o[V_ACROSS] = v0, v1
        o[W_ALONG], o[W_ACROSS], o[W_NORMAL] = w0, w1, w[i, 2]
        o[LAYER_PEAK] = math.sqrt(peak)
        o[U_ALONG], o[U_ACROSS], o[P_ALONG], o[P_ACROSS] = u0, u1, p0, p1
        o[SURFACE_ENERGY] = 0.5 * (p0 * u0 + p1 * u1)
        o[LAYER_ENERGY] = 0.5 * (m_c * l0 * l0 + m_m * l1 * l1 + k_c * s0 * s0 + k_m * s1 * s1)
        o[ENERGY_OUT] = 0.5 * m * (v0 * v0 + v1 * v1) + o[SURFACE_ENERGY]
        o[ENERGY_OUT] += 0.5 * inertia * (w0 * w0 + w1 * w1) + o[LAYER_ENERGY]
        k_end = k_t[i, last]
        o[ENERGY_OUT] += sa * _stored(xa0, xa1, k_end, secant) + sb * _stored(xb0, xb1, k_end,
                                                                             secant)  # fmt: skip
