"""The racket's motion when the ball has left, split into its dc and ac parts, and the
energy budget, compiled: one pass over the impacts instead of some sixty small numpy
operations per call (:func:`racket.solver.outcome.outcome` reads the columns).

The sums run in index order, so a number may differ from numpy's (pairwise sums, BLAS
products) in its last bit or two; they skip the terms that the basis or the stiffness makes
zero (:func:`_nonzero`: most of a free racket's), which leaves their bits as they were for
finite states (a state that is not finite gives NaN in e and the vibration either way, though
a mode's energy may now come out finite).
"""

from __future__ import annotations

import numpy as np
from numba import njit

# Columns of the per-impact result of :func:`split`.
V_CM, OMEGA, ROLL_RATE, V2_DC, V2_TOTAL, RACKET_ENERGY, VIBRATION = range(7)
ENERGY_INITIAL, BALL_ENERGY, E, E_A, E_VAN_ZANDT, CLOSING_ENERGY, STRING_VIBRATION = range(7, 14)
N_COLUMNS = 14


@njit(cache=True)
def _dot(row, state):
    """The row (2 nb) over the block states (nb, 2), summed in the blocks' order."""
    total = 0.0
    for k in range(state.shape[0]):
        total += row[2 * k] * state[k, 0] + row[2 * k + 1] * state[k, 1]
    return total


@njit(cache=True)
def _nonzero(matrix, width):
    """Where each row of ``matrix`` (R, K width) has a group of ``width`` numbers not all
    zero: their group indices k, first in each row of a (R, K) table, and how many (R,).  A
    sum of products over a row skips the other groups and keeps its bits: their products are
    zeros (the states are finite), and the running sum starts at +0.0 and, rounding to
    nearest, never becomes -0.0, so adding a zero of either sign changes nothing.  A free
    racket's basis has one group a row, its stiffness one term a column.
    """
    groups = matrix.shape[1] // width
    index = np.zeros((matrix.shape[0], groups), dtype=np.int64)
    count = np.zeros(matrix.shape[0], dtype=np.int64)
    for r in range(matrix.shape[0]):
        for k in range(groups):
            for g in range(width):
                if matrix[r, width * k + g] != 0.0:
                    index[r, count[r]] = k
                    count[r] += 1
                    break
    return index, count


@njit(cache=True)
def split(state, basis, stiffness, rigid_rows, phi, x, y, frame, omega, ball, swing_qd, bed, out,
          modes):  # fmt: skip
    """Fill ``out`` (P, N_COLUMNS) and ``modes`` (P, n_bending) from the block states.

    A string bed with a mass (``bed``) is part of the racket: the dc motion is the frame's
    and the bed mass's together, as one rigid body once the bed's own vibration has died
    (their momenta kept), and what the bed holds beyond moving with it (its kinetic and
    elastic energy, less its share of the one body's) is the strings' vibration.

    Parameters
    ----------
    state : ndarray (P, nb, 2)
        Block states when the ball left; z = (q, q') = basis s.
    basis : ndarray (2N, 2 nb)
        :attr:`racket.system.BlockSystem.basis`.
    stiffness : ndarray (N, N)
        W (+ the hand's K_h) in modal coordinates [1/s**2].
    rigid_rows : ndarray (R, 2 nb)
        Rows over the block states giving the velocities of the rigid-body coordinates'
        dc motion: translation, rotation (and roll)
        (:meth:`racket.system.BlockSystem.rigid_rows`).
    phi : ndarray (P, N)
        Mode shapes at the impact points [1/sqrt(kg)].
    x, y : ndarray (P,)
        Impact points [m from the tip] and offsets [m] (0 on the axis).
    frame : ndarray (6,)
        Centre of mass [m from the tip], sqrt(mass) [sqrt(kg)], sqrt(I_cm), sqrt(I_roll)
        [sqrt(kg) m] (0: no roll), the number of coordinates up to the last bending mode
        whose energy goes into ``modes`` (the first two, rigid, left out), and the ball's
        mass [kg].
    omega : ndarray (N,)
        Free-free angular frequencies [rad/s] of the modes.
    ball : ndarray (P, 3)
        The ball's velocity after (towards the strings) [m/s], the closing speed [m/s] and
        the ball's speed before [m/s].
    swing_qd : ndarray (P, 2)
        Rigid-mode velocities of the swing before the impact [sqrt(kg) m/s].
    bed : ndarray (P, 4)
        The bed's moving mass [kg] (0: massless), its velocity when the ball left [m/s],
        the energy it would then give back [J] and its velocity before the impact [m/s].
    out, modes : ndarray
        Filled: the columns V_CM ... STRING_VIBRATION [SI], each bending mode's energy [J].
    """
    n = stiffness.shape[0]
    count = state.shape[0]
    z = np.empty(2 * n)
    kq = np.empty(n)
    pairs, pair_count = _nonzero(basis, 2)  # (each block's pair of numbers a group)
    terms, term_count = _nonzero(stiffness.T, 1)
    com, root_mass, root_inertia, root_roll = frame[0], frame[1], frame[2], frame[3]
    bending, mass = int(frame[4]), frame[5]
    for p in range(count):
        for r in range(2 * n):
            total = 0.0
            for j in range(pair_count[r]):
                k = pairs[r, j]
                total += basis[r, 2 * k] * state[p, k, 0] + basis[r, 2 * k + 1] * state[p, k, 1]
            z[r] = total
        rigid0 = _dot(rigid_rows[0], state[p]) if n else 0.0
        rigid1 = _dot(rigid_rows[1], state[p]) if n else 0.0
        v_cm = rigid0 / root_mass
        spin = rigid1 / root_inertia
        v2_dc = v_cm + (com - x[p]) * spin
        roll_rate = 0.0
        racket_energy = rigid0 * rigid0 + rigid1 * rigid1
        if root_roll > 0.0 and n:  # the roll: y times its angular velocity
            rigid2 = _dot(rigid_rows[2], state[p])
            roll_rate = rigid2 / root_roll
            v2_dc = v2_dc + y[p] * roll_rate
            racket_energy += rigid2 * rigid2
        racket_energy *= 0.5
        frame_energy = racket_energy  # the frame's rigid-body energy
        m_s, bed_vel = bed[p, 0], bed[p, 1]
        if m_s > 0.0 and n:  # frame and bed as one body: their momenta kept
            lever = com - x[p]
            inverse = 1.0 / root_mass**2 + lever * lever / root_inertia**2
            if root_roll > 0.0:
                inverse += y[p] * y[p] / root_roll**2
            share = m_s * inverse
            v2_dc = (v2_dc + share * bed_vel) / (1.0 + share)
            pull = m_s * (v2_dc - bed_vel)
            v_cm -= pull / root_mass**2
            spin -= pull * lever / root_inertia**2
            if root_roll > 0.0:
                roll_rate -= pull * y[p] / root_roll**2
            racket_energy = 0.5 * (
                (root_mass * v_cm) ** 2 + (root_inertia * spin) ** 2
                + (root_roll * roll_rate) ** 2 + m_s * v2_dc * v2_dc
            )  # fmt: skip
        v2_total, mechanical = 0.0, 0.0
        for i in range(n):
            total = 0.0
            for j in range(term_count[i]):
                k = terms[i, j]
                total += z[k] * stiffness[k, i]
            kq[i] = total
        for i in range(n):
            v2_total += phi[p, i] * z[n + i]
            mechanical += z[n + i] * z[n + i] + kq[i] * z[i]
        for i in range(2, bending):
            modes[p, i - 2] = 0.5 * (z[n + i] ** 2 + (omega[i] * z[i]) ** 2)
        after, closing, speed = ball[p, 0], ball[p, 1], ball[p, 2]
        swing = swing_qd[p, 0] ** 2 + swing_qd[p, 1] ** 2
        row = out[p]
        row[V_CM], row[OMEGA], row[ROLL_RATE] = v_cm, spin, roll_rate
        row[V2_DC], row[V2_TOTAL] = v2_dc, v2_total
        row[RACKET_ENERGY] = racket_energy
        bed_energy = 0.5 * m_s * bed_vel * bed_vel + bed[p, 2]
        row[VIBRATION] = 0.5 * mechanical - frame_energy
        row[STRING_VIBRATION] = frame_energy + bed_energy - racket_energy
        row[ENERGY_INITIAL] = 0.5 * mass * speed**2 + 0.5 * swing + 0.5 * m_s * bed[p, 3] ** 2
        row[BALL_ENERGY] = 0.5 * mass * after**2
        row[E] = (v2_dc - after) / closing
        row[E_A] = (-after - (closing - speed)) / closing  # (V1 - v2) / (v1 + v2)
        row[E_VAN_ZANDT] = (v2_total - after) / closing
        row[CLOSING_ENERGY] = 0.5 * mass * closing**2
