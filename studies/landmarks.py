"""Landmarks on a racket that players and coaches ask about: where the hand is, and the
centre of percussion.
"""

from __future__ import annotations

from racket import Racket

HAND_FROM_BUTT = 0.07
"""Where the hand holds the racket, for the centre of percussion [m from the butt]."""


def center_of_percussion(racket: Racket, pivot: float) -> float:
    """Centre of percussion [m from the tip]: an impact there leaves the pivot at rest (no
    jar to the hand).

    Parameters
    ----------
    racket : Racket
        The racket (its rigid-body mass properties count).
    pivot : float
        The pivot, e.g. the hand [m from the tip].
    """
    beam = racket.beam
    d = pivot - beam.center_of_mass
    return pivot - (beam.inertia_cm + beam.mass * d**2) / (beam.mass * d)


def sweet_spots(
    racket: Racket,
    ball,
    speed: float = 16.5,
    swing=None,
    grip_from_butt: float = HAND_FROM_BUTT,
    points: int = 201,
):
    """The racket's sweet spots in one table, every position in cm from the butt (as spec
    sheets give them) with the distance from the tip beside it.

    Rows: the node(s) of the first free bending mode (no vibration excited), the centre of
    percussion for a hand at ``grip_from_butt`` (no jar to the hand), the points of largest
    e (Eq. 21) and largest e_A along the strings (racket at rest, ball at ``speed``), the
    dead spot (smallest e_A, where the ball bounces least), the point of largest exit
    speed for ``swing`` (if given; the ball at ``speed``, 0 for a serve), and the sweet area
    of the face map (rackets whose roll inertia is modelled).

    Parameters
    ----------
    racket : Racket
    ball : Ball
    speed : float
        Ball speed towards the strings [m/s] (default 16.5, TWU's).
    swing : Swing, optional
        A swing of the (free) racket for the exit speed.
    grip_from_butt : float
        Where the hand pivots [m from the butt], in [0, 0.3]; default
        :data:`HAND_FROM_BUTT`.
    points : int
        Points along the strings, in [11, 10001].

    Returns
    -------
    DataFrame
        ``spot``, ``from_butt_cm``, ``from_tip_cm``, ``value``, ``unit``, ``meaning``.
    """
    import numpy as np
    import pandas as pd

    from common.checks import in_range
    from racket import impact
    from studies.maps import MAP_SPEED, face_map

    grip = in_range("grip_from_butt", grip_from_butt, 0.0, 0.3, "m")
    points = int(in_range("points", points, 11, 10001))
    beam, length = racket.beam, racket.beam.length
    x = np.linspace(*racket.strings.extent, points)
    still = impact(racket, ball, x, speed or MAP_SPEED)
    rows = []

    def add(spot, where, value, unit, meaning):
        rows.append(
            {
                "spot": spot,
                "from_butt_cm": 100 * (length - where),
                "from_tip_cm": 100 * where,
                "value": value,
                "unit": unit,
                "meaning": meaning,
            }
        )

    start, end = racket.strings.extent
    for node in beam.modes.nodes(1):
        where = "on the strings" if start <= node <= end else "off the strings"
        add(f"node of mode 1 ({where})", node, beam.modes.frequencies[0], "Hz",
            "mode 1 (the frame's fundamental) is not excited, nor felt there")  # fmt: skip
    cop = center_of_percussion(racket, length - grip)
    add("centre of percussion", cop, 100 * grip, "cm (grip from the butt)", "no jar to the hand")
    for name, values, pick, meaning in (
        ("largest e", still.e, np.argmax, "Eq. 21: the racket's rebound quality"),
        ("largest e_A", still.e_A, np.argmax, "most power, racket at rest"),
        ("dead spot", still.e_A, np.argmin, "least power, racket at rest"),
    ):
        i = pick(values)
        add(name, x[i], float(values[i]), "", meaning)
    if swing is not None:
        swung = impact(racket, ball, x, speed, **swing.impact_kwargs(racket, x))
        i = np.argmax(swung.ball_rebound)
        add("largest exit speed", x[i], float(swung.ball_rebound[i]), "m/s",
            f"swung at {swing.head_speed:.4g} m/s head speed")  # fmt: skip
    if beam.roll_inertia is not None:
        face = face_map(racket, ball, speed or MAP_SPEED)
        i = np.argmax(face.e_A.max(axis=1))
        add("sweet area", face.positions[i], face.sweet_area_cm2, "cm^2",
            "e_A within 5 % of its largest (centred where e_A is largest)")  # fmt: skip
    return pd.DataFrame(rows)
