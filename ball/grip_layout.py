"""The columns of :func:`ball.grip_kernel.grip_kernel`'s output, one row per impact (apart,
so that reading them loads no numba).
"""

(V_ALONG, V_ACROSS, W_ALONG, W_ACROSS, W_NORMAL, U_ALONG, U_ACROSS, P_ALONG, P_ACROSS,
 SLIP_LOSS, LAYER_LOSS, OFFSET_WORK, LAYER_ENERGY, SURFACE_ENERGY, GRIP_TIME, REVERSALS,
 LAYER_PEAK, ENERGY_IN, ENERGY_OUT, STIFFNESS_WORK) = range(20)  # fmt: skip
N_OUT = 20
"""Columns of the kernel's output, one row per impact."""

# the woven layer's row: stiffness and mass of its strings that move along (2 columns from
# LAYER_STIFFNESS and LAYER_MASS: along, across), static and kinetic friction, the ball's
# force's share pressing the crossings, their preload [N], and the ball's grip's share on
# the strings that move across
LAYER_STIFFNESS, LAYER_MASS, LAYER_STATIC, LAYER_KINETIC = 0, 2, 4, 5
LAYER_PRESS, LAYER_PRELOAD, LAYER_SHARE = 6, 7, 8
N_LAYER = 9
"""Columns of the kernel's layer rows, one row per impact."""
