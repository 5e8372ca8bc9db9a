"""Landmarks on a racket that players and coaches ask about: where the hand is, and the
centre of percussion.

The centre of percussion comes out of the simulation (:func:`percussion_centre`: the impact
point after which the hand's rigid-body velocity is zero); :func:`rigid_centre_of_percussion`
is the rigid-body formula, which the tests compare it with (they agree for a free racket; a
hand-held one differs, the hand pushing during the contact).  The sweet spots in one table:
:mod:`studies.face.sweetspots`.
"""

from __future__ import annotations

import numpy as np

from common.checks import finite, in_range
from racket import Racket
from racket.hand import Hand

HAND_FROM_BUTT = 0.5 * Hand.grip_length
"""Where the hand holds the racket [m from the butt]: the middle of the default hand's grip.
The model spreads the hand evenly over :attr:`racket.hand.Hand.grip_length` from the butt
(``racket.system``) and reads the handle there (:func:`racket.feel.hand_feel`); the mean of a
rigid-body velocity over an even grip is its value at the middle.  (Not the flex test's
handle support, ``racket.specs.stiffness.HANDLE_SUPPORT``, a testing machine's.)"""


HANDLE_REACH = 0.3
"""How far from the butt a hand may hold the racket [m]: the handle and throat (an
assumption, generous on purpose)."""


def hand_pivot(racket: Racket, hand_from_tip: float | None = None) -> float:
    """Where the hand pivots [m from the tip].

    Parameters
    ----------
    racket : Racket
        The racket (its length, and its hand's grip).
    hand_from_tip : float, optional
        The hand [m from the tip], on the handle: within :data:`HANDLE_REACH` of the butt;
        default the middle of ``racket.hand``'s grip (:data:`HAND_FROM_BUTT` from the butt
        for the default hand).
    """
    length = racket.beam.length
    if hand_from_tip is None:
        return length - 0.5 * racket.hand.grip_length
    return in_range("hand_from_tip", hand_from_tip, length - HANDLE_REACH, length, "m")


def rigid_centre_of_percussion(racket: Racket, pivot: float) -> float:
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
    rigid-body formula (:func:`rigid_centre_of_percussion`) is met to round-off.

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
