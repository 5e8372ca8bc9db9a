"""The budget's split (racket.solver.budget) skips the zero groups of a free racket's basis and
the zero terms of its stiffness: the same bits as the full sums in the blocks' order."""

import numpy as np
import pytest

import racket
from racket.solver import budget
from racket.solver.stepper import Stepper


def _full_sums(state, basis, stiffness, phi):
    """V2_TOTAL and twice the mechanical energy per impact, every term of every sum taken in
    order, in Python's numbers (IEEE's operations, as the compiled split's)."""
    n = stiffness.shape[0]
    v2, mechanical = [], []
    for p in range(state.shape[0]):
        z = []
        for r in range(2 * n):
            total = 0.0
            for k in range(state.shape[1]):
                total += basis[r, 2 * k] * state[p, k, 0] + basis[r, 2 * k + 1] * state[p, k, 1]
            z.append(total)
        kq = []
        for i in range(n):
            total = 0.0
            for k in range(n):
                total += z[k] * stiffness[k, i]
            kq.append(total)
        v, m = 0.0, 0.0
        for i in range(n):
            v += phi[p, i] * z[n + i]
            m += z[n + i] * z[n + i] + kq[i] * z[i]
        v2.append(v)
        mechanical.append(m)
    return np.array(v2), np.array(mechanical)


@pytest.mark.parametrize("support", ["free", "hand-held"])
@pytest.mark.parametrize("offset", [None, 0.02])
def test_split_skips_only_zeros(support, offset):
    frame = racket.default_racket(support)
    x = np.linspace(*frame.strings.extent, 9)[1:-1]
    y = None if offset is None else np.full(x.size, offset)
    stepper = Stepper(frame, racket.default_ball(), x, y, 20.0, 0.0, None, 300)
    state = stepper.run(stepper.points.x_o).state
    system = stepper.system
    if support == "free":  # the sparse case: one group a row, one term a column
        assert budget._nonzero(system.basis, 2)[1].max() == 1
    out = np.zeros((x.size, budget.N_COLUMNS))
    modes = np.zeros((x.size, max(system.count - 2, 0)))
    zeros = np.zeros((x.size, 4))
    ball = np.column_stack([np.full(x.size, -5.0), np.full(x.size, 20.0), np.full(x.size, 20.0)])
    frame_numbers = np.array([0.3, 0.5, 0.1, 0.05 if offset is not None else 0.0,
                              min(system.count, frame.beam.modes.count), 0.057])  # fmt: skip
    budget.split(state, system.basis, system.stiffness, system.rigid_rows, stepper.phi, x,
                 np.zeros(x.size) if y is None else y, frame_numbers, frame.beam.modes.omega,
                 ball, np.zeros((x.size, 2)), zeros, out, modes)  # fmt: skip
    v2, mechanical = _full_sums(state, system.basis, system.stiffness, stepper.phi)
    assert out[:, budget.V2_TOTAL].tolist() == v2.tolist()
    frame_energy = out[:, budget.RACKET_ENERGY]  # (no bed mass: the frame's rigid energy)
    assert out[:, budget.VIBRATION].tolist() == (0.5 * mechanical - frame_energy).tolist()


def test_nonzero_lists_each_rows_groups_in_order():
    # Row by row, the groups of `width` numbers not all zero (a -0.0 is a zero), in order; on
    # a transposed matrix, its columns' (as the stiffness's terms are asked for).
    matrix = np.array([[0.0, 1.0, 0.0, 0.0, -0.0, 2.0], [0.0, 0.0, 0.0, 0.0, 0.0, 0.0],
                       [3.0, 0.0, 0.0, -0.0, 4.0, 5.0]])  # fmt: skip
    index, count = budget._nonzero(matrix, 2)
    assert count.tolist() == [2, 0, 2]
    assert index[0, :2].tolist() == [0, 2] and index[2, :2].tolist() == [0, 2]
    index, count = budget._nonzero(np.array([[0.0, 1.0], [0.0, 0.0]]).T, 1)
    assert count.tolist() == [0, 1] and index[1, 0] == 0
