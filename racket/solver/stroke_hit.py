"""A stroke hit (issue 36): a :class:`racket.stroke.Stroke` resolved on the face, the oblique
impact at its closing speed in the frame of the racket's own motion (the swing superposes:
the racket's velocity before is added back), and the ball's flight after.
"""

from __future__ import annotations

from dataclasses import dataclass

from ball.bodies import Ball
from common.checks import finite
from common.typechecks import instance
from racket.racket import Racket
from racket.solver.oblique import ObliqueImpact, oblique_impact
from racket.strings.sideways import BedSideways
from racket.stroke import Flight, Stroke


@dataclass(frozen=True)
class StrokeImpact:
    """Outcome of :func:`hit`.

    Attributes
    ----------
    stroke : Stroke
        The stroke.
    position : float
        The impact point [m from the tip].
    offset : float
        Its distance from the long axis [m, + towards 3 o'clock].
    oblique : ObliqueImpact
        The impact on the face, in the frame of the racket's motion before.
    flight : Flight
        The ball after: speed, launch angle, spin and its split.
    """

    stroke: Stroke
    position: float
    offset: float
    oblique: ObliqueImpact
    flight: Flight

    @property
    def contact_time(self) -> float:
        """Duration of the contact [s]."""
        return float(self.oblique.normal.contact_time)

    @property
    def slid_throughout(self) -> bool:
        """True when the ball slid on the strings for the whole contact (it never gripped)."""
        return bool(self.oblique.grip.slid_throughout[0])

    @property
    def racket_share(self) -> float:
        """The part [-] of the ball's speed away from the face that the racket's own speed
        gave it: (1 + e_A) v2 / ((1 + e_A) v2 + e_A v1), Eq. 22's split, with v1 and v2 the
        ball's and the racket's speeds along the normal before (1 for a ball at rest).
        """
        frame = self.stroke.face_frame()
        e_a = float(self.oblique.normal.e_A)
        racket = (1.0 + e_a) * frame.racket_normal_speed
        return racket / (racket + e_a * frame.ball_normal_speed)


def hit(
    stroke: Stroke,
    racket: Racket,
    ball: Ball,
    position: float | None = None,
    *,
    offset: float | None = None,
    side: BedSideways | None = None,
) -> StrokeImpact:
    """The ball's flight after ``stroke`` with ``racket`` at ``position``.

    The impact runs in the frame of the racket point's velocity before (the racket at rest,
    the ball closing at the stroke's closing speed, sliding and spinning as the face sees
    it); its answer, relative to that frame, is turned back into the world's
    (:meth:`racket.stroke.Stroke.to_world`).

    Parameters
    ----------
    stroke : Stroke
        The stroke.
    racket : Racket
        The racket (free or hand-held; a clamped head cannot swing).
    ball : Ball
        The ball.
    position : float, optional
        The impact point [m from the tip]; default the string bed's centre.
    offset : float, optional
        Its distance from the long axis [m, + towards 3 o'clock] (pros hit most forehands
        1/2-1 in off it: Yandell, ``data/measurements.md`` sec. 9); default on the axis.
    side : BedSideways, optional
        The bed sideways (default: the racket's bed's, :func:`racket.strings.sideways.sideways`).

    Returns
    -------
    StrokeImpact
    """
    instance("stroke", stroke, Stroke, "a racket.Stroke", " (e.g. racket.STROKES['volley'])")
    instance("racket", racket, Racket, "a racket.Racket")
    instance("ball", ball, Ball, "a ball.Ball")
    if racket.support == "clamped-head":
        raise ValueError(
            "racket must move for a stroke (support 'free' or 'hand-held'), got support "
            "'clamped-head': a clamped head cannot swing"
        )
    if position is not None:
        position = finite("position", position, "m from the tip")
    position = racket.strings.center if position is None else position
    if offset is not None:
        offset = finite("offset", offset, "m from the long axis")
    frame = stroke.face_frame()
    oblique = oblique_impact(
        racket, ball, position, frame.closing_speed, slip_velocity=frame.slip_velocity,
        spin=frame.spin, side=side, offset=offset or None,
    )  # fmt: skip
    velocity = oblique.velocity[0]
    flight = stroke.to_world(velocity[:2], velocity[2], oblique.spin[0])
    return StrokeImpact(stroke, position, offset or 0.0, oblique, flight)
