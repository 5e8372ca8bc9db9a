"""A bat pivoted as in the certification rig: a point of its handle held still, the bat free
to turn about it.

The rig (A. M. Nathan, notes on his program ACOR (2026), Sec. II C, p. 11): a ball "fired
from a high-speed air cannon onto a stationary bat which is attached at the handle to a
structure that allows it to pivot freely about a point"; the pivot axis "six inches from
the knob", the bat clamped at two points r_p = 1 inch either side of it.  The clamps turn
with the axis, y(clamp 2) = -y(clamp 1) = r_p theta, so the one constraint on the bat is
that the mean deflection of the two clamp points stays 0 (with no clamp width, the pivot
point's own deflection: Nathan 2000's pivoted bat, "an additional force at the pivot point
... to make the acceleration of the bat at that point vanish").  The structure's own moment
of inertia I_p is not stated in the sources: 0 here, **an assumption** (it adds to the
bat's I about the pivot).

ACOR's own rig model (its eqs. 18-21) differs: it turns the rig with the rigid bat,
theta'' = r_0 f / (I_0 + I_p), and solves the two clamp forces, which can then hold a torque;
here the rig turns freely and has no mass, so the two clamps pull alike.  Nathan 2000's
single pivot point is the case without clamp width.

The constraint c . q = 0 on the modal coordinates q (c the constraint's row of mode
shapes) is imposed exactly: q = T r with T an orthonormal basis of the modes orthogonal to
c (the modes are mass-normalised, so T keeps the kinetic energy ``|r'|**2 / 2``), and the
equations of motion projected, r'' + T' D T r' + T' W T r = T' phi F (the constraint force,
along c, does no work).  Nothing beyond the truncation to the beam's modes is approximated:
a rigid bat pivoted so obeys angular momentum about the pivot to round-off.  The truncation
costs more here than on a free bat, since the constraint acts on the modes kept only and
the modes left out count through the free bat's residual flexibility: near the pivot (45 cm
from the R161's knob) e_A moves by 2e-3 from 18 to 40 modes (a free bat's, 2e-5); on the
barrel by about 1e-5.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from beam import Modes
from racket.system import BlockSystem, held_blocks

PIVOT_FROM_KNOB = 0.1524
"""Distance [m] of the certification rig's pivot axis from the knob, 6 in (ACOR p. 11;
ASTM F2398-11 Sec. 3.1.2: "6 in. (152 mm) from the knob end")."""

CLAMP_OFFSET = 0.0254
"""Distance [m] of each of the rig's two clamps from the pivot axis, 1 in (ACOR p. 11)."""


def pivoted_system(modes: Modes, points) -> BlockSystem:
    """The bat held so that the mean deflection of ``points`` stays 0 (see the module
    docstring), in real blocks; its modal coordinates are the free bat's, q.

    Parameters
    ----------
    modes : Modes
        The bat's free-free modes.
    points : array_like
        The clamp points [m from the tip] (one: a single pivot point).
    """
    points = np.atleast_1d(np.asarray(points, dtype=float))
    c = modes.shape(points).mean(axis=1)
    n = c.size
    frame = np.linalg.qr(np.column_stack([c, np.eye(n)]))[0][:, :n]
    turn = frame[:, 1:]  # orthonormal, orthogonal to c
    stiffness = np.diag(modes.omega**2)
    damping = np.diag(2.0 * modes.damping * modes.omega)
    pivot = float(points.mean())
    # The free motion left: the rigid turn about the pivot (1 rad/s; see beam.Modes).
    turning = np.zeros(n)
    turning[0] = np.sqrt(modes.mass) * (pivot - modes.center_of_mass)
    turning[1] = np.sqrt(modes.inertia_cm)
    null = turn.T @ turning
    system = held_blocks(
        turn.T @ stiffness @ turn,
        turn.T @ damping @ turn,
        0.5 * modes.omega[2],
        (0, 1),
        null / np.linalg.norm(null),
    )
    basis = np.kron(np.eye(2), turn) @ system.basis
    # The dc motion: the turn about the pivot alone, the velocities' projection on it (the
    # angular momentum about the pivot over I_pivot; the bending modes of the held bat
    # carry the rest of the free coordinates' velocities).
    dc_rows = np.outer(turning[:2], turning) / (turning @ turning) @ basis[n:]
    return replace(system, basis=basis, stiffness=stiffness, damping=damping, dc_rows=dc_rows)
