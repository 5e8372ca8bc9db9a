"""The racket's linear dynamics in real 2x2 blocks, the form the time-stepper advances.

The frame is described by its free-free modes q (rigid-body modes first, mass-normalised,
see :class:`beam.Modes`): q'' + D q' + W q = phi(b) F, W = diag(omega**2), D = diag(2 zeta
omega), with F the contact force at the impact point b.

* A free racket is already in blocks: block i holds (q_i, q_i').
* A hand-held racket adds the hand, a spring k and a dashpot c per unit length over the
  grip: W += K_h and D += C_h with K_h,ij = int_grip k phi_i phi_j dx (and C_h likewise).
  The modes are then coupled and the damping is not proportional, so the first-order
  system z' = A z, z = (q, q'), is brought to real block-diagonal form exactly: each complex
  pair of eigenvalues sigma +- i w gives a block [[sigma, w], [-w, sigma]], two real
  eigenvalues a block diag(l1, l2).  Nothing is approximated beyond the truncation to the
  beam's modes.

In both cases the state s (blocks, 2 values each) maps to z by ``basis``: z = basis s.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from functools import cached_property

import numpy as np

from beam import Modes
from beam.torsion import RollModes
from racket.hand import GRIP_RADIUS, Hand

_GRIP_POINTS = 24  # Gauss-Legendre points over the grip


@dataclass(frozen=True)
class BlockSystem:
    """z' = A z + B F in real 2x2 blocks (see the module docstring).

    Attributes
    ----------
    blocks : (nb, 2, 2)
        The block matrices.
    basis : (2N, 2 nb)
        z = basis @ s, s the blocks' states in order (s_0a, s_0b, s_1a, ...), z = (q, q');
        square but for a constrained system (:mod:`bat.pivot`: nb = N - 1).
    dc : (nb,) bool
        Blocks of the rigid-body motion (free) or of the racket rocking on the hand
        (hand-held): left out of the vibration's reach when deciding that the ball has left.
    metric : (nb, 2)
        Weights w with sqrt(w0 s_a**2 + w1 s_b**2) bounding a block's future amplitude.
    stiffness, damping : (N, N)
        W (+ K_h) and D (+ C_h) in modal coordinates.
    rigid : tuple of int
        The modal coordinates of rigid-body modes (translation and rotation; the roll too
        in a :func:`face_system`): the impact point's dc velocity is theirs.
    hand_coordinate : int or None
        The coordinate of a hand with mass (:func:`held_system`), after the frame's bending
        modes; None without one.  The frame's shapes are 0 there.
    dc_rows : ndarray (len(rigid), 2 nb) or None
        Rows over the block states giving the rigid coordinates' velocities [sqrt(kg) m/s]
        of the dc motion alone, where it is not theirs whole (:mod:`bat.pivot`: the turn
        about the pivot); None: :attr:`rigid`'s rows of ``basis``, the frame's momentum.
    step_memo : dict
        The solver's memo of this system's exact steps, by time step
        (:func:`racket.solver.steps.system_steps`); not part of the system's value.
    """

    blocks: np.ndarray
    basis: np.ndarray
    dc: np.ndarray
    metric: np.ndarray
    stiffness: np.ndarray
    damping: np.ndarray
    rigid: tuple = (0, 1)
    hand_coordinate: int | None = None
    dc_rows: np.ndarray | None = None
    step_memo: dict = field(default_factory=dict, compare=False, repr=False)

    @property
    def count(self) -> int:
        """Number of modal coordinates N."""
        return self.stiffness.shape[0]

    def _blocks_of(self, rows: np.ndarray) -> np.ndarray:
        """(P, 2N) rows over the state s as (P, nb, 2), contiguous for the kernel."""
        return np.ascontiguousarray(rows).reshape(rows.shape[0], self.blocks.shape[0], 2)

    @cached_property
    def _to_blocks(self) -> np.ndarray:
        """basis^-1 (transposed): s = z @ this (the pseudo-inverse for a constrained
        system's, :mod:`bat.pivot`, which has fewer blocks than coordinates).
        """
        square = self.basis.shape[0] == self.basis.shape[1]
        inverse = np.linalg.inv(self.basis) if square else np.linalg.pinv(self.basis)
        return np.ascontiguousarray(inverse.T)

    def state(self, z: np.ndarray) -> np.ndarray:
        """Block states (P, nb, 2) of modal states z = (q, q') (P, 2N).

        Parameters
        ----------
        z : ndarray (P, 2N)
            Modal displacements q [sqrt(kg) m] and velocities q' [sqrt(kg) m/s].
        """
        return self._blocks_of(z @ self._to_blocks if self.count else z)

    def inputs(self, phi: np.ndarray) -> np.ndarray:
        """Block inputs (P, nb, 2) of a unit force at points with mode shapes phi (P, N).

        Parameters
        ----------
        phi : ndarray (P, N)
            Mode shapes at the points [1/sqrt(kg)].
        """
        z = np.zeros((phi.shape[0], 2 * phi.shape[1]))  # (cheaper than stacking)
        z[:, phi.shape[1] :] = phi
        return self.state(z)

    def outputs(self, phi: np.ndarray):
        """Rows (P, nb, 2) giving the displacement, the velocity and the dc (rigid-body)
        velocity of points with mode shapes phi (P, N) from the block states.

        Parameters
        ----------
        phi : ndarray (P, N)
            Mode shapes at the points [1/sqrt(kg)].
        """
        n, rigid = self.count, list(self.rigid)
        disp = self._blocks_of(phi @ self.basis[:n])
        vel = self._blocks_of(phi @ self.basis[n:])
        dc = self._blocks_of(phi[:, rigid] @ self.rigid_rows)
        return disp, vel, dc

    @cached_property
    def vibrating(self) -> np.ndarray:
        """(nb,) bool: the blocks that are not dc motion (``~dc``), whose reach the
        solver watches; computed once (the system is frozen).
        """
        return ~self.dc

    @cached_property
    def rigid_rows(self) -> np.ndarray:
        """Rows (len(rigid), 2 nb) over the block states giving the velocities of the
        rigid coordinates' dc motion (:attr:`dc_rows`, or the basis's rows); computed once
        (the system is frozen).
        """
        if self.dc_rows is not None:
            return self.dc_rows
        return np.ascontiguousarray(self.basis[[self.count + i for i in self.rigid]])

    @cached_property
    def damping_rows(self):
        """The dissipated power q'^T D q' as sum_r (L_r . s)**2, sparsely.

        Returns blocks (R, K) and rows (R, K, 2): L_r is non-zero only on the K blocks
        ``blocks[r]`` (K = 1 for a free racket, whose damping is diagonal).
        """
        c, u = np.linalg.eigh(self.damping)
        keep = c > 1e-12 * max(c.max(initial=0.0), 1e-300)
        rows = self._blocks_of(
            (np.sqrt(c[keep])[:, None] * u[:, keep].T) @ self.basis[self.count :]
        )
        nonzero = np.any(rows != 0.0, axis=2)
        width = max(int(nonzero.sum(axis=1).max(initial=0)), 1)
        blocks = np.zeros((rows.shape[0], width), dtype=np.int64)
        values = np.zeros((rows.shape[0], width, 2))
        for r, row in enumerate(nonzero):
            j = np.nonzero(row)[0]
            blocks[r, : j.size] = j
            values[r, : j.size] = rows[r, j]
        return blocks, values

    def modal_state(self, s: np.ndarray):
        """Modal displacements and velocities (P, N) from block states (P, nb, 2) (fewer
        blocks than coordinates for a constrained system, :mod:`bat.pivot`).

        Parameters
        ----------
        s : ndarray (P, nb, 2)
            Block states.
        """
        z = s.reshape(s.shape[0], -1) @ self.basis.T
        return z[:, : self.count], z[:, self.count :]


def point_shapes(system: BlockSystem, modes: Modes, x: np.ndarray) -> np.ndarray:
    """The bending system's modal shapes (P, N) at points ``x`` [m from the tip]: the beam's
    modes, and 0 for a hand's coordinate (:attr:`BlockSystem.hand_coordinate`: no force
    on the hand's mass).

    Parameters
    ----------
    system : BlockSystem
        The block system of the frame and its support.
    modes : Modes
        The frame's free-free modes.
    x : ndarray
        The points [m from the tip].
    """
    phi = modes.shape(x).T[:, : min(system.count, modes.count)]
    if system.hand_coordinate is not None:
        phi = np.hstack([phi, np.zeros((x.size, 1))])
    return phi


def free_system(modes: Modes) -> BlockSystem:
    """The free racket: block i is mode i, (q_i, q_i').

    Parameters
    ----------
    modes : Modes
        The frame's free-free modes.
    """
    return _free_blocks(modes.omega, modes.damping, (0, 1))


def _free_blocks(omega, zeta, rigid: tuple) -> BlockSystem:
    """Uncoupled modes ``omega`` [rad/s] with damping ratios ``zeta``: block i is mode i,
    (q_i, q_i').
    """
    n = omega.size
    w2 = omega**2
    d = 2.0 * zeta * omega
    blocks = np.zeros((n, 2, 2))
    blocks[:, 0, 1] = 1.0
    blocks[:, 1, 0] = -w2
    blocks[:, 1, 1] = -d
    basis = np.zeros((2 * n, 2 * n))
    basis[np.arange(n), 2 * np.arange(n)] = 1.0
    basis[n + np.arange(n), 2 * np.arange(n) + 1] = 1.0
    dc = omega == 0.0
    metric = np.column_stack([np.ones(n), np.where(dc, 0.0, 1.0 / np.maximum(w2, 1e-300))])
    return BlockSystem(blocks, basis, dc, metric, np.diag(w2), np.diag(d), rigid)


def _grip_overlap(shapes, length: float, hand: Hand) -> np.ndarray:
    """Int phi_i phi_j dx over the grip / grip length, for ``shapes(x)`` (N, len(x)) of a
    beam ``length`` [m] long (Gauss-Legendre).
    """
    nodes, weights = np.polynomial.legendre.leggauss(_GRIP_POINTS)
    start = length - hand.grip_length
    x = start + 0.5 * hand.grip_length * (nodes + 1.0)
    w = 0.5 * hand.grip_length * weights
    phi = shapes(x)
    return (phi * w) @ phi.T / hand.grip_length


def hand_matrices(modes: Modes, hand: Hand):
    """K_h and C_h (N, N) of the hand over the grip (see the module docstring).

    Parameters
    ----------
    modes : Modes
        The frame's free-free modes.
    hand : Hand
        The hand: its total stiffness [N/m] and damping [N s/m], spread over the grip.
    """
    overlap = _grip_overlap(modes.shape, modes.length, hand)
    return hand.stiffness * overlap, hand.damping * overlap


def held_blocks(stiffness, damping, slow: float, rigid: tuple, null=None) -> BlockSystem:
    """Coordinates of unit mass coupled by ``stiffness`` and ``damping`` (N, N), in real
    blocks; blocks slower than ``slow`` [rad/s] are the dc motion.  ``null``, a unit vector
    with stiffness @ null = damping @ null = 0 (a free motion of the whole: the racket and
    the hand's mass translating together), is split off first as a block [[0, 1], [0, 0]]
    (the eigenvectors of a free motion are defective; the rest are not).

    Parameters
    ----------
    stiffness, damping : ndarray
        The coordinates' stiffness [N/m per kg] and damping [N s/m per kg] matrices (N, N).
    slow : float
        The fastest a block may be and still be dc motion [rad/s].
    rigid : tuple of int
        The coordinates of the rigid-body motion (the dc motion's rows).
    null : ndarray or None
        A free motion of the whole (N,), a unit vector [-], or None.
    """
    n = stiffness.shape[0]
    turn = np.eye(n)
    if null is not None:  # an orthonormal basis whose first vector is the free motion
        turn = np.linalg.qr(np.column_stack([null, np.eye(n)]))[0][:, :n]
        turn[:, 0] = null
    k_t, c_t = turn.T @ stiffness @ turn, turn.T @ damping @ turn
    m = n - (null is not None)
    a = np.block([[np.zeros((m, m)), np.eye(m)], [-k_t[n - m :, n - m :], -c_t[n - m :, n - m :]]])
    lam, vec = np.linalg.eig(a)
    scale = np.abs(lam).max()
    complex_ = lam.imag > 1e-10 * scale
    real = np.abs(lam.imag) <= 1e-10 * scale
    blocks, columns, freq = [], [], []
    for i in np.nonzero(complex_)[0]:
        s, w = lam[i].real, lam[i].imag
        blocks.append([[s, w], [-w, s]])
        columns += [vec[:, i].real, vec[:, i].imag]
        freq.append(abs(lam[i]))
    reals = np.sort(np.nonzero(real)[0])
    for i, j in zip(reals[::2], reals[1::2], strict=True):
        blocks.append([[lam[i].real, 0.0], [0.0, lam[j].real]])
        columns += [vec[:, i].real, vec[:, j].real]
        freq.append(max(abs(lam[i]), abs(lam[j])))
    reduced = np.column_stack(columns)
    rows = np.r_[np.arange(n - m, n), n + np.arange(n - m, n)]
    basis = np.zeros((2 * n, reduced.shape[1] + 2 * (n - m)))
    basis[rows, 2 * (n - m) :] = reduced
    if null is not None:
        basis[0, 0] = basis[n, 1] = 1.0
        blocks.insert(0, [[0.0, 1.0], [0.0, 0.0]])
        freq.insert(0, 0.0)
    basis = np.kron(np.eye(2), turn) @ basis
    blocks, freq = np.array(blocks), np.array(freq)
    dc = freq < slow
    # A rotating block's output never exceeds |c| |s|; a pair of decaying exponentials
    # never exceeds |c0 s0| + |c1 s1| <= sqrt(2) |c| |s|.
    metric = np.repeat(np.where(blocks[:, 0, 1] == 0.0, 2.0, 1.0)[:, None], 2, axis=1)
    return BlockSystem(blocks, basis, dc, metric, stiffness, damping, rigid)


def held_system(modes: Modes, hand: Hand) -> BlockSystem:
    """The hand-held racket in real blocks (see the module docstring).  Blocks of the
    racket rocking on the hand, slower than half the first bending mode, are its dc
    motion.

    A hand of finite ``mass`` adds its own coordinate, last (its displacement times
    sqrt(mass)): the grip's springs and dashpots join the handle to that mass, which is
    otherwise free.  A hand of infinite mass is the grip held still (the springs and
    dashpots join the handle to the ground).

    Parameters
    ----------
    modes : Modes
        The frame's free-free modes.
    hand : Hand
        The hand holding the grip.
    """
    slow = 0.5 * modes.omega[2]
    if np.isinf(hand.mass):
        k_h, c_h = hand_matrices(modes, hand)
        stiffness = np.diag(modes.omega**2) + k_h
        damping = np.diag(2.0 * modes.damping * modes.omega) + c_h
        return held_blocks(stiffness, damping, slow, (0, 1))
    # The grip's springs stretch by y(x) - w: over the grip the shapes of (q, w sqrt(m)) are
    # (phi(x), -1/sqrt(m)), so K_h = k D O D with O the overlap of (phi, 1) and D scaling
    # the last by -1/sqrt(m) (and C_h likewise): one overlap for all of it.
    overlap = _grip_overlap(
        lambda x: np.vstack([modes.shape(x), np.ones_like(x)]), modes.length, hand
    )
    root = np.sqrt(hand.mass)
    scale = np.r_[np.ones(modes.count), -1.0 / root]
    grip = scale[:, None] * overlap * scale[None, :]
    stiffness = np.diag(np.r_[modes.omega**2, 0.0]) + hand.stiffness * grip
    damping = np.diag(np.r_[2.0 * modes.damping * modes.omega, 0.0]) + hand.damping * grip
    null = np.zeros(modes.count + 1)
    null[0], null[-1] = np.sqrt(modes.mass), root  # racket and hand translating together
    system = held_blocks(stiffness, damping, slow, (0, 1), null / np.linalg.norm(null))
    return replace(system, hand_coordinate=modes.count)


def held_mode(system: BlockSystem, coordinate: int) -> tuple[float, float]:
    """The held racket's mode that a free mode became: the vibration (not dc) block in which
    modal ``coordinate`` (2 for the first bending mode) takes the largest part.

    Parameters
    ----------
    system : BlockSystem
        A :func:`held_system`.
    coordinate : int
        The free mode's modal coordinate.

    Returns
    -------
    tuple of float
        Frequency [Hz] and damping ratio [-] of that block's eigenvalue sigma +- i w.
    """
    share = np.hypot(system.basis[coordinate, 0::2], system.basis[coordinate, 1::2])
    block = int(np.argmax(np.where(system.dc, -np.inf, share)))
    root = complex(system.blocks[block, 0, 0], system.blocks[block, 0, 1])
    return abs(root.imag) / (2.0 * np.pi), -root.real / abs(root)


def held_roll_system(roll: RollModes, length: float, hand: Hand) -> BlockSystem:
    """The roll and torsion modes of a hand-held racket in real blocks.  The hand's
    springs act at the handle's surface, :data:`GRIP_RADIUS` from the axis, so it resists
    twist with k r**2 (and c r**2) per unit length; blocks slower than half the first
    torsion mode (the racket rolling in the hand) are the dc motion.

    Parameters
    ----------
    roll : RollModes
        The frame's roll and torsion modes.
    length : float
        Racket length [m] (the grip ends at the butt).
    hand : Hand
        The hand holding the grip.
    """
    overlap = _grip_overlap(roll.twist, length, hand) * GRIP_RADIUS**2
    slow = 0.5 * roll.omega[1] if roll.count > 1 else np.inf
    stiffness = np.diag(roll.omega**2) + hand.stiffness * overlap
    damping = np.diag(2.0 * roll.damping * roll.omega) + hand.damping * overlap
    return held_blocks(stiffness, damping, slow, (0,))


def face_system(bending: BlockSystem, roll: BlockSystem) -> BlockSystem:
    """The bending and the roll systems side by side (uncoupled: the frame is symmetric
    about its long axis, see :mod:`beam.torsion`); modal coordinates (q_bending, q_roll).

    Parameters
    ----------
    bending : BlockSystem
        The bending (and rigid-body) modes' system.
    roll : BlockSystem
        The roll and torsion modes' system.
    """
    from scipy.linalg import block_diag  # scipy loads on first use (import time)

    nb, nr = bending.count, roll.count
    n = nb + nr
    # rows of z = (q_b, q_r, q_b', q_r') from those of (q_b, q_b') and (q_r, q_r')
    rows_b = np.r_[np.arange(nb), n + np.arange(nb)]
    rows_r = np.r_[nb + np.arange(nr), n + nb + np.arange(nr)]
    basis = np.zeros((2 * n, 2 * n))
    basis[np.ix_(rows_b, np.arange(2 * nb))] = bending.basis
    basis[np.ix_(rows_r, 2 * nb + np.arange(2 * nr))] = roll.basis
    return BlockSystem(
        blocks=np.concatenate([bending.blocks, roll.blocks]),
        basis=basis,
        dc=np.concatenate([bending.dc, roll.dc]),
        metric=np.concatenate([bending.metric, roll.metric]),
        stiffness=block_diag(bending.stiffness, roll.stiffness),
        damping=block_diag(bending.damping, roll.damping),
        rigid=(*bending.rigid, *(nb + i for i in roll.rigid)),
        hand_coordinate=bending.hand_coordinate,
    )


def clamped_system() -> BlockSystem:
    """A clamped head: nothing moves, no blocks."""
    empty = np.zeros((0, 0))
    return BlockSystem(
        np.zeros((0, 2, 2)), empty, np.zeros(0, bool), np.zeros((0, 2)), empty, empty, ()
    )


def racket_system(modes: Modes, support: str, hand: Hand) -> BlockSystem:
    """The block system of a free, hand-held or clamped-head racket.

    Parameters
    ----------
    modes : Modes
        The frame's free-free modes.
    support : str
        ``"free"``, ``"hand-held"`` or ``"clamped-head"``.
    hand : Hand
        The hand of a hand-held racket (ignored otherwise).
    """
    if support == "clamped-head":
        return clamped_system()
    return held_system(modes, hand) if support == "hand-held" else free_system(modes)


def roll_system(roll: RollModes, length: float, support: str, hand: Hand) -> BlockSystem:
    """The block system of the roll and torsion modes of a free or hand-held racket.

    Parameters
    ----------
    roll : RollModes
        The frame's roll and torsion modes.
    length : float
        Racket length [m].
    support : str
        ``"free"`` or ``"hand-held"`` (anything else is treated as free).
    hand : Hand
        The hand of a hand-held racket (ignored otherwise); one that does not resist twist
        leaves the roll free.
    """
    if support == "hand-held" and hand.resists_twist:
        return held_roll_system(roll, length, hand)
    return _free_blocks(roll.omega, roll.damping, (0,))
