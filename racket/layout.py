"""The layout of the time-stepper's inputs and outputs: ball-law codes, the columns of its
per-impact summary and the rows of its histories (:func:`racket.kernel.run_impacts`).

Kept apart from the compiled kernel so that reading results needs no numba.
"""

LINEAR, POWER, SINE = 0, 1, 2

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
) = range(10)
N_SUMMARY = 10

# Rows of the history array.
H_FORCE, H_BALL_COMP, H_STRING, H_BALL_VEL, H_POINT_VEL, H_POINT_VEL_DC = range(6)
N_HISTORY = 6
