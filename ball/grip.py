"""The tangential half of a contact: a ball that slides, grips, springs back and spins on a
surface that may move and may carry a layer that slides on it (issue 36).

The normal force N(t) comes first, from the normal problem (:func:`ball.collide` on a
court, :func:`racket.impact` on strings), and drives this one.  The coupling is one-way:
a tangential force in the plane of the surface moves nothing along its normal (for a
racket, in-plane forces at the string plane, which holds the centre of mass, give in-plane
motion only), so the normal outcome is the head-on one, unchanged, and the tangential motion
follows from the force history.

**The ball** (:class:`ball.spin.BallSpin`): mass m, moment of inertia I = k m R^2.  Its
contact patch sits at -R n from the centre and is joined to it by a tangential spring of
stiffness k_t (a Jenkins element): the patch's displacement xi from the ball's contact point
grows with the slip velocity while it grips, and is cut back to |k_t xi| = mu N when the
force would beat friction (it slides).  The force on the ball is F = k_t xi, the torque
-R n x F.  While the ball slides, the normal force acts a distance d behind the centre (as
seen along the sliding), so its torque d N adds to friction's (Cross 2002: "the spin of the
ball was found to be larger than that due to the friction force alone, a result that can be
explained if the normal reaction force acts vertically through a point behind the center of
the ball"); the work it does on the spin is taken from the normal motion, which this one-way
coupling does not debit (:attr:`Grip.offset_work`).  Spin about the normal is untouched.

**The surface**: the contact point's in-plane velocity follows the impulse P it has
received, u = W P, with W the inverse-mass matrix of the point (0 for a court or a clamped
head; for a free racket its rigid-body in-plane motion).  A **layer** (the mains of a string
bed) may sit between the ball and the surface: a mass m_l held by a spring k_l (the mains'
tension pulling them back: "snapback"), and by Coulomb friction mu_l N on the surface
(mains on crosses), which it sticks to or slides over.

**Stepping**: velocity Verlet (half kick, drift, half kick) on sub-steps of the history's
step, N linear between samples.  The offset's torque is an impulse outside the forces'
kick, before it in the first half kick and after it in the second, so that the step stays
symmetric.  The layer's Coulomb friction is an implicit impulse after the forces in both
half kicks (as RATTLE enforces a constraint: a layer that sticks moves with the surface
through the drift, and does not creep), its loss the impulse's work on the slip averaged
over the half kick (zero while stuck).  The slip loss is booked as the work the contact
took in each drift less what its spring kept, so the budget closes to round-off without a
layer (:attr:`Grip.residual`), and to about 1e-8 of the energy with mains sliding.  The
stick-slip switches fall at step boundaries: the outcome converges about as the step.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import NamedTuple

import numpy as np
from numba import njit

from ball.spin import BallSpin
from common.checks import in_range, non_negative, whole

(V_ALONG, V_ACROSS, W_ALONG, W_ACROSS, W_NORMAL, U_ALONG, U_ACROSS, P_ALONG, P_ACROSS,
 SLIP_LOSS, LAYER_LOSS, OFFSET_WORK, LAYER_ENERGY, SURFACE_ENERGY, GRIP_TIME, REVERSALS,
 LAYER_PEAK, ENERGY_IN, ENERGY_OUT) = range(19)  # fmt: skip
N_OUT = 19
"""Columns of the kernel's output, one row per impact."""

FRICTION_RANGE = (0.0, 2.0)
"""Coefficients of friction [-] :func:`slide` accepts."""


class Layer(NamedTuple):
    """A layer between the ball and the surface that slides on it (the mains of a string
    bed on its crosses).

    Attributes
    ----------
    stiffness : float
        Spring [N/m] pulling the layer back to its place on the surface.
    mass : float
        Its moving mass [kg], > 0.
    friction : float
        Coefficient [-] of the Coulomb friction on the surface; its limit is friction x N.
    """

    stiffness: float
    mass: float
    friction: float


@dataclass(frozen=True)
class Grip:
    """Outcome of :func:`slide`; arrays over the impacts (one row each), face-frame
    components ordered (along, across[, normal]).

    Attributes
    ----------
    velocity : ndarray
        (n, 2) ball's tangential velocity after [m/s], relative to the surface point's
        velocity before.
    spin : ndarray
        (n, 3) ball's angular velocity after [rad/s].
    surface_velocity : ndarray
        (n, 2) change of the surface point's in-plane velocity [m/s].
    impulse : ndarray
        (n, 2) tangential impulse the surface received [N s].
    slip_loss, layer_loss : ndarray
        Energy [J] lost to the ball sliding on the surface (or layer), and to the layer
        sliding on the surface.
    offset_work : ndarray
        Energy [J] the normal force's offset took from the spin (negative: gave it; taken
        from the normal motion).
    layer_energy : ndarray
        Kinetic and elastic energy [J] left in the layer when the force has gone.
    surface_energy : ndarray
        In-plane kinetic energy [J] the surface took.
    grip_time : ndarray
        Time [s] the ball gripped while pressed (N > 0).
    reversals : ndarray
        How many times the friction force reversed along the ball's first slip [-].
    layer_peak : ndarray
        Largest sideways displacement [m] of the layer.
    energy_in, energy_out : ndarray
        Tangential and rotational energy [J] before, and all of it after (ball, layer,
        surface), losses not included.
    """

    velocity: np.ndarray
    spin: np.ndarray
    surface_velocity: np.ndarray
    impulse: np.ndarray
    slip_loss: np.ndarray
    layer_loss: np.ndarray
    offset_work: np.ndarray
    layer_energy: np.ndarray
    surface_energy: np.ndarray
    grip_time: np.ndarray
    reversals: np.ndarray
    layer_peak: np.ndarray
    energy_in: np.ndarray
    energy_out: np.ndarray

    @property
    def residual(self) -> np.ndarray:
        """Energy [J] the budget leaves unaccounted: in - out - losses (the stepping's
        error).
        """
        losses = self.slip_loss + self.layer_loss + self.offset_work
        return self.energy_in - self.energy_out - losses

    @property
    def slid_throughout(self) -> np.ndarray:
        """True where the ball never gripped."""
        return self.grip_time == 0.0


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
def grip_kernel(force, dt, substeps, m, radius, inertia, k_t, offset, mu, inv_mass, layer, v, w,
                out, start, stop, stride):  # fmt: skip
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
    m, radius, inertia, k_t, offset : float
        Ball mass [kg], radius [m], moment of inertia [kg m^2], tangential stiffness [N/m],
        normal force's offset [m].
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
    for i in range(start, stop, stride):
        o = out[i]
        # v(0:2) w_t(2:4) xi(4, 7) u(5:7) s(8:10) layer v(10:12) P(12:14) sliding(14)
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
                _kick(st, f0, f1, n_a, 0.5 * h, m, radius, inertia, offset, w00, w01, w11, k_l,
                      m_l, mu_l, o, True)  # fmt: skip
                # drift: the patch follows the surface (or layer) while it grips
                c0 = (st[10] if m_l > 0.0 else st[5]) - (st[0] - radius * st[3])
                c1 = (st[11] if m_l > 0.0 else st[6]) - (st[1] + radius * st[2])
                if m_l > 0.0:
                    st[8] += h * (st[10] - st[5])
                    st[9] += h * (st[11] - st[6])
                    peak = max(peak, st[8] * st[8] + st[9] * st[9])  # squared
                x0, x1 = st[4] + h * c0, st[7] + h * c1
                limit = mu[i] * max(n_b, 0.0)
                trial = k_t * math.sqrt(x0 * x0 + x1 * x1)
                stored = st[4] ** 2 + st[7] ** 2
                st[14] = 0.0
                if trial > limit:
                    cut = limit / trial
                    x0 *= cut
                    x1 *= cut
                    st[14] = 1.0 if limit > 0.0 else 0.0
                elif n_b > 0.0:
                    o[GRIP_TIME] += h
                # the work the contact took in the drift, less what its spring kept
                taken = 0.5 * h * ((f0 + k_t * x0) * c0 + (f1 + k_t * x1) * c1)
                o[SLIP_LOSS] += taken - 0.5 * k_t * (x0**2 + x1**2 - stored)
                st[4], st[7] = x0, x1
                f0, f1 = k_t * x0, k_t * x1
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
        o[ENERGY_OUT] += 0.5 * k_t * (st[4] ** 2 + st[7] ** 2)


def slide(
    force,
    dt: float,
    mass: float,
    spin: BallSpin,
    friction,
    velocity,
    angular_velocity,
    *,
    inv_mass=None,
    layer: Layer | None = None,
    substeps: int = 4,
    runner=None,
) -> Grip:
    """The tangential contact of a ball along its normal force history(ies).

    Parameters
    ----------
    force : array_like
        (T,) or (n, T) normal force [N] from first touch, every ``dt``.
    dt : float
        The history's step [s].
    mass : float
        Ball mass [kg].
    spin : BallSpin
        The ball's radius, inertia, tangential stiffness and offset.
    friction : float or array_like
        Ball-surface coefficient of friction [-], in [0, 2] (per impact, or one).
    velocity : array_like
        (2,) or (n, 2) ball's tangential velocity [m/s] relative to the surface point,
        (along, across) the face.
    angular_velocity : array_like
        (3,) or (n, 3) ball's spin [rad/s], (along, across, normal) components.
    inv_mass : array_like, optional
        (2, 2) or (n, 2, 2) the surface point's in-plane inverse mass [1/kg]; None: a
        surface that does not move.
    layer : Layer, optional
        A layer that slides on the surface (the mains); None: none.
    substeps : int
        Sub-steps per history step, in [1, 64].
    runner : callable, optional
        ``runner(kernel, args, count)`` runs ``kernel(*args, start, stop, stride)`` over the
        ``count`` rows (on threads of its own); None: ``kernel(*args, 0, count, 1)``.

    Returns
    -------
    Grip
        Arrays over the impacts (n,) or (n, k); one row when ``force`` is one history.
    """
    force = np.atleast_2d(np.asarray(force, float))
    n = force.shape[0]
    dt = in_range("dt", dt, 1e-9, 1e-3, "s")
    substeps = whole("substeps", substeps, 1, 64)
    mu = np.broadcast_to(np.asarray(friction, float), (n,)).copy()
    for value in mu:
        in_range("friction", value, *FRICTION_RANGE)
    v = np.broadcast_to(np.asarray(velocity, float), (n, 2)).copy()
    w = np.broadcast_to(np.asarray(angular_velocity, float), (n, 3)).copy()
    if inv_mass is None:
        inv_mass = np.zeros((2, 2))
    inv_mass = np.broadcast_to(np.asarray(inv_mass, float), (n, 2, 2)).copy()
    stack = np.zeros((n, 3))
    if layer is not None:
        stack[:] = [
            non_negative("layer stiffness", layer.stiffness, "N/m"),
            in_range("layer mass", layer.mass, 1e-6, 1.0, "kg"),
            in_range("layer friction", layer.friction, *FRICTION_RANGE),
        ]
    out = np.zeros((n, N_OUT))
    args = (force, dt, substeps, float(mass), spin.radius, spin.inertia(mass),
            spin.tangential_stiffness, spin.offset, mu, inv_mass, stack, v, w, out)  # fmt: skip
    if runner is None:
        grip_kernel(*args, 0, n, 1)
    else:
        runner(grip_kernel, args, n)
    return Grip(
        velocity=out[:, V_ALONG : V_ACROSS + 1],
        spin=out[:, W_ALONG : W_NORMAL + 1],
        surface_velocity=out[:, U_ALONG : U_ACROSS + 1],
        impulse=out[:, P_ALONG : P_ACROSS + 1],
        slip_loss=out[:, SLIP_LOSS],
        layer_loss=out[:, LAYER_LOSS],
        offset_work=out[:, OFFSET_WORK],
        layer_energy=out[:, LAYER_ENERGY],
        surface_energy=out[:, SURFACE_ENERGY],
        grip_time=out[:, GRIP_TIME],
        reversals=out[:, REVERSALS].astype(int),
        layer_peak=out[:, LAYER_PEAK],
        energy_in=out[:, ENERGY_IN],
        energy_out=out[:, ENERGY_OUT],
    )
