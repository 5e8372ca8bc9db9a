"""The calibration of the ball's grip on Cross's oblique bounces (issue 44): the ratio kappa of
the contact's tangential stiffness to the ball's normal stiffness, the normal force's offset
and each lab surface's friction, fitted on Cross, Am. J. Phys. 70 (2002) 482, Table II
(:data:`~studies.validation.spin_rows.CROSS_TABLE_II`, six bounces without spin; calibration
rows, never validation ones).

Each row's misfit is the largest of its rebound angle's, spin's and vx2/vx1's errors, each
over its target (:data:`TARGETS`: 3 degrees, 15 %, 0.07, the targets ``tests/test_court.py``
holds the rows to).  For each kappa and offset, each surface takes the friction (on a grid of
:data:`FRICTION_STEP`) that minimises the larger misfit of its two rows; the pair (kappa,
offset) kept is the one whose worst row is best.  ``python -m
studies.validation.grip_calibration`` redoes it and prints the table (a minute or two).
"""

from __future__ import annotations

import math
from functools import cache

import numpy as np

from ball import BALL_PRESETS, DEFAULT_BALL
from ball.court import LAB_SURFACES, normal_force
from ball.grip import slide
from ball.spin import BallSpin
from studies.validation.spin_rows import CROSS_TABLE_II

TARGETS = (3.0, 0.15, 0.07)
"""The misfits [deg, -, -] a row's rebound angle, spin (relative) and vx2/vx1 may reach."""

FRICTION_STEP = 0.01
"""The grid of the surfaces' friction [-]."""

KAPPAS = tuple(np.round(np.arange(1.0, 2.21, 0.05), 2))
"""The ratios kappa [-] scanned."""

OFFSETS = (0.06, 0.07, 0.08, 0.09)
"""The offset ratios [-] scanned: the source's range, "about R/10 (2-3 mm for tennis balls)"
(Cross 2002, ``data/measurements.md`` sec. 6), 2.0-3.0 mm on a 33.5 mm ball.  (Below it the
fit improves a little, 0.58 of the targets at 0.04, but the offset leaves what was measured.)"""

FRICTIONS = tuple(np.round(np.arange(0.10, 0.81, FRICTION_STEP), 2))
"""The frictions [-] scanned for each surface."""


@cache
def _pulse(surface: str, speed: float, angle_deg: float):
    """The normal force history of a row's bounce (it does not depend on the grip)."""
    ball = BALL_PRESETS[DEFAULT_BALL].ball()
    theta = math.radians(angle_deg)
    v_y = speed * math.sin(theta)
    force, dt, _ = normal_force(ball, LAB_SURFACES[surface].cor, v_y, 2000)
    return ball, force, dt, speed * math.cos(theta), v_y


def row_misfit(row: str, kappa: float, offset: float, friction) -> np.ndarray:
    """The misfit [-] of Table II's ``row`` with the grip (``kappa``, ``offset``) and the
    surface's ``friction`` (one or many, run together): the largest of its three errors
    over their targets.

    Parameters
    ----------
    row : str
        A key of :data:`CROSS_TABLE_II`.
    kappa, offset : float
        The tangential stiffness ratio [-] and the offset ratio [-]
        (:class:`ball.spin.BallSpin`).
    friction : float or array_like
        The surface's friction [-].
    """
    surface, theta1, v1, theta2, omega2, ratio = CROSS_TABLE_II[row]
    ball, force, dt, v_x, v_y = _pulse(surface, v1, theta1)
    friction = np.atleast_1d(np.asarray(friction, dtype=float))
    histories = np.broadcast_to(force, (friction.size, force.size))
    spin = BallSpin(radius=ball.radius, stiffness_ratio=kappa, offset_ratio=offset)
    grip = slide(histories, dt, ball.mass, spin, friction, [v_x, 0.0], [0.0, 0.0, 0.0],
                 law=ball.law)  # fmt: skip
    vx2, spin2 = grip.velocity[:, 0], grip.spin[:, 1]
    vy2 = LAB_SURFACES[surface].cor * v_y
    errors = (
        np.abs(np.degrees(np.arctan2(vy2, vx2)) - theta2) / TARGETS[0],
        np.abs(spin2 / omega2 - 1.0) / TARGETS[1],
        np.abs(vx2 / v_x - ratio) / TARGETS[2],
    )
    return np.max(errors, axis=0)


def _surface_best(surface: str, kappa: float, offset: float) -> tuple[float, float]:
    """(friction, misfit): the friction of :data:`FRICTIONS` that fits ``surface``'s rows
    best.
    """
    rows = [name for name, row in CROSS_TABLE_II.items() if row[0] == surface]
    misfit = np.max([row_misfit(r, kappa, offset, FRICTIONS) for r in rows], axis=0)
    best = int(np.argmin(misfit))
    return FRICTIONS[best], float(misfit[best])


def calibrate(kappas=KAPPAS, offsets=OFFSETS) -> dict:
    """The best (kappa, offset) and each lab surface's friction, and the worst row's misfit.

    Parameters
    ----------
    kappas, offsets : sequence of float
        The ratios [-] scanned.

    Returns
    -------
    dict
        ``kappa``, ``offset``, ``frictions`` (by surface) and ``misfit`` (the worst row's,
        over its targets: below 1 meets them all).
    """
    best = None
    for kappa in kappas:
        for offset in offsets:
            fits = {s: _surface_best(s, kappa, offset) for s in LAB_SURFACES}
            worst = max(misfit for _, misfit in fits.values())
            if best is None or worst < best["misfit"]:
                frictions = {s: mu for s, (mu, _) in fits.items()}
                best = dict(kappa=kappa, offset=offset, frictions=frictions, misfit=worst)
    return best


if __name__ == "__main__":  # pragma: no cover (a minute or two)
    print(calibrate())
