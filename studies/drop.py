"""A ball dropped from a height onto the floor, onto clamped strings or onto a free racket
(``racket-impact drop``): how high it bounces, its COR, and the force and compression
against time, the classroom demonstration of the paper's Secs. III-IV.

The ball reaches the surface at v = sqrt(2 g h) (air drag neglected) and bounces back up to
h' = V^2 / (2 g), V its rebound speed: on the floor (a rigid, immovable surface,
:func:`ball.collide`) V / v is the ball's own COR, so h' / h = e^2, the ITF's rebound test;
on strings it is the apparent COR e_A of what it hits (:func:`racket.impact`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ball import WALL, Ball, collide
from common.checks import CM_AS_M, in_range
from common.typechecks import instance
from common.units import GRAVITY
from racket import Racket, impact

HEIGHT_RANGE = (0.01, 50.0)
"""Drop heights [m] accepted: from a centimetre to a tall building's roof, 50 m (an
assumption, generous on purpose: from that high a real ball, slowed by the air, arrives well
below the drag-free 31 m/s that :func:`drop` assumes)."""


@dataclass(frozen=True)
class Drop:
    """A dropped ball's bounce (:func:`drop`).

    Attributes
    ----------
    height : float
        Drop height [m].
    speed : float
        Speed on reaching the surface, sqrt(2 g h) [m/s].
    rebound_speed : float
        Speed leaving it, upwards [m/s] (0 if the ball stays).
    bounce_height : float
        How high it rises again, V^2 / (2 g) [m].
    rebound_ratio : float
        rebound_speed / speed [-]: the ball's COR on the floor, the apparent COR on strings.
    contact_time : float
        Contact duration [s].
    peak_force : float
        Largest contact force [N].
    t : ndarray
        Time since first contact [s].
    force : ndarray
        Contact force [N] at ``t``.
    compression : ndarray
        The ball's compression [m] at ``t``.
    """

    height: float
    speed: float
    rebound_speed: float
    bounce_height: float
    rebound_ratio: float
    contact_time: float
    peak_force: float
    t: np.ndarray
    force: np.ndarray
    compression: np.ndarray


def drop(ball: Ball, height: float, onto: Racket | None = None) -> Drop:
    """Drop ``ball`` from ``height`` onto the floor (``onto`` None) or onto the string centre
    of the racket ``onto`` (with its support: ``"clamped-head"`` for strings on an immovable
    frame, ``"free"`` for a racket lying free).

    Parameters
    ----------
    ball : Ball
        The ball.
    height : float
        Drop height [m], in :data:`HEIGHT_RANGE`.
    onto : Racket, optional
        What it lands on; None: the floor.

    Returns
    -------
    Drop

    Examples
    --------
    >>> from ball import BALL_PRESETS
    >>> bounce = drop(BALL_PRESETS["itf-type-2"].ball(), 2.54)  # the ITF rebound test
    >>> 1.35 <= bounce.bounce_height <= 1.47
    True
    """
    ball = instance("ball", ball, Ball, "a ball.Ball")
    onto = instance("onto", onto, Racket | type(None), "a racket.Racket or None (the floor)", (
        " (the command line's --onto strings is onto=replace(racket, support='clamped-head'), "
        "--onto racket is a free racket)" if isinstance(onto, str) else ""))  # fmt: skip
    height = in_range("height", height, *HEIGHT_RANGE, "m", slips=(CM_AS_M,))
    speed = math.sqrt(2.0 * GRAVITY * height)
    if onto is None:
        c = collide(ball, WALL, speed)
        rebound = max(0.0, -c.v_a_after)
        t, force, compression = c.history.t, c.history.force, c.history.compression_a
        contact, peak = c.contact_time, c.peak_force
    else:
        hit = impact(onto, ball, onto.strings.center, speed, histories=True)
        rebound = max(0.0, float(hit.ball_rebound))
        inside = np.isfinite(hit.force)
        t, force, compression = hit.t[inside], hit.force[inside], hit.ball_compression[inside]
        contact, peak = float(hit.contact_time), float(hit.peak_force)
    return Drop(
        height=height,
        speed=speed,
        rebound_speed=rebound,
        bounce_height=rebound**2 / (2.0 * GRAVITY),
        rebound_ratio=rebound / speed,
        contact_time=contact,
        peak_force=peak,
        t=np.asarray(t),
        force=np.asarray(force),
        compression=np.asarray(compression),
    )
