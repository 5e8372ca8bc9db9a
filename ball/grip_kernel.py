"""The compiled tangential contact of :mod:`ball.grip` (numba loads it on first use, not on
``import ball``): velocity Verlet on the history's sub-steps, the two patches' Jenkins
elements and their return mapping, the offset's torque and the woven layer's implicit
friction (the model and its stepping are described in :mod:`ball.grip`).
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
)  # fmt: skip  # fmt: skip

# the state of one impact: the ball's velocity and spin (along, across), the surface
# point's velocity and the impulse it received, the layer's offsets and velocities (its
# strings that move along, across), each patch's spring (xi or F per unit share), whether
# it slides, its last force per unit share, and whether the layer slides
# (patch p's: spring at _SPRING + 2 p, flag at _SLIDES + p, force at _FORCE + 2 p)
_V, _W, _U, _P, _S, _L = 0, 2, 4, 6, 8, 10
_SPRING, _SLIDES, _FORCE = 12, 16, 18
_LAYER_SLIDES = 22
_STATE = 23


@njit(cache=True, inline="always")
def _kick(st, normal, h, m, radius, inertia, offset, inv, lay, solve, share, out, first):
    """Half kick of ``h`` [s]: the patches' forces on the ball and on what they sit on (the
    surface, or the layer's strings that move in that direction); the offset's torque while
    a patch slides, outside the forces' kick (before it in the first half kick, after it in
    the second: the step stays symmetric, and the budget second order); the layer's
    friction, an impulse solved implicitly after the forces in both.  ``inv`` is the
    surface's inverse mass (w00, w01, w11), ``lay`` the layer's row (its mass 0: none),
    ``solve`` its friction's 2 x 2 system (a00, a11, det), ``share`` the patches' shares of
    the grip.
    """
    if first:
        _offset_torque(st, normal, h, inertia, offset, share, out)
    r0, r1 = st[_L] - st[_U], st[_L + 1] - st[_U + 1]  # the layer's slip, at the start
    a, b = _FORCE, _FORCE + 2
    f0 = share[0] * st[a] + share[1] * st[b]
    f1 = share[0] * st[a + 1] + share[1] * st[b + 1]
    st[_V] += f0 * h / m
    st[_V + 1] += f1 * h / m
    st[_W] += radius * f1 * h / inertia
    st[_W + 1] -= radius * f0 * h / inertia
    m0, m1 = lay[LAYER_MASS], lay[LAYER_MASS + 1]
    if m0 > 0.0:
        # patch a sits on the frame along and on the strings that move across (the mains),
        # patch b on the strings that move along (the crosses) and on the frame across
        k0, k1 = lay[LAYER_STIFFNESS], lay[LAYER_STIFFNESS + 1]
        st[_L] -= (share[1] * st[b] + k0 * st[_S]) * h / m0
        st[_L + 1] -= (share[0] * st[a + 1] + k1 * st[_S + 1]) * h / m1
        p0 = (k0 * st[_S] - share[0] * st[a]) * h
        p1 = (k1 * st[_S + 1] - share[1] * st[b + 1]) * h
        _push(st, inv, p0, p1)
        # the layer's friction after the forces in both half kicks (as RATTLE enforces a
        # constraint): strings that stick then move with the surface through the drift
        press = lay[LAYER_PRESS] * normal + lay[LAYER_PRELOAD]
        _layer_friction(st, press * h, lay, inv, solve, r0, r1, out)
    else:
        _push(st, inv, -f0 * h, -f1 * h)
    if not first:
        _offset_torque(st, normal, h, inertia, offset, share, out)


@njit(cache=True, inline="always")
def _offset_torque(st, normal, h, inertia, offset, share, out):
    """While a patch slides, its share of the normal force's offset adds d N to its
    friction's torque.
    """
    if normal <= 0.0 or st[_SLIDES] + st[_SLIDES + 1] == 0.0:
        return
    before = st[_W] ** 2 + st[_W + 1] ** 2
    for p in range(2):
        g0, g1 = st[_FORCE + 2 * p], st[_FORCE + 2 * p + 1]
        if share[p] > 0.0 and st[_SLIDES + p] > 0.0:
            scale = share[p] * offset * normal / math.sqrt(g0 * g0 + g1 * g1) * h / inertia
            st[_W] += scale * g1
            st[_W + 1] -= scale * g0
    out[OFFSET_WORK] += 0.5 * inertia * (before - st[_W] ** 2 - st[_W + 1] ** 2)


@njit(cache=True, inline="always")
def _layer_friction(st, press, lay, inv, solve, r0, r1, out):
    """The layer's Coulomb friction on the surface at the crossings, an impulse J: the one
    that stops their relative motion if it is within the limit (they stick), else the
    limit, ``press`` [N s] times the coefficient: static friction's while they stick,
    kinetic friction's while they slide (once sliding, they stick again only when kinetic
    friction can stop them: no chatter between the two at the step's rate).  It acts with the half
    kick's forces, so its loss is -J . (r0 + r_end) / 2 with (r0, r1) the slip at the half
    kick's start: exact for the layer and the surface, and zero while they stay stuck.
    """
    m0, m1 = lay[LAYER_MASS], lay[LAYER_MASS + 1]
    t0, t1 = st[_L] - st[_U], st[_L + 1] - st[_U + 1]
    a00, a11, det = solve[0], solve[1], solve[2]
    j0 = -(a11 * t0 - inv[1] * t1) / det
    j1 = -(a00 * t1 - inv[1] * t0) / det
    coefficient = lay[LAYER_KINETIC] if st[_LAYER_SLIDES] > 0.0 else lay[LAYER_STATIC]
    st[_LAYER_SLIDES] = 0.0
    if math.sqrt(j0 * j0 + j1 * j1) > coefficient * press:
        limit = lay[LAYER_KINETIC] * press
        r = math.sqrt(t0 * t0 + t1 * t1)
        j0, j1 = -limit * t0 / r, -limit * t1 / r
        st[_LAYER_SLIDES] = 1.0
    st[_L] += j0 / m0
    st[_L + 1] += j1 / m1
    _push(st, inv, -j0, -j1)
    t0, t1 = st[_L] - st[_U], st[_L + 1] - st[_U + 1]
    out[LAYER_LOSS] -= 0.5 * (j0 * (r0 + t0) + j1 * (r1 + t1))


@njit(cache=True, inline="always")
def _push(st, inv, p0, p1):
    """The surface receives the impulse (p0, p1) [N s]."""
    st[_P] += p0
    st[_P + 1] += p1
    st[_U] = inv[0] * st[_P] + inv[1] * st[_P + 1]
    st[_U + 1] = inv[1] * st[_P] + inv[2] * st[_P + 1]


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
        Damping ratio [-] of the patches' dashpot, c = 2 zeta sqrt(k_t m_t) (m_t the ball's
        tangential effective mass), while they grip.
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
    fraction = 1.0 / substeps
    m_t = m * inertia / (inertia + m * radius * radius)  # the ball's tangential mass
    for i in range(start, stop, stride):
        o = out[i]
        lay = layer[i]
        woven = lay[LAYER_MASS] > 0.0
        share = np.array([lay[LAYER_SHARE], 1.0 - lay[LAYER_SHARE]]) if woven else np.array(
            [1.0, 0.0])  # fmt: skip
        inv = np.array([inv_mass[i, 0, 0], inv_mass[i, 0, 1], inv_mass[i, 1, 1]])
        solve = np.zeros(3)  # the crossings' friction: (1/m + W) J = -slip
        if woven:
            solve[0] = 1.0 / lay[LAYER_MASS] + inv[0]
            solve[1] = 1.0 / lay[LAYER_MASS + 1] + inv[2]
            solve[2] = solve[0] * solve[1] - inv[1] * inv[1]
        # the ball has left after the last positive force: nothing moves it after the step
        # that ends there (the strings may ring on, pressed by the weave alone)
        stop = steps - 1
        while stop > 0 and force[i, stop] <= 0.0 and force[i, stop - 1] <= 0.0:
            stop -= 1
        st = np.zeros(_STATE)
        st[_V], st[_V + 1], st[_W], st[_W + 1] = v[i, 0], v[i, 1], w[i, 0], w[i, 1]
        o[ENERGY_IN] = 0.5 * m * (v[i, 0] ** 2 + v[i, 1] ** 2)
        o[ENERGY_IN] += 0.5 * inertia * (w[i, 0] ** 2 + w[i, 1] ** 2)
        slip0 = v[i, 0] - radius * w[i, 1]
        slip1 = v[i, 1] + radius * w[i, 0]
        size = math.sqrt(slip0 * slip0 + slip1 * slip1)
        d0, d1 = (slip0 / size, slip1 / size) if size > 0.0 else (1.0, 0.0)
        sign = peak = 0.0
        for j in range(stop):
            n_j, dn = force[i, j], force[i, j + 1] - force[i, j]
            k_j, dk = k_t[i, j], k_t[i, j + 1] - k_t[i, j]
            n_b, k_b = n_j, max(k_j, 0.0)
            for k in range(substeps):
                # N and k_t linear over the step (k_t >= 0: falling to 0 it may round to
                # -1 ulp of its last value)
                n_a, k_a = n_b, k_b
                n_b = n_j + dn * ((k + 1) * fraction)
                k_b = max(k_j + dk * ((k + 1) * fraction), 0.0)
                _kick(st, n_a, 0.5 * h, m, radius, inertia, offset, inv, lay, solve, share, o, True)
                # drift: each patch follows what it sits on while it grips
                b0 = st[_V] - radius * st[_W + 1]  # the ball's contact point
                b1 = st[_V + 1] + radius * st[_W]
                if woven:
                    st[_S] += h * (st[_L] - st[_U])
                    st[_S + 1] += h * (st[_L + 1] - st[_U + 1])
                    peak = max(peak, st[_S] * st[_S] + st[_S + 1] * st[_S + 1])  # squared
                gripped = n_b > 0.0
                damp = 2.0 * zeta * math.sqrt(k_b * m_t)
                limit = mu[i] * max(n_b, 0.0)
                for p in range(2):
                    if share[p] == 0.0:
                        continue
                    c0 = (st[_U] if p == 0 or not woven else st[_L]) - b0
                    c1 = (st[_L + 1] if p == 0 and woven else st[_U + 1]) - b1
                    slides = _patch(st, p, k_a, k_b, h, c0, c1, secant, damp, limit, share[p], o)
                    gripped = gripped and not slides
                if gripped:
                    o[GRIP_TIME] += h
                a, b = _FORCE, _FORCE + 2
                f0 = share[0] * st[a] + share[1] * st[b]
                f1 = share[0] * st[a + 1] + share[1] * st[b + 1]
                along = f0 * d0 + f1 * d1
                if along != 0.0:
                    if sign != 0.0 and along * sign < 0.0:
                        o[REVERSALS] += 1.0
                    sign = along
                _kick(
                    st, n_b, 0.5 * h, m, radius, inertia, offset, inv, lay, solve, share, o, False
                )
        o[V_ALONG], o[V_ACROSS] = st[_V], st[_V + 1]
        o[W_ALONG], o[W_ACROSS], o[W_NORMAL] = st[_W], st[_W + 1], w[i, 2]
        o[LAYER_PEAK] = math.sqrt(peak)
        o[U_ALONG], o[U_ACROSS], o[P_ALONG], o[P_ACROSS] = st[_U], st[_U + 1], st[_P], st[_P + 1]
        o[SURFACE_ENERGY] = 0.5 * (st[_P] * st[_U] + st[_P + 1] * st[_U + 1])
        for d in range(2):
            o[LAYER_ENERGY] += 0.5 * lay[LAYER_MASS + d] * st[_L + d] ** 2
            o[LAYER_ENERGY] += 0.5 * lay[LAYER_STIFFNESS + d] * st[_S + d] ** 2
        o[ENERGY_OUT] = 0.5 * m * (st[_V] ** 2 + st[_V + 1] ** 2) + o[SURFACE_ENERGY]
        o[ENERGY_OUT] += 0.5 * inertia * (st[_W] ** 2 + st[_W + 1] ** 2) + o[LAYER_ENERGY]
        for p in range(2):
            o[ENERGY_OUT] += share[p] * _stored(st, p, k_t[i, stop], secant)


@njit(cache=True, inline="always")
def _patch(st, p, k_a, k_b, h, c0, c1, secant, damp, limit, share, out) -> bool:
    """Patch ``p`` moved by the drift (c0, c1) [m/s] over ``h`` [s] as its stiffness goes
    from ``k_a`` to ``k_b`` [N/m] (per unit share): its spring and dashpot ``damp`` [N s/m]
    while it grips, cut back to friction's ``limit`` [N] when they would beat it (True: it
    slides).  Its force per unit share goes to the state; what the stiffness change added,
    at the start's state, is booked as :data:`STIFFNESS_WORK` (work of the normal motion on
    the spring), the work the patch took in the drift less what its spring kept as
    :data:`SLIP_LOSS`, both times ``share``.
    """
    x = _SPRING + 2 * p
    if secant:
        held = 0.5 * (st[x] * st[x] + st[x + 1] * st[x + 1])
        before, stored = k_a * held, k_b * held
    else:
        before, stored = _stored(st, p, k_a, secant), _stored(st, p, k_b, secant)
    out[STIFFNESS_WORK] += share * (stored - before)
    if secant:  # the spring holds the displacement xi
        st[x] += h * c0
        st[x + 1] += h * c1
        g0, g1 = k_b * st[x], k_b * st[x + 1]
    else:  # it holds the elastic force
        st[x] += k_b * h * c0
        st[x + 1] += k_b * h * c1
        g0, g1 = st[x], st[x + 1]
    g0, g1 = g0 + damp * c0, g1 + damp * c1  # the dashpot, while it grips
    trial = math.sqrt(g0 * g0 + g1 * g1)
    slides = trial > limit
    st[_SLIDES + p] = 0.0
    if slides:  # it slides: the spring carries the friction force
        cut = limit / trial
        g0 *= cut
        g1 *= cut
        st[_SLIDES + p] = 1.0 if limit > 0.0 else 0.0
        if not secant:
            st[x], st[x + 1] = g0, g1
        elif k_b > 0.0:
            st[x], st[x + 1] = g0 / k_b, g1 / k_b
    f = _FORCE + 2 * p
    taken = 0.5 * h * ((st[f] + g0) * c0 + (st[f + 1] + g1) * c1)
    out[SLIP_LOSS] += share * (taken - (_stored(st, p, k_b, secant) - stored))
    st[f], st[f + 1] = g0, g1
    return slides


@njit(cache=True, inline="always")
def _stored(st, p, k, secant) -> float:
    """Energy [J] per unit share in patch ``p``'s spring at stiffness ``k`` [N/m]."""
    x = _SPRING + 2 * p
    if secant:
        return 0.5 * k * (st[x] * st[x] + st[x + 1] * st[x + 1])
    return 0.5 * (st[x] * st[x] + st[x + 1] * st[x + 1]) / k if k > 0.0 else 0.0
