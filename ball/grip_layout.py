"""The columns of :func:`ball.grip_kernel.grip_kernel`'s output, one row per impact (apart,
so that reading them loads no numba).
"""

(V_ALONG, V_ACROSS, W_ALONG, W_ACROSS, W_NORMAL, U_ALONG, U_ACROSS, P_ALONG, P_ACROSS,
 SLIP_LOSS, LAYER_LOSS, OFFSET_WORK, LAYER_ENERGY, SURFACE_ENERGY, GRIP_TIME, REVERSALS,
 LAYER_PEAK, ENERGY_IN, ENERGY_OUT, STIFFNESS_WORK) = range(20)  # fmt: skip
N_OUT = 20
"""Columns of the kernel's output, one row per impact."""
