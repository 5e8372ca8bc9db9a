"""The racket's rigid-body motion in the plane of its strings (issue 36): how a point of the
string bed moves under a force along the face.

A force in the string plane, which holds the frame's centre line and its centre of mass,
moves the racket in that plane only: it translates and turns about the face's normal, with
the moment of inertia I_z = I_cm + I_roll (the swing's, about the centre of mass, and the
twist's).  It neither bends nor twists the frame.  **Left out**: the frame's bending in its
own plane (the head and the shaft are stiffer that way than out of the plane, and no
in-plane frequency was found to build a modal model on), taken as rigid.  Its possible
weight is bounded: the ball's tangential effective mass, m / (1 + m R^2 / I) = 20 g, is
small against the racket's in-plane effective mass at the strings (0.1-0.3 kg), so that the
racket's whole in-plane motion changes the spin by about 10 % (free against clamped,
``tests/test_oblique.py``), and a flexibility could only move a part of that.

The hand (hand-held): its mass sits at the middle of the grip, joined rigidly in the plane
(**an assumption**: its springs are stiff enough out of the plane, 10 ms and more, to be
taken so for a 4-5 ms pull; an infinite mass pins the grip).  A clamped head does not move.
"""

from __future__ import annotations

import math

import numpy as np


def inverse_mass(racket, x, y=0.0) -> np.ndarray:
    """The in-plane inverse mass W [1/kg] of the impact points: a force F (along, across) on
    the strings at a point changes its velocity by W F per unit impulse.

    Parameters
    ----------
    racket : Racket
        The racket (its support decides: free, hand-held or clamped-head).
    x : float or array_like
        Impact points [m from the tip].
    y : float or array_like, optional
        Their offsets from the long axis [m].

    Returns
    -------
    ndarray
        (n, 2, 2), axes (along the long axis towards the tip, across towards 3 o'clock).
    """
    x, y = np.broadcast_arrays(np.atleast_1d(np.asarray(x, float)), np.asarray(y, float))
    out = np.zeros((x.size, 2, 2))
    if racket.support == "clamped-head":
        return out
    beam = racket.beam
    mass, centre = beam.mass, beam.center_of_mass
    inertia = beam.inertia_cm + (beam.roll_inertia or 0.0)
    if racket.support == "hand-held":
        grip = beam.length - 0.5 * racket.hand.grip_length
        hand = racket.hand.mass
        if math.isinf(hand):  # the grip pinned: the racket turns about it
            a = grip - x
            inertia += mass * (centre - grip) ** 2
            out[:, 0, 0] = y * y / inertia
            out[:, 0, 1] = out[:, 1, 0] = -a * y / inertia
            out[:, 1, 1] = a * a / inertia
            return out
        joined = mass + hand
        moved = (mass * centre + hand * grip) / joined
        inertia += mass * (centre - moved) ** 2 + hand * (grip - moved) ** 2
        mass, centre = joined, moved
    a = centre - x
    out[:, 0, 0] = 1.0 / mass + y * y / inertia
    out[:, 0, 1] = out[:, 1, 0] = -a * y / inertia
    out[:, 1, 1] = 1.0 / mass + a * a / inertia
    return out
