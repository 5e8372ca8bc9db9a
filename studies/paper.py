"""Every quantitative claim of the paper, computed by the simulator (``racket-impact paper``)."""

from __future__ import annotations

import dataclasses
import functools
from typing import TYPE_CHECKING

import numpy as np

from ball import WALL, Ball, Collision, LinearSpring, SineLaw, collide, series_cor, unhappy_cor
from racket import TENNIS_BALL_MASS, Racket, impact, paper_ball, paper_racket
from studies.serve import serve_rows

if TYPE_CHECKING:
    import pandas as pd

UNHAPPY = Ball(0.0103, SineLaw(k0=2e4))


def happy(k2: float) -> Ball:
    """The paper's happy ball: 10.3 g, elastic, stiffness ``k2`` [N/m].

    Parameters
    ----------
    k2 : float
        Stiffness of the ball [N/m], > 0.
    """
    return Ball(0.0103, LinearSpring(k2))


@functools.cache
def free_racket() -> Racket:
    """The paper's free racket (:func:`racket.paper_racket`), kept: the claims and the
    figures of ``racket-impact paper`` ask for the same one, its modes, static flexibility
    and time steps then computed once.  Every caller is given the same object: the Racket
    is frozen, but its arrays (the modes' frequencies, damping, shapes) are not made
    read-only (the compiled kernels would then be compiled again for read-only arrays), so
    a caller must not write to them.
    """
    return paper_racket()


@functools.lru_cache(maxsize=3)
def figure_collision(k2: float | None) -> Collision:
    """The collision of the paper's Figs. 2-4: the unhappy ball at 4 m/s on a happy ball at
    rest of stiffness ``k2`` [N/m], or on the rigid wall (None).  Kept: the claims and the
    figures of ``racket-impact paper`` ask for the same three; its histories are read-only,
    so that no reader can change what the next one is given.

    Parameters
    ----------
    k2 : float or None
        Stiffness of the happy ball [N/m], > 0; None: the rigid wall.
    """
    collision = collide(UNHAPPY, WALL if k2 is None else happy(k2), 4.0)
    for field in dataclasses.fields(collision.history):
        getattr(collision.history, field.name).flags.writeable = False
    return collision


def _stored_fraction(mass_ratio: float, ball_speed: float, racket_speed: float) -> float:
    """Fraction of the lab-frame kinetic energy stored elastically at closest approach, from
    a collision of an elastic ball (m1) and an elastic racket of mass ``mass_ratio`` m1.
    """
    m1 = TENNIS_BALL_MASS
    racket = Ball(mass_ratio * m1, LinearSpring(4e4))
    ball = Ball(m1, LinearSpring(4e4))
    r = collide(racket, ball, racket_speed, -ball_speed)
    h = r.history
    kinetic = 0.5 * racket.mass * h.velocity_a**2 + 0.5 * m1 * h.velocity_b**2
    return float(1.0 - kinetic.min() / r.energy_initial)


def paper_table() -> pd.DataFrame:
    """The paper's numbers beside the simulator's.

    Returns
    -------
    DataFrame
        Columns ``claim``, ``paper``, ``simulated``, ``difference``, ``tolerance``, ``ok``.
    """
    import pandas as pd

    return pd.DataFrame(paper_columns())


def paper_columns() -> dict:
    """The columns of :func:`paper_table` as lists, without pandas (``racket-impact paper``'s
    table).

    Returns
    -------
    dict
        ``claim``, ``paper``, ``simulated``, ``difference``, ``tolerance``, ``ok`` -> one
        value per claim.
    """
    claim, paper, simulated, tolerance = map(list, zip(*_claims(), strict=True))
    difference = [s - p for s, p in zip(simulated, paper, strict=True)]
    ok = [abs(d) <= t for d, t in zip(difference, tolerance, strict=True)]
    return {
        "claim": claim,
        "paper": paper,
        "simulated": simulated,
        "difference": difference,
        "tolerance": tolerance,
        "ok": ok,
    }


def _claims() -> list[tuple[str, float, float, float]]:
    """Each claim of the paper: its words, the paper's number, the simulator's and the
    tolerance.
    """
    rows = []

    def add(claim, paper, simulated, tolerance):
        rows.append((claim, float(paper), float(simulated), float(tolerance)))

    fig2 = figure_collision(None)
    add(
        "Fig. 2: force peak time [ms]",
        0.36,
        1e3 * fig2.history.t[np.argmax(fig2.history.force)],
        0.02,
    )
    add("Fig. 2: rebound speed [m/s]", 0.0, fig2.v_a_after, 1e-3)
    fig3 = figure_collision(2e4)
    add("Fig. 3: happy ball after [m/s]", 3.034, fig3.v_b_after, 0.002)
    add("Fig. 3: unhappy ball after [m/s]", 0.966, fig3.v_a_after, 0.002)
    add("Fig. 3: e", 0.517, fig3.e, 0.002)
    fig4 = figure_collision(1e5)
    add("Fig. 4: e", 0.001, fig4.e, 0.005)
    add("Fig. 4: happy ball after [m/s]", 2.00, fig4.v_b_after, 0.01)
    add("Fig. 4: unhappy ball after [m/s]", 2.00, fig4.v_a_after, 0.01)
    cm = collide(UNHAPPY, happy(2e4), 2.0, -2.0)
    add("Sec. VI: recoil speed in the CM frame [m/s]", 1.034, cm.v_b_after, 0.002)
    swapped = collide(happy(2e4), UNHAPPY, 4.0)
    add(
        "Sec. VI: happy ball at 4 m/s sends the unhappy one off at [m/s]",
        3.034,
        swapped.v_b_after,
        0.002,
    )
    add(
        "Eq. 16 at k2 = 2 k0 (analytic vs numerical)",
        unhappy_cor(2e4, 4e4),
        collide(UNHAPPY, happy(4e4), 4.0).e,
        0.01,
    )

    clamped = impact(paper_racket("clamped-head"), paper_ball(), 0.16, 10.0)
    add("Eq. 6: tennis ball on head-clamped strings, e", 0.88, clamped.e, 0.01)
    add("Eq. 6 (formula) vs simulation", series_cor(0.75, 4e4, 4e4), clamped.e, 1e-3)

    racket = free_racket()
    x = np.linspace(0.0, 0.32, 321)
    sweep = impact(racket, paper_ball(), x, 10.0)
    add("Sec. VII: largest e, at the vibration node", 0.86, sweep.e.max(), 0.03)
    add(
        "Sec. VII: position of largest e minus mode-1 node [m]",
        0.0,
        x[np.argmax(sweep.e)] - racket.beam.modes.nodes(1)[0],
        0.01,
    )
    add("Sec. VII: e at the tip (0.01 m)", 0.54, np.interp(0.01, x, sweep.e), 0.04)
    add("Sec. VII: e at the throat (0.30 m)", 0.71, np.interp(0.30, x, sweep.e), 0.03)
    add(
        "Sec. VIII: effective mass / ball mass, centre of strings",
        3.0,
        np.interp(racket.strings.center, x, sweep.effective_mass) / TENNIS_BALL_MASS,
        0.35,
    )

    zero = impact(paper_racket("clamped-head"), Ball(TENNIS_BALL_MASS, SineLaw(4e4)), 0.16, 10.0)
    add("Sec. VIII: zero-COR ball on clamped strings, e", 0.5, zero.e, 0.05)
    normal, zero_cor = serve_rows(racket, paper_ball(), racket_speed=40.0)
    add(
        "Sec. VIII: serve speed / racket speed, normal ball",
        1.39,
        normal["ratio_simulated"],
        0.07,
    )
    add(
        "Sec. VIII: serve speed / racket speed, zero-COR ball",
        1.12,
        zero_cor["ratio_simulated"],
        0.07,
    )
    add(
        "Sec. VIII: serve-speed reduction [%]",
        19.0,
        zero_cor["reduction_simulated_percent"],
        4.0,
    )
    add(
        "Sec. VIII: energy stored, m2 = 3 m1, ball at rest (Eq. 23)",
        0.25,
        _stored_fraction(3.0, 0.0, 1.0),
        0.005,
    )
    add(
        "Sec. VIII: energy stored, m2 = 3 m1, v1 = v2 (Eq. 23)",
        0.75,
        _stored_fraction(3.0, 1.0, 1.0),
        0.005,
    )
    return rows
