"""The compiled block transition matrices against scipy's expm of the augmented system."""

import numpy as np
import pytest
from scipy.linalg import expm

from racket import Hand, paper_racket
from racket.solver.steps import block_steps
from racket.system import free_system, held_system


def _reference(blocks, dt):
    out = []
    for a in blocks:
        aug = np.zeros((6, 6))
        aug[:2, :2] = a
        aug[:2, 2:4] = np.eye(2)
        aug[2:4, 4:6] = np.eye(2)
        e = expm(aug * dt)
        g1 = e[:2, 4:6] / dt
        out.append((e[:2, :2], e[:2, 2:4] - g1, g1))
    return [np.array(m) for m in zip(*out, strict=True)]


MODES = paper_racket().beam.modes


@pytest.mark.parametrize(
    "system",
    [free_system(MODES), held_system(MODES, Hand()), held_system(MODES, Hand(1e5, 100.0))],
    ids=["free", "hand-held", "stiff hand"],
)
@pytest.mark.parametrize("dt", [1e-7, 7.4e-6, 1e-4])
def test_block_steps_match_the_matrix_exponential(system, dt):
    ours = block_steps(system.blocks, dt)
    for mine, ref in zip(ours, _reference(system.blocks, dt), strict=True):
        scale = np.abs(ref).max(axis=(1, 2), keepdims=True)
        assert np.abs(mine - ref).max() <= 2e-13 * scale.max()
        assert np.all(np.abs(mine - ref) <= 2e-13 * scale)


def test_rigid_block_is_exact():
    # The rigid mode [[0, 1], [0, 0]]: T = [[1, dt], [0, 1]], G0 = [[dt^2/3, .], [dt/2, .]]
    dt = 1e-5
    (t,), (g0,), (g1,) = block_steps(np.array([[[0.0, 1.0], [0.0, 0.0]]]), dt)
    assert np.allclose(t, [[1.0, dt], [0.0, 1.0]], rtol=1e-15, atol=0)
    assert g0[:, 1] == pytest.approx([dt**2 / 3, dt / 2], rel=1e-15)
    assert g1[:, 1] == pytest.approx([dt**2 / 6, dt / 2], rel=1e-15)
