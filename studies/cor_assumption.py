"""How the headline answers move with the one assumption of the real-ball presets: the ITF
type 2 ball's rigid-surface COR at 30 m/s (:data:`ball.catalog.COR_AT_30`, plausible range
:data:`ball.catalog.COR_AT_30_RANGE`).

Three answers a player reads, each computed with the type 2 ball recalibrated to each value
(:func:`ball.catalog.pressurised_law`; its COR at 7.06 m/s stays the middle of the ITF band):
the Pure Drive's serve at 100 mph racket-head speed (string centre, swung about the wrist),
e at the node of its fundamental at 40 m/s closing speed, and the serve's reduction with the
zero-COR twin (paper Sec. VIII).
"""

from __future__ import annotations

import numpy as np
import pandas as pd

from ball import Ball
from ball.catalog import (
    BALL_MASS,
    COR_AT_30,
    COR_AT_30_RANGE,
    RADIUS,
    TYPE_2_BANDS,
    pressurised_law,
)
from ball.falling_cor import COR_FLOOR
from common.checks import in_range
from common.units import MPH
from racket import CATALOG, impact
from studies.serve import serve_table

HEAD_SPEED_MPH = 100.0
"""Racket-head speed of the headline serve [mph]."""

NODE_SPEED = 40.0
"""Closing speed of the headline e at the node [m/s]."""


def cor_assumption_table(cors=(COR_AT_30_RANGE[0], COR_AT_30, COR_AT_30_RANGE[1])):
    """The headline answers for each assumed COR at 30 m/s (see the module docstring).

    Parameters
    ----------
    cors : sequence of float
        Values of the type 2 ball's rigid-surface COR at 30 m/s [-], each in [COR_FLOOR,
        0.745] (below the COR at 7.06 m/s).

    Returns
    -------
    DataFrame
        One row per value: ``cor_at_30``, ``serve_mph``, ``e_node_40``,
        ``zero_cor_reduction_percent``, and ``assumed`` (True for the project's value).
    """
    cors = np.atleast_1d(np.asarray(cors, dtype=float))
    if cors.size == 0 or cors.ndim != 1:
        raise ValueError(f"cors must be one or more CORs at 30 m/s, got {cors!r}")
    slow = 0.5 * sum(TYPE_2_BANDS.cor)  # the COR at 7.06 m/s: it must fall from there
    cors = [in_range("cor_at_30", c, COR_FLOOR, slow, hint=" (below the COR at 7.06 m/s)")
            for c in cors]  # fmt: skip
    racket = CATALOG["pure-drive-2021"].racket()
    nodes = racket.beam.modes.nodes(1)
    start, end = racket.strings.extent
    node = float(nodes[(nodes >= start) & (nodes <= end)][0])
    rows = []
    for cor in cors:
        ball = Ball(BALL_MASS, pressurised_law(TYPE_2_BANDS, RADIUS, cor), RADIUS)
        serve = serve_table(racket, ball, None, HEAD_SPEED_MPH * MPH, zero_cor=True)
        rows.append(
            {
                "cor_at_30": float(cor),
                "serve_mph": float(serve.loc["normal", "serve_simulated_m_s"]) / MPH,
                "e_node_40": float(impact(racket, ball, node, NODE_SPEED).e),
                "zero_cor_reduction_percent": float(
                    serve.loc["zero-COR", "reduction_simulated_percent"]
                ),
                "assumed": bool(cor == COR_AT_30),
            }
        )
    return pd.DataFrame(rows)
