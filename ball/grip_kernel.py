"""The compiled tangential contact of :mod:`ball.grip` (numba loads it on first use, not on
``import ball``): velocity Verlet on the history's sub-steps, the Jenkins element's return
mapping, the offset's torque and the layer's implicit friction (the model and its stepping
are described in :mod:`ball.grip`).
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from ball.grip_layout import (
    ENERGY_IN,
    ENERGY_OUT,
    GRIP_TIME,
    LAYER_ENERGY,
    LAYER_LOSS,
    LAYER_PEAK,
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


@njit(cache=True, inline="always")
def _kick(st, f0, f1, normal, h, m, radius, inertia, offset, w00, w01, w11, k_l, m_l, mu_l, out,
          first):  # fmt: skip
    """Half kick of ``h`` [s]: the ball's force (f0, f1) on the ball and the layer (or the
    surface); the offset's torque while sliding, outside the forces' kick (before it in the
    first half kick, after it in the second: the step stays symmetric, and the budget second
    order); the layer's friction, an impulse solved implicitly after the forces in both.
    The surface's inverse mass is (w00, w01, w11), the layer's stiffness, mass and friction
    (k_l, m_l, mu_l): all numbers, no arrays made per call.
    """
    if first:
        _offset_torque(st, f0, f1, normal, h, inertia, offset, out)
    r0, r1 = st[10] - st[5], st[11] - st[6]  # the layer's slip on the surface, at the start
    st[0] += f0 * h / m
    st[1] += f1 * h / m
    st[2] += radius * f1 * h / inertia
    st[3] -= radius * f0 * h / inertia
    if m_l > 0.0:
        # the layer (absolute velocity st[10:12], offset st[8:10] from its place)
        st[10] -= (f0 + k_l * st[8]) * h / m_l
        st[11] -= (f1 + k_l * st[9]) * h / m_l
        _push(st, w00, w01, w11, k_l * st[8] * h, k_l * st[9] * h)
    else:
        _push(st, w00, w01, w11, -f0 * h, -f1 * h)
    # the layer's friction after the forces in both half kicks (as RATTLE enforces a
    # constraint): a layer that sticks then moves with the surface through the drift
    _layer_friction(st, normal * mu_l * h, m_l, w00, w01, w11, r0, r1, out)
    if not first:
        _offset_torque(st, f0, f1, normal, h, inertia, offset, out)


@njit(cache=True, inline="always")
def _offset_torque(st, f0, f1, normal, h, inertia, offset, out):
    """While the ball slides, the normal force's offset adds d N to friction's torque."""
    if st[14] > 0.0 and normal > 0.0:
        scale = offset * normal / math.sqrt(f0 * f0 + f1 * f1) * h / inertia
        before = st[2] ** 2 + st[3] ** 2
        st[2] += scale * f1
        st[3] -= scale * f0
        out[OFFSET_WORK] += 0.5 * inertia * (before - st[2] ** 2 - st[3] ** 2)


@njit(cache=True, inline="always")
def _layer_friction(st, limit, m_l, w00, w01, w11, r0, r1, out):
    """The layer's Coulomb friction on the surface, an impulse J of at most ``limit`` [N s]:
    the one that stops their relative motion if it is within the limit (they stick).  It
    acts with the half kick's forces, so its loss is -J . (r0 + r_end) / 2 with (r0, r1) the
    slip at the half kick's start: exact for the layer and the surface, and zero while they
    stay stuck.
    """
    if m_l == 0.0:
        return
    t0, t1 = st[10] - st[5], st[11] - st[6]
    a00 = 1.0 / m_l + w00
    a11 = 1.0 / m_l + w11
    det = a00 * a11 - w01 * w01
    j0 = -(a11 * t0 - w01 * t1) / det
    j1 = -(a00 * t1 - w01 * t0) / det
    if math.sqrt(j0 * j0 + j1 * j1) > limit:
        r = math.sqrt(t0 * t0 + t1 * t1)
        j0, j1 = -limit * t0 / r, -limit * t1 / r
    st[10] += j0 / m_l
    st[11] += j1 / m_l
    _push(st, w00, w01, w11, -j0, -j1)
    out[LAYER_LOSS] -= 0.5 * (j0 * (r0 + st[10] - st[5]) + j1 * (r1 + st[11] - st[6]))


@njit(cache=True, inline="always")
def _push(st, w00, w01, w11, p0, p1):
    """The surface receives the impulse (p0, p1) [N s]."""
    st[12] += p0
    st[13] += p1
    st[5] = w00 * st[12] + w01 * st[13]
    st[6] = w01 * st[12] + w11 * st[13]


@njit(cache=True, nogil=True)
def grip_kernel(force, dt, substeps, m, radius, inertia, k_t, offset, zeta, secant, mu, inv_mass,
                layer, v, w, out, start, stop, stride):  # fmt: skip
    """The tangential contact of impacts ``start``, ``start + stride``, ... before ``stop``
    (rows) along each one's normal force history, into ``out`` (it releases the GIL: threads
    may share the rows).

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
        Damping ratio [-] of the patch's dashpot, c = 2 zeta sqrt(k_t m_t) (m_t the ball's
        tangential effective mass), while it grips.
    secant : bool
        True: the patch's spring is secant, F = k_t xi (the stored force rescaled as k_t
        changes); False: incremental, dF = k_t dxi.
    mu : ndarray
        (n,) ball-surface friction coefficient [-].
    inv_mass : ndarray
        (n, 2, 2) the surface point's in-plane inverse mass [1/kg].
    layer : ndarray
        (n, 3) the layer's stiffness [N/m], mass [kg] (0: none) and friction [-].
    v, w : ndarray
        (n, 2) ball's tangential velocity relative to the surface [m/s]; (n, 3) its spin
        [rad/s].
    out : ndarray
        (n, N_OUT) zeros, for the outcome, columns as named in this module.
    start, stop, stride : int
        The rows to run.
    """
    steps = force.shape[1]
    h = dt / substeps
    m_t = m * inertia / (inertia + m * radius * radius)  # the ball's tangential mass
    for i in range(start, stop, stride):
        o = out[i]
        # v(0:2) w_t(2:4) xi or F(4, 7) u(5:7) s(8:10) layer v(10:12) P(12:14) sliding(14)
        st = np.zeros(15)
        st[0], st[1], st[2], st[3] = v[i, 0], v[i, 1], w[i, 0], w[i, 1]
        o[ENERGY_IN] = 0.5 * m * (v[i, 0] ** 2 + v[i, 1] ** 2)
        o[ENERGY_IN] += 0.5 * inertia * (w[i, 0] ** 2 + w[i, 1] ** 2)
        slip0 = v[i, 0] - radius * w[i, 1]
        slip1 = v[i, 1] + radius * w[i, 0]
        size = math.sqrt(slip0 * slip0 + slip1 * slip1)
        d0, d1 = (slip0 / size, slip1 / size) if size > 0.0 else (1.0, 0.0)
        f0 = f1 = 0.0
        sign = peak = 0.0
        w00, w01, w11 = inv_mass[i, 0, 0], inv_mass[i, 0, 1], inv_mass[i, 1, 1]
        k_l, m_l, mu_l = layer[i, 0], layer[i, 1], layer[i, 2]
        for j in range(steps - 1):
            for k in range(substeps):
                n_a = force[i, j] + (force[i, j + 1] - force[i, j]) * k / substeps
                n_b = force[i, j] + (force[i, j + 1] - force[i, j]) * (k + 1) / substeps
                # (>= 0: a stiffness falling to 0 may round to -1 ulp of its last value)
                k_a = max(k_t[i, j] + (k_t[i, j + 1] - k_t[i, j]) * k / substeps, 0.0)
                k_b = max(k_t[i, j] + (k_t[i, j + 1] - k_t[i, j]) * (k + 1) / substeps, 0.0)
                _kick(st, f0, f1, n_a, 0.5 * h, m, radius, inertia, offset, w00, w01, w11, k_l,
                      m_l, mu_l, o, True)  # fmt: skip
                # drift: the patch follows the surface (or layer) while it grips
                c0 = (st[10] if m_l > 0.0 else st[5]) - (st[0] - radius * st[3])
                c1 = (st[11] if m_l > 0.0 else st[6]) - (st[1] + radius * st[2])
                if m_l > 0.0:
                    st[8] += h * (st[10] - st[5])
                    st[9] += h * (st[11] - st[6])
                    peak = max(peak, st[8] * st[8] + st[9] * st[9])  # squared
                g0, g1, stored = _spring(st, k_a, k_b, h, c0, c1, secant, o)
                damp = 2.0 * zeta * math.sqrt(k_b * m_t)
                g0, g1 = g0 + damp * c0, g1 + damp * c1  # the dashpot, while it grips
                limit = mu[i] * max(n_b, 0.0)
                trial = math.sqrt(g0 * g0 + g1 * g1)
                st[14] = 0.0
                if trial > limit:  # it slides: the spring carries the friction force
                    cut = limit / trial
                    g0 *= cut
                    g1 *= cut
                    st[14] = 1.0 if limit > 0.0 else 0.0
                    _hold(st, g0, g1, k_b, secant)
                elif n_b > 0.0:
                    o[GRIP_TIME] += h
                # the work the contact took in the drift, less what its spring kept
                taken = 0.5 * h * ((f0 + g0) * c0 + (f1 + g1) * c1)
                o[SLIP_LOSS] += taken - (_stored(st, k_b, secant) - stored)
                f0, f1 = g0, g1
                along = f0 * d0 + f1 * d1
                if along != 0.0:
                    if sign != 0.0 and along * sign < 0.0:
                        o[REVERSALS] += 1.0
                    sign = along
                _kick(st, f0, f1, n_b, 0.5 * h, m, radius, inertia, offset, w00, w01, w11, k_l,
                      m_l, mu_l, o, False)  # fmt: skip
        o[V_ALONG], o[V_ACROSS], o[W_ALONG], o[W_ACROSS] = st[0], st[1], st[2], st[3]
        o[W_NORMAL] = w[i, 2]
        o[LAYER_PEAK] = math.sqrt(peak)
        o[U_ALONG], o[U_ACROSS], o[P_ALONG], o[P_ACROSS] = st[5], st[6], st[12], st[13]
        o[SURFACE_ENERGY] = 0.5 * (st[12] * st[5] + st[13] * st[6])
        o[LAYER_ENERGY] = 0.5 * m_l * (st[10] ** 2 + st[11] ** 2)
        o[LAYER_ENERGY] += 0.5 * k_l * (st[8] ** 2 + st[9] ** 2)
        o[ENERGY_OUT] = 0.5 * m * (st[0] ** 2 + st[1] ** 2) + o[SURFACE_ENERGY]
        o[ENERGY_OUT] += 0.5 * inertia * (st[2] ** 2 + st[3] ** 2) + o[LAYER_ENERGY]
        o[ENERGY_OUT] += _stored(st, k_t[i, steps - 1], secant)


@njit(cache=True, inline="always")
def _spring(st, k_a, k_b, h, c0, c1, secant, out):
    """The patch's spring moved by the drift (c0, c1) [m/s] over ``h`` [s] as its stiffness
    goes from ``k_a`` to ``k_b`` [N/m]: its trial elastic force, and the energy it held at
    the drift's start at ``k_b`` (what the stiffness change added, at the start's state,
    is booked as :data:`STIFFNESS_WORK`: work of the normal motion on the spring).
    """
    before = _stored(st, k_a, secant)
    stored = _stored(st, k_b, secant)
    out[STIFFNESS_WORK] += stored - before
    if secant:  # st[4], st[7] hold the displacement xi
        st[4] += h * c0
        st[7] += h * c1
        return k_b * st[4], k_b * st[7], stored
    st[4] += k_b * h * c0  # st[4], st[7] hold the elastic force
    st[7] += k_b * h * c1
    return st[4], st[7], stored


@njit(cache=True, inline="always")
def _hold(st, g0, g1, k, secant):
    """The spring set to carry the force (g0, g1) [N] at stiffness ``k`` [N/m]."""
    if not secant:
        st[4], st[7] = g0, g1
    elif k > 0.0:
        st[4], st[7] = g0 / k, g1 / k


@njit(cache=True, inline="always")
def _stored(st, k, secant) -> float:
    """Energy [J] in the patch's spring at stiffness ``k`` [N/m]."""
    if secant:
        return 0.5 * k * (st[4] * st[4] + st[7] * st[7])
    return 0.5 * (st[4] * st[4] + st[7] * st[7]) / k if k > 0.0 else 0.0
