"""What reaches the hands from a bat (issue 37): the handle's motion after an impact, at
points of the handle, split into the bat's rigid motion and its vibration, and the energy
left in each bending mode (:func:`bat_feel`).

The impact's contact force (:func:`racket.impact`'s history) drives the bat's block system
from rest (:func:`racket.feel.driven_motion`, the same exact steps as the solver's), on past
the moment the ball leaves.  The swing's own motion is not in it (the system is linear: it
adds to this), so a displacement is the one the impact causes, along the ball's incoming path
(+: the way the ball pushes the bat).  The defaults are N2000's Figs. 13-15 (A. M. Nathan,
Am. J. Phys. 68, 979 (2000); ``data/bats.md`` section 3 C): the high-speed case's swing and
pitch, the ball at 68 cm from the knob, the handle read at 6, 13 and 19 cm over 15 ms.  A
mode's energy is N2000's eq. 13 in the bat's free-free modal coordinates, 1/2 (a'**2 +
omega**2 a**2) (mass-normalised), as :attr:`racket.Impact.mode_energy`: for a free bat
without damping it stays what it was when the ball left; a pivoted or hand-held bat's
support couples the free-free modes.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from common.checks import finite_array, in_range
from common.typechecks import choice
from common.units import SPEED_UNITS
from racket import impact
from racket.feel import driven_motion
from studies.bat.sweep import (
    DEFAULT_SWING,
    PITCH_SPEED,
    _bat_and_ball,
    _speed,
    bat_conditions,
    swing_argument,
    swing_kwargs,
    tip_positions,
)

if TYPE_CHECKING:
    import pandas as pd

HANDLE_POINTS = (0.06, 0.13, 0.19)
"""Where the handle is read [m from the knob]: N2000 Fig. 13's 6, 13 and 19 cm."""

FEEL_FROM_KNOB = 0.68
"""The impact point of the feel [m from the knob]: N2000 Fig. 13's 68 cm."""

FEEL_DURATION = 0.015
"""How long the handle is followed [s]: N2000 Figs. 13 and 15's 15 ms."""

DURATION_RANGE = (0.001, 1.0)
"""How long [s] :func:`bat_feel` may follow the bat: from 1 ms (N2000 Fig. 14 shows 2 ms)
to 1 s (**an assumption**: the vibration has long been felt; about 40 bytes per step and
point)."""


LEFT_OUT = ("the bat's own damping", "the hands'")
"""What may be left out of a bat's ringing (:func:`left_out`): its own damping, the hands'."""


def left_out(bat) -> tuple[str, ...]:
    """What damps a real bat's ringing and ``bat`` leaves out: "the bat's own damping" when its
    modes have none (Nathan's R161: N2000 has none; Van Zandt's Q = 10 for wood,
    ``data/bats.md`` section 5), "the hands'" unless it is held in them (a free or pivoted
    bat); empty for a damped bat in the hands (:class:`racket.Hand`'s dashpots).

    Parameters
    ----------
    bat : Bat
        The bat.
    """
    own, hands = LEFT_OUT
    parts = () if np.any(np.asarray(bat.beam.damping) > 0.0) else (own,)
    return parts if bat.support == "hand-held" else (*parts, hands)


@dataclass(frozen=True)
class BatFeel:
    """The handle's motion after one impact (built by :func:`bat_feel`).

    Attributes
    ----------
    table : DataFrame
        One row per time step and handle point: ``t_s``, ``force_N`` (the ball's on the bat,
        0 once it has left), ``point_from_knob_cm``, and at that point ``displacement_m``,
        ``velocity_m_s``, ``acceleration_m_s2``, each with its ``rigid_`` (the bat's rigid
        motion; a pivoted bat's turn) and ``vibration_`` parts.
    modes : DataFrame
        One row per free-free bending mode: ``mode``, ``frequency_Hz``,
        ``nodes_from_knob_cm``, ``energy_J`` (at the end), ``energy_at_separation_J`` (when
        the ball left, :attr:`racket.Impact.mode_energy`) and ``share`` (of the modes' energy
        at the end).
    t : (T,) ndarray
        Time since first contact [s].
    force : (T,) ndarray
        The ball's force on the bat [N].
    points_from_knob : (P,) ndarray
        The handle points [m from the knob].
    displacement, velocity, acceleration : (P, T) ndarray
        The handle's motion there [m, m/s, m/s^2], caused by the impact.
    rigid_displacement, rigid_velocity, rigid_acceleration : (P, T) ndarray
        Their rigid parts [m, m/s, m/s^2]; the rest is the vibration.
    mode_energy : ndarray
        Energy of each free-free bending mode at the end [J].
    from_knob : float
        The impact point [m from the knob].
    contact_time : float
        [s].
    exit_speed : float
        The ball's exit speed [m/s].
    vibration_energy : float
        The bat's vibration energy when the ball left [J] (:attr:`racket.Impact.vibration_energy`).
    left_out : tuple of str
        What damps a real bat's ringing and this one leaves out (:func:`left_out`).
    conditions : str
        What it was computed for, with what is left out.
    """

    table: pd.DataFrame
    modes: pd.DataFrame
    t: np.ndarray
    force: np.ndarray
    points_from_knob: np.ndarray
    displacement: np.ndarray
    velocity: np.ndarray
    acceleration: np.ndarray
    rigid_displacement: np.ndarray
    rigid_velocity: np.ndarray
    rigid_acceleration: np.ndarray
    mode_energy: np.ndarray
    from_knob: float
    contact_time: float
    exit_speed: float
    vibration_energy: float
    left_out: tuple
    conditions: str

    @property
    def vibration_displacement(self) -> np.ndarray:
        """The vibration's part of the displacement [m], (P, T)."""
        return self.displacement - self.rigid_displacement

    @property
    def vibration_acceleration(self) -> np.ndarray:
        """The vibration's part of the acceleration [m/s^2], (P, T)."""
        return self.acceleration - self.rigid_acceleration


def bat_feel(
    bat=None,
    ball=None,
    from_knob: float = FEEL_FROM_KNOB,
    speed: float = PITCH_SPEED,
    swing=DEFAULT_SWING,
    points_from_knob=HANDLE_POINTS,
    duration: float = FEEL_DURATION,
    unit: str = "m/s",
    bat_name: str | None = None,
    ball_name: str | None = None,
) -> BatFeel:
    """The handle's motion after one impact (see the module docstring).

    Parameters
    ----------
    bat : Bat or str, optional
        The bat (free, pivoted or hand-held), or a preset's name (free); default
        :data:`bat.DEFAULT_BAT`.
    ball : Ball, optional
        The ball; default :data:`ball.DEFAULT_BASEBALL`.
    from_knob : float
        The impact point [m from the knob]; default :data:`FEEL_FROM_KNOB`.
    speed : float
        The ball's speed towards the bat [m/s]; default
        :data:`studies.bat.sweep.PITCH_SPEED`.
    swing : BatSwing or None
        The bat's swing; default :data:`studies.bat.sweep.DEFAULT_SWING`; None: at rest.
    points_from_knob : sequence of float
        Where the handle is read [m from the knob]; default :data:`HANDLE_POINTS`.
    duration : float
        How long after first contact [s], in :data:`DURATION_RANGE`, longer than the contact.
    unit : str
        "m/s", "mph" or "km/h": the unit of the speeds in the conditions.
    bat_name, ball_name : str, optional
        Their names as the user gave them, for the conditions.

    Returns
    -------
    BatFeel

    Examples
    --------
    >>> feel = bat_feel(duration=0.005)
    >>> feel.displacement.shape[0]
    3
    """
    import pandas as pd

    bat, ball = _bat_and_ball(bat, ball)
    x = float(tip_positions(bat, from_knob))
    bat.check_points(x)
    z = np.atleast_1d(finite_array("points_from_knob", points_from_knob, "m from the knob"))
    if z.ndim != 1 or z.size == 0:
        raise ValueError("points_from_knob must give one point or more [m from the knob]")
    points = tip_positions(bat, z, "points_from_knob")
    speed = _speed("speed", speed)
    swing = swing_argument(bat, swing)
    duration = in_range("duration", duration, *DURATION_RANGE, "s")
    choice("unit", unit, tuple(SPEED_UNITS))
    hit = impact(bat, ball, x, speed, histories=True, **swing_kwargs(bat, swing, x))
    if duration <= hit.contact_time:
        raise ValueError(
            f"duration must be longer than the contact, {1e3 * hit.contact_time:.3g} ms here, "
            f"got {1e3 * duration:g} ms"
        )
    dt = hit.t[1] - hit.t[0]
    steps = int(np.ceil(duration / dt)) + 1
    force = np.nan_to_num(np.atleast_1d(hit.frame_force), nan=0.0)
    force = np.concatenate([force, np.zeros(max(steps - force.size, 0))])[:steps]
    motion = driven_motion(bat, x, force, dt)
    shapes = bat.beam.modes.shape(points)  # (N bat's, P)
    n = shapes.shape[0]

    def at(values):  # modal histories (T, N) read at the points: (P, T)
        return (values[:, :n] @ shapes).T

    modes = bat.beam.modes
    omega = modes.omega[2:]
    energy = 0.5 * (motion.qd[-1, 2:n] ** 2 + (omega * motion.q[-1, 2:n]) ** 2)
    t = np.arange(steps) * dt
    parts = {
        "displacement_m": (at(motion.q), at(motion.rigid_q)),
        "velocity_m_s": (at(motion.qd), at(motion.rigid_qd)),
        "acceleration_m_s2": (at(motion.qdd), at(motion.rigid_qdd)),
    }
    columns = {"t_s": np.tile(t, z.size), "force_N": np.tile(force, z.size),
               "point_from_knob_cm": np.repeat(100 * z, steps)}  # fmt: skip
    for name, (total, rigid) in parts.items():
        columns[name] = total.ravel()
        columns[f"rigid_{name}"] = rigid.ravel()
        columns[f"vibration_{name}"] = (total - rigid).ravel()
    length = bat.beam.length
    missing = left_out(bat)
    conditions = bat_conditions(bat, ball, speed, swing, unit, bat_name, ball_name)
    if missing:
        conditions += f"; left out: {' and '.join(missing)}"
    mode_table = pd.DataFrame({
        "mode": np.arange(1, omega.size + 1),
        "frequency_Hz": modes.frequencies,
        "nodes_from_knob_cm": [", ".join(f"{100 * (length - node):.1f}"
                                         for node in sorted(modes.nodes(k), reverse=True))
                               for k in range(1, omega.size + 1)],
        "energy_J": energy,
        "energy_at_separation_J": np.atleast_1d(hit.mode_energy),
        "share": energy / energy.sum() if energy.sum() > 0 else np.zeros_like(energy),
    })  # fmt: skip
    return BatFeel(
        table=pd.DataFrame(columns), modes=mode_table, t=t, force=force, points_from_knob=z,
        displacement=parts["displacement_m"][0], velocity=parts["velocity_m_s"][0],
        acceleration=parts["acceleration_m_s2"][0],
        rigid_displacement=parts["displacement_m"][1], rigid_velocity=parts["velocity_m_s"][1],
        rigid_acceleration=parts["acceleration_m_s2"][1], mode_energy=energy,
        from_knob=float(length - x), contact_time=float(hit.contact_time),
        exit_speed=float(hit.ball_rebound), vibration_energy=float(hit.vibration_energy),
        left_out=missing, conditions=conditions,
    )  # fmt: skip
