"""The outcome of an impact: the :class:`Impact` result, and its numbers from the state at
the moment the ball finally left (:func:`outcome`): the dc (rigid-body) and ac parts of the
racket's motion, the CORs and the energy budget (paper Sec. VII).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from racket.solver import layout
from racket.solver.stepper import Stepper

SELF_CONSISTENT_TOL = 1e-4
"""An unhappy-ball impact is self-consistent when its compression at separation equals
Xo to this relative tolerance (where the ball crosses its fold it ends within 1e-10 of Xo;
without a fold, strings stiffer than pi k0, it approaches Xo only asymptotically and the
stepped contact ends within 7e-5 of it)."""

_HISTORY_ROWS = {
    "force": layout.H_FORCE,
    "ball_compression": layout.H_BALL_COMP,
    "string_deflection": layout.H_STRING,
    "ball_velocity": layout.H_BALL_VEL,
    "point_velocity": layout.H_POINT_VEL,
    "point_velocity_dc_history": layout.H_POINT_VEL_DC,
    "frame_force": layout.H_FRAME_FORCE,
}
"""Impact attribute of each history row of the kernel."""


@dataclass(frozen=True)
class Impact:
    """Outcome of :func:`impact`; every attribute is an array over the impact positions
    (a float, or 1-D history, when a single position was given).

    On a bat (:class:`bat.Bat`) "racket" reads "bat" and "strings" its bare surface: the
    string fields (``string_vibration``, ``string_loss``, ``string_deflection``) are 0.  A
    pivoted bat's ``v_cm`` and ``omega`` are its turn about the pivot (its dc motion), its
    ``effective_mass`` is I_pivot / d**2, and its ``mode_energy`` (of the free bat's modes,
    which the pivot couples) does not add up to ``vibration_energy``, the held bat's own.

    Attributes
    ----------
    position : float or ndarray
        Impact point [m from the tip].
    offset : float or ndarray or None
        Impact point's distance from the long axis [m, + towards 3 o'clock], or None for
        impacts on the axis without the roll and torsion modes (the paper's 1-D model).
    speed : float
        Ball speed towards the strings before impact [m/s].
    swing_speed : float or ndarray
        Racket (impact-point) speed towards the ball before impact [m/s].
    e : float or ndarray
        COR [-] from the dc (rigid-body) motion, Eq. 21 / Eq. 1.
    e_A : float or ndarray
        Apparent COR V1 / v1 [-] of a racket at rest; for a swung racket (impact point at v2
        towards the ball) the same in the frame of the swing, (V1 - v2) / (v1 + v2), which
        equals the racket at rest's at the closing speed v1 + v2 (the swing superposes).
    e_van_zandt : float or ndarray
        COR [-] with the vibration at separation wrongly included (Sec. VII).
    effective_mass : float or ndarray
        Racket effective mass at the impact point [kg] (Eq. 20, with y^2 / I_roll off the
        axis, plus the string bed's moving mass, which sits at the point; for the free
        racket, also quoted for a hand-held one; inf clamped).
    ball_rebound : float or ndarray
        V1, the ball's speed after, away from the strings [m/s] (its exit speed).
    v_cm : float or ndarray
        Racket centre-of-mass velocity after [m/s] (along the ball's incoming path; with a
        string bed's mass, the velocity at the frame's centre of mass of frame and bed moving
        as one body).
    omega : float or ndarray
        Racket angular velocity after [rad/s]; the point at x moves at v_cm + (x_cm - x)
        omega.
    roll_rate : float or ndarray
        Racket's angular velocity about its long axis after [rad/s] (the twist rate; the
        point at offset y moves at y roll_rate more; 0 without offsets).
    point_velocity_dc : float or ndarray
        V2 = v_cm + b omega (+ y roll_rate), dc velocity of the impact point after [m/s]
        (Eq. 21).
    contact_time : float or ndarray
        Duration of the contact [s].
    peak_force : float or ndarray
        Largest contact force [N].
    vibration_energy : float or ndarray
        The racket's mechanical energy beyond its rigid-body kinetic energy when the ball
        leaves [J]: the bending (and torsion) modes, and for a hand-held racket also the
        energy in the hand's spring.
    string_vibration : float or ndarray
        The string bed's own vibration when the ball leaves [J]: its moving mass's kinetic
        and elastic energy beyond moving with the racket (0 for a massless bed), energy the
        ball does not get back.
    mode_energy : ndarray
        (..., n_bending) energy of each free-free bending mode when the ball leaves [J].
    energy_initial, ball_energy, racket_energy, ball_loss, string_loss, damping_loss, \
energy_residual : float or ndarray
        Energy budget [J]: initial kinetic energy = ball_energy + racket_energy (rigid
        body) + vibration_energy + string_vibration + ball_loss + string_loss + damping_loss
        + energy_residual; the residual is the integration error.  string_loss is what the
        string bed dissipates (its hysteresis and the friction between mains and crosses;
        0 for the paper's lossless bed).
    closing_energy : float or ndarray
        The ball's kinetic energy in the frame of the racket's swing, m (v1 + v2)^2 / 2 [J]
        (energy_initial for a racket at rest): what the impact has to share out.
    x_o : float or ndarray
        The unhappy ball's Xo [m], the smallest that does not snap (NaN for other laws).
    self_consistent : bool or ndarray
        The unhappy ball's compression at separation equals Xo (to
        ``SELF_CONSISTENT_TOL``) [-]; always True for other laws.
    recontacts : int or ndarray
        Times the frame caught the ball again after it had left [-].
    t : ndarray or None
        (T,) time since first touch [s] of the histories (None unless ``histories``).
    force, ball_compression, string_deflection, ball_velocity, point_velocity, \
point_velocity_dc_history : ndarray or None
        (..., T) histories [N, m, m, m/s, m/s, m/s] (NaN after the ball has left; None
        unless ``histories``); the impact point's velocity is split into its dc part and
        the rest (ac = total - dc).
    frame_force : ndarray or None
        (..., T) history of the force on the frame [N]: the string bed's push, which for a
        bed with a mass differs from the ball's ``force`` (the same without).
    """

    position: np.ndarray
    offset: np.ndarray | None
    speed: float
    swing_speed: float
    e: np.ndarray
    e_A: np.ndarray
    e_van_zandt: np.ndarray
    effective_mass: np.ndarray
    ball_rebound: np.ndarray
    v_cm: np.ndarray
    omega: np.ndarray
    roll_rate: np.ndarray
    point_velocity_dc: np.ndarray
    contact_time: np.ndarray
    peak_force: np.ndarray
    vibration_energy: np.ndarray
    string_vibration: np.ndarray
    mode_energy: np.ndarray
    energy_initial: np.ndarray
    closing_energy: np.ndarray
    ball_energy: np.ndarray
    racket_energy: np.ndarray
    ball_loss: np.ndarray
    string_loss: np.ndarray
    damping_loss: np.ndarray
    energy_residual: np.ndarray
    x_o: np.ndarray
    self_consistent: np.ndarray
    recontacts: np.ndarray
    t: np.ndarray
    force: np.ndarray
    ball_compression: np.ndarray
    string_deflection: np.ndarray
    ball_velocity: np.ndarray
    point_velocity: np.ndarray
    point_velocity_dc_history: np.ndarray
    frame_force: np.ndarray

    @classmethod
    def of(cls, fields: dict) -> Impact:
        """The Impact of ``fields``, every attribute by name, as the solver makes them:
        without the frozen dataclass's ``__init__``, which sets them one call at a time
        (some 40 calls; a single impact's outcome is made thousands of times a second).

        Parameters
        ----------
        fields : dict
            Every attribute of the class, by name.
        """
        if fields.keys() != _FIELDS.keys():
            raise TypeError(f"Impact.of needs every attribute, got {sorted(fields)}")
        impact = object.__new__(cls)
        impact.__dict__.update({name: fields[name] for name in _FIELDS})  # (in their order)
        return impact

    @property
    def point_velocity_ac_history(self) -> np.ndarray:
        """Ac (vibration) part of the impact point's velocity against time [m/s] (None
        without histories).
        """
        if self.point_velocity is None:
            return None
        return self.point_velocity - self.point_velocity_dc_history


_FIELDS = dict.fromkeys(Impact.__dataclass_fields__)
"""The names of the Impact's attributes, in their order (:meth:`Impact.of` makes one of all
of them)."""

N_ROWS = layout.N_HISTORY
"""Histories a full record holds [-]."""

HISTORY_MEMORY = 64e6
"""Bytes the first run may record histories into before it knows how long they are
(:func:`history_bound`); beyond, the histories come from a second run."""


def history_bound(stepper: Stepper, count: int, extra_steps: int, rows: int = N_ROWS) -> int:
    """Steps [-] the first run records, when histories are asked for: three contacts' worth
    at the stiffest spot and the extra steps (a contact at the bed's centre is about 1.5
    times as long; a later catch by the frame may need more, and then the histories come
    from a second run), or 0 when that would take more than :data:`HISTORY_MEMORY`.

    Parameters
    ----------
    stepper : Stepper
        The kernel's inputs.
    count : int
        Impacts in the run [-].
    extra_steps : int
        Steps [-] the run goes on after each ball has left for good.
    rows : int, optional
        Histories recorded [-]: all of them, or 1 (the force's alone).
    """
    steps = 3 * stepper.steps_per_contact + extra_steps
    return steps if 8 * rows * count * steps <= HISTORY_MEMORY else 0


def outcome(stepper: Stepper, racket, ball, x, y, speed, x_o, outputs, histories, extra_steps):
    """The Impact's fields from the kernel's outputs, and the ball's largest compression
    (``compression``); the histories (if asked for) from the run's own record when it
    recorded long enough (:func:`history_bound`), else from a second run, recording.

    Parameters
    ----------
    stepper : Stepper
        The kernel's inputs, as run.
    racket : Racket
        The racket.
    ball : Ball
        The ball.
    x, y : ndarray or None
        Impact points [m from the tip] and offsets [m from the long axis] (None on it).
    speed : float
        Ball speed [m/s] towards the strings before impact.
    x_o : ndarray
        The unhappy ball's Xo [m] per impact (NaN for other laws).
    outputs : racket.solver.layout.Outputs
        What :meth:`Stepper.run` returned.
    histories : bool or str
        Also the histories against time (``"force"``: the force's alone).
    extra_steps : int
        Steps [-] the run went on after each ball had left for good.

    Returns
    -------
    tuple
        The fields (a dict of arrays over the impacts) and the histories' times [s] (None
        without histories).
    """
    out_ball, out_state, summary, recorded = outputs
    closing, dt, modes, system = stepper.closing, stepper.dt, stepper.modes, stepper.system
    code = stepper.code
    n = system.count

    # dc part (rigid-body motion) and ac part (the rest) when the ball has left, and the
    # energies: compiled, one pass (racket.solver.budget).
    import racket.solver.budget as budget  # numba loads on first use (import time; this
    # form, unlike "from racket.solver import", skips importlib's Python-level fromlist)

    face = stepper.face and n
    frame = np.array(
        [
            modes.center_of_mass,
            math.sqrt(modes.mass),  # (math's: numpy's costs more on a number, the same bits)
            math.sqrt(modes.inertia_cm),
            math.sqrt(racket.beam.roll_modes.roll_inertia) if face else 0.0,
            min(n, modes.count),  # the bending coordinates come first
            ball.mass,
        ]
    )
    motion = np.empty((x.size, 3))  # (filled column by column: cheaper than stacking)
    motion[:, 0], motion[:, 1], motion[:, 2] = out_ball[:, 1], closing, speed
    m_s = stepper.ball.bed[2]
    bed = np.zeros((x.size, 4))
    if m_s > 0.0:  # a bed with a mass, moving with the frame's point before
        before = np.einsum("pjr,pjr->p", stepper.points.out_v, stepper.points.state0)
        bed = np.column_stack([np.full(x.size, m_s), summary[:, layout.BED_VEL],
                               summary[:, layout.BED_ELASTIC], before])  # fmt: skip
    split = np.empty((x.size, budget.N_COLUMNS))
    mode_energy = np.empty((x.size, max(min(n, modes.count) - 2, 0)))
    budget.split(
        out_state,
        system.basis,
        system.stiffness,
        system.rigid_rows,
        stepper.phi,
        x,
        y if face else np.zeros(x.size),
        frame,
        modes.omega,
        motion,
        stepper.swing_qd,
        bed,
        split,
        mode_energy,
    )
    racket_energy, vibration = split[:, budget.RACKET_ENERGY], split[:, budget.VIBRATION]
    string_vibration = split[:, budget.STRING_VIBRATION]
    energy_initial, ball_energy = split[:, budget.ENERGY_INITIAL], split[:, budget.BALL_ENERGY]
    if code == layout.SINE:
        ball_loss = summary[:, layout.SINE_WORK]  # X never decreases: all work on it is lost
        self_consistent = np.abs(summary[:, layout.X_END] - x_o) <= SELF_CONSISTENT_TOL * x_o
    else:
        ball_loss, squashed = ball.law.at_peak(summary[:, layout.F_PEAK])
        self_consistent = np.full(x.size, True)  # (np.ones costs twice as much)
    peak = summary[:, layout.F_PEAK]
    string_loss = np.zeros(x.size)
    bed_law = stepper.ball.bed
    if bed_law[1] > 0.0:
        from racket.solver.bed_kernel import bed_losses  # numba loads on first use

        bed_peak = summary[:, layout.BED_PEAK] if m_s > 0.0 else peak
        bed_losses(bed_law, stepper.points.inv_ks, bed_peak, string_loss)
    damping_loss = summary[:, layout.DAMPING_LOSS]
    residual = energy_initial - (
        ball_energy + racket_energy + vibration + string_vibration + ball_loss + string_loss
        + damping_loss
    )  # fmt: skip

    history, t = dict.fromkeys(_HISTORY_ROWS), None
    if histories:
        steps = np.rint(summary[:, layout.T_END] / dt).astype(int)
        used = int(steps.max()) + 1
        t = np.arange(used) * dt
        force_only = histories == "force"
        if recorded.shape[2] >= used and recorded.shape[1] == x.size:
            hist = recorded[:, :, :used].copy()
        else:
            hist = stepper.run(x_o, extra_steps=extra_steps, history_steps=used,
                               force_only=force_only)[3]  # fmt: skip
        hist[:, np.arange(used)[None, :] > steps[:, None]] = np.nan  # after the ball left
        rows = {"force": layout.H_FORCE} if force_only else _HISTORY_ROWS
        history.update({name: hist[row] for name, row in rows.items()})

    if n:  # (with the string bed's moving mass, which moves with the point)
        m_eff = racket.effective_mass(x, y if stepper.face else None) + m_s
    else:  # a clamped head
        m_eff = np.full(x.size, np.inf)
    fields = dict(
        position=x,
        offset=y,
        swing_speed=stepper.closing - speed,
        e=split[:, budget.E],
        e_A=split[:, budget.E_A],
        e_van_zandt=split[:, budget.E_VAN_ZANDT],
        effective_mass=m_eff,
        ball_rebound=-out_ball[:, 1],
        v_cm=split[:, budget.V_CM],
        omega=split[:, budget.OMEGA],
        roll_rate=split[:, budget.ROLL_RATE],
        point_velocity_dc=split[:, budget.V2_DC],
        contact_time=summary[:, layout.T_CONTACT],
        peak_force=summary[:, layout.F_PEAK],
        vibration_energy=vibration,
        string_vibration=string_vibration,
        mode_energy=mode_energy,
        energy_initial=energy_initial,
        closing_energy=split[:, budget.CLOSING_ENERGY],
        ball_energy=ball_energy,
        racket_energy=racket_energy,
        ball_loss=np.asarray(ball_loss, dtype=float),
        string_loss=string_loss,
        damping_loss=damping_loss,
        energy_residual=residual,
        x_o=x_o,
        self_consistent=self_consistent,
        recontacts=summary[:, layout.RECONTACTS].astype(int),
        compression=x_o if code == layout.SINE else squashed,
        **history,
    )
    return fields, t
