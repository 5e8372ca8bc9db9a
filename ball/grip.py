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
stiffness k_t (a Jenkins element), kappa times the ball's own normal stiffness at the normal
force (:meth:`ball.spin.BallSpin.stiffness`, issue 44): the patch's displacement xi from the
ball's contact point grows with the slip velocity while it grips, and is cut back to
|k_t xi| = mu N when the force would beat friction (it slides).  The force on the ball is
F = k_t xi (secant; or dF = k_t dxi, incremental), with a dashpot while it grips, the torque
-R n x F.  While the ball slides, the normal force acts a distance d behind the centre (as
seen along the sliding), so its torque d N adds to friction's (Cross 2002: "the spin of the
ball was found to be larger than that due to the friction force alone, a result that can be
explained if the normal reaction force acts vertically through a point behind the center of
the ball"); the work it does on the spin is taken from the normal motion, which this one-way
coupling does not debit (:attr:`Grip.offset_work`).  Spin about the normal is untouched.

**The surface**: the contact point's in-plane velocity follows the impulse P it has
received, u = W P, with W the inverse-mass matrix of the point (0 for a court or a clamped
head; for a free racket its rigid-body in-plane motion).  A woven **layer** (:class:`Layer`:
a string bed's mains and crosses) may sit between the ball and the surface: two families of
strings, each moving only across its own length, a mass held by a spring (their tension
pulling them back: "snapback") and by Coulomb friction at the crossings (static to stick,
kinetic while sliding), pressed by the weave's preload and the ball's force.  The ball then
grips through two patches sharing its centre (issue 44), each a Jenkins element with its
share of the stiffness, the dashpot and the friction limit: one on the strings that move
across the face (held by the frame along it), one on those that move along it (held
across).  Without a layer one patch grips the surface.

**Stepping**: velocity Verlet (half kick, drift, half kick) on sub-steps of the history's
step, N linear between samples.  The offset's torque is an impulse outside the forces'
kick, before it in the first half kick and after it in the second, so that the step stays
symmetric.  The layer's Coulomb friction is an implicit impulse after the forces in both
half kicks (as RATTLE enforces a constraint: a layer that sticks moves with the surface
through the drift, and does not creep), its loss the impulse's work on the slip averaged
over the half kick (zero while stuck).  The slip loss is booked as the work each patch took
in each drift less what its spring kept, so the budget closes to round-off without a layer
(:attr:`Grip.residual`), and at second order with the strings sliding (1e-7 to 3e-5 of the
energy at the racket's default step).  The stick-slip switches fall at step boundaries: the
outcome converges about as the step.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import NamedTuple

import numpy as np

from ball import grip_layout as col
from ball.spin import BallSpin
from common.checks import finite_array, in_range, non_negative, whole

FRICTION_RANGE = (0.0, 2.0)
"""Coefficients of friction [-] :func:`slide` accepts."""


class Layer(NamedTuple):
    """A woven layer between the ball and the surface (a string bed's strings on its
    frame): two families of strings that cross, each sliding only across its own length,
    pressed together at the crossings and pulled back to their places by their tension.
    The ball grips the layer through two patches sharing its centre: one on the strings
    that move across (the mains, lying along the face's first axis; along the face they are
    held by the frame), one on those that move along (the crosses; held across).

    Attributes
    ----------
    stiffness : float or (float, float)
        Spring [N/m] pulling the strings back to their places, (along, across): the crosses'
        and the mains'; one number for both.
    mass : float or (float, float)
        Their moving mass [kg] (along, across), each > 0.
    friction : float
        Static coefficient of friction [-] at the crossings: the strings stick while the
        impulse that keeps them stuck is within friction x the pressing force.
    kinetic : float, optional
        Kinetic coefficient [-] while they slide, at most ``friction``; None: ``friction``.
    preload : float, optional
        The crossings' own pressing force [N] under the ball (the weave's), before, during
        and after the ball's.
    press : float, optional
        The share [-] of the ball's normal force that presses the crossings.
    share : float, optional
        The share [-] of the ball's grip (stiffness, damping and friction limit) on the
        strings that move across; the rest grips those that move along.
    """

    stiffness: float | tuple
    mass: float | tuple
    friction: float
    kinetic: float | None = None
    preload: float = 0.0
    press: float = 1.0
    share: float = 0.5

    def row(self) -> np.ndarray:
        """The layer as the kernel's row (:data:`ball.grip_layout.N_LAYER` numbers), each
        input checked.
        """
        out = np.zeros(col.N_LAYER)
        pairs = (("stiffness", self.stiffness, "N/m", 0.0, math.inf, col.LAYER_STIFFNESS),
                 ("mass", self.mass, "kg", 1e-6, 1.0, col.LAYER_MASS))  # fmt: skip
        for name, value, unit, low, high, at in pairs:
            values = np.broadcast_to(finite_array(f"layer {name}", value, unit), (2,))
            for d, each in enumerate(values):
                out[at + d] = in_range(f"layer {name}", each, low, high, unit)
        out[col.LAYER_STATIC] = in_range("layer friction", self.friction, *FRICTION_RANGE)
        kinetic = self.friction if self.kinetic is None else self.kinetic
        out[col.LAYER_KINETIC] = in_range("layer kinetic friction", kinetic, 0.0, self.friction)
        out[col.LAYER_PRELOAD] = non_negative("layer preload", self.preload, "N")
        out[col.LAYER_PRESS] = in_range("layer press", self.press, 0.0, 10.0)
        out[col.LAYER_SHARE] = in_range("layer share", self.share, 0.0, 1.0)
        return out


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
        surface, the patches' springs), losses not included.
    stiffness_work : ndarray
        Energy [J] the patches' springs gained as their stiffness changed with the normal force
        (from the normal motion, which the one-way coupling does not debit).
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
    stiffness_work: np.ndarray

    @property
    def residual(self) -> np.ndarray:
        """Energy [J] the budget leaves unaccounted: in + the stiffness's work - out -
        losses (the stepping's error).
        """
        losses = self.slip_loss + self.layer_loss + self.offset_work
        return self.energy_in + self.stiffness_work - self.energy_out - losses

    @property
    def slid_throughout(self) -> np.ndarray:
        """True where the ball never gripped."""
        return self.grip_time == 0.0


RESOLVED_PHASE = 0.2
"""The largest phase [rad] the stiffest ringing of the contact (the ball's tangential spring
on the ball and the layer) may turn through in a sub-step: 32 sub-steps per period.  (With a
tangential stiffness of 1e8 N/m on the mains, a fixed 2 sub-steps turned it through 5.6 rad,
beyond velocity Verlet's 2: 21 % off in spin.)"""


def stable_substeps(
    spin: BallSpin, mass: float, dt: float, layer: Layer | None = None, stiffness=None
) -> int:
    """Sub-steps [-] per step ``dt`` [s] that keep the contact's stiffest ringing within
    :data:`RESOLVED_PHASE` per sub-step: omega^2 = k_t (1/m_t + 1/m_l) + k_l/m_l, with m_t the
    ball's tangential effective mass m I / (I + m R^2) (1/m_l and k_l/m_l without a layer
    are 0), k_t the largest tangential stiffness; at most 4096.

    Parameters
    ----------
    spin : BallSpin
        The ball's radius and inertia (and its fixed tangential stiffness, if it has one).
    mass : float
        Ball mass [kg].
    dt : float
        The step [s].
    layer : Layer, optional
        The sliding layer.
    stiffness : array_like, optional
        The tangential stiffness history [N/m] (:meth:`BallSpin.stiffness`); None: the
        ball's fixed one.
    """
    inertia = spin.inertia(mass)
    if stiffness is None and spin.tangential_stiffness is None:
        raise ValueError(
            "stable_substeps needs the tangential stiffness history (stiffness=, from "
            "BallSpin.stiffness), or a BallSpin with a fixed tangential_stiffness"
        )
    k_t = spin.tangential_stiffness if stiffness is None else float(np.max(stiffness))
    omega2 = k_t * (inertia + mass * spin.radius**2) / (mass * inertia)
    if layer is not None:
        row = layer.row()
        stiffest = np.max(row[col.LAYER_STIFFNESS : col.LAYER_STIFFNESS + 2])
        omega2 += (k_t + stiffest) / np.min(row[col.LAYER_MASS : col.LAYER_MASS + 2])
    return min(4096, max(1, math.ceil(dt * math.sqrt(omega2) / RESOLVED_PHASE)))


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
    law=None,
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
        A woven layer that slides on the surface (the strings); None: none.
    law : MonotoneLaw, optional
        The ball's own normal force law, whose incremental stiffness at the normal force the
        tangential stiffness follows (:meth:`BallSpin.stiffness`); None only with a
        ``spin`` of a fixed tangential stiffness.
    substeps : int
        Sub-steps per history step, in [1, 4096], at least: more when the contact's stiffest
        ringing needs them (:func:`stable_substeps`).
    runner : callable, optional
        ``runner(kernel, args, count)`` runs ``kernel(*args, start, stop, stride)`` over the
        ``count`` rows (on threads of its own); None: ``kernel(*args, 0, count, 1)``.

    Returns
    -------
    Grip
        Arrays over the impacts (n,) or (n, k); one row when ``force`` is one history.
    """
    force = np.atleast_2d(finite_array("force", force, "N"))
    if np.any(force < 0.0):
        raise ValueError("force must be >= 0 N (a normal force pushes), got a negative one")
    n = force.shape[0]
    dt = in_range("dt", dt, 1e-9, 1e-3, "s")
    mu = np.broadcast_to(finite_array("friction", friction), (n,)).copy()
    outside = (mu < FRICTION_RANGE[0]) | (mu > FRICTION_RANGE[1])
    if outside.any():  # the first one out, named as one value is
        in_range("friction", mu[outside][0], *FRICTION_RANGE)
    v = np.broadcast_to(finite_array("velocity", velocity, "m/s"), (n, 2)).copy()
    w = np.broadcast_to(finite_array("angular_velocity", angular_velocity, "rad/s"), (n, 3)).copy()
    if inv_mass is None:
        inv_mass = np.zeros((2, 2))
    inv_mass = np.broadcast_to(finite_array("inv_mass", inv_mass, "1/kg"), (n, 2, 2)).copy()
    if not np.allclose(inv_mass, inv_mass.transpose(0, 2, 1), rtol=1e-12, atol=0.0) or np.any(
        np.linalg.eigvalsh(inv_mass) < -1e-12 * np.abs(inv_mass).max(initial=1.0)
    ):
        raise ValueError("inv_mass must be symmetric and positive semi-definite (a body's)")
    stack = np.zeros((n, col.N_LAYER))
    if layer is not None:
        stack[:] = layer.row()
    k_t = spin.stiffness(law, force)
    substeps = max(
        whole("substeps", substeps, 1, 4096), stable_substeps(spin, mass, dt, layer, k_t)
    )
    out = np.zeros((n, col.N_OUT))
    args = (force, dt, substeps, float(mass), spin.radius, spin.inertia(mass), k_t, spin.offset,
            spin.damping(law), spin.form == "secant", mu, inv_mass, stack, v, w, out)  # fmt: skip
    from ball.grip_kernel import grip_kernel  # numba loads on first use

    if runner is None:
        grip_kernel(*args, 0, n, 1)
    else:
        runner(grip_kernel, args, n)
    return Grip(
        velocity=out[:, col.V_ALONG : col.V_ACROSS + 1],
        spin=out[:, col.W_ALONG : col.W_NORMAL + 1],
        surface_velocity=out[:, col.U_ALONG : col.U_ACROSS + 1],
        impulse=out[:, col.P_ALONG : col.P_ACROSS + 1],
        slip_loss=out[:, col.SLIP_LOSS],
        layer_loss=out[:, col.LAYER_LOSS],
        offset_work=out[:, col.OFFSET_WORK],
        layer_energy=out[:, col.LAYER_ENERGY],
        surface_energy=out[:, col.SURFACE_ENERGY],
        grip_time=out[:, col.GRIP_TIME],
        reversals=out[:, col.REVERSALS].astype(int),
        layer_peak=out[:, col.LAYER_PEAK],
        energy_in=out[:, col.ENERGY_IN],
        energy_out=out[:, col.ENERGY_OUT],
        stiffness_work=out[:, col.STIFFNESS_WORK],
    )
