"""The lockstep kernel's test that a contact has ended (:mod:`racket.solver.lockstep`): the
tile's open contacts in one pass a step, with the same numbers as
:func:`racket.solver.kernel._one_impact`.

The test runs every step of every open contact until it passes, some 25-40 steps an impact
after the ball leaves (a tenth of a sweep's steps).  Impact by impact, each call passed the
points' arrays and the tile's, it cost some 45 of numba's atomic reference counts an impact
and step, on arrays both threads' tiles share: a fifth of the paper racket's kernel time
(counted with gdb, sampled with perf).  One pass over the tile that calls nothing
(:func:`watch_tile`) has them cancelled at compile time.  What depends on the ball's largest
force alone, the compression at which the contact closes again, is kept per impact in the
tile's rows ``Z_REST`` and ``Z_REST_FOR`` and made again (:func:`rest`, called from the tile
for that impact alone) only when that force has changed.
"""

from __future__ import annotations

import math

from numba import njit

from racket.solver import tile_layout as tl
from racket.solver.ball_kernel import ball_compression
from racket.solver.bed_mass_kernel import _remember, gap_from
from racket.solver.contact_kernel import contact_compression


@njit(cache=True)
def rest(law, params, bed, massed, inv_ks, v, flags, memo, i):
    """Slot ``i``'s compression at which its contact closes again, made for the ball's
    largest force: the ball's alone on a bed with a mass (``massed``;
    :func:`racket.solver.bed_mass_kernel.bed_gap`, which adds the bed's own reach each
    step), else the ball's and the bed's (:func:`racket.solver.contact_kernel.
    contact_compression`); with a bed mass, its memo made for the bed's largest force, as
    :func:`racket.solver.bed_mass_kernel.bed_elastic` makes it.
    """
    f_peak = v[tl.F_PEAK_, i]
    if v[tl.Z_REST_FOR, i] != f_peak:
        if massed:
            v[tl.Z_REST, i] = ball_compression(law, params, 0.0, f_peak)
        else:
            p = flags[tl.IMPACT, i]
            v[tl.Z_REST, i] = contact_compression(law, params, bed, inv_ks[p], 0.0, f_peak)
        v[tl.Z_REST_FOR, i] = f_peak
    if massed and memo[0, i] != v[tl.F2_PEAK, i]:
        _remember(v[tl.K_BED, i], bed[0], bed[1], v[tl.F2_PEAK, i], memo, i)


@njit(cache=True, error_model="numpy")
def watch_tile(massed, sine, s, mass, out_dc, out_d, out_v, reach_w, series, inv_ks, metric, s0,
               s1, v, flags, memo, step, extra_steps, n):  # fmt: skip
    """The tile's contacts open after ``step`` and not yet over (after
    :func:`racket.solver.lockstep_slot.after_step`) over for good, their STOP_AT
    ``extra_steps`` on, once each separates in the dc motion and its gap exceeds the largest
    deflection the remaining vibration can bring to the point, as
    :func:`racket.solver.kernel._one_impact` (the points' rows read in place at the impact's
    row: ``out_dc``, ``out_d``, ``out_v``, ``reach_w``, ``series`` and ``inv_ks`` of
    :class:`racket.solver.layout.Points`, ``metric`` the frame's; ``s0`` and ``s1`` the
    tile's block states; the bed's stretch ``s`` [1/m^2] and moving ``mass`` [kg]).  The
    compression at which a contact closes again is :func:`rest`'s, made first (the unhappy
    ball's, ``sine``, its own; one not made for the ball's largest force never ends a watch,
    so that a missed remaking shows as an impact that runs to its last step); the pass calls
    nothing with an array (:func:`racket.solver.bed_mass_kernel.gap_from` takes numbers), so numba
    cancels its arrays' reference counts.  Its error model is numpy's, as
    the lockstep passes' (a division by zero gives inf, not an exception; the divisors here
    are a stiffness and a largest force, both positive).
    """
    nb = s0.shape[0]
    for i in range(n):
        if flags[tl.DONE, i] != 0 or flags[tl.STOP_AT, i] >= 0 or v[tl.FORCE, i] != 0.0:
            continue
        p = flags[tl.IMPACT, i]
        dc = 0.0
        for j in range(nb):
            dc += out_dc[p, j, 0] * s0[j, i] + out_dc[p, j, 1] * s1[j, i]
        if not dc > v[tl.UD, i]:
            continue
        if not sine and v[tl.Z_REST_FOR, i] != v[tl.F_PEAK_, i]:
            continue  # (a rest not made for this peak never ends the watch: see rest)
        z_open = v[tl.X_BALL, i] if sine else v[tl.Z_REST, i]
        if massed:  # bed_gap, from the memo made for the bed's peak (rest)
            point_v = 0.0
            for j in range(nb):
                point_v += out_v[p, j, 0] * s0[j, i] + out_v[p, j, 1] * s1[j, i]
            z_open = gap_from(z_open, s, mass, v[tl.K_BED, i], series[p] - inv_ks[p],
                              memo[3, i], memo[2, i], v[tl.F2, i], v[tl.F2_PEAK, i],
                              v[tl.QD, i] - point_v)  # fmt: skip
        d = 0.0
        for j in range(nb):
            d += out_d[p, j, 0] * s0[j, i] + out_d[p, j, 1] * s1[j, i]
        gap = z_open - (v[tl.U, i] - d)
        reach = 0.0  # as kernel._reach, ended where it passes the gap
        for j in range(reach_w.shape[1]):
            if reach_w[p, j] > 0.0:
                reach += reach_w[p, j] * math.sqrt(
                    metric[j, 0] * s0[j, i] ** 2 + metric[j, 1] * s1[j, i] ** 2
                )
                if reach > gap:
                    break
        if gap >= reach:
            flags[tl.STOP_AT, i] = step + extra_steps
