"""What the strings do, for a stringer: one racket strung with each string in turn (issue 35).

For each string (a preset of :data:`racket.strings.stringing.STRINGS` or a hybrid), at the racket's
tension, pattern and state: the bed's numbers (its stiffness and the ERT's DT, its stretch,
its loss, its mass) and what they do at the string centre: the apparent COR e_A (the
power a stationary racket gives), e, the dwell time, the serve at a head speed
(:func:`studies.serve.serve`, the swing about the wrist), the topspin forehand's spin (the
stroke model, :mod:`studies.strokes.stroke`) and the feel at the hand
(:mod:`studies.feel`).  Control is not modelled: nothing here says where the ball goes.
"""

from __future__ import annotations

from dataclasses import replace

import pandas as pd

from ball import Ball
from common.checks import finite
from common.checks import speed as check_speed
from common.typechecks import ask, instance
from racket import STROKES, Racket, Swing, impact
from racket.feel import hand_feel
from racket.strings.ert import dt_reading, stiffness_from_dt
from racket.strings.stringing import STRING_CHOICES, restrung
from studies.feel import FEEL_SUPPORT, feel_numbers
from studies.serve import serve
from studies.strings.inputs import stiff_dt
from studies.strokes.stroke import stroke_table

SPIN_STROKE = "topspin-forehand"
"""The stroke whose spin the table gives: the topspin forehand, the stroke ``validate``
checks (:data:`studies.strokes.stroke.VALIDATED`)."""


def string_table(
    racket: Racket,
    ball: Ball,
    speed: float,
    head_speed: float,
    strings=STRING_CHOICES,
    gauge=None,
    dt=None,
) -> pd.DataFrame:
    """``racket`` strung with each of ``strings`` in turn, at its own tension, pattern and
    state (the racket's bed must have a string: :attr:`racket.StringBed.stringing`): the
    bed, its power, its dwell time, the serve, the spin of the topspin forehand (the stroke
    model, :data:`SPIN_STROKE`) and the feel at the hand (:data:`studies.feel.FEEL_SUPPORT`).
    Control (where the ball goes for a given swing) is not modelled.

    Parameters
    ----------
    racket : Racket
        The racket and its bed (its stringing gives the tension, pattern and state).
    ball : Ball
        The ball.
    speed : float
        Ball speed onto the racket at rest [m/s] (e, e_A and the dwell time).
    head_speed : float
        Racket-head (string centre) speed of the serve [m/s], about the wrist.
    strings : sequence of str
        Presets or "MAINS/CROSSES" hybrids.
    gauge : float or str, optional
        Every string's gauge [m, or a name: "17"]; default each string's own.
    dt : float, optional
        A measured ERT reading [kp/cm]: each row's bed reads it, its stiffness solved on its
        own strings (:func:`racket.strings.ert.stiffness_from_dt`); default the racket's
        tension (or measured stiffness) for all.

    Returns
    -------
    pandas.DataFrame
        One row per string: ``string`` (material and gauge; the pattern, tension and state
        are the racket's), ``dt_kp_cm``, ``stiffness_kN_m``, ``stretch_1_m2``,
        ``loss_percent``, ``bed_mass_g``, ``moving_mass_g`` (the strings inside the
        head, and the part moving with the ball), ``e``, ``e_A``, ``dwell_ms``, ``serve_m_s``,
        ``serve_ratio`` (the serve over the head speed), ``forehand_spin_rpm`` (the
        :data:`SPIN_STROKE`'s spin, its own swing, on dry strings that slide) and
        ``feel_shock_g``, ``feel_vibration_g`` (:func:`studies.feel.feel_numbers`, the
        racket held as :data:`studies.feel.FEEL_SUPPORT` says, hit at ``speed``).
    """
    instance("racket", racket, Racket, "a racket.Racket")
    instance("ball", ball, Ball, "a ball.Ball")
    speed = check_speed("speed", speed)
    head_speed = check_speed("head_speed", head_speed)
    if racket.strings.stringing is None:
        raise ValueError(
            "the racket's string bed has no string (the paper's spring): string it first, "
            "e.g. --string polyester"
        )
    if dt is not None:  # a DT in N/cm typed as kp/cm asked about (refused by the search)
        ask(stiff_dt, "dt", finite("dt", dt, "kp/cm"))
    strings = [strings] if isinstance(strings, str) else list(strings)
    if not strings:
        raise ValueError("strings names no string to compare: give at least one, e.g. 'nylon'")
    rows = []
    for name in strings:
        bed = restrung(racket.strings, string=name, gauge=gauge)
        if dt is not None:
            bed = restrung(bed, stiffness=stiffness_from_dt(bed, dt, "dt"))
        strung = replace(racket, strings=bed)
        rows.append(_row(strung, ball, speed, head_speed))
    return pd.DataFrame(rows)


def _row(racket: Racket, ball: Ball, speed: float, head_speed: float) -> dict:
    bed, centre = racket.strings, racket.strings.center
    hit = impact(racket, ball, centre, speed)
    served = serve(racket, ball, centre, Swing(head_speed))
    spin = [(SPIN_STROKE, STROKES[SPIN_STROKE])]
    held = replace(racket, support=FEEL_SUPPORT)
    feel = feel_numbers(hand_feel(held, ball, centre, speed), held)
    strung = bed.stringing
    pattern = f" {strung.pattern[0]}x{strung.pattern[1]}"  # the racket's, in the conditions
    return {
        "string": strung.describe().rsplit(pattern, 1)[0],
        "dt_kp_cm": dt_reading(bed.stiffness, bed.stretch),
        "stiffness_kN_m": bed.stiffness / 1e3,
        "stretch_1_m2": bed.stretch,
        "loss_percent": 100.0 * bed.loss,
        "bed_mass_g": 1e3 * bed.stringing.mass(bed.area, bed.aspect),
        "moving_mass_g": 1e3 * bed.moving_mass,
        "e": hit.e,
        "e_A": hit.e_A,
        "dwell_ms": 1e3 * hit.contact_time,
        "serve_m_s": served["serve_simulated_m_s"],
        "serve_ratio": served["ratio_simulated"],
        "forehand_spin_rpm": float(stroke_table(spin, racket, ball)["spin_rpm"].iloc[0]),
        **{key: feel[key] for key in ("feel_shock_g", "feel_vibration_g")},
    }
