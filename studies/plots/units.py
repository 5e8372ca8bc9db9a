"""Speeds on a plot in the unit the user typed (m/s, mph or km/h)."""

from __future__ import annotations

from common.units import SPEED_UNITS


def speed_scale(unit: str) -> float:
    """The size [m/s] of a speed unit (divide a speed in m/s by it to show it in that unit).

    Parameters
    ----------
    unit : str
        One of :data:`common.units.SPEED_UNITS`: "m/s", "mph" or "km/h".
    """
    if unit not in SPEED_UNITS:
        raise ValueError(f"unit must be one of {', '.join(SPEED_UNITS)}, got {unit!r}")
    return SPEED_UNITS[unit]
