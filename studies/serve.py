"""Serve what-ifs (paper Sec. VIII): how fast a racket sends a ball, normal or zero-COR.

Two ways, side by side:

* **Eq. 22**: V1 = (1 + e) m2 v2 / (m1 + m2), with e and the effective mass m2 taken from the
  simulation of the ball hitting the racket at rest at the same point and relative speed;
* **full simulation**: the racket, swung about a pivot (:class:`racket.Swing`: the wrist by
  default) so that the impact point moves at v2, hits the ball at rest; its speed afterwards
  is read off the impact.

The swing is "the same swing" everywhere: its racket-head speed is the string centre's, and
an impact point farther from the pivot (towards the tip) moves faster, v2 = omega (pivot -
x).  :func:`head_speed_for` solves for the head speed that gives a target serve speed.

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

import warnings
from dataclasses import replace
from typing import TYPE_CHECKING

import numpy as np

from ball import Ball, LinearHysteresis, SineLaw, StiffeningHysteresis, serve_speed
from common.checks import SPEED_RANGE, finite, finite_array, in_range, positive, shown
from common.checks import speed as check_speed
from common.typechecks import asked_by_caller, flag
from common.units import MPH
from racket import Racket, Swing, impact
from racket.solver import Unanswered
from racket.strings.stringing import restrung
from racket.swing import ask_head_speed
from studies.arguments import ball_argument, racket_argument

if TYPE_CHECKING:
    import pandas as pd


def zero_cor_ball(ball: Ball, force: float) -> Ball:
    """The paper's what-if ball (Sec. VIII): the same ball with a sine law (COR 0) whose k0
    is the ball's secant stiffness F / X(F) on its loading curve at the peak ``force`` it
    reaches in the impact at hand (k for a linear ball, at any force); a sine-law ball is
    returned as it is.

    The force, not the speed: a ball whose stiffness grows with its compression is squashed
    far less on strings than on a rigid surface at the same speed, so its secant stiffness
    on a rigid surface would make the twin much stiffer than the ball it stands for (and,
    storing less, lose less than the real ball: a "zero-COR" serve faster than the real one).

    Parameters
    ----------
    ball : Ball
        The real ball.
    force : float
        Peak force [N] of the real ball's impact, > 0.
    """
    force = positive("force", force, "N")
    if isinstance(ball_argument(ball).law, SineLaw):
        return ball
    return replace(ball, law=SineLaw(k0=force / float(ball.law.compression(force, force))))


def serve(racket: Racket, ball: Ball, position: float, swing: Swing, eq22: bool = True) -> dict:
    """Serve speed of ``ball`` from ``racket`` hit at ``position`` by ``swing``, both ways
    (see the module docstring).

    Parameters
    ----------
    racket : Racket
    ball : Ball
    position : float
        Impact point [m from the tip].
    swing : Swing
        The swing: its head speed is the string centre's; the impact point moves at
        v2 = :meth:`Swing.point_speeds` (faster towards the tip).
    eq22 : bool
        Both ways; False: the simulated serve alone (one impact, not two), the values of
        Eq. 22 (``e``, ``effective_mass_kg``, ``serve_eq22_*``, ``ratio_eq22``) NaN.

    Returns
    -------
    dict
        ``position_from_tip_m``, ``position_from_tip_cm``, ``head_speed_m_s``,
        ``point_speed_m_s`` (v2), ``e``, ``effective_mass_kg``, ``serve_eq22_m_s``,
        ``serve_simulated_m_s``, their ratios to v2 ``ratio_eq22`` and ``ratio_simulated``,
        the speeds in mph (``*_mph``), and the peak force ``peak_force_N``.
    """
    eq22 = flag("eq22", eq22)
    v2 = float(swing.point_speeds(racket, position))
    e = mass = by_eq22 = float("nan")
    if eq22:
        at_rest = impact(racket, ball, position, v2)  # the same collision as the swung one
        e, mass = at_rest.e, at_rest.effective_mass
        by_eq22 = serve_speed(min(max(e, 0.0), 1.0), ball.mass, mass, v2)
    swung = impact(racket, ball, position, 0.0, **swing.impact_kwargs(racket, position))
    return {
        "position_from_tip_m": float(position),
        "position_from_tip_cm": 100 * position,
        "head_speed_m_s": swing.head_speed,
        "point_speed_m_s": v2,
        "e": e,
        "effective_mass_kg": mass,
        "serve_eq22_m_s": by_eq22,
        "serve_simulated_m_s": swung.ball_rebound,
        "ratio_eq22": by_eq22 / v2,
        "ratio_simulated": swung.ball_rebound / v2,
        "head_speed_mph": swing.head_speed / MPH,
        "point_speed_mph": v2 / MPH,
        "serve_eq22_mph": by_eq22 / MPH,
        "serve_simulated_mph": swung.ball_rebound / MPH,
        "peak_force_N": swung.peak_force,
    }


def serve_table(
    racket: Racket,
    ball: Ball,
    position=None,
    racket_speed: float = 40.0,
    pivot_from_tip: float | None = None,
    zero_cor: bool = True,
) -> pd.DataFrame:
    """Serve speeds of ``ball`` (and of its zero-COR twin) at each position, for one swing.

    Parameters
    ----------
    racket : Racket
    ball : Ball
    position : float or sequence of float, optional
        Impact point(s) [m from the tip]; default the centre of the strings.
    racket_speed : float
        Racket-head speed [m/s]: the string centre's speed (:class:`racket.Swing`); the
        impact point's speed follows from its distance to the pivot.  One faster than any
        stroke's is asked about in a warning (mph typed as m/s?), as ``racket_speed``.
    pivot_from_tip : float, optional
        The swing's pivot [m from the tip]; default the wrist, 5 cm beyond the butt.
    zero_cor : bool
        Add the rows of the zero-COR twin (:func:`zero_cor_ball` at the peak force of the
        ball's serve at each position; for a sine-law ball the same ball, so the reduction
        is 0) and the reductions.  The twin takes the strings as a linear, lossless,
        massless spring, as any sine-law ball does: on a real bed its reduction is against
        the ball on that same spring, so that the two differ in the ball alone.

    Returns
    -------
    DataFrame
        Index ``ball`` (``normal``, ``zero-COR``), one row per ball and position; columns
        those of :func:`serve`, plus ``reduction_eq22_percent`` and
        ``reduction_simulated_percent`` with ``zero_cor`` (0 for the normal ball).
    """
    import pandas as pd

    rows = serve_rows(racket, ball, position, racket_speed, pivot_from_tip, zero_cor)
    return pd.DataFrame(rows).set_index("ball")


def serve_rows(
    racket: Racket,
    ball: Ball,
    position=None,
    racket_speed: float = 40.0,
    pivot_from_tip: float | None = None,
    zero_cor: bool = True,
    eq22: bool = True,
) -> list[dict]:
    """The rows of :func:`serve_table` as dicts, without pandas: the normal ball's, one per
    position, then (with ``zero_cor``) its twin's.

    Parameters
    ----------
    racket : Racket
    ball : Ball
    position : float or sequence of float, optional
        Impact point(s) [m from the tip]; default the centre of the strings.
    racket_speed : float
        Racket-head speed [m/s], as in :func:`serve_table`.
    pivot_from_tip : float, optional
        The swing's pivot [m from the tip]; default the wrist, 5 cm beyond the butt.
    zero_cor : bool
        Add the rows of the zero-COR twin, as in :func:`serve_table`.
    eq22 : bool
        Both ways; False: the simulated serves alone, half the impacts, the values of Eq. 22
        (:func:`serve`) and ``reduction_eq22_percent`` NaN.

    Returns
    -------
    list of dict
        Each row's ``ball`` (``normal``, ``zero-COR``) and the columns of :func:`serve_table`.
    """
    racket, ball = racket_argument(racket), ball_argument(ball)
    zero_cor, eq22 = flag("zero_cor", zero_cor), flag("eq22", eq22)
    racket_speed = check_speed("racket_speed", racket_speed)
    where = racket.strings.center if position is None else position
    positions = np.atleast_1d(finite_array("position", where, "m from the tip"))
    if positions.size == 0 or positions.ndim != 1:
        raise ValueError(
            f"position must be one impact point or a list of them [m from the tip], got "
            f"{shown(position)}"
        )
    ask_head_speed("racket_speed", racket_speed)
    with asked_by_caller():  # asked about as racket_speed, its name here
        swing = Swing(racket_speed, pivot_from_tip)
    rows = [{"ball": "normal", **serve(racket, ball, float(x), swing, eq22)} for x in positions]
    if not zero_cor:
        return rows
    twins = _twin_rows(racket, ball, rows, positions, swing, eq22)
    for row in rows:  # (the normal ball's reductions: none)
        row.update(reduction_eq22_percent=0.0, reduction_simulated_percent=0.0)
    return rows + twins


def _twin_rows(racket, ball, rows, positions, swing, eq22: bool) -> list[dict]:
    """The zero-COR twin's rows of :func:`serve_rows`, each with its reductions against the
    normal ball's serve (its ``rows``, read only, or on the twin's bed).
    """
    # The twin meets the bed a sine-law ball can take, linear, lossless and massless (the
    # same for the paper's racket), and so, for its reduction, does the real ball.
    plain, reference = racket, rows
    if not racket.strings.plain:
        plain = replace(racket, strings=replace(racket.strings, stretch=0.0, loss=0.0,
                                                moving_mass=0.0))  # fmt: skip
        reference = [serve(plain, ball, float(x), swing, eq22) for x in positions]
    twins = [  # each point's twin as stiff as the ball is in that point's serve
        {"ball": "zero-COR", **serve(plain, zero_cor_ball(ball, row["peak_force_N"]),
                                     row["position_from_tip_m"], swing, eq22)}
        for row in reference
    ]  # fmt: skip
    for twin, row in zip(twins, reference, strict=True):  # the ball on the twin's bed
        for how in ("eq22", "simulated"):
            col = f"serve_{how}_m_s"
            twin[f"reduction_{how}_percent"] = 100.0 * (1.0 - twin[col] / row[col])
    return twins


SLOWEST_HEAD_SPEED = 0.1
"""Slowest racket-head speed [m/s] the serve search tries (an assumption: far below any
stroke, so a target it cannot reach is a typo or the wrong unit)."""


def head_speed_for(
    racket: Racket,
    ball: Ball,
    target: float,
    position: float | None = None,
    pivot_from_tip: float | None = None,
) -> float:
    """The racket-head speed [m/s] whose swing sends ``ball`` (at rest) off at ``target``
    (the simulated serve, solved by Brent's method to 1e-9 m/s).

    Parameters
    ----------
    racket : Racket
        A free racket.
    ball : Ball
        The ball, at rest before the impact.
    target : float
        Serve (ball exit) speed to reach [m/s].
    position : float, optional
        Impact point [m from the tip]; default the centre of the strings.
    pivot_from_tip : float, optional
        The swing's pivot [m from the tip]; default the wrist, 5 cm beyond the butt.
    """
    from scipy.optimize import brentq

    racket, ball = racket_argument(racket), ball_argument(ball)
    target = check_speed("target", target)
    if position is None:
        position = racket.strings.center
    position = float(racket.check_positions(finite("position", position, "m from the tip"))[0])
    heads, reach = serve_reach(racket, ball, position, pivot_from_tip)
    if not reach[0] < target < reach[1]:
        raise ValueError(
            f"target ball speed must be in ({reach[0]:.4g}, {reach[1]:.4g}) m/s at "
            f"{100 * position:.1f} cm from the tip (head speeds of "
            f"{heads[0]:g}-{heads[1]:.4g} m/s), got {shown(target)}"
        )

    def miss(head):
        return _serve(racket, ball, position, head, pivot_from_tip) - target

    with warnings.catch_warnings():  # the search passes through absurd speeds
        warnings.simplefilter("ignore")
        return float(brentq(miss, *heads, xtol=1e-9))


def serve_reach(
    racket: Racket, ball: Ball, position: float, pivot_from_tip: float | None = None
) -> tuple[tuple[float, float], tuple[float, float]]:
    """The racket-head speeds [m/s] :func:`head_speed_for` searches, and the serve speeds
    [m/s] they reach (the simulated serve at each end): from :data:`SLOWEST_HEAD_SPEED` to
    the head speed that moves the impact point at the fastest speed racket-impact accepts,
    or answers (:class:`racket.solver.Unanswered`) where that is slower.

    Parameters
    ----------
    racket, ball, position, pivot_from_tip :
        As in :func:`head_speed_for` (``position`` given).
    """
    ratio = float(Swing(1.0, pivot_from_tip).point_speeds(racket, position))
    slowest, fastest = SLOWEST_HEAD_SPEED, SPEED_RANGE[1] / max(ratio, 1.0)
    with warnings.catch_warnings():  # the ends are absurd speeds
        warnings.simplefilter("ignore")
        reach = _serve(racket, ball, position, slowest, pivot_from_tip)
        try:
            top = _serve(racket, ball, position, fastest, pivot_from_tip)
        except Unanswered as beyond:  # the model's limit, below the fastest accepted
            fastest = beyond.limit / max(ratio, 1.0)
            top = _serve(racket, ball, position, fastest, pivot_from_tip)
    return (slowest, fastest), (reach, top)


def _serve(racket, ball, position, head, pivot_from_tip) -> float:
    """The simulated serve speed [m/s] alone (:func:`serve` would also run the impact at
    rest).
    """
    moved = Swing(head, pivot_from_tip).impact_kwargs(racket, position)
    return float(impact(racket, ball, position, 0.0, **moved).ball_rebound)


def serve_what_if(
    racket: Racket,
    ball: Ball,
    position: float | None = None,
    racket_speed: float = 40.0,
    string_stiffness=None,
    ball_stiffness=None,
    pivot_from_tip: float | None = None,
) -> pd.DataFrame:
    """Serve-speed reduction from a zero-COR ball against string and ball stiffness.

    Parameters
    ----------
    racket, ball, position, racket_speed, pivot_from_tip :
        As in :func:`serve_table` (one position).
    string_stiffness : sequence of float, optional
        String-bed stiffnesses [N/m] (tension), each in
        :data:`studies.sweeps.STRING_STIFFNESS_RANGE`; default 1e4 to 1e5 N/m.
    ball_stiffness : sequence of float, optional
        Ball stiffnesses k [N/m] (the normal ball keeps its COR; a StiffeningHysteresis
        ball's k is its small-compression stiffness); default 2e4 to 1e5 N/m.

    Returns
    -------
    DataFrame
        One row per case: ``varied`` ("strings" or "ball"), ``value``,
        then the zero-COR row of :func:`serve_table` (serve speeds and reductions).
    """
    import pandas as pd

    return pd.DataFrame(
        serve_what_if_columns(
            racket, ball, position, racket_speed, string_stiffness, ball_stiffness, pivot_from_tip
        )
    )


def serve_what_if_columns(
    racket: Racket,
    ball: Ball,
    position: float | None = None,
    racket_speed: float = 40.0,
    string_stiffness=None,
    ball_stiffness=None,
    pivot_from_tip: float | None = None,
    eq22: bool = True,
) -> dict:
    """The columns of :func:`serve_what_if` as lists, without pandas.

    Parameters
    ----------
    racket, ball, position, racket_speed, string_stiffness, ball_stiffness, pivot_from_tip :
        As in :func:`serve_what_if`.
    eq22 : bool
        Both ways; False: the simulated serves alone, half the impacts, the values of
        Eq. 22 (:func:`serve`) and ``reduction_eq22_percent`` NaN.

    Returns
    -------
    dict
        The columns of :func:`serve_what_if` -> one value per case.
    """
    racket, ball = racket_argument(racket), ball_argument(ball)
    eq22 = flag("eq22", eq22)
    if position is not None:
        position = finite("position", position, "m from the tip")
    racket_speed = check_speed("racket_speed", racket_speed)
    if not isinstance(ball.law, (LinearHysteresis, StiffeningHysteresis)):
        raise ValueError(
            "ball must have a LinearHysteresis or StiffeningHysteresis law (a stiffness k in "
            f"N/m) for a stiffness what-if, got {type(ball.law).__name__}"
        )
    position = racket.strings.center if position is None else position
    from studies.sweeps import STRING_STIFFNESS_RANGE

    string_stiffness = np.geomspace(1e4, 1e5, 7) if string_stiffness is None else string_stiffness
    string_stiffness = [
        in_range("string_stiffness", k_s, *STRING_STIFFNESS_RANGE, "N/m")
        for k_s in np.atleast_1d(string_stiffness)
    ]
    ball_stiffness = np.geomspace(2e4, 1e5, 5) if ball_stiffness is None else ball_stiffness
    ball_stiffness = [
        positive("ball_stiffness", k_b, "N/m") for k_b in np.atleast_1d(ball_stiffness)
    ]
    ask_head_speed("racket_speed", racket_speed)  # once, not once a row
    rows = []
    with asked_by_caller():
        for k_s in string_stiffness:
            variant = replace(racket, strings=restrung(racket.strings, stiffness=float(k_s)))
            twin = serve_rows(variant, ball, position, racket_speed, pivot_from_tip, True, eq22)[-1]
            rows.append({"varied": "strings", "value": float(k_s), **twin})
        for k_b in ball_stiffness:
            stiff = replace(ball, law=replace(ball.law, k=float(k_b)))
            twin = serve_rows(racket, stiff, position, racket_speed, pivot_from_tip, True, eq22)[-1]
            rows.append({"varied": "ball", "value": float(k_b), **twin})
    names = [name for name in rows[0] if name != "ball"] if rows else []  # (no cases: none)
    return {name: [row[name] for row in rows] for name in names}
