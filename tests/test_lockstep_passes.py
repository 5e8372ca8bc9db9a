"""The lockstep kernel's shortcuts decide and sum as the passes they replace, to the bit:
the dissipated power folded into the blocks' response (racket.solver.lockstep), the reach of
the remaining vibration ended where it passes the gap (racket.solver.kernel._reach,
racket.solver.lockstep_watch), and the test that an open contact is over in one pass over the
tile (racket.solver.lockstep_watch) against the scalar kernel's functions."""

import numpy as np
import pytest

import racket
from racket.solver import lockstep
from racket.solver import lockstep_watch as watch
from racket.solver import tile_layout as tl
from racket.solver.bed_mass_kernel import BED_MEMO_ROWS, bed_gap
from racket.solver.contact_kernel import MEMO_ROWS, contact_compression
from racket.solver.kernel import _dot, _reach, damping_diagonal
from racket.solver.stepper import Stepper


def _frame(model):
    x = np.linspace(*model.strings.extent, 3)
    return Stepper(model, racket.paper_ball(), x, None, np.full(3, 10.0), 0.0, None, 300).frame


@pytest.mark.parametrize("model", [racket.paper_racket(), racket.default_racket()])
def test_the_power_folded_into_the_response_has_the_separate_passes_bits(model):
    frame = _frame(model)
    blocks, rows = frame.damp_blocks, frame.damp_rows
    assert damping_diagonal(blocks)  # a free racket's modal damping
    rng = np.random.default_rng(7)
    nb, n = frame.trans.shape[0], 64
    s0, s1 = rng.normal(size=(nb, n)), rng.normal(size=(nb, n)) * 1e3
    gin1_0, gin1_1 = rng.normal(size=(nb, n)) * 1e-6, rng.normal(size=(nb, n)) * 1e-3
    f_new = np.abs(rng.normal(size=n)) * 1e3
    a0, a1, power_a, row = s0.copy(), s1.copy(), np.full(n, np.nan), np.empty(n)
    shapes, out_d0 = np.empty((nb, 4)), np.empty((nb, n))  # (the stored inputs read)
    no_rows = np.empty((0, 1), dtype=np.int64)  # the response alone, then the separate pass
    lockstep._force_blocks(shapes, False, a0, a1, gin1_0, gin1_1, out_d0, f_new, no_rows, rows,
                           power_a, n)  # fmt: skip
    lockstep._powers(blocks, rows, a0, a1, power_a, row, n)
    b0, b1, power_b = s0.copy(), s1.copy(), np.full(n, np.nan)
    lockstep._force_blocks(shapes, False, b0, b1, gin1_0, gin1_1, out_d0, f_new, blocks, rows,
                           power_b, n)  # fmt: skip
    assert a0.tobytes() == b0.tobytes() and a1.tobytes() == b1.tobytes()
    assert power_a.tobytes() == power_b.tobytes()


def test_the_power_is_folded_only_for_rows_of_one_block_in_the_blocks_order():
    assert not damping_diagonal(_frame(racket.paper_racket(support="hand-held")).damp_blocks)
    assert damping_diagonal(np.array([[2], [3], [5]]))
    assert not damping_diagonal(np.array([[3], [2]]))
    assert not damping_diagonal(np.array([[2], [2]]))
    assert not damping_diagonal(np.array([[2, 3], [4, 5]]))


def test_the_reach_ended_at_the_gap_decides_as_the_whole_sum():
    rng = np.random.default_rng(11)
    for _ in range(300):
        nb = int(rng.integers(1, 16))
        reach_w = np.where(rng.random((1, nb)) < 0.3, 0.0, rng.random((1, nb)))
        metric, s = rng.random((nb, 2)), rng.normal(size=(nb, 2))
        whole = _reach(reach_w, 0, metric, s, np.inf)
        # the gaps at and about every partial sum, where an early end could differ
        partial, gaps = 0.0, [0.0, -1.0, whole, np.nextafter(whole, 0.0), np.nan]
        for j in range(nb):
            if reach_w[0, j] > 0.0:
                partial += reach_w[0, j] * np.sqrt(metric[j, 0] * s[j, 0] ** 2
                                                   + metric[j, 1] * s[j, 1] ** 2)  # fmt: skip
                gaps += [partial, np.nextafter(partial, -np.inf), np.nextafter(partial, np.inf)]
        for gap in gaps:
            assert (gap >= _reach(reach_w, 0, metric, s, gap)) == (gap >= whole)


@pytest.mark.parametrize("model", [racket.paper_racket(), racket.default_racket()])
def test_the_watch_pass_decides_as_the_scalar_kernels_functions_at_the_edge(model):
    """Each open contact set a hair inside or outside its reach, or at it to the bit, as the
    scalar kernel's functions (bed_gap, contact_compression, _reach) place it: the pass ends
    exactly those outside or at it (a watch that ended early would miss a late re-contact,
    and no whole impact shows it otherwise)."""
    ball = racket.default_ball()
    x = np.linspace(*model.strings.extent, 10)[1:-1]
    stepper = Stepper(model, ball, x, None, np.full(x.size, 16.5), 0.0, None, 300)
    points, bed, law, params = (
        stepper.points,
        stepper.ball.bed,
        stepper.ball.law,
        stepper.ball.params,
    )
    massed, n, nb = bed[2] > 0.0, x.size, stepper.frame.trans.shape[0]
    rng = np.random.default_rng(3)
    w = np.zeros((tl.N_ROWS, nb, tl.TILE))
    v = np.zeros((tl.N_SCALARS, tl.TILE))
    flags = np.zeros((tl.N_FLAGS, tl.TILE), dtype=np.int64)
    memo = np.full((max(MEMO_ROWS, BED_MEMO_ROWS), tl.TILE), -1.0)
    flags[tl.IMPACT, :n], flags[tl.STOP_AT, :n] = np.arange(n), -1
    w[tl.S0, :, :n], w[tl.S1, :, :n] = rng.normal(size=(nb, n)) * 1e-4, rng.normal(size=(nb, n))
    v[tl.F_PEAK_, :n], v[tl.Z_REST_FOR, :n] = rng.uniform(200.0, 800.0, n), np.nan
    v[tl.F2, :n], v[tl.F2_PEAK, :n] = rng.uniform(-20.0, 20.0, n), rng.uniform(200.0, 800.0, n)
    v[tl.QD, :n], v[tl.K_BED, :n] = rng.normal(size=n), 1.0 / points.inv_ks
    memo[3, :n] = rng.uniform(-1e-3, 3e-3, n)
    expected = np.full(n, -1)
    for i in range(n):
        s = np.ascontiguousarray(np.stack([w[tl.S0, :, i], w[tl.S1, :, i]], axis=1))
        v[tl.UD, i] = _dot(points.out_dc[i], s) - 1.0  # separating in the dc motion
        watch.rest(law, params, bed, massed, points.inv_ks, v, flags, memo, i)
        if massed:
            z_open = bed_gap(law, params, bed, v[tl.K_BED, i], points.series[i] - points.inv_ks[i],
                             memo.copy(), i, v[tl.F_PEAK_, i], v[tl.F2, i], v[tl.F2_PEAK, i],
                             v[tl.QD, i] - _dot(points.out_v[i], s))  # fmt: skip
        else:
            z_open = contact_compression(law, params, bed, points.inv_ks[i], 0.0, v[tl.F_PEAK_, i])
        reach = _reach(points.reach_w, i, stepper.frame.metric, s, np.inf)
        d = _dot(points.out_d[i], s)
        outside = i % 3 != 1  # the gap a hair beyond the reach, or a hair short of it
        gap = reach * (1.0 + (1e-9 if outside else -1e-9))
        v[tl.U, i] = z_open + d - gap
        if i % 3 == 2:  # the gap the reach to the bit, where one is found: over
            u = z_open + d - reach
            for _ in range(64):
                if z_open - (u - d) == reach:
                    v[tl.U, i] = u
                    break
                u = np.nextafter(u, np.inf if z_open - (u - d) > reach else -np.inf)
        expected[i] = 7 + 3 if outside else -1
    watch.watch_tile(massed, False, bed[0], bed[2], points.out_dc, points.out_d, points.out_v,
                     points.reach_w, points.series, points.inv_ks, stepper.frame.metric,
                     w[tl.S0], w[tl.S1], v, flags, memo, 7, 3, n)  # fmt: skip
    assert flags[tl.STOP_AT, :n].tolist() == expected.tolist()


def _tile_rows(model, count=64):
    """A tile's rows as the lockstep kernel's slots hold them (lockstep_slot.start_slot)."""
    x = np.linspace(*model.strings.extent, count)
    stepper = Stepper(model, racket.paper_ball(), x, None, np.full(count, 10.0), 0.0, None, 300)
    frame, unit, out_d = stepper.frame, stepper.points.unit, stepper.points.out_d
    w = np.zeros((tl.N_ROWS, frame.trans.shape[0], count))
    for r in range(2):
        w[tl.GIN0_0 + r] = (frame.g0[:, r, 0] * unit[:, :, 0] + frame.g0[:, r, 1] * unit[:, :, 1]).T
        w[tl.GIN1_0 + r] = (frame.g1[:, r, 0] * unit[:, :, 0] + frame.g1[:, r, 1] * unit[:, :, 1]).T
        w[tl.OUT_D0 + r] = out_d[:, :, r].T
    return frame, w


def test_a_free_rackets_blocks_read_the_points_row_alone_and_a_held_ones_do_not():
    for model, modal in ((racket.paper_racket(), True), (racket.default_racket(), True),
                         (racket.paper_racket(support="hand-held"), False)):  # fmt: skip
        frame, w = _tile_rows(model)
        shapes = np.empty((frame.trans.shape[0], 4))
        assert lockstep._modal(frame.g0, frame.g1, w, shapes, w.shape[2]) == modal


@pytest.mark.parametrize("model", [racket.paper_racket(), racket.default_racket()])
def test_the_blocks_passes_from_the_points_row_have_the_stored_inputs_bits(model):
    """Zeros of either sign in the states and the forces, where a sum's sign could part."""
    frame, w = _tile_rows(model)
    nb, n = w.shape[1], w.shape[2]
    shapes = np.empty((nb, 4))
    assert lockstep._modal(frame.g0, frame.g1, w, shapes, n)
    rng = np.random.default_rng(5)
    signed_zeros = np.array([0.0, -0.0])
    s0, s1 = rng.normal(size=(nb, n)) * 1e-3, rng.normal(size=(nb, n))
    for s in (s0, s1):
        zero = rng.random((nb, n)) < 0.2
        s[zero] = rng.choice(signed_zeros, size=zero.sum())
    force = np.abs(rng.normal(size=n)) * 1e3
    force[::3] = signed_zeros[rng.integers(0, 2, force[::3].size)]
    runs = []
    for modal in (False, True):
        a0, a1, z = s0.copy(), s1.copy(), np.zeros(n)
        lockstep._free_blocks(frame.trans, shapes, modal, a0, a1, w[tl.GIN0_0], w[tl.GIN0_1],
                              w[tl.OUT_D0], w[tl.OUT_D1], force, z, n)  # fmt: skip
        b0, b1, power = a0.copy(), a1.copy(), np.empty(n)
        no_rows = np.empty((0, 1), dtype=np.int64)
        lockstep._force_blocks(shapes, modal, b0, b1, w[tl.GIN1_0], w[tl.GIN1_1], w[tl.OUT_D0],
                               force, no_rows, frame.damp_rows, power, n)  # fmt: skip
        lockstep._force_blocks(shapes, modal, a0, a1, w[tl.GIN1_0], w[tl.GIN1_1], w[tl.OUT_D0],
                               force, frame.damp_blocks, frame.damp_rows, power, n)  # fmt: skip
        runs.append(b"".join(r.tobytes() for r in (z, a0, a1, b0, b1, power)))
    assert runs[0] == runs[1]


@pytest.mark.parametrize("spoil", ["minus_zero_input", "velocity_row", "one_bit"])
def test_the_points_row_is_refused_where_one_stored_input_differs(spoil):
    """One slot, one block, one input off (a zero of the other sign, a velocity row not zero,
    the last bit): the check refuses the whole tile (the racket's own rows pass it)."""
    frame, w = _tile_rows(racket.paper_racket())
    nb, n = w.shape[1], w.shape[2]
    shapes = np.empty((nb, 4))
    assert lockstep._modal(frame.g0, frame.g1, w, shapes, n)
    j, i = nb - 1, n - 1  # the last block and slot, read last
    if spoil == "minus_zero_input":
        w[tl.OUT_D0, j, i] = 0.0
        for k in range(4):
            w[tl.GIN0_0 + k, j, i] = -(shapes[j, k] * 0.0)  # the product's sign flipped
    elif spoil == "velocity_row":
        w[tl.OUT_D1, j, i] = 1e-300
    else:
        w[tl.GIN1_1, j, i] = np.nextafter(w[tl.GIN1_1, j, i], np.inf)
    assert not lockstep._modal(frame.g0, frame.g1, w, shapes, n)
