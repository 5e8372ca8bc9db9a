"""A ball's bounce on a rigid surface against impact speed (``racket-impact ball``), beside
what the ITF rules require of it.

The ITF's rebound test drops the ball from 254 cm (100 in) onto concrete; a type 2 (medium)
ball must rebound 135-147 cm (ITF Rules of Tennis, Appendix I, as tabulated by Tennis
Warehouse University, "Tennis Ball Performance Testing", C. Lindsey 2021, and by R. Cross and
C. Lindsey, "Ball Testing", Tennis Industry magazine, July 2007).  With e = sqrt(rebound /
drop), that is a COR of 0.729-0.761 at the drop's impact speed, sqrt(2 g 2.54 m) = 7.06 m/s
(air drag neglected).
"""

from __future__ import annotations

import math

import numpy as np
import pandas as pd

from ball import WALL, Ball, collide
from common.checks import shown
from common.checks import speed as check_speed

ITF_DROP_M = 2.54
"""Drop height of the ITF rebound test [m] (100 in; ITF Rules of Tennis, Appendix I)."""

ITF_TYPE2_REBOUND_M = (1.35, 1.47)
"""Rebound a type 2 ball must reach from ITF_DROP_M [m] (ITF Rules of Tennis, Appendix I)."""

GRAVITY = 9.80665
"""Standard gravity [m/s^2] (the 8.165 kg ITF deformation load is 80.07 N with it)."""

ITF_DROP_SPEED = math.sqrt(2.0 * GRAVITY * ITF_DROP_M)
"""Impact speed of the ITF rebound test [m/s] (7.06, air drag neglected)."""

ITF_TYPE2_COR = tuple(math.sqrt(h / ITF_DROP_M) for h in ITF_TYPE2_REBOUND_M)
"""The rigid-surface COR band those rebounds mean at ITF_DROP_SPEED (0.729-0.761)."""

DEFAULT_SPEEDS = (ITF_DROP_SPEED, 10.0, 15.0, 20.0, 25.0, 30.0, 40.0, 50.0)
"""Impact speeds [m/s] of the default table: the ITF drop, then groundstroke to serve."""


def rigid_bounce_table(ball: Ball, speeds=DEFAULT_SPEEDS) -> pd.DataFrame:
    """The ball's head-on bounce on a rigid surface at each speed, simulated (``collide``).

    Parameters
    ----------
    ball : Ball
        Any ball.
    speeds : float or sequence of float
        Impact speeds [m/s], one or more, each in [0.001, 300].

    Returns
    -------
    DataFrame
        Columns ``speed_m_s``, ``e`` (rebound speed / impact speed), ``contact_time_s``,
        ``peak_force_N`` and ``peak_compression_m``.
    """
    if np.size(speeds) == 0 or np.ndim(speeds) > 1:
        raise ValueError(f"speeds must be one speed or a list of them [m/s], got {shown(speeds)}")
    speeds = [check_speed("speed", v) for v in np.atleast_1d(speeds)]
    rows = []
    for v in speeds:
        c = collide(ball, WALL, v)
        rows.append(
            {
                "speed_m_s": v,
                "e": c.e,
                "contact_time_s": c.contact_time,
                "peak_force_N": c.peak_force,
                "peak_compression_m": float(np.max(c.history.compression_a)),
            }
        )
    return pd.DataFrame(rows)
