"""Where the lockstep kernel keeps a tile's impacts (:mod:`racket.solver.lockstep`): how
many at most, and the rows of its per-impact scalars, integers and per-block arrays.
"""

from __future__ import annotations

TILE = 64
"""Impacts advanced together, at most: their per-block arrays (8 of nb x TILE) stay in the
L1 and L2 caches, and a pass over them is long enough to pay for its start (on the paper
racket 16 took a third longer than 64; 32 and 128 no less time than 64)."""

# Rows of the per-impact scalars (``v`` in :func:`_tile`).
(
    U, UD, FORCE, F_BEFORE, F_PEAK_, A, C0, C1, C2, X_O, X_BALL, RESIDUAL, DAMPING, WORK,
    POWER_PREV, CLOSING, TAU, U_P, UD_P, Z, F_NEW, POWER, ROW, NEED,
    Q, QD, F2, F2_NEW, F2_PEAK, COMP, C1_0, C1_1, C1_2, A1, F2_BEFORE, K_BED, Z_REST, Z_REST_FOR,
) = range(38)  # fmt: skip
N_SCALARS = 38
# (Q ... K_BED: a bed with a mass, racket.solver.bed_mass_kernel: its displacement and
# velocity, its force at the step's start and end, its largest, the compliance in series
# with it, the ball's force coefficients and compliance beside the bed's mass, its force
# a step before, and its stiffness at the point; Z_REST the compression at which an open
# contact closes again, made for the ball's largest force Z_REST_FOR:
# racket.solver.lockstep_watch.)

# Rows of the per-impact integers (``flags``).
IMPACT, STOP_AT, RECONTACT, SNAP, DONE = range(5)
N_FLAGS = 5

# Rows of the per-block arrays (``w``, nb x TILE each).
S0, S1, GIN0_0, GIN0_1, GIN1_0, GIN1_1, OUT_D0, OUT_D1 = range(8)
N_ROWS = 8
