"""What the interactive page shows, computed apart from the page (so that it is tested
without a browser): a racket (a catalogue preset or a spec sheet, lead tape by clock
position, a tension), a ball and a swing in; e, e_A and exit speed along the racket, the face
map, the sweet spots and the serve out.
"""

from __future__ import annotations

import warnings
from dataclasses import dataclass, replace

import numpy as np

from ball import DEFAULT_BALL
from common.checks import SPEED_RANGE, in_range, non_negative
from common.units import LB, MPH
from racket import CATALOG, Swing, from_specs, impact
from racket.specs.ra import ra_note
from racket.specs.sheet import SPEC_RANGES
from racket.specs.strings import with_tension
from racket.swing import PIVOT_RANGE, equal_effort
from studies.config import BALLS
from studies.landmarks import sweet_spots
from studies.maps import face_map
from studies.serve import serve_table
from studies.tables import impact_table

MY_SHEET = "my spec sheet"
"""The racket choice that fits the page's spec-sheet fields."""


@dataclass(frozen=True)
class PageInputs:
    """The page's controls, in the units a player types.

    Parameters
    ----------
    racket : str
        A catalogue name (:data:`racket.CATALOG`) or :data:`MY_SHEET`.
    mass_g, balance_cm, swingweight_kgcm2, head_size_in2 : float
        The spec sheet used with :data:`MY_SHEET` [g, cm from the butt, kg cm^2, in^2].
    f1_hz, ra : float or None
        Its frame stiffness, one of the two (the other None): the first free frequency [Hz],
        or the RA rating [-] (f1 from it by :func:`racket.specs.ra.f1_from_ra`).
    lead_g : float
        Lead tape per side [g] (0 for none).
    lead_at : str
        Its clock position ("12", "3 and 9", ...).
    ball : str
        A ball preset (:data:`studies.config.BALLS`); default the ITF type 2 ball.
    tension_lb : float
        String tension [lb].
    ball_speed : float
        Incoming ball speed [m/s] (racket at rest, and the groundstroke).
    swing_mph : float
        Racket-head speed of the swing [mph] (the serve and the groundstroke).
    pivot_cm_from_butt : float
        The swing's pivot [cm from the butt, negative beyond it].
    """

    racket: str = "pure-drive-2021"
    mass_g: float = 300.0
    balance_cm: float = 33.0
    swingweight_kgcm2: float = 315.0
    head_size_in2: float = 100.0
    f1_hz: float | None = 150.0
    ra: float | None = None
    lead_g: float = 0.0
    lead_at: str = "3 and 9"
    ball: str = DEFAULT_BALL
    tension_lb: float = 55.0
    ball_speed: float = 16.5
    swing_mph: float = 60.0
    pivot_cm_from_butt: float = -5.0


@dataclass(frozen=True)
class PageResults:
    """What the page shows (built by :func:`page_results`).

    Attributes
    ----------
    racket : Racket
        The racket the controls describe.
    along : DataFrame
        Impacts along the racket at rest (:func:`studies.tables.impact_table`) with the
        swung exit speed ``exit_speed_swung_mph``.
    face : FaceMap
        The face map (:func:`studies.maps.face_map`).
    spots : DataFrame
        The sweet spots (:func:`studies.landmarks.sweet_spots`).
    serve : DataFrame
        The serve at the centre and 5 cm towards the tip (:func:`studies.serve.serve_table`).
    summary : dict
        The page's headline numbers (g, cm, kg cm^2, Hz, e_A, cm^2, mph); with an RA rating,
        ``f1_from_ra`` says which f1 it gave and how uncertain (:func:`racket.specs.ra.ra_note`).
    warnings : tuple of str
        The simulation's warnings, one of each.
    """

    racket: object
    along: object
    face: object
    spots: object
    serve: object
    summary: dict
    warnings: tuple = ()


def page_racket(inputs: PageInputs):
    """The racket the controls describe.

    Parameters
    ----------
    inputs : PageInputs
        The page's controls.
    """
    return _with_tape(_untaped(inputs), inputs)


def _untaped(inputs: PageInputs):
    """The racket the controls describe, before its lead tape."""
    if inputs.racket == MY_SHEET:
        low, high, _ = SPEC_RANGES["mass_kg"]  # checked in grams, as the page asks for them
        mass_g = in_range("mass_g", inputs.mass_g, 1e3 * low, 1e3 * high, "g")
        racket = from_specs(
            mass_kg=mass_g / 1e3,
            balance_cm=inputs.balance_cm,
            swingweight_kgcm2=inputs.swingweight_kgcm2,
            head_size_in2=inputs.head_size_in2,
            f1_hz=inputs.f1_hz,
            ra=inputs.ra,
            tension_lb=inputs.tension_lb,
        )
    elif inputs.racket in CATALOG:
        low, high, unit = SPEC_RANGES["tension_lb"]
        tension = in_range("tension_lb", inputs.tension_lb, low, high, unit) * LB
        racket = with_tension(CATALOG[inputs.racket].racket(), tension)
    else:
        raise ValueError(f"racket must be one of {[*CATALOG, MY_SHEET]}, got {inputs.racket!r}")
    return racket


def _with_tape(racket, inputs: PageInputs):
    """``racket`` with the controls' lead tape (if any)."""
    lead_g = non_negative("lead_g", inputs.lead_g, "g")
    return racket.with_lead_tape(lead_g / 1e3, inputs.lead_at) if lead_g > 0 else racket


def page_results(inputs: PageInputs, points: int = 61) -> PageResults:
    """Everything the page shows for ``inputs`` (the warnings on the way, e.g. a ball
    squashed beyond its radius, collected for the page: one of each).

    Parameters
    ----------
    inputs : PageInputs
        The page's controls.
    points : int
        Impact points along the racket.
    """
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        results = _page_results(inputs, points)
    seen = dict.fromkeys(str(w.message) for w in caught)
    return replace(results, warnings=tuple(seen))


def page_swing(inputs: PageInputs, racket, positions) -> Swing:
    """The page's swing, its head speed checked in mph and its pivot in cm, as the page
    asks for them, for the impact points ``positions`` [m from the tip]
    (:meth:`racket.Swing.check_points`).

    Parameters
    ----------
    inputs : PageInputs
        The page's controls.
    racket : Racket
        The racket swung.
    positions : array_like
        The impact points [m from the tip].
    """
    low, high = (100 * end for end in PIVOT_RANGE)
    pivot_cm = in_range("pivot_cm_from_butt", inputs.pivot_cm_from_butt, low, high, "cm")
    swing_mph = in_range("swing_mph", inputs.swing_mph, *(v / MPH for v in SPEED_RANGE), "mph")
    swing = Swing(swing_mph * MPH, pivot_cm / 100)
    swing.check_points(
        racket,
        positions,
        head=("swing_mph", inputs.swing_mph, "mph", MPH),
        pivot=("pivot_cm_from_butt", inputs.pivot_cm_from_butt, "cm", 0.01),
    )
    return swing


def _equal_effort(inputs: PageInputs, base, racket, ball, swing: Swing) -> dict:
    """With lead tape: the swing the player makes with the taped racket at the effort that
    swings the untaped one at the page's swing (:func:`racket.swing.equal_effort`, Cross
    and Bower 2006), and the exit speed at the string centre of each [mph]; {} without.
    """
    if racket is base:  # no tape
        return {}
    taped = equal_effort(swing, base.beam.swingweight, racket.beam.swingweight)
    exits = [
        impact(r, ball, r.strings.center, inputs.ball_speed, **s.impact_kwargs(r, r.strings.center))
        for r, s in ((base, swing), (racket, taped))
    ]  # fmt: skip
    return {
        "effort_head_untaped_mph": swing.head_speed / MPH,
        "effort_head_taped_mph": taped.head_speed / MPH,
        "effort_exit_untaped_mph": float(exits[0].ball_rebound) / MPH,
        "effort_exit_taped_mph": float(exits[1].ball_rebound) / MPH,
    }


def _page_results(inputs: PageInputs, points: int) -> PageResults:
    if inputs.ball not in BALLS:
        raise ValueError(f"ball must be one of {list(BALLS)}, got {inputs.ball!r}")
    base, ball = _untaped(inputs), BALLS[inputs.ball]()
    racket = _with_tape(base, inputs)
    x = np.linspace(*racket.strings.extent, points)
    swing = page_swing(inputs, racket, x)
    along = impact_table(impact(racket, ball, x, inputs.ball_speed))
    hit = impact(racket, ball, x, inputs.ball_speed, **swing.impact_kwargs(racket, x))
    along["exit_speed_swung_mph"] = hit.ball_rebound / MPH
    face = face_map(racket, ball, inputs.ball_speed)
    spots = sweet_spots(racket, ball, inputs.ball_speed, swing)
    centre = racket.strings.center
    serve = serve_table(racket, ball, [centre, centre - 0.05], swing.head_speed,
                        swing.pivot_from_butt, zero_cor=False)  # fmt: skip
    best = int(np.argmax(along["e_A"]))
    summary = {
        **_equal_effort(inputs, base, racket, ball, swing),
        "mass_g": 1e3 * racket.beam.mass,
        "balance_cm": 100 * racket.beam.balance,
        "swingweight_kgcm2": racket.beam.swingweight_kgcm2,
        "twistweight_kgcm2": racket.beam.twistweight_kgcm2,
        "f1_hz": float(racket.beam.modes.frequencies[0]),
        "e_A_centre": face.e_A_centre,
        "e_A_3_oclock": face.e_A_side,
        "largest_e_A": float(along["e_A"].iloc[best]),
        "largest_e_A_from_butt_cm": float(along["position_from_butt_cm"].iloc[best]),
        "sweet_area_cm2": face.sweet_area_cm2,
        "serve_centre_mph": float(serve["serve_simulated_mph"].iloc[0]),
        "serve_tipward_mph": float(serve["serve_simulated_mph"].iloc[1]),
    }
    if inputs.racket == MY_SHEET and inputs.ra is not None:
        summary["f1_from_ra"] = ra_note(inputs.ra)
    return PageResults(racket, along, face, spots, serve, summary)
