"""The bat-certification numbers (issue 37): BBCOR, collision efficiency, BESR and BPF of a
bat, from simulated speeds as the standards define them (:mod:`bat.certification`,
``data/bats.md`` section 4.3), at the location of maximum BBCOR (:func:`bbcor_test`).

The test as the sources describe it (``data/bats.md`` section 4.1): a ball fired from a
cannon onto the bat at rest, pivoted 6 in from the knob and clamped 1 in either side of the
pivot (:func:`bat.Bat` ``support="pivoted"``); the BBCOR "at the maximum BBCOR location
... must not exceed 0.500" (:data:`bat.certification.BBCOR_LIMIT`).  Here:

* BBCOR is the COR of the pivoted bat's rigid turn, the relative speeds after over before
  (:attr:`racket.Impact.e`), which equals BBCOR = e_A (1 + r) + r from the ball's own
  v_out / v_in on the rig (e_A) and r = m_ball d**2 / I_pivot (the test checks it);
* the collision efficiency e_a as ASTM F2219-2023 derives it, "assuming the bat is
  unconstrained": e_a = (BBCOR - R0) / (1 + R0), R0 = m_ball / M (1 + b**2 / r_g**2) of the
  free bat (N2000 eq. 16); BESR = e_a + 1/2 (WSU); BPF = BBCOR over the ball's own COR on a
  rigid wall at the test's speed (:func:`ball.collide` with :data:`ball.WALL`);
* beside them, the free bat struck at rest at the same point: its own simulated e_A and COR,
  what the derivation above stands for.

Where the maximum lies: BBCOR along the barrel (:attr:`bat.Bat.barrel`, short of the
clamps), every cm, then a fine sweep between
the best point's neighbours and the parabola through its best three; the numbers are
simulated there.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import TYPE_CHECKING

import numpy as np

from ball import WALL, collide
from ball.baseball import E0_FIG2, E0_HIGH_SPEED
from bat import certification as cert
from common.typechecks import choice
from common.units import MPH, SPEED_UNITS
from racket import impact
from studies.bat.sweep import (
    REFINE_POINTS,
    SWEEP_STEP,
    _bat_and_ball,
    _speed,
    bat_words,
    parabola_peak,
)
from studies.conditions import speed_text

if TYPE_CHECKING:
    import pandas as pd

BBCOR_TEST_SPEED = 136.0 * MPH
"""The ball's speed [m/s] in the BBCOR test: 136 mph, **an ASSUMPTION**: "often cited; not
confirmed" (``data/bats.md`` section 4.1: the nominal inbound speed was not found; the
NCAA's cannon fires at "at least 150 mph", as quoted there)."""

BBCOR_UNCERTAINTY = round(E0_FIG2 - E0_HIGH_SPEED, 12)
"""How far [-] the model's BBCOR may lie from the test's, either way: 0.03, **an
ASSUMPTION**.  No measured bat output was at hand to check the model against
(``docs/validation.md``, "Bats: no row yet"), so it is the spread of its largest unknown
input.  A bat that barely rings at its best point gives back the ball's own COR (a BPF near
1: BBCOR = BPF e0), and the test ball's COR at the test's speed was not found
(``data/bats.md`` section 4.1).  N2000 gives a baseball's e0 at high speed twice: 0.50,
assumed for its high-speed case (p. 986, :data:`ball.baseball.E0_HIGH_SPEED`), and 0.53,
its Fig. 2 curve's, a 58 m/s impact on a rigid surface near the test's 60.8 m/s
(:data:`ball.baseball.E0_FIG2`); the gap between them is taken as the BBCOR's (BBCOR moves
by about BPF times a change of e0: ``tests/test_bat_study.py`` checks it).  The test's speed,
136 mph or the quoted "at least 150 mph", moves the R161's BBCOR by less than a tenth of
it (checked there too)."""

BBCOR_CANNON_SPEED = 150.0 * MPH
"""The NCAA BBCOR machine's cannon's speed [m/s]: "a muzzle velocity of at least 150 mph"
(markrichard.org, a reader's summary of the NCAA protocol, as quoted in ``data/bats.md``
section 4.1).  With :data:`BBCOR_TEST_SPEED` it brackets the speeds the sources give the
test: a verdict at a speed outside them is not the standard's, and the command line says so
(``racket-impact bat bbcor --pitch 136``: mph typed as m/s?)."""

VERDICTS = ("passes", "fails", "cannot call")
"""What :func:`verdict` says of a BBCOR."""


@dataclass(frozen=True)
class BbcorTest:
    """A bat's certification numbers (built by :func:`bbcor_test`).

    Attributes
    ----------
    table : DataFrame
        Two rows, ``method`` "pivoted rig" (the test: BBCOR simulated on the rig, e_a
        derived for the free bat as ASTM F2219-2023) and "free bat" (the bat free and at
        rest, its own COR and e_A simulated); columns ``bat``, ``method``,
        ``position_from_knob_cm``, ``position_from_tip_cm``, ``test_speed_m_s``,
        ``bbcor`` [-], ``ball_e_A`` [-] (the ball's v_out / v_in on that set-up),
        ``mass_ratio`` [-] (the rig's r, the free bat's R0), ``collision_efficiency``
        [-], ``besr`` [-], ``bpf`` [-], ``limit`` [-], ``passes`` (BBCOR at most the
        limit), ``uncertainty`` [-] (:data:`BBCOR_UNCERTAINTY`) and ``verdict``
        (:func:`verdict`; the free bat's row has neither, the limit is the rig's).
    along : DataFrame
        BBCOR along the search, one row per point: ``bat``, ``position_from_knob_cm``,
        ``position_from_tip_cm``, ``bbcor``, ``ball_e_A``, ``mass_ratio`` and
        ``bbcor_closed_form`` (e_A (1 + r) + r).
    from_knob : float
        The location of maximum BBCOR [m from the knob].
    bbcor : float
        BBCOR there [-], from the simulated speeds.
    closed_form : float
        e_A (1 + r) + r there [-] from the rig's simulated e_A and r.
    rig_efficiency : float
        The ball's v_out / v_in on the rig [-].
    mass_ratio : float
        r = m_ball d**2 / I_pivot [-].
    free_ratio : float
        R0 of the free bat there [-].
    collision_efficiency : float
        e_a derived as ASTM F2219-2023 [-].
    besr : float
        e_a + 1/2 [-].
    bpf : float
        BBCOR over the ball's COR [-].
    ball_cor : float
        The ball's COR on a rigid wall at the test's speed [-].
    passes : bool
        BBCOR at most :data:`bat.certification.BBCOR_LIMIT`.
    verdict : str
        "passes", "fails" or "cannot call" (:func:`verdict`): the comparison with the limit
        said only where the BBCOR lies farther from it than :data:`BBCOR_UNCERTAINTY`.
    free_efficiency, free_cor : float
        The free bat at rest struck there: its simulated e_A and COR [-].
    speed : float
        The test's speed [m/s].
    conditions : str
        What it was computed for.
    unit : str
        The unit the speeds are said in.
    """

    table: pd.DataFrame
    along: pd.DataFrame
    from_knob: float
    bbcor: float
    closed_form: float
    rig_efficiency: float
    mass_ratio: float
    free_ratio: float
    collision_efficiency: float
    besr: float
    bpf: float
    ball_cor: float
    passes: bool
    verdict: str
    free_efficiency: float
    free_cor: float
    speed: float
    conditions: str
    unit: str = "m/s"


def verdict(bbcor: float, uncertainty: float = BBCOR_UNCERTAINTY) -> str:
    """The verdict on a BBCOR against :data:`bat.certification.BBCOR_LIMIT`: "passes" below
    it by more than ``uncertainty``, "fails" above it by more, and "cannot call" within
    ``uncertainty`` of it, where the model cannot tell (:data:`VERDICTS`).

    Parameters
    ----------
    bbcor : float
        The bat-ball COR [-].
    uncertainty : float
        How far the model's BBCOR may lie from the test's [-]; default
        :data:`BBCOR_UNCERTAINTY`.

    Examples
    --------
    >>> verdict(0.5003), verdict(0.44), verdict(0.66)
    ('cannot call', 'passes', 'fails')
    """
    margin = bbcor - cert.BBCOR_LIMIT
    if abs(margin) <= uncertainty:
        return "cannot call"
    return "fails" if margin > 0 else "passes"


def search_points(rig, step: float = SWEEP_STEP) -> np.ndarray:
    """Where the maximum BBCOR is searched [m from the tip]: every ``step`` from the barrel's
    end along the barrel (:attr:`bat.Bat.barrel`, **an assumption**: the standard's search
    procedure was not found, ``data/bats.md`` section 4.1; the thin handle, where a 60 m/s
    ball bends a pivoted bat far beyond a beam's small deflections, is left out), short of
    the rig's clamps.

    Parameters
    ----------
    rig : Bat
        The pivoted bat.
    step : float
        The spacing [m].
    """
    end = min(rig.barrel[1], rig.pivot - rig.clamp_offset - step)
    return np.round(step * np.arange(int(np.floor(end / step + 1e-9)) + 1), 12)


def bbcor_test(
    bat=None,
    ball=None,
    speed: float = BBCOR_TEST_SPEED,
    unit: str = "m/s",
    bat_name: str | None = None,
    ball_name: str | None = None,
) -> BbcorTest:
    """The certification numbers of ``bat`` at its location of maximum BBCOR (see the
    module docstring).

    Parameters
    ----------
    bat : Bat or str, optional
        The bat (its pivot and clamps are the rig's: by default 6 in from the knob, 1 in
        either side; its support is set to "pivoted" and, for the comparison, "free"), or a
        preset's name; default :data:`bat.DEFAULT_BAT`.
    ball : Ball, optional
        The ball; default :data:`ball.DEFAULT_BASEBALL`.
    speed : float
        The ball's speed [m/s]; default :data:`BBCOR_TEST_SPEED` (an assumption).
    unit : str
        "m/s", "mph" or "km/h": the speed also in this unit.
    bat_name, ball_name : str, optional
        Their names as the user gave them, for the conditions.

    Returns
    -------
    BbcorTest

    Examples
    --------
    >>> test = bbcor_test()
    >>> abs(test.bbcor - test.closed_form) < 1e-6
    True
    """
    import pandas as pd

    from studies.tables import speeds_in

    bat, ball = _bat_and_ball(bat, ball)
    rig, free = replace(bat, support="pivoted"), replace(bat, support="free")
    speed = _speed("speed", speed)
    choice("unit", unit, tuple(SPEED_UNITS))
    length, name = rig.beam.length, bat_name or bat.name
    x = search_points(rig)
    along = impact(rig, ball, x, speed)
    k = int(np.argmax(along.e))
    fine = np.linspace(x[max(k - 1, 0)], x[min(k + 1, x.size - 1)], REFINE_POINTS)
    found = impact(rig, ball, fine, speed)
    best = parabola_peak(fine, np.asarray(found.e))[0]
    hit = impact(rig, ball, best, speed)
    r = float(cert.mass_ratio(ball.mass, rig.pivot - best, rig.inertia_pivot))
    bbcor, rig_e_a = float(hit.e), float(hit.e_A)
    r0 = float(ball.mass / free.effective_mass(best))
    e_a = float(cert.collision_efficiency(bbcor, r0))
    ball_cor = float(collide(ball, WALL, speed).e)
    on_free = impact(free, ball, best, speed)
    free_e_a, free_cor = float(on_free.e_A), float(on_free.e)
    ratios = cert.mass_ratio(ball.mass, rig.pivot - x, rig.inertia_pivot)
    along_table = pd.DataFrame({
        "bat": name,
        "position_from_knob_cm": 100 * (length - x),
        "position_from_tip_cm": 100 * x,
        "bbcor": along.e,
        "ball_e_A": along.e_A,
        "mass_ratio": ratios,
        "bbcor_closed_form": cert.bbcor(along.e_A, ratios),
    })  # fmt: skip
    rows = [
        ("pivoted rig", bbcor, rig_e_a, r, e_a),
        ("free bat", free_cor, free_e_a, r0, free_e_a),
    ]
    table = pd.DataFrame([
        {"bat": name, "method": method, "position_from_knob_cm": 100 * (length - best),
         "position_from_tip_cm": 100 * best, "test_speed_m_s": speed, "bbcor": cor,
         "ball_e_A": measured, "mass_ratio": ratio, "collision_efficiency": efficiency,
         "besr": float(cert.besr(efficiency)), "bpf": float(cert.bpf(cor, ball_cor)),
         "limit": cert.BBCOR_LIMIT,
         # (the limit is the rig's: the free bat's row has no verdict)
         "passes": bool(cor <= cert.BBCOR_LIMIT) if method == "pivoted rig" else None,
         "uncertainty": BBCOR_UNCERTAINTY if method == "pivoted rig" else None,
         "verdict": verdict(cor) if method == "pivoted rig" else None}
        for method, cor, measured, ratio, efficiency in rows
    ])  # fmt: skip
    conditions = (
        f"{bat_words(rig, bat_name)}, ball {ball_name or f'of {1e3 * ball.mass:.4g} g'} at "
        f"{speed_text(speed, unit)} (the test's speed: an assumption), the bat at rest; the "
        "free bat beside it"
    )
    return BbcorTest(
        table=speeds_in(table, unit, ("test_speed",)), along=along_table,
        from_knob=float(length - best), bbcor=bbcor,
        closed_form=float(cert.bbcor(rig_e_a, r)), rig_efficiency=rig_e_a, mass_ratio=r,
        free_ratio=r0, collision_efficiency=e_a, besr=float(cert.besr(e_a)),
        bpf=float(cert.bpf(bbcor, ball_cor)), ball_cor=ball_cor,
        passes=bool(bbcor <= cert.BBCOR_LIMIT), verdict=verdict(bbcor),
        free_efficiency=free_e_a, free_cor=free_cor, speed=speed, conditions=conditions, unit=unit,
    )  # fmt: skip
