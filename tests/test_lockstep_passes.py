"""The lockstep kernel's shortcuts decide and sum as the passes they replace, to the bit:
the dissipated power folded into the blocks' response (racket.solver.lockstep), and the
reach of the remaining vibration ended where it passes the gap (racket.solver.kernel._reach,
racket.solver.lockstep_watch)."""

import numpy as np
import pytest

import racket
from racket.solver import lockstep
from racket.solver.kernel import _reach, damping_diagonal
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
    lockstep._force_blocks(a0, a1, gin1_0, gin1_1, f_new, n)
    lockstep._powers(blocks, rows, a0, a1, power_a, row, n)
    b0, b1, power_b = s0.copy(), s1.copy(), np.full(n, np.nan)
    lockstep._force_blocks_damped(b0, b1, gin1_0, gin1_1, f_new, blocks, rows, power_b, n)
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
