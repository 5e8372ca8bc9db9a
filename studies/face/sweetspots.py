"""The racket's sweet spots in one table: the node of the first bending mode, the centre of
percussion for the hand, the points of largest e and e_A, the dead spot, the point of largest
exit speed for a swing, and the sweet area of the face map.
"""

from __future__ import annotations

import numpy as np
import pandas as pd

from common.checks import speed as check_speed
from common.checks import whole
from racket import TENNIS_BALL_RADIUS, Racket, impact
from studies.arguments import ball_argument, racket_argument, swing_argument
from studies.face.landmarks import hand_pivot, percussion_centre
from studies.face.maps import SWEET_FRACTION, face_map
from studies.sweeps import BALL_SPEED


def sweet_spots(
    racket: Racket,
    ball,
    speed: float | None = None,
    swing=None,
    hand_from_tip: float | None = None,
    points: int = 201,
):
    """The racket's sweet spots in one table, every position in cm from the tip (as every
    position here).

    Rows: the node(s) of the first free bending mode on the strings (no vibration
    excited), the centre of percussion for a hand at ``hand_from_tip`` (no jar to the
    hand: the impact point after which the hand's rigid-body velocity is zero,
    :func:`studies.face.landmarks.percussion_centre`), the points of largest e (Eq. 21) and
    largest e_A along the strings (racket at rest, ball at ``speed``), the
    dead spot (smallest e_A, where the ball bounces least), the point of largest exit
    speed for ``swing`` (if given; the ball at ``speed``, 0 for a serve), and the sweet area
    of the face map (rackets whose roll inertia is modelled).

    Every spot lies where the ball's centre can be on the strings: a ball radius inside
    the string bed's ends (as the face map's grid, :func:`studies.face.maps.face_map`).

    Parameters
    ----------
    racket : Racket
    ball : Ball
    speed : float, optional
        Ball speed towards the strings [m/s]; default (None)
        :data:`studies.sweeps.BALL_SPEED`, TWU's; 0 for a serve (the racket at rest then hit
        at :data:`studies.sweeps.BALL_SPEED`).
    swing : Swing, optional
        A swing of the (free) racket for the exit speed.
    hand_from_tip : float, optional
        Where the hand pivots [m from the tip], on the handle; default the middle of the
        racket's grip (:func:`studies.face.landmarks.hand_pivot`).
    points : int
        Points along the strings, a whole number in [11, 10001].

    Returns
    -------
    DataFrame
        ``spot`` (a key: "node of mode 1", "centre of percussion", "largest e", "largest
        e_A", "dead spot", "largest exit speed", "sweet area"), ``said`` (the spot in a
        player's words, with its value), ``from_tip_cm``, ``value``,
        ``unit``, ``meaning``.
    """
    racket, ball, swing = racket_argument(racket), ball_argument(ball), swing_argument(swing)
    speed = BALL_SPEED if speed is None else check_speed("speed", speed, allow_zero=True)
    pivot = hand_pivot(racket, hand_from_tip)
    points = whole("points", points, 11, 10001)
    beam = racket.beam
    start, end = racket.strings.extent
    margin = min(TENNIS_BALL_RADIUS if ball.radius is None else ball.radius, 0.25 * (end - start))
    x = np.linspace(start + margin, end - margin, points)
    still = impact(racket, ball, x, speed or BALL_SPEED)
    rows = []

    def add(spot, said, where, value, unit, meaning):
        rows.append(
            {
                "spot": spot,
                "said": said,
                "from_tip_cm": 100 * where,
                "value": value,
                "unit": unit,
                "meaning": meaning,
            }
        )

    f1 = float(beam.modes.frequencies[0])
    for node in beam.modes.nodes(1):
        if x[0] <= node <= x[-1]:
            add("node of mode 1", f"node of the first mode ({f1:.0f} Hz)", node, f1, "Hz",
                "the frame's first mode is not set ringing: least vibration")  # fmt: skip
    cop = percussion_centre(racket, x, still.v_cm, still.omega, pivot)
    hand = 100 * pivot
    add("centre of percussion", f"centre of percussion (hand at {hand:.1f} cm)",
        cop, hand, "cm from the tip (the hand)", "no jar to the hand")  # fmt: skip
    for spot, said, values, pick, meaning in (
        ("largest e", "best rebound of the frame, e", still.e, np.argmax,
         "the frame gives back most (Eq. 21)"),
        ("largest e_A", "most power, e_A", still.e_A, np.argmax,
         "the ball comes back fastest off the racket at rest"),
        ("dead spot", "dead spot (least power), e_A", still.e_A, np.argmin,
         "the ball comes back slowest off the racket at rest"),
    ):  # fmt: skip
        i = pick(values)
        add(spot, f"{said} {float(values[i]):.3f}", x[i], float(values[i]), "", meaning)
    if swing is not None:
        swung = impact(racket, ball, x, speed, **swing.impact_kwargs(racket, x))
        i = np.argmax(swung.ball_rebound)
        add("largest exit speed", f"fastest exit, {float(swung.ball_rebound[i]):.1f} m/s",
            x[i], float(swung.ball_rebound[i]), "m/s",
            f"swung at {swing.head_speed:.4g} m/s head speed")  # fmt: skip
    if beam.roll_inertia is not None:
        face = face_map(racket, ball, speed or BALL_SPEED)
        i = np.argmax(face.e_A.max(axis=1))
        add("sweet area", f"sweet area, {face.sweet_area_cm2:.1f} cm^2, its best row",
            face.positions[i], face.sweet_area_cm2, "cm^2",
            f"e_A within {100 * SWEET_FRACTION:g} % of its largest")  # fmt: skip
    return pd.DataFrame(rows)
