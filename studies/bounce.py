"""A ball's bounce on a rigid surface against impact speed (``racket-impact ball``), beside
what is measured of it: the ITF's bands of its type, and the ITF's static deformation test,
reported apart (a quasi-static test of a viscoelastic ball, see :mod:`ball.catalog`).

The ITF's rebound test drops the ball from 254 cm (100 in) onto concrete; a type 2 (medium)
ball must rebound 135-147 cm (ITF Rules of Tennis, Appendix I, as tabulated by Tennis
Warehouse University, "Tennis Ball Performance Testing", C. Lindsey 2021, and by R. Cross and
C. Lindsey, "Ball Testing", Tennis Industry magazine, July 2007).  With e = sqrt(rebound /
drop), that is a COR of 0.729-0.761 at the drop's impact speed, sqrt(2 g 2.54 m) = 7.06 m/s
(air drag neglected).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from ball import BALL_PRESETS, WALL, Ball, MonotoneLaw, collide
from ball.catalog import BALL_MASS, ITF_DROP_SPEED, ITF_FORCE
from ball.collision import largest_closing_speed, too_fast_to_store
from common.checks import shown
from common.checks import speed as check_speed
from common.typechecks import instance

if TYPE_CHECKING:
    import pandas as pd

DEFAULT_SPEEDS = (ITF_DROP_SPEED, 10.0, 15.0, 20.0, 25.0, 30.0, 40.0, 50.0, 60.0, 70.0)
"""Impact speeds [m/s] of the default table: the ITF drop, then groundstroke to serve and
beyond (the fastest serves reach about 73 m/s, 163 mph)."""


def preset_table() -> pd.DataFrame:
    """The real-ball presets (:data:`ball.BALL_PRESETS`): what each is, its law's numbers,
    its ITF bands and where each number comes from.

    Returns
    -------
    DataFrame
        One row per preset: ``preset``, ``description``, ``mass_g``, ``diameter_cm``, the
        law's ``k_N_m``, ``e0``, ``slope_per_m``, the ITF band of the COR at 7.06 m/s
        (``itf_cor_low``, ``itf_cor_high``; empty for a ball no type admits) and
        ``sources``.
    """
    import pandas as pd

    rows = []
    for name, preset in BALL_PRESETS.items():
        law = preset.build()
        band = preset.bands.cor if preset.bands else (np.nan, np.nan)
        rows.append(
            {
                "preset": name,
                "description": preset.description,
                "mass_g": 1e3 * BALL_MASS,
                "diameter_cm": 200.0 * preset.radius,
                "k_N_m": law.k,
                "e0": law.e0,
                "slope_per_m": law.slope,
                "itf_cor_low": band[0],
                "itf_cor_high": band[1],
                "sources": "; ".join(preset.sources),
            }
        )
    return pd.DataFrame(rows)


def static_test(ball: Ball, preset: str | None = None) -> dict:
    """The ITF's static deformation test beside the ball's dynamic law: the law's compression
    under 80.07 N, and the ITF's forward-deformation band of the preset's type.

    Parameters
    ----------
    ball : Ball
        The ball (its law's loading curve gives the dynamic compression).
    preset : str, optional
        Its preset's name (:data:`ball.BALL_PRESETS`), for the ITF band; None: none.

    Returns
    -------
    dict
        ``force_N``; ``dynamic_compression_m`` (None for a law without a loading curve in
        the force domain); ``itf_forward_m`` (low, high) or None.
    """
    law = ball.law
    monotone = isinstance(law, MonotoneLaw)
    dynamic = float(law.compression(ITF_FORCE, ITF_FORCE)) if monotone else None
    entry = BALL_PRESETS.get(preset) if preset else None
    bands = entry.bands if entry else None
    forward = tuple(0.01 * d for d in bands.forward_deformation_cm) if bands else None
    return {"force_N": ITF_FORCE, "dynamic_compression_m": dynamic, "itf_forward_m": forward}


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
    import pandas as pd

    ball = instance("ball", ball, Ball, "a ball.Ball")
    if np.size(speeds) == 0 or np.ndim(speeds) > 1:
        raise ValueError(f"speeds must be one speed or a list of them [m/s], got {shown(speeds)}")
    speeds = [check_speed("speed", v) for v in np.atleast_1d(speeds)]
    fastest = largest_closing_speed(ball, WALL)
    for v in speeds:
        if v > fastest:  # named as given, not as collide's v_a
            raise too_fast_to_store("speeds", v, fastest)
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
