"""Serve what-ifs (paper Sec. VIII): how fast does a racket send a ball, normal or zero-COR?

Two ways, side by side:

* **Eq. 22**: V1 = (1 + e) m2 v2 / (m1 + m2), with e and the effective mass m2 taken from the
  simulation of the ball hitting the racket at rest at the same point and relative speed;
* **full simulation**: the racket, swung so that the impact point moves at v2 (a rotation
  about ``pivot``), hits the ball at rest; its speed afterwards is read off the impact.

The two agree to round-off (1e-15 measured; 3e-11 for a sine-law ball, whose Xo is found
to about that), for a rotation about the wrist as for a translation.  The racket's
equations are linear in its motion (small rotations), so the swing's rigid-body motion, a
free motion that the racket keeps without force, superposes on the collision: the contact
sees only the approach of the ball to the impact point, v2 either way, and Eq. 22 holds
with e and m2 of the simulated collision, not as an approximation.

The zero-COR ball of the paper (Sec. VIII) is a sine-law ball (Eq. 7, COR 0 on a rigid
surface) "of about the same stiffness" as the real ball: :func:`zero_cor_ball` gives it k0
equal to the ball's secant stiffness F_max / X_max on a rigid surface at the impact speed
(k for a linear ball; for a power-law ball the stiffness it actually has at that speed).
A sine-law ball is its own zero-COR ball.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pandas as pd

from ball import Ball, LinearHysteresis, SineLaw, serve_speed
from common.checks import positive
from racket import Racket, StringBed, impact

WRIST_BEYOND_BUTT = 0.05
"""Default swing pivot: the wrist, this far beyond the butt [m]."""


def zero_cor_ball(ball: Ball, speed: float) -> Ball:
    """The paper's what-if ball (Sec. VIII): the same ball with a sine law (COR 0) whose k0
    is the ball's secant stiffness on a rigid surface at ``speed`` [m/s] (k for a linear
    ball); a sine-law ball is returned as it is."""
    if isinstance(ball.law, SineLaw):
        return ball
    return replace(ball, law=SineLaw(k0=ball.law.secant_stiffness(ball.mass, speed)))


def serve(
    racket: Racket, ball: Ball, position: float, racket_speed: float, pivot: float | None = None
) -> dict:
    """Serve speed of ``ball`` from ``racket`` at ``position``, both ways (see module docs).

    Parameters
    ----------
    racket : Racket
    ball : Ball
    position : float
        Impact point [m from the tip].
    racket_speed : float
        Speed v2 of the impact point towards the ball [m/s].
    pivot : float, optional
        Swing pivot [m from the tip]; default the wrist, 5 cm beyond the butt.

    Returns
    -------
    dict
        ``e``, ``effective_mass_kg``, ``serve_eq22_m_s``, ``serve_simulated_m_s`` and the two
        ratios to v2, ``ratio_eq22`` and ``ratio_simulated``.
    """
    racket_speed = positive("racket_speed", racket_speed, "m/s")
    if pivot is None:
        pivot = racket.beam.length + WRIST_BEYOND_BUTT
    at_rest = impact(racket, ball, position, racket_speed)
    swung = impact(racket, ball, position, 0.0, swing_speed=racket_speed, pivot=pivot)
    eq22 = serve_speed(
        min(max(at_rest.e, 0.0), 1.0), ball.mass, at_rest.effective_mass, racket_speed
    )
    return {
        "e": at_rest.e,
        "effective_mass_kg": at_rest.effective_mass,
        "serve_eq22_m_s": eq22,
        "serve_simulated_m_s": swung.ball_rebound,
        "ratio_eq22": eq22 / racket_speed,
        "ratio_simulated": swung.ball_rebound / racket_speed,
    }


def serve_table(
    racket: Racket,
    ball: Ball,
    position: float | None = None,
    racket_speed: float = 40.0,
    pivot: float | None = None,
) -> pd.DataFrame:
    """Serve speeds of ``ball`` and of its zero-COR twin, with the reduction in percent.

    ``position`` defaults to the centre of the strings.  Rows: ``normal``, ``zero-COR``
    (:func:`zero_cor_ball` at the racket speed; for a sine-law ball the same ball, so the
    reduction is 0); columns: those of :func:`serve`, plus ``reduction_eq22_percent`` and
    ``reduction_simulated_percent`` (zero-COR row; 0 for the normal ball).
    """
    position = racket.strings.center if position is None else position
    twin = zero_cor_ball(ball, positive("racket_speed", racket_speed, "m/s"))
    rows = {
        name: serve(racket, b, position, racket_speed, pivot)
        for name, b in (("normal", ball), ("zero-COR", twin))
    }
    table = pd.DataFrame.from_dict(rows, orient="index")
    table.index.name = "ball"
    for how in ("eq22", "simulated"):
        col = f"serve_{how}_m_s"
        table[f"reduction_{how}_percent"] = 100.0 * (1.0 - table[col] / table.loc["normal", col])
    return table


def serve_what_if(
    racket: Racket,
    ball: Ball,
    position: float | None = None,
    racket_speed: float = 40.0,
    string_stiffness=None,
    ball_stiffness=None,
    pivot: float | None = None,
) -> pd.DataFrame:
    """Serve-speed reduction from a zero-COR ball against string and ball stiffness.

    Parameters
    ----------
    string_stiffness : sequence of float, optional
        String-bed stiffnesses [N/m] (tension); default 1e4 to 1e5 N/m.
    ball_stiffness : sequence of float, optional
        Ball stiffnesses k [N/m] (the normal ball keeps its COR); default 2e4 to 1e5 N/m.

    Returns
    -------
    DataFrame
        One row per case: ``varied`` ("string_stiffness" or "ball_stiffness"), ``value``,
        then the zero-COR row of :func:`serve_table` (serve speeds and reductions).
    """
    if not isinstance(ball.law, LinearHysteresis):
        raise ValueError(
            f"ball must have a LinearHysteresis law for a stiffness what-if, got {ball.law!r}"
        )
    position = racket.strings.center if position is None else position
    string_stiffness = np.geomspace(1e4, 1e5, 7) if string_stiffness is None else string_stiffness
    ball_stiffness = np.geomspace(2e4, 1e5, 5) if ball_stiffness is None else ball_stiffness
    rows = []
    for k_s in string_stiffness:
        variant = Racket(racket.beam, StringBed(k_s, racket.strings.extent), racket.support)
        row = serve_table(variant, ball, position, racket_speed, pivot).loc["zero-COR"]
        rows.append({"varied": "string_stiffness", "value": float(k_s), **row.to_dict()})
    for k_b in ball_stiffness:
        stiff = Ball(ball.mass, replace(ball.law, k=float(k_b)))
        row = serve_table(racket, stiff, position, racket_speed, pivot).loc["zero-COR"]
        rows.append({"varied": "ball_stiffness", "value": float(k_b), **row.to_dict()})
    return pd.DataFrame(rows)
