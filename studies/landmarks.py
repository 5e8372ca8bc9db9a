"""Landmarks on a racket that players and coaches ask about: where the hand is, and the
centre of percussion.

The centre of percussion comes out of the simulation (:func:`percussion_centre`: the impact
point after which the hand's rigid-body velocity is zero); :func:`center_of_percussion` is
the rigid-body formula, which the tests compare it with (they agree for a free racket; a
hand-held one differs, the hand pushing during the contact).
"""

from __future__ import annotations

import numpy as np

from common.checks import finite, in_range
from racket import Racket
from racket.racket import Hand

HAND_FROM_BUTT = 0.5 * Hand.grip_length
"""Where the hand holds the racket [m from the butt]: the middle of the default hand's grip.
The model spreads the hand evenly over :attr:`racket.racket.Hand.grip_length` from the butt
(``racket.system``) and reads the handle there (:func:`racket.feel.hand_feel`); the mean of a
rigid-body velocity over an even grip is its value at the middle.  (Not the flex test's
handle support, ``racket.specs.stiffness.HANDLE_SUPPORT``, a testing machine's.)"""


def hand_pivot(racket: Racket, grip_from_butt: float | None = None) -> float:
    """Where the hand pivots [m from the tip].

    Parameters
    ----------
    racket : Racket
        The racket (its length, and its hand's grip).
    grip_from_butt : float, optional
        The hand [m from the butt], in [0, 0.3]; default the middle of ``racket.hand``'s
        grip (:data:`HAND_FROM_BUTT` for the default hand).
    """
    if grip_from_butt is None:
        grip = 0.5 * racket.hand.grip_length
    else:
        grip = in_range("grip_from_butt", grip_from_butt, 0.0, 0.3, "m")
    return racket.beam.length - grip


def center_of_percussion(racket: Racket, pivot: float) -> float:
    """Centre of percussion [m from the tip] by the rigid-body formula: an impulse there
    leaves the pivot of a free rigid racket at rest.  The simulated one is
    :func:`percussion_centre`.

    Parameters
    ----------
    racket : Racket
        The racket (its rigid-body mass properties count).
    pivot : float
        The pivot, e.g. the hand [m from the tip], on the handle's side of the centre of
        mass: in (centre of mass, length].
    """
    beam = racket.beam
    pivot = in_range("pivot", pivot, 0.0, beam.length, "m")
    if pivot <= beam.center_of_mass:
        raise ValueError(
            f"pivot must be in ({beam.center_of_mass:.4g}, {beam.length:.4g}] m (beyond the "
            f"centre of mass, towards the butt), got {pivot:g}"
        )
    d = pivot - beam.center_of_mass
    return pivot - (beam.inertia_cm + beam.mass * d**2) / (beam.mass * d)


def percussion_centre(racket: Racket, positions, v_cm, omega, pivot: float) -> float:
    """Centre of percussion [m from the tip] from simulated impacts: the impact point after
    which the pivot's dc (rigid-body) velocity v_cm + (x_cm - pivot) omega is zero,
    interpolated linearly between ``positions``; NaN if it is not among them, or if the
    racket is clamped at the head (at rest after any impact: it has none).

    The velocity is taken over v_cm (> 0: the ball pushes the racket), which for a free
    racket is linear in the impact point, so that the interpolation is exact there and the
    rigid-body formula (:func:`center_of_percussion`) is met to round-off.

    Parameters
    ----------
    racket : Racket
        The racket that was hit (its centre of mass).
    positions : array_like
        Impact points on the racket's axis [m from the tip], increasing.
    v_cm : array_like
        The racket's centre-of-mass velocity after each impact [m/s] (``Impact.v_cm`` of
        :func:`racket.impact`, the racket at rest before).
    omega : array_like
        Its angular velocity after each impact [rad/s] (``Impact.omega``).
    pivot : float
        The pivot, e.g. the hand [m from the tip].
    """
    pivot = finite("pivot", pivot, "m")
    if racket.support == "clamped-head":  # v_cm = omega = 0: never 0/0
        return float("nan")
    x = np.asarray(positions, dtype=float)
    dc = 1.0 + (racket.beam.center_of_mass - pivot) * np.asarray(omega) / np.asarray(v_cm)
    crossing = np.flatnonzero(np.sign(dc[:-1]) != np.sign(dc[1:]))
    if dc.size < 2 or crossing.size == 0:
        return float("nan")
    i = crossing[0]
    return float(x[i] - dc[i] * (x[i + 1] - x[i]) / (dc[i + 1] - dc[i]))


def sweet_spots(
    racket: Racket,
    ball,
    speed: float | None = None,
    swing=None,
    grip_from_butt: float | None = None,
    points: int = 201,
):
    """The racket's sweet spots in one table, every position in cm from the butt (as spec
    sheets give them) with the distance from the tip beside it.

    Rows: the node(s) of the first free bending mode (no vibration excited), the centre of
    percussion for a hand at ``grip_from_butt`` (no jar to the hand: the impact point after
    which the hand's rigid-body velocity is zero, :func:`percussion_centre`), the points of largest
    e (Eq. 21) and largest e_A along the strings (racket at rest, ball at ``speed``), the
    dead spot (smallest e_A, where the ball bounces least), the point of largest exit
    speed for ``swing`` (if given; the ball at ``speed``, 0 for a serve), and the sweet area
    of the face map (rackets whose roll inertia is modelled).

    Parameters
    ----------
    racket : Racket
    ball : Ball
    speed : float, optional
        Ball speed towards the strings [m/s]; default (None) :data:`studies.maps.MAP_SPEED`,
        TWU's; 0 for a serve (the racket at rest then hit at :data:`studies.maps.MAP_SPEED`).
    swing : Swing, optional
        A swing of the (free) racket for the exit speed.
    grip_from_butt : float, optional
        Where the hand pivots [m from the butt], in [0, 0.3]; default the middle of the
        racket's grip (:func:`hand_pivot`).
    points : int
        Points along the strings, a whole number in [11, 10001].

    Returns
    -------
    DataFrame
        ``spot``, ``from_butt_cm``, ``from_tip_cm``, ``value``, ``unit``, ``meaning``.
    """
    import pandas as pd

    from racket import impact
    from studies.maps import MAP_SPEED, SWEET_FRACTION, face_map

    speed = MAP_SPEED if speed is None else speed
    pivot = hand_pivot(racket, grip_from_butt)
    points = whole("points", points, 11, 10001)
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
    cop = percussion_centre(racket, x, still.v_cm, still.omega, pivot)
    add("centre of percussion", cop, 100 * (length - pivot), "cm (grip from the butt)",
        "no jar to the hand")  # fmt: skip
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
            f"e_A within {100 * SWEET_FRACTION:g} % of its largest (centred where e_A is "
            "largest)")  # fmt: skip
    return pd.DataFrame(rows)


def whole(name: str, value, low: int, high: int) -> int:
    """``value`` as an int; raise ``ValueError`` unless it is a whole number in [low, high].

    Parameters
    ----------
    name : str
        The argument's name, as the message quotes it.
    value : object
        The count [-].
    low, high : int
        The bounds [-], inclusive.
    """
    x = in_range(name, value, low, high)
    if x != int(x):
        raise ValueError(f"{name} must be a whole number in [{low}, {high}], got {x:g}")
    return int(x)
