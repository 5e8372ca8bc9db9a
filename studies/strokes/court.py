"""Courts (issue 36): does this court play fast?  A ball's bounce on each court, one row per
court, in a player's units (degrees, rpm, ms), with the court's ITF Court Pace Rating.

Each row is one :func:`ball.court.bounce` of the ball as given (by default the ITF's pace
test: 30 m/s, 16 degrees above the court, no spin) and the court's
:func:`ball.court.court_pace_rating` (always from the ITF's test bounce, with the same ball):
the court's friction and COR and whether they are sourced or an assumption
(:data:`ball.court.COURT_SOURCES`), then the ball after the bounce (speed, angle above the
court, topspin), vx2/vx1, the vertical COR e_y, the apparent friction, the contact time,
whether the ball slid throughout or gripped the court, and the CPR with its category.

Angles are in degrees and spins in rpm in the table (:func:`ball.court.bounce` takes radians
and rad/s); speeds are in m/s, and also in mph or km/h with ``unit``.
"""

from __future__ import annotations

import math

import pandas as pd

from ball.court import (
    COURT_SOURCES,
    COURTS,
    CPR_ANGLE,
    CPR_CATEGORIES,
    CPR_SPEED,
    LAB_SURFACES,
    Court,
    bounce,
    court_pace_rating,
)
from common.typechecks import choice, instance
from common.units import SPEED_UNITS
from racket.stroke import RPM
from studies.arguments import ball_argument
from studies.tables import speeds_in

SPEED_COLUMNS = ("ball_speed", "speed_after")
"""The speeds of a court table (``*_m_s``, and ``*_mph`` or ``*_kmh`` with ``unit``): the
ball's before and after the bounce."""

PACE_NAMES = {number: name for number, name, _ in CPR_CATEGORIES}
"""The ITF court pace categories' names by number (1 "slow" to 5 "fast")."""


def _courts(courts) -> list[Court]:
    """``courts`` as Court objects: each a name of :data:`ball.court.COURTS` or
    :data:`ball.court.LAB_SURFACES`, or a :class:`ball.court.Court`; a name once.
    """
    if isinstance(courts, str | Court):
        courts = [courts]
    known = {**COURTS, **LAB_SURFACES}
    checked = []
    for k, court in enumerate(list(courts)):
        if isinstance(court, str):
            if court not in known:
                raise ValueError(
                    f"unknown court {court!r}; the courts: {', '.join(COURTS)} (and the lab "
                    f"surfaces: {', '.join(repr(s) for s in LAB_SURFACES)})"
                )
            court = known[court]
        instance(f"courts[{k}]", court, Court, "a court's name or a ball.court.Court",
                 " (e.g. 'clay', or Court('mine', 0.6, 0.8))")  # fmt: skip
        if court.name in (c.name for c in checked):
            raise ValueError(f"court {court.name!r} is named twice; name it once")
        checked.append(court)
    if not checked:
        raise ValueError("courts must hold one court or more, got none")
    return checked


def source_word(court: Court) -> str:
    """Where ``court``'s friction and COR come from, in a word: "sourced" (a preset or lab
    surface measured or calibrated on a measurement), "assumption" (a preset whose numbers
    are assumed, :data:`ball.court.COURT_SOURCES`) or "given" (a court of one's own).

    Parameters
    ----------
    court : Court
        The court.
    """
    instance("court", court, Court, "a ball.court.Court")
    preset = COURTS.get(court.name) or LAB_SURFACES.get(court.name)
    if preset != court:
        return "given"
    return "assumption" if COURT_SOURCES[court.name].startswith("ASSUMPTION") else "sourced"


def court_row(court: Court, speed: float, angle: float, spin: float, ball) -> dict:
    """One row of :func:`court_table` (SI speeds, angles in degrees, spins in rpm).

    Parameters
    ----------
    court : Court
        The court.
    speed : float
        Ball speed before [m/s].
    angle : float
        Its angle above the court [rad].
    spin : float
        Its spin before [rad/s], topspin positive.
    ball : Ball
        The ball.
    """
    after = bounce(court, speed, angle, spin, ball)
    cpr, number = court_pace_rating(court, ball)
    return {
        "court": court.name,
        "friction": court.friction,
        "cor": court.cor,
        "source": source_word(court),
        "ball_speed_m_s": speed,
        "ball_angle_deg": round(math.degrees(angle), 9),
        "ball_topspin_rpm": spin / RPM,
        "speed_after_m_s": after.speed_after,
        "angle_after_deg": math.degrees(after.angle_after),
        "topspin_after_rpm": after.spin_after / RPM,
        "vx_ratio": after.vx_ratio,
        "e_y": after.e_y,
        "apparent_friction": after.apparent_friction,
        "contact_time_ms": 1e3 * after.contact_time,
        "contact": "slid" if after.slid_throughout else "gripped",
        "cpr": cpr,
        "category": number,
        "pace": PACE_NAMES[number],
    }


def court_table(
    courts=tuple(COURTS),
    speed: float = CPR_SPEED,
    angle: float = CPR_ANGLE,
    spin: float = 0.0,
    ball=None,
    unit: str = "m/s",
) -> pd.DataFrame:
    """A ball's bounce on each court and the court's ITF pace rating, one row per court.

    Parameters
    ----------
    courts : sequence of str or Court, optional
        Names of :data:`ball.court.COURTS` or :data:`ball.court.LAB_SURFACES`, or
        :class:`ball.court.Court` objects (one's own); default grass, clay and hard.
    speed : float, optional
        Ball speed before [m/s], in (0, 80]; default the ITF pace test's, 30 m/s.
    angle : float, optional
        Its angle above the court [rad], in (0, pi/2); default the test's, 16 degrees.
    spin : float, optional
        Its spin before [rad/s], topspin positive, backspin negative; default none.
    ball : Ball, optional
        The ball (of the bounce and of the pace test); None: the default preset's.
    unit : str, optional
        "m/s", "mph" or "km/h": the speeds also in this unit (``*_mph``, ``*_kmh``), the one
        the user typed.

    Returns
    -------
    DataFrame
        ``court`` (the name), its ``friction`` [-] and ``cor`` [-] and their ``source``
        ("sourced", "assumption" or "given"), the ball before: ``ball_speed_m_s``,
        ``ball_angle_deg``, ``ball_topspin_rpm``; the ball after: ``speed_after_m_s``,
        ``angle_after_deg`` (above the court), ``topspin_after_rpm`` (negative: backspin),
        ``vx_ratio`` (vx2/vx1), ``e_y`` (vy2/vy1), ``apparent_friction`` (as the ITF
        measures it), ``contact_time_ms``, ``contact`` ("slid": throughout; "gripped"); and
        the court's ITF Court Pace Rating ``cpr`` [-], its ``category`` (1 to 5) and its
        ``pace`` ("slow" to "fast").

    Examples
    --------
    >>> table = court_table(["grass", "clay"])
    >>> list(table["category"])
    [5, 1]
    """
    checked = _courts(courts)
    if ball is not None:
        ball = ball_argument(ball)
    choice("unit", unit, tuple(SPEED_UNITS))
    rows = [court_row(court, speed, angle, spin, ball) for court in checked]
    return speeds_in(pd.DataFrame(rows), unit, SPEED_COLUMNS)
