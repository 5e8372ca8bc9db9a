"""What the hand feels: the shock and the vibration of the handle at the grip after an
impact.

:func:`hand_feel` takes the contact force of an impact (the solver's history) and drives the
racket's linear dynamics with it (the same real 2x2 blocks, each stepped exactly for a force
varying linearly over a step, :func:`racket.solver.steps.system_steps`), on past the moment
the ball leaves, for ``duration``, and reads the handle at the middle of the hand
(:func:`driven_motion` does the driving, for a racket or a bat, read at any point).  Its
motion is split by the blocks (:attr:`racket.system.BlockSystem.dc`) into the two things a
player feels (R. Cross, "The sweet spots of a tennis racquet", Sports Engineering 1 (1998)
63-78: "Forces on the hand arise from rotation, translation and vibration of the handle"):

* the shock, the jolt of the impact: the racket's motion as a rigid body in the hand (a free
  racket's rigid-body modes; a held one's slow blocks, the racket and the hand's mass
  translating and rocking together), its largest acceleration at the grip while the ball is
  on the strings.  A ball at the centre of percussion sets the racket turning about the hand:
  no shock on a free racket, the least on a held one (its hand pushes during the contact);
* the vibration: the other blocks, the frame's bending (and, held, the hand springing on the
  handle), its largest acceleration at the grip after the ball has left, and its spectrum.

Both are accelerations, so the motion of the racket and the hand drifting away together
after the impact (nothing holds a model hand to a body) is in neither.  Also: the twist rate
at the grip for an impact off the axis and, for a hand-held racket, the energy the hand's
dashpot takes out of the frame beside the frame's vibration energy left at the end.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from common.checks import finite, finite_array, in_range
from common.checks import speed as check_speed
from common.typechecks import instance
from racket.racket import Racket
from racket.solver import impact, system_steps


@dataclass(frozen=True)
class HandFeel:
    """The handle's motion at the grip after one impact (built by :func:`hand_feel`; see
    the module docstring for the shock and the vibration).

    Attributes
    ----------
    t : (T,) ndarray
        Time since first contact [s].
    force : (T,) ndarray
        Force of the strings on the frame [N] (the ball's on the strings, for a massless
        bed; 0 once the ball has left).
    velocity, acceleration : (T,) ndarray
        Velocity [m/s] and acceleration [m/s^2] of the handle at ``grip`` along the ball's
        path, all of it (the velocity includes the racket and hand drifting away together).
    shock_acceleration, vibration_acceleration : (T,) ndarray
        The acceleration's two parts [m/s^2]: the racket's rigid-body motion in the hand and
        the vibration (they add up to ``acceleration``).
    shock : float
        The largest magnitude of ``shock_acceleration`` while the ball is on the strings
        (``t <= contact_time``) [m/s^2].
    vibration : float
        The largest magnitude of ``vibration_acceleration`` after the ball has left
        [m/s^2].
    twist_rate : (T,) ndarray or None
        The handle's angular velocity about the long axis [rad/s] (impacts off the axis).
    frequencies, spectrum : ndarray
        The amplitude spectrum of ``vibration_acceleration`` [m/s^2] (Hann window) against
        frequency [Hz].
    peak_acceleration : float
        Largest magnitude of ``acceleration`` [m/s^2].
    hand_energy : float
        Energy the hand's dashpot took out of the racket over ``t`` [J] (0 for a free
        racket): the racket's recoil and its vibration.
    hand_vibration_energy : float
        The part of it from the vibration alone: the dashpot's dissipation of the velocities
        of the vibration (the blocks that are not the dc motion, :mod:`racket.system`: the
        racket's rigid-body motion and its rocking on the hand), the cross terms with the dc
        motion left out (so an estimate, not an exact share) [J].
    vibration_energy_end : float
        The energy left at the end in the frame's own bending and torsion modes (their
        free-free modal coordinates and frequencies; the hand's spring excluded) [J].
    grip : float
        Where the handle is read, the middle of the hand [m from the tip].
    contact_time : float
        [s].
    mode_frequencies : ndarray or None
        The natural frequencies of the racket as it is supported (free, or held: the
        coupled system the handle's motion comes from), each once [Hz]: the damped
        frequencies of its modal equations (the imaginary parts of their eigenvalues).
    """

    t: np.ndarray
    force: np.ndarray
    velocity: np.ndarray
    acceleration: np.ndarray
    shock_acceleration: np.ndarray
    vibration_acceleration: np.ndarray
    shock: float
    vibration: float
    twist_rate: np.ndarray | None
    frequencies: np.ndarray
    spectrum: np.ndarray
    peak_acceleration: float
    hand_energy: float
    hand_vibration_energy: float
    vibration_energy_end: float
    grip: float
    contact_time: float
    mode_frequencies: np.ndarray | None = None

    def strongest(self, above: float = 20.0) -> tuple[float, bool]:
        """The strongest vibration of the handle above ``above`` [Hz]: the spectrum's peak,
        or the natural frequency of the racket nearest to it when one lies within two of
        the spectrum's bins (the peak resolves only ``1 / duration``, 20 Hz for 50 ms; the
        mode's frequency is exact) [Hz], and whether it is a mode's.

        Parameters
        ----------
        above : float
            Frequencies at or below this are left out (the recoil) [Hz].
        """
        keep = self.frequencies > above
        peak = float(self.frequencies[keep][np.argmax(self.spectrum[keep])])
        modes = np.asarray([] if self.mode_frequencies is None else self.mode_frequencies)
        if modes.size:
            nearest = float(modes[np.argmin(np.abs(modes - peak))])
            if abs(nearest - peak) <= 2.0 * self.frequencies[1]:
                return nearest, True
        return peak, False


@dataclass(frozen=True)
class DrivenMotion:
    """An implement's motion driven from rest by a contact force history at one point (built
    by :func:`driven_motion`), in its free-free modal coordinates q (a racket's or a bat's;
    the hand's mass, if any, after them): read it at any point with the modal shapes there
    (``q @ phi``).

    Attributes
    ----------
    q, qd, qdd : (T, N) ndarray
        Modal displacements, velocities and accelerations [SI] at each time step.
    rigid_q, rigid_qd, rigid_qdd : (T, N) ndarray
        Their part from the dc blocks [SI] (:attr:`racket.system.BlockSystem.dc`: a free
        implement's rigid-body motion, a pivoted bat's turn about its pivot, a held one's
        slow rocking on the hand); the rest is the vibration.
    states : (T, nb, 2) ndarray
        The blocks' states [SI] (:mod:`racket.system`).
    system : BlockSystem
        The implement's block system for its support.
    face : bool
        Whether the roll and torsion modes take part (an impact off a racket's axis).
    """

    q: np.ndarray
    qd: np.ndarray
    qdd: np.ndarray
    rigid_q: np.ndarray
    rigid_qd: np.ndarray
    rigid_qdd: np.ndarray
    states: np.ndarray
    system: object
    face: bool


def driven_motion(implement, position: float, force, dt: float, offset=None) -> DrivenMotion:
    """The motion of a racket or a bat, at rest at first, driven by the contact force
    ``force`` at ``position``: the same real 2x2 blocks the solver steps, each advanced
    exactly for a force varying linearly over a step
    (:func:`racket.solver.steps.system_steps`).  The implement's motion before the impact
    (a swing) is not in it: the system is linear, so it adds to this.

    Parameters
    ----------
    implement : Racket or Bat
        What is struck (its support: :meth:`point_dynamics`).
    position : float
        Where the force acts [m from the tip].
    force : (T,) array_like
        The force on the implement at each step [N], from the first contact (0 once the
        ball has left).
    dt : float
        The time step [s].
    offset : float, optional
        The point's distance from the long axis [m] (a racket's face).

    Returns
    -------
    DrivenMotion
    """
    force = finite_array("force", force, "N").ravel()
    dt = finite("dt", dt, "s")
    y = None if offset is None else np.atleast_1d(float(offset))
    system, phi, face = implement.point_dynamics(position, y)
    trans, g0, g1 = system_steps(system, dt)
    unit = system.inputs(phi)[0]  # (nb, 2): a unit force at the impact point
    states = np.empty((force.size, *unit.shape))
    s = np.zeros(unit.shape)
    states[0] = s
    g0u, g1u = np.einsum("bij,bj->bi", g0, unit), np.einsum("bij,bj->bi", g1, unit)
    for k in range(1, force.size):  # exact for a force linear over each step
        s = np.einsum("bij,bj->bi", trans, s) + g0u * force[k - 1] + g1u * force[k]
        states[k] = s
    rates = np.einsum("bij,tbj->tbi", system.blocks, states) + force[:, None, None] * unit
    dc = system.dc[None, :, None]
    q, qd = system.modal_state(states)
    rigid_q, rigid_qd = system.modal_state(states * dc)
    return DrivenMotion(
        q=q, qd=qd, qdd=system.modal_state(rates)[1], rigid_q=rigid_q, rigid_qd=rigid_qd,
        rigid_qdd=system.modal_state(rates * dc)[1], states=states, system=system, face=face,
    )  # fmt: skip


def hand_feel(
    racket: Racket,
    ball,
    position: float,
    speed: float,
    *,
    offset: float | None = None,
    duration: float = 0.05,
) -> HandFeel:
    """The handle's motion at the middle of the hand after one impact: its shock and its
    vibration (see the module docstring).

    Parameters
    ----------
    racket : Racket
        A free or hand-held racket (the hand's grip, :class:`racket.Hand`, says where the
        handle is read: the middle of the grip).
    ball : Ball
    position : float
        Impact point [m from the tip]: one number (one impact).
    speed : float
        Ball speed [m/s]: one number.
    offset : float, optional
        Impact point's distance from the long axis [m] (:func:`racket.impact`): one number.
    duration : float
        How long after first contact to follow the racket [s], in [0.005, 1].

    Returns
    -------
    HandFeel
    """
    instance("racket", racket, Racket, "a racket.Racket")
    if racket.support == "clamped-head":
        raise ValueError("support must be 'free' or 'hand-held' for the feel at the hand")
    duration = in_range("duration", duration, 0.005, 1.0, "s")
    position = finite("position", position, "m from the tip")
    speed = check_speed("speed", speed)
    offset = None if offset is None else finite("offset", offset, "m")
    hit = impact(racket, ball, position, speed, offset=offset, histories=True)
    if duration <= hit.contact_time:
        raise ValueError(
            f"duration must be longer than the contact, {1e3 * hit.contact_time:.3g} ms here, "
            f"got {1e3 * duration:g} ms"
        )
    dt = hit.t[1] - hit.t[0]
    # the force on the frame (the bed's; its own vibration after the ball has left is not
    # carried on)
    force = np.nan_to_num(np.atleast_1d(hit.frame_force), nan=0.0)
    steps = int(np.ceil(duration / dt)) + 1
    force = np.concatenate([force, np.zeros(max(steps - force.size, 0))])[:steps]
    motion = driven_motion(racket, position, force, dt, offset)
    system, states, face = motion.system, motion.states, motion.face
    y = None if offset is None else np.zeros(1)
    grip = racket.beam.length - 0.5 * racket.hand.grip_length
    _, phi_grip, _ = racket.point_dynamics(grip, y)
    n = system.count
    q, qd = motion.q, motion.qd
    velocity = qd @ phi_grip[0]
    acceleration = motion.qdd @ phi_grip[0]
    shock = motion.rigid_qdd @ phi_grip[0]
    vibration = acceleration - shock
    t = np.arange(steps) * dt
    touching = t <= hit.contact_time  # the ball on the strings
    twist = None
    frame = np.arange(n)  # the frame's coordinates (not a hand's mass), in order
    if system.hand_coordinate is not None:
        frame = np.delete(frame, system.hand_coordinate)
    if face:
        roll = racket.beam.roll_modes
        twist = qd[:, n - roll.count :] @ roll.twist(grip)[:, 0]
    # The hand's dashpot: the system's damping less the modes' own (2 zeta omega).
    modal = [racket.beam.modes] + ([racket.beam.roll_modes] if face else [])
    own, omega = np.zeros(n), np.zeros(n)
    own[frame] = np.concatenate([2.0 * m.damping * m.omega for m in modal])[: frame.size]
    omega[frame] = np.concatenate([m.omega for m in modal])[: frame.size]
    c_hand = system.damping - np.diag(own)
    elastic = np.setdiff1d(frame, system.rigid)  # bending and torsion coordinates

    def absorbed(v, c):
        power = np.einsum("ti,ij,tj->t", v, c, v)
        return float(np.sum(0.5 * (power[1:] + power[:-1])) * dt)

    hand_energy = absorbed(qd, c_hand)
    vibrating = system.modal_state(states * ~system.dc[None, :, None])[1]  # the ac blocks
    hand_vibration = absorbed(vibrating, c_hand)
    vibration_end = 0.5 * float(
        np.sum(qd[-1, elastic] ** 2 + (omega[elastic] * q[-1, elastic]) ** 2)
    )
    window = np.hanning(steps)
    spectrum = 2.0 * np.abs(np.fft.rfft(vibration * window)) / window.sum()
    return HandFeel(
        t=t,
        force=force,
        velocity=velocity,
        acceleration=acceleration,
        shock_acceleration=shock,
        vibration_acceleration=vibration,
        shock=float(np.abs(shock[touching]).max()),
        vibration=float(np.abs(vibration[~touching]).max()),
        twist_rate=twist,
        frequencies=np.fft.rfftfreq(steps, dt),
        spectrum=spectrum,
        peak_acceleration=float(np.abs(acceleration).max()),
        hand_energy=hand_energy,
        hand_vibration_energy=hand_vibration,
        vibration_energy_end=vibration_end,
        grip=grip,
        contact_time=float(hit.contact_time),
        mode_frequencies=_natural_frequencies(system.stiffness, system.damping),
    )


def _natural_frequencies(stiffness: np.ndarray, damping: np.ndarray) -> np.ndarray:
    """The damped natural frequencies [Hz] of q'' + C q' + K q = 0 (``damping`` C [1/s],
    ``stiffness`` K [1/s^2], in modal coordinates), each once, in order: the eigenvalues'
    imaginary parts over 2 pi (a rigid-body pair's, round-off, left out).
    """
    n = stiffness.shape[0]
    state = np.block([[np.zeros((n, n)), np.eye(n)], [-stiffness, -damping]])
    imag = np.linalg.eigvals(state).imag
    scale = np.sqrt(np.max(np.abs(stiffness), initial=1.0))
    return np.sort(imag[imag > 1e-6 * scale]) / (2 * np.pi)
