"""The time-stepper's inputs and outputs (:func:`racket.solver.kernel.run_impacts`): four named
tuples of arrays and numbers in, one out, the columns of the per-impact summary and the
rows of the histories.

Kept apart from the compiled kernel so that preparing its inputs and reading its results
needs no numba.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from ball.laws import GROWING, LINEAR, POWER, SINE, STIFFENING  # noqa: F401  (law codes)


class Frame(NamedTuple):
    """The racket's linear dynamics in real 2x2 blocks (:mod:`racket.system`), the same for
    every impact point.

    Attributes
    ----------
    blocks : ndarray (nb, 2, 2)
        The blocks: s' = blocks s (+ the force's input) [1/s].
    trans, g0, g1 : ndarray (nb, 2, 2)
        Exact step of each block [SI], s_next = trans s + g0 u_start + g1 u_end, for a block
        input u varying linearly over the step.
    metric : ndarray (nb, 2)
        sqrt(metric . s**2) bounds a block's future amplitude [SI].
    damp_blocks : ndarray (R, K) of int
        The K blocks of each row r that can be non-zero [-] (one for a free racket's diagonal
        damping).
    damp_rows : ndarray (R, K, 2)
        Dissipated power [W] = sum_r (sum_k damp_rows[r, k] . s[damp_blocks[r, k]])**2.
    """

    blocks: np.ndarray
    trans: np.ndarray
    g0: np.ndarray
    g1: np.ndarray
    metric: np.ndarray
    damp_blocks: np.ndarray
    damp_rows: np.ndarray


class Points(NamedTuple):
    """What differs between impacts: arrays whose first axis runs over them (P).

    Attributes
    ----------
    unit : ndarray (P, nb, 2)
        Each block's input from a unit contact force at the impact point [SI].
    out_d, out_v, out_dc : ndarray (P, nb, 2)
        Rows giving the impact point's displacement [m], velocity [m/s] and dc (rigid-body)
        velocity [m/s] from the block states.
    reach_w : ndarray (P, nb)
        Size of each block's share of the point's displacement [SI] (0 for dc).
    series : ndarray (P,)
        Compliance in series with the ball [m/N]: the string bed's, plus the residual
        flexibility of the bending (and torsion) modes left out (static correction).
    inv_ks : ndarray (P,)
        1 / string-bed stiffness at the impact point [m/N] (for the string deflection
        history).
    ball_velocity : ndarray (P,)
        Ball velocity at first touch [m/s], towards the racket positive.
    state0 : ndarray (P, nb, 2)
        Block states at first touch [SI] (a swung racket's rigid-body motion).
    x_o : ndarray (P,)
        The sine law's Xo [m] (ignored by the other laws).
    """

    unit: np.ndarray
    out_d: np.ndarray
    out_v: np.ndarray
    out_dc: np.ndarray
    reach_w: np.ndarray
    series: np.ndarray
    inv_ks: np.ndarray
    ball_velocity: np.ndarray
    state0: np.ndarray
    x_o: np.ndarray


class BallModel(NamedTuple):
    """The ball: its exact step as a free mass under a force varying linearly over the
    step (force -F on it), and its law (``law``, ``params`` from
    :attr:`ball.laws.MonotoneLaw.kernel_law`).

    Attributes
    ----------
    trans : ndarray (2, 2)
        Exact step of the ball's state (displacement [m], velocity [m/s]), as for a block.
    g0, g1 : ndarray (2,)
        Input of the force at the start and at the end of the step, as for a block [SI].
    law : int
        The law's code: LINEAR, POWER, SINE, GROWING or STIFFENING.
    params : ndarray (4,)
        The law's numbers [SI].
    bed : ndarray (3,)
        The string bed's law: its stretch [1/m^2], loss [-] and moving mass [kg]
        (:mod:`racket.solver.bed_kernel`, :mod:`racket.solver.bed_mass_kernel`; all 0 for the
        paper's linear, lossless, massless bed, in series with the ball).
    """

    trans: np.ndarray
    g0: np.ndarray
    g1: np.ndarray
    law: int
    params: np.ndarray
    bed: np.ndarray


class Controls(NamedTuple):
    """How to step.

    Attributes
    ----------
    dt : float
        Time step [s].
    max_steps : int
        Most steps in all.
    extra_steps : int
        Steps to go on after the ball has left for good.
    force_tol : float
        A sine-law contact approaching a common speed without a fold ends when its force
        has fallen to this fraction [-] of its peak and the relative speed to this fraction of
        the closing speed.
    cross_tol : float
        A sine-law ball closer than this times Xo [-] to its fold's maximum may cross the fold.
    stop_on_snap : bool
        Stop an impact at its first snap (an Xo search needs no more).
    record : bool
        Fill the histories (as far as they reach).
    """

    dt: float
    max_steps: int
    extra_steps: int
    force_tol: float
    cross_tol: float
    stop_on_snap: bool
    record: bool


class Outputs(NamedTuple):
    """Filled by the kernel: ball (P, 2) and block (P, nb, 2) states when the ball finally
    left, the summary (P, N_SUMMARY) and the histories (N_HISTORY, P, T) of the first T
    steps (if recorded).

    Attributes
    ----------
    ball : ndarray (P, 2)
        Ball state (displacement [m], velocity [m/s]) when the ball finally left.
    state : ndarray (P, nb, 2)
        Block states when the ball finally left [SI].
    summary : ndarray (P, N_SUMMARY)
        Per-impact summary, columns T_END, T_CONTACT, ... [SI].
    history : ndarray (N_HISTORY, P, T)
        Histories of the first T steps, rows H_FORCE, H_BALL_COMP, ... [SI].
    """

    ball: np.ndarray
    state: np.ndarray
    summary: np.ndarray
    history: np.ndarray


# Columns of the per-impact summary array.
(
    T_END,
    T_CONTACT,
    F_PEAK,
    SINE_WORK,
    DAMPING_LOSS,
    SNAPPED,
    ENDED,
    SNAP_RESIDUAL,
    X_END,
    RECONTACTS,
    BED_VEL,
    BED_ELASTIC,
    BED_PEAK,
) = range(13)
N_SUMMARY = 13
"""The summary's columns: when the ball left [s], the contact's duration [s], the largest
force [N], the unhappy ball's work [J], the damping's loss [J], whether it snapped, whether
it ended, the snap residual [m], the unhappy ball's compression at the end [m], the
re-contacts, and for a bed with a mass its velocity [m/s], the energy it would give back
(and the modes left out, pushed by it, would) [J] and its largest force [N] (0 for a
massless bed)."""

# Rows of the history array.
H_FORCE, H_BALL_COMP, H_STRING, H_BALL_VEL, H_POINT_VEL, H_POINT_VEL_DC, H_FRAME_FORCE = range(7)
N_HISTORY = 7
