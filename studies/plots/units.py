"""Speeds on a plot in the unit the user typed (m/s, mph or km/h)."""

from __future__ import annotations

from common.units import SPEED_UNITS


def speed_scale(unit: str) -> float:
    """The size [m/s] of the speed unit ``unit``, one of :data:`common.units.SPEED_UNITS`
    (divide a speed in m/s by it to show it in ``unit``).
    """
    if unit not in SPEED_UNITS:
        raise ValueError(f"unit must be one of {', '.join(SPEED_UNITS)}, got {unit!r}")
    return SPEED_UNITS[unit]
