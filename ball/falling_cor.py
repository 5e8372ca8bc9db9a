"""The rigid-surface COR that falls as a ball is squashed harder: its floor, the law and its
parameters' check, shared by :class:`ball.laws.GrowingHysteresis` and
:class:`ball.stiffening.StiffeningHysteresis`.
"""

from __future__ import annotations

import numpy as np

from common.checks import finite, shown

COR_FLOOR = 0.1
"""Lowest rigid-surface COR a :class:`~ball.laws.GrowingHysteresis` ball reaches however hard it is
hit (an assumption: the calibrated range ends well above it, and results beyond that range
warn)."""


def falling_cor(e0: float, slope: float, x_max):
    """Rigid-surface COR max(e0 - slope X_max, COR_FLOOR) of a bounce compressing a ball by
    ``x_max`` [m]: the COR of :class:`~ball.laws.GrowingHysteresis` and
    :class:`~ball.stiffening.StiffeningHysteresis`.

    Parameters
    ----------
    e0 : float
        COR of a vanishingly slow bounce [-].
    slope : float
        Fall of the COR per metre of peak compression [1/m].
    x_max : float or array
        Largest compression [m].
    """
    return np.maximum(e0 - slope * np.asarray(x_max, dtype=float), COR_FLOOR)


def falling_cor_parameters(e0, slope) -> tuple[float, float]:
    """``e0`` in (COR_FLOOR, 1] and ``slope`` >= 0 [1/m] of :func:`falling_cor`, checked;
    ValueError naming the bad one otherwise.

    Parameters
    ----------
    e0, slope
        As in :func:`falling_cor`.
    """
    e0 = finite("e0", e0)
    if not COR_FLOOR < e0 <= 1.0:
        raise ValueError(f"e0 must be in ({COR_FLOOR:g}, 1], got {shown(e0)}")
    slope = finite("slope", slope, "1/m")
    if slope < 0:
        raise ValueError(f"slope must be >= 0 [1/m], got {shown(slope)}")
    return e0, slope
