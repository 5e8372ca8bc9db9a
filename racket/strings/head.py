"""The racket's head seen face-on: the elliptical string bed, the frame hoop around it, and
the clock positions players use to place lead tape.

Coordinates: x along the long axis [m from the tip], y across it in the string plane [m from
the long axis], + towards 3 o'clock (the right-hand side of the face seen with the tip up).
"""

from __future__ import annotations

import re
from dataclasses import dataclass

import numpy as np

from common.checks import positive

HEAD_ASPECT = 1.33
"""Length / width of the elliptical string bed.  A 100 in^2 head of a 27 in racket is about
13.5 in long and 10 in wide (ITF Rules of Tennis, Appendix I, limit the strung surface to
15.5 x 11.5 in; modern mid-plus heads sit near 13.5 x 10)."""

_CLOCK = re.compile(r"^\s*(\d{1,2})\s*(?:(?:and|&|/|,)\s*(\d{1,2})\s*)?$")


@dataclass(frozen=True)
class Hoop:
    """The frame's centre line around the head: an ellipse through the racket's tip.

    Parameters
    ----------
    center : float
        Centre of the ellipse [m from the tip]; also its semi-axis along the racket.
    half_width : float
        Semi-axis across the racket [m].
    """

    center: float
    half_width: float

    def __post_init__(self):
        positive("hoop center", self.center, "m from the tip")
        positive("hoop half_width", self.half_width, "m")

    def at_angle(self, angle) -> tuple[np.ndarray, np.ndarray]:
        """Points (x [m from the tip], y [m]) of the hoop seen from its centre at the polar
        ``angle`` [rad], measured clockwise from 12 o'clock (the tip) on the face.

        Parameters
        ----------
        angle : float or array_like
            Polar angle [rad], clockwise from 12 o'clock (the tip).
        """
        angle = np.asarray(angle, dtype=float)
        a, b = self.center, self.half_width
        r = a * b / np.hypot(b * np.cos(angle), a * np.sin(angle))
        # On the long axis (12 and 6 o'clock) y is 0 exactly, not sin(pi)'s 1e-17 m round-off:
        # a point mass there keeps the racket symmetric about its long axis.
        across = np.where(np.isclose(np.sin(angle), 0.0, rtol=0.0, atol=1e-12), 0.0, np.sin(angle))
        return a - r * np.cos(angle), r * across

    def clock(self, at: str) -> tuple[np.ndarray, np.ndarray]:
        """Where lead tape placed at clock position ``at`` sits on the hoop: (x, y) arrays,
        one point per side.

        ``at`` is ``"12"`` (the tip), ``"6"`` (the bottom of the head, at the throat), or a
        mirrored pair ``"H and K"`` with H + K = 12 (``"3 and 9"``, ``"2 and 10"``, ...); the
        hours are the directions of a clock face laid over the head, from its centre.  One
        side alone (``"3"``) is refused: the model is symmetric about the long axis.

        Parameters
        ----------
        at : str
            The clock position: ``"12"``, ``"6"`` or a mirrored pair such as ``"3 and 9"``.
        """
        match = _CLOCK.match(at) if isinstance(at, str) else None
        hours = [int(h) for h in match.groups() if h is not None] if match else []
        valid = "'12', '6' or a mirrored pair such as '3 and 9', '2 and 10', '1 and 11'"
        if not hours or any(not 1 <= h <= 12 for h in hours):
            raise ValueError(f"at must be a clock position, {valid}; got {at!r}")
        if len(hours) == 1 and hours[0] not in (6, 12):
            raise ValueError(
                f"at {at!r} puts lead on one side only; give both sides, "
                f"'{hours[0]} and {12 - hours[0]}' (the racket model is symmetric about its "
                f"long axis)"
            )
        if len(hours) == 2 and (hours[0] + hours[1] != 12 or hours[0] == 6):
            raise ValueError(f"at must be {valid}: {at!r} is not a mirrored pair")
        return self.at_angle(np.radians(30.0 * (np.array(hours) % 12)))


def ellipse_axes(area: float, aspect: float = HEAD_ASPECT) -> tuple[float, float]:
    """Semi-axes (along, across) [m] of an ellipse of ``area`` [m^2] and length / width
    ``aspect``.

    Parameters
    ----------
    area : float
        Area of the ellipse [m^2].
    aspect : float, optional
        Length / width of the ellipse [-].
    """
    along = np.sqrt(area * aspect / np.pi)
    return float(along), float(along / aspect)
