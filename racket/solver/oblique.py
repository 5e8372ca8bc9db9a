"""An oblique impact of a spinning ball on the strings (issue 36): the head-on impact
(:func:`racket.solver.driver.impact`, unchanged) for the normal part, and the ball's
sliding, gripping and spinning on the strings (:func:`ball.grip.slide`) driven by its force
history, for all impact points at once.

The coupling is one-way (:mod:`ball.grip`): the normal outcome is the head-on one to the
last bit, whatever the tangential speed and spin; the tangential force moves the racket in
the plane of its strings (:mod:`racket.in_plane`) and pulls the mains and crosses sideways
(:mod:`racket.strings.sideways`).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ball.bodies import Ball
from ball.grip import Grip, slide
from ball.spin import BallSpin, ask_spin
from common.checks import SPEED_RANGE, finite_array
from common.typechecks import instance
from racket.in_plane import inverse_mass
from racket.racket import Racket
from racket.solver.dispatch import run_rows
from racket.solver.driver import impact
from racket.solver.outcome import Impact
from racket.strings.sideways import BedSideways, sideways
from racket.stroke import LIMITS

GRIP_SUBSTEPS = 2
"""Sub-steps of the tangential contact per step of the normal one [-]: the strings'
stick-slip falls at sub-step boundaries, so the spin converges at first order; 2 keep the
change of spin within 1e-2 of 128 sub-steps over the Pure Drive's strings, free and clamped
(about 10 rpm in 2000; ``tests/test_oblique.py`` fits the order), at a fifth of a head-on
sweep's time."""


@dataclass(frozen=True)
class ObliqueImpact:
    """Outcome of :func:`oblique_impact`: the head-on :class:`Impact` for the normal part,
    the :class:`ball.grip.Grip` for the tangential one, and the bed's sideways description.
    Face-frame components are (along the long axis towards the tip, across towards 3
    o'clock, normal out of the strings towards the ball).

    Attributes
    ----------
    normal : Impact
        The head-on impact at the normal closing speed.
    grip : Grip
        The tangential contact.
    side : BedSideways
        The bed's friction and sliding strings used.
    """

    normal: Impact
    grip: Grip
    side: BedSideways

    @property
    def velocity(self) -> np.ndarray:
        """(n, 3) ball's velocity after [m/s], relative to the impact point's velocity
        before, in face-frame components (its normal one is the head-on rebound,
        :attr:`Impact.ball_rebound`, less the point's own speed towards the ball).
        """
        normal = np.atleast_1d(self.normal.ball_rebound - self.normal.swing_speed)
        return np.column_stack([self.grip.velocity, normal])

    @property
    def spin(self) -> np.ndarray:
        """(n, 3) ball's spin after [rad/s], face-frame components."""
        return self.grip.spin

    @property
    def energy_residual(self) -> np.ndarray:
        """The whole budget's residual [J]: the head-on impact's (the integration error)
        and the tangential contact's (round-off), the latter relative to nothing lost.
        """
        return np.atleast_1d(self.normal.energy_residual) + self.grip.residual


SPIN_MAX = LIMITS["topspin"][1]
"""The largest spin [rad/s] an oblique impact takes: a stroke's (:data:`racket.stroke.LIMITS`,
9549 rpm, twice the most measured)."""


def _vectors(name: str, values, size: int, unit: str, largest: float, points: int) -> np.ndarray:
    """``values`` as finite numbers of shape (size,), or (n, size) with n 1 or ``points``
    (the impact points), each vector's size at most ``largest``; one line otherwise.
    """
    values = finite_array(name, values, unit)
    rows = (1, points) if points > 1 else (1,)
    if (
        values.ndim not in (1, 2)
        or values.shape[-1] != size
        or (values.ndim == 2 and values.shape[0] not in rows)
    ):
        per_point = f" ({points} points: shape ({points}, {size}))" if points > 1 else ""
        raise ValueError(f"{name} must be {size} numbers [{unit}], or a row of {size} per impact "
                         f"point{per_point}, got shape {values.shape}")  # fmt: skip
    size_of = float(np.max(np.linalg.norm(values, axis=-1)))
    if size_of > largest:
        raise ValueError(f"{name} must be at most {largest:g} {unit} in size, got {size_of:.4g}")
    return values


def oblique_impact(
    racket: Racket,
    ball: Ball,
    position,
    speed: float,
    *,
    slip_velocity=(0.0, 0.0),
    spin=(0.0, 0.0, 0.0),
    offset=None,
    swing_speed=0.0,
    pivot: float | None = None,
    ball_spin: BallSpin | None = None,
    side: BedSideways | None = None,
    steps_per_contact: int | None = None,
) -> ObliqueImpact:
    """A spinning ball meets the strings obliquely at ``position``.

    Parameters
    ----------
    racket, ball, position, speed, offset, swing_speed, pivot, steps_per_contact
        As :func:`racket.impact`: ``speed`` and ``swing_speed`` are the ball's and the impact
        point's speeds along the strings' normal [m/s].  The tangential contact needs the
        force's history, which needs one time step for all the points: one closing speed
        (speed + swing speed), or a ball whose contact time does not depend on it (a point's
        own swing speed with the ITF ball: one call per point).
    slip_velocity : array_like
        (2,) or (n, 2) ball's velocity along the strings [m/s] relative to the impact point,
        (along, across): one for every point, or a row per point (n the points' number);
        another shape is refused before any impact runs.
    spin : array_like
        (3,) or (n, 3) ball's spin [rad/s], (along, across, normal) components, shaped as
        ``slip_velocity``; a spin larger than :data:`ball.spin.MOST_SPIN` (about 5000 rpm) is
        asked about in a warning (rpm typed as rad/s?).
    ball_spin : BallSpin, optional
        The ball's radius, inertia, tangential stiffness and offset (default
        :class:`ball.spin.BallSpin`, a tennis ball's; its radius is the ball's if it has one).
    side : BedSideways, optional
        The bed sideways; default :func:`racket.strings.sideways.sideways` of the racket's bed.

    Returns
    -------
    ObliqueImpact
    """
    instance("racket", racket, Racket, "a racket.Racket")
    instance("ball", ball, Ball, "a ball.Ball")
    instance("ball_spin", ball_spin, (BallSpin, type(None)), "a ball.spin.BallSpin or None")
    instance(
        "side", side, (BedSideways, type(None)), "a racket.strings.sideways.BedSideways or None"
    )
    points = racket.check_points(position, offset)[0].size  # refused as impact refuses them
    slip_velocity = _vectors("slip_velocity", slip_velocity, 2, "m/s", SPEED_RANGE[1], points)
    spin = _vectors("spin", spin, 3, "rad/s", SPIN_MAX, points)
    ask_spin("|spin|", float(f"{np.max(np.linalg.norm(spin, axis=-1)):.4g}"))  # the largest
    if ball_spin is None:
        ball_spin = BallSpin() if ball.radius is None else BallSpin(radius=ball.radius)
    side = sideways(racket.strings) if side is None else side
    normal = impact(
        racket, ball, position, speed, offset=offset, swing_speed=swing_speed, pivot=pivot,
        steps_per_contact=steps_per_contact, histories="force",
    )  # fmt: skip
    force = np.nan_to_num(np.atleast_2d(normal.force))  # NaN once the ball has left
    x = np.broadcast_to(np.atleast_1d(normal.position), (force.shape[0],))
    y = 0.0 if normal.offset is None else normal.offset
    dt = float(normal.t[1] - normal.t[0])
    grip = slide(
        force, dt, ball.mass, ball_spin, side.ball_friction, slip_velocity, spin,
        inv_mass=inverse_mass(racket, x, y), layer=side.layer(), law=ball.law,
        substeps=GRIP_SUBSTEPS, runner=run_rows,
    )  # fmt: skip
    return ObliqueImpact(normal, grip, side)
