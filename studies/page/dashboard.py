"""What the interactive page shows, computed apart from the page (so that it is tested
without a browser): two rackets, A and B (each a catalogue preset or the spec sheet; lead
tape by clock position on A; one string and tension for both), a ball and a swing in; for
each, the headline numbers a coach reads (serve speed, the flat and kick serves' spin, a
topspin forehand's speed, spin and launch, power at the centre, sweet area, feel, the
racket's own numbers), the serve speed against the head speed, e_A and the swung exit speed
along the racket, the face map and the sweet spots out; and B - A.  Every number comes from
the functions the command line calls (:func:`studies.serve.serve_table`,
:func:`studies.strokes.stroke.stroke_table`, :func:`studies.face.maps.face_map`, ...) with the same
defaults (:data:`racket.DEFAULT_RACKET`, :data:`ball.DEFAULT_BALL`,
:data:`studies.sweeps.BALL_SPEED`), and every output says what it was computed for
(:func:`page_conditions`).  A racket that cannot be built (an impossible spec sheet) is one
line in its place, the other racket's outputs intact.
"""

from __future__ import annotations

import functools
import re
import warnings
from dataclasses import dataclass, field, replace

import numpy as np
import pandas as pd

from ball import DEFAULT_BALL
from common.checks import FASTEST_HEAD, SPEED_RANGE, in_range
from common.units import MPH
from racket import CATALOG, DEFAULT_RACKET, Swing, from_specs, impact
from racket.feel import hand_feel
from racket.racket import ADDED_MASS_MAX
from racket.specs.ra import ra_note
from racket.specs.sheet import SPEC_RANGES
from racket.swing import PIVOT_FROM_TIP_RANGE, equal_effort
from studies.config import BALLS
from studies.face.maps import face_map
from studies.face.sweetspots import sweet_spots
from studies.feel import FEEL_SUPPORT, feel_numbers
from studies.page.conditions import page_conditions
from studies.page.strings import OWN_STRINGS, STRING_LABELS, checked_strings, strung
from studies.page.strokes import STROKE_COMPARED, STROKE_HEAD_MAX, stroke_conditions, stroke_summary
from studies.serve import serve, serve_table
from studies.sweeps import BALL_SPEED
from studies.tables import impact_table

MY_SHEET = "my spec sheet"
"""The racket choice that fits the page's spec-sheet fields."""

HEAD_SPEED_MAX_MPH = float(np.floor(FASTEST_HEAD / MPH))
"""The page's fastest racket-head speed [mph] (114): the fastest head speed assumed for any
stroke (:data:`common.checks.FASTEST_HEAD`) in whole mph, the slider's step.  The catalogue's
rackets, strung with polyester, serve the fastest recorded serve
(:data:`common.checks.FASTEST_STROKE`, 263.4 km/h, Sam Groth, Busan 2012; Reuters, "Groth
fires down fastest recorded serve at 263kph", 12 May 2012) off the string centre about the
wrist at about 117 mph (:func:`studies.serve.head_speed_for`, measured on this model): no
position of the slider serves faster than anyone has (tests/test_page_truth.py)."""

LEAD_MAX_G = 1e3 * ADDED_MASS_MAX
"""The most lead tape per side the page takes [g]: what the command line's ``--lead``, the
TOML's ``lead_tape`` and the API take (:data:`racket.racket.ADDED_MASS_MAX`)."""

HEAD_SPEEDS_MPH = np.r_[np.arange(20.0, HEAD_SPEED_MAX_MPH, 10.0), HEAD_SPEED_MAX_MPH]
"""Head speeds of the serve-speed curve [mph]: a slow feed to :data:`HEAD_SPEED_MAX_MPH`."""

COMPARED = (
    "exit_centre_mph", "e_A_centre", "sweet_area_cm2", "feel_shock_g", "feel_vibration_g",
    "feel_hz", "mass_g", "balance_cm", "swingweight_kgcm2", "twistweight_kgcm2", "f1_hz",
    *STROKE_COMPARED,
)  # fmt: skip
"""The headline numbers the cards show for A, B and B - A (``serve_mph``: the plot's)."""

SHEET_FIELDS = {
    "mass_g": "Strung mass [g]",
    "balance_cm": "Balance [cm from the butt]",
    "swingweight_kgcm2": "Swingweight [kg cm²]",
    "head_size_in2": "Head size [in²]",
    "f1_hz": "Frame frequency f1 [Hz]",
    "ra": "RA",
}
"""The spec sheet's fields as the page labels them (its inputs and its error messages; the
balance from the butt, as spec sheets give it)."""

CONTROL_LABELS = {
    "swing_mph": "Racket-head speed [mph]",
    "ball_speed_mph": "Incoming ball speed [mph]",
    "pivot_cm_from_tip": "Swing pivot [cm from the tip]",
    "tension_lb": "Tension, both [lb]",
    **STRING_LABELS,
    "lead_g": "Lead tape on A, per side [g]",
}
"""The speed, pivot, strings, tension and lead controls as the page labels them (its
sliders, select, box and its messages)."""

_SHEET = tuple(SHEET_FIELDS)
_FIT_NAMES = {  # how racket.specs names the sheet's fields in its messages
    "mass_kg": "mass_g", "balance_cm": "balance_cm", "balance": "balance_cm",
    "swingweight_kgcm2": "swingweight_kgcm2", "head_size_in2": "head_size_in2",
    "head size": "head_size_in2", "f1_hz": "f1_hz", "ra": "ra",
}  # fmt: skip


@dataclass(frozen=True)
class PageInputs:
    """The page's controls, in the units a player types; the defaults are the command
    line's (:data:`racket.DEFAULT_RACKET`, :data:`ball.DEFAULT_BALL`,
    :data:`studies.sweeps.BALL_SPEED`, the catalogue's tension, the swing about the wrist).

    Parameters
    ----------
    racket, racket_b : str
        Rackets A and B: a catalogue name (:data:`racket.CATALOG`) or :data:`MY_SHEET`.
    mass_g, balance_cm, swingweight_kgcm2, head_size_in2 : float
        The spec sheet used with :data:`MY_SHEET` [g, cm from the butt, kg cm^2, in^2].
    f1_hz, ra : float or None
        Its frame stiffness, one of the two (the other None): the first free frequency [Hz],
        or the RA rating [-] (f1 from it by :func:`racket.specs.ra.f1_from_ra`).
    lead_g : float
        Lead tape per side on racket A [g] (0 for none).
    lead_at : str
        Its clock position ("12", "3 and 9", ...).
    ball : str
        A ball preset (:data:`studies.config.BALLS`); default the ITF type 2 ball.
    string, played : str, bool
        What both rackets are strung with (:mod:`studies.page.strings`: default each
        racket's own), played (True) or fresh.
    tension_lb : float
        String (reference) tension of both rackets [lb]; default the catalogue's (55 lb).
    ball_speed_mph : float
        Incoming ball speed [mph] (racket at rest, the groundstroke and the feel); default
        :data:`studies.sweeps.BALL_SPEED` (16.5 m/s, TWU's).
    swing_mph : float
        Racket-head (string centre) speed of the swing [mph] (the serve and the
        groundstroke), as ``racket-impact serve --racket-speed-mph`` takes it.
    pivot_cm_from_tip : float or None
        The swing's pivot [cm from the tip]; None (default) the wrist, 5 cm beyond the butt
        of each racket (:class:`racket.Swing`), as the command line's default.
    """

    racket: str = DEFAULT_RACKET
    racket_b: str = "pro-staff-97l-cv"
    mass_g: float = 300.0
    balance_cm: float = 33.0
    swingweight_kgcm2: float = 315.0
    head_size_in2: float = 100.0
    f1_hz: float | None = 150.0
    ra: float | None = None
    lead_g: float = 0.0
    lead_at: str = "3 and 9"
    ball: str = DEFAULT_BALL
    string: str = OWN_STRINGS
    played: bool = False
    tension_lb: float = CATALOG[DEFAULT_RACKET].specs["tension_lb"]
    ball_speed_mph: float = BALL_SPEED / MPH
    swing_mph: float = 70.0
    pivot_cm_from_tip: float | None = None


@dataclass(frozen=True)
class RacketResults:
    """What the page shows for one racket (built by :func:`racket_results`).

    Attributes
    ----------
    name : str
        The racket's choice on the page.
    racket : Racket
        The racket the controls describe.
    along : DataFrame
        Impacts along the racket at rest (:func:`studies.tables.impact_table`) with the
        swung exit speed ``exit_speed_swung_mph``.
    face : FaceMap
        The face map (:func:`studies.face.maps.face_map`).
    spots : DataFrame
        The sweet spots (:func:`studies.face.sweetspots.sweet_spots`).
    serves : DataFrame
        The serve at the string centre (:func:`studies.serve.serve`) for each of
        :data:`HEAD_SPEEDS_MPH`.
    summary : dict
        The headline numbers: ``serve_mph`` (the serve off the centre at the page's head
        speed) and ``serve_tipward_mph`` (5 cm towards the tip), ``exit_centre_mph`` (the
        groundstroke off the centre), ``e_A_centre``, ``e_A_3_oclock``, ``largest_e_A`` and
        where (``largest_e_A_from_tip_cm``), ``sweet_area_cm2``, the feel
        (:func:`feel_summary`: ``feel_shock_g``, ``feel_vibration_g``, ``feel_hz``,
        ``feel_mode``, ``feel_support``, ``feel_grip``), ``mass_g``, ``balance_cm``,
        ``swingweight_kgcm2``, ``twistweight_kgcm2``, ``f1_hz``, the strokes with spin
        (:func:`studies.page.strokes.stroke_summary`); with lead tape the swing at equal
        effort (``effort_*``); with an RA rating, ``f1_from_ra`` (:func:`racket.specs.ra.ra_note`).
    warnings : tuple of str
        The simulation's warnings for this racket, one of each.
    """

    name: str
    racket: object
    along: object
    face: object
    spots: object
    serves: object
    summary: dict
    warnings: tuple = ()


@dataclass(frozen=True)
class PageResults:
    """What the page shows (built by :func:`page_results`).

    Attributes
    ----------
    a, b : RacketResults or None
        Rackets A and B; None for one that cannot be built (its line in ``errors``).
    difference : dict
        B - A of each of :data:`COMPARED` ({} unless both are built).
    warnings : tuple of str
        The simulation's warnings, one of each.
    errors : dict
        ``"A"`` or ``"B"`` -> why that racket cannot be built, one line naming the input as
        the page labels it, with its range.
    conditions : dict
        What each output was computed for, one line each (:func:`page_conditions`, and
        :func:`studies.page.strokes.stroke_conditions` for the strokes with spin).
    """

    a: RacketResults | None
    b: RacketResults | None
    difference: dict = field(default_factory=dict)
    warnings: tuple = ()
    errors: dict = field(default_factory=dict)
    conditions: dict = field(default_factory=dict)


def page_racket(inputs: PageInputs):
    """Racket A as the controls describe it, with its lead tape.

    Parameters
    ----------
    inputs : PageInputs
        The page's controls.
    """
    return _with_tape(_untaped(inputs, inputs.racket, "racket"), inputs)


def _untaped(inputs: PageInputs, name: str, which: str):
    """The racket ``name`` (input ``which``) strung as the controls say, before any tape."""
    if name not in [*CATALOG, MY_SHEET]:
        raise ValueError(f"{which} must be one of {[*CATALOG, MY_SHEET]}, got {name!r}")
    sheet = None
    if name == MY_SHEET:
        low, high, _ = SPEC_RANGES["mass_kg"]  # checked in grams, as the page asks for them
        in_range(SHEET_FIELDS["mass_g"], inputs.mass_g, 1e3 * low, 1e3 * high, "g")
        sheet = tuple(getattr(inputs, k) for k in _SHEET)
    return _built(name, inputs.tension_lb, sheet, *checked_strings(inputs.string, inputs.played))


@functools.lru_cache(maxsize=8)
def _built(name: str, tension_lb: float, sheet: tuple | None, string: str, played: bool):
    """The racket ``name`` at ``tension_lb`` [lb], strung with ``string``, fresh or
    ``played`` (:func:`studies.page.strings.strung`), from the spec ``sheet`` (mass [g],
    balance [cm], swingweight [kg cm^2], head size [in^2], f1 [Hz], RA) for :data:`MY_SHEET`,
    else its catalogue sheet (kept: a fit and its modes take a second or two); a refusal of
    the sheet in the page's words (:func:`said_on_page`).
    """
    keywords = strung(name, string, played)
    if sheet is not None:
        mass_g, balance_cm, swingweight, head, f1_hz, ra = sheet
        try:
            return from_specs(
                mass_kg=mass_g / 1e3,
                balance_cm=balance_cm,
                swingweight_kgcm2=swingweight,
                head_size_in2=head,
                f1_hz=f1_hz,
                ra=ra,
                tension_lb=tension_lb,
                **keywords,
            )
        except ValueError as err:
            raise ValueError(said_on_page(str(err))) from None
    tension_lb = in_range("tension_lb", tension_lb, *SPEC_RANGES["tension_lb"])
    return from_specs(**(CATALOG[name].specs | {"tension_lb": tension_lb}), **keywords)


def said_on_page(message: str) -> str:
    """A refusal of :func:`racket.specs.from_specs` in the page's words: the spec sheet's
    field named as the page labels it (:data:`SHEET_FIELDS`), units as the page writes
    them, no module paths.

    Parameters
    ----------
    message : str
        The refusal, e.g. "swingweight_kgcm2 must be in (257, 333) kg cm^2 for a 300 g
        racket ... (racket.specs.parts.PARTS), got 370".
    """
    names = "|".join(sorted(map(re.escape, _FIT_NAMES), key=len, reverse=True))
    said = re.sub(rf"^({names})\b", lambda m: SHEET_FIELDS[_FIT_NAMES[m[1]]], message)
    said = re.sub(r" \((?:[a-z_]+\.)+[A-Za-z_]+\)", "", said)  # "(racket.specs.parts.PARTS)"
    return said.replace("kg cm^2", "kg cm²").replace("in^2", "in²")


def _with_tape(racket, inputs: PageInputs):
    """``racket`` with the controls' lead tape (if any)."""
    lead_g = in_range("lead_g", inputs.lead_g, 0.0, LEAD_MAX_G, "g")
    return racket.with_lead_tape(lead_g / 1e3, inputs.lead_at) if lead_g > 0 else racket


def page_swing(inputs: PageInputs, racket, positions) -> Swing:
    """The page's swing, its head speed checked in mph (to a stroke's fastest,
    :data:`STROKE_HEAD_MAX`) and its pivot in cm from the tip, as the page asks for them, for
    the impact points ``positions`` [m from the tip] (:meth:`racket.Swing.check_points`).

    Parameters
    ----------
    inputs : PageInputs
        The page's controls.
    racket : Racket
        The racket swung.
    positions : array_like
        The impact points [m from the tip].
    """
    head, at = CONTROL_LABELS["swing_mph"], CONTROL_LABELS["pivot_cm_from_tip"]
    swing_mph = in_range(head, inputs.swing_mph, SPEED_RANGE[0] / MPH, STROKE_HEAD_MAX / MPH, "mph")
    pivot = inputs.pivot_cm_from_tip
    if pivot is not None:
        low, high = (100 * end for end in PIVOT_FROM_TIP_RANGE)
        pivot = in_range(at, pivot, low, high, "cm from the tip") / 100
    swing = Swing(swing_mph * MPH, pivot)
    swing.check_points(racket, positions, head=(head, inputs.swing_mph, "mph", MPH),
                       pivot=(at, inputs.pivot_cm_from_tip, "cm from the tip", 0.01))  # fmt: skip
    return swing


def page_results(inputs: PageInputs, points: int = 61) -> PageResults:
    """Everything the page shows for ``inputs`` (the warnings on the way, e.g. a ball
    squashed beyond its radius, collected for the page: one of each).  Each racket's
    results are kept for the last few controls that feed it, so that choosing B does not
    compute A again.  A racket that cannot be built (e.g. an impossible spec sheet) is left
    out with its reason in ``errors``; the controls both share are checked first
    (``ValueError``).

    Parameters
    ----------
    inputs : PageInputs
        The page's controls.
    points : int
        Impact points along each racket.
    """
    for which in ("racket", "racket_b"):
        if getattr(inputs, which) not in [*CATALOG, MY_SHEET]:
            raise ValueError(
                f"{which} must be one of {[*CATALOG, MY_SHEET]}, got {getattr(inputs, which)!r}"
            )
    if inputs.ball not in BALLS:
        raise ValueError(f"ball must be one of {list(BALLS)}, got {inputs.ball!r}")
    low, high = (v / MPH for v in SPEED_RANGE)
    in_range(CONTROL_LABELS["ball_speed_mph"], inputs.ball_speed_mph, low, high, "mph")
    in_range(CONTROL_LABELS["tension_lb"], inputs.tension_lb, *SPEC_RANGES["tension_lb"])
    checked_strings(inputs.string, inputs.played)
    in_range(CONTROL_LABELS["lead_g"], inputs.lead_g, 0.0, LEAD_MAX_G, "g")
    sides, errors = {}, {}
    for side, name, lead_g in (("A", inputs.racket, inputs.lead_g), ("B", inputs.racket_b, 0)):
        try:
            sides[side] = _side(_fed(inputs, name, lead_g), points)
        except ValueError as err:
            errors[side] = f"Racket {side} ({name}): {err}"
    a, b = sides.get("A"), sides.get("B")
    difference = {} if errors else {k: b.summary[k] - a.summary[k] for k in COMPARED}
    said = tuple(dict.fromkeys(w for s in sides.values() for w in s.warnings))
    conditions = page_conditions(inputs, a, b) | stroke_conditions(inputs, a, b)
    return PageResults(a, b, difference, said, errors, conditions)


def _fed(inputs: PageInputs, name: str, lead_g: float) -> PageInputs:
    """The controls that feed the racket ``name`` with ``lead_g`` of tape (the others at
    their defaults: one cache entry per racket).
    """
    fed = replace(inputs, racket=name, racket_b=name, lead_g=lead_g)
    if lead_g == 0:
        fed = replace(fed, lead_at=PageInputs.lead_at)
    if name != MY_SHEET:
        fed = replace(fed, **{k: getattr(PageInputs, k) for k in _SHEET})
    return fed


@functools.lru_cache(maxsize=8)
def _side(inputs: PageInputs, points: int) -> RacketResults:
    """:func:`racket_results` for ``inputs.racket`` with ``inputs.lead_g`` of tape, and
    the equal-effort swing when taped, the warnings on the way recorded.
    """
    speed = inputs.ball_speed_mph * MPH
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        base = _untaped(inputs, inputs.racket, "racket")  # built once (_built keeps it)
        results = racket_results(inputs.racket, page_racket(inputs), inputs, speed, points)
        results.summary.update(_equal_effort(inputs, base, results.racket, speed))
    return replace(results, warnings=tuple(dict.fromkeys(str(w.message) for w in caught)))


def racket_results(
    name: str, racket, inputs: PageInputs, speed: float, points: int = 61
) -> RacketResults:
    """What the page shows for ``racket`` (the page's choice ``name``), each number from the
    function the command line calls for it: the serve from
    :func:`studies.serve.serve_table` (``racket-impact serve``), the face map from
    :func:`studies.face.maps.face_map` (``map``), the impacts along the racket from
    :func:`racket.impact` (``sweep``), the feel from :func:`feel_summary` (``feel``), the
    strokes with spin from :func:`studies.page.strokes.stroke_summary` (``stroke``).

    Parameters
    ----------
    name : str
        The racket's choice on the page.
    racket : Racket
        The racket (taped if it is).
    inputs : PageInputs
        The page's controls (ball, swing, spec sheet).
    speed : float
        Incoming ball speed [m/s].
    points : int
        Impact points along the racket.
    """
    ball = BALLS[inputs.ball]()
    x = np.linspace(*racket.strings.extent, points)
    swing = page_swing(inputs, racket, x)
    along = impact_table(impact(racket, ball, x, speed))
    hit = impact(racket, ball, x, speed, **swing.impact_kwargs(racket, x))
    along["exit_speed_swung_mph"] = hit.ball_rebound / MPH
    face = face_map(racket, ball, speed)
    centre = racket.strings.center
    served = serve_table(racket, ball, [centre, centre - 0.05], swing.head_speed,
                         swing.pivot_from_tip, zero_cor=False)  # fmt: skip
    curve = [
        serve(racket, ball, centre, replace(swing, head_speed=v * MPH)) for v in HEAD_SPEEDS_MPH
    ]
    swung = impact(racket, ball, centre, speed, **swing.impact_kwargs(racket, centre))
    best = int(np.argmax(along["e_A"]))
    summary = {
        "serve_mph": float(served["serve_simulated_mph"].iloc[0]),
        "serve_tipward_mph": float(served["serve_simulated_mph"].iloc[1]),
        "exit_centre_mph": float(swung.ball_rebound) / MPH,
        "e_A_centre": face.e_A_centre,
        "e_A_3_oclock": face.e_A_side,
        "largest_e_A": float(along["e_A"].iloc[best]),
        "largest_e_A_from_tip_cm": float(along["position_from_tip_cm"].iloc[best]),
        "sweet_area_cm2": face.sweet_area_cm2,
        **feel_summary(racket, ball, speed),
        **stroke_summary(racket, ball, inputs.swing_mph),
        "mass_g": 1e3 * racket.beam.mass,
        "balance_cm": float(100 * racket.beam.balance),
        "swingweight_kgcm2": racket.beam.swingweight_kgcm2,
        "twistweight_kgcm2": racket.beam.twistweight_kgcm2,
        "f1_hz": float(racket.beam.modes.frequencies[0]),
    }
    if name == MY_SHEET and inputs.ra is not None:
        summary["f1_from_ra"] = ra_note(inputs.ra)
    spots = sweet_spots(racket, ball, speed, swing)
    return RacketResults(name, racket, along, face, spots, pd.DataFrame(curve), summary)


def feel_summary(racket, ball, speed: float) -> dict:
    """What the hand feels when a ball at ``speed`` [m/s] hits the string centre of
    ``racket`` at rest, the racket held as ``racket-impact feel`` holds it by default
    (:data:`studies.feel.FEEL_SUPPORT`, with the racket's own grip): the numbers that command
    prints (:func:`racket.feel.hand_feel`, :func:`studies.feel.feel_numbers`).

    Parameters
    ----------
    racket : Racket
        The racket (its support is replaced by :data:`studies.feel.FEEL_SUPPORT`).
    ball : Ball
    speed : float
        Ball speed [m/s].

    Returns
    -------
    dict
        ``feel_shock_g`` and ``feel_vibration_g`` [g], ``feel_hz`` [Hz], ``feel_mode``
        (words), ``feel_support`` and ``feel_grip`` (:func:`studies.feel.feel_numbers`).
    """
    held = replace(racket, support=FEEL_SUPPORT)
    return feel_numbers(hand_feel(held, ball, held.strings.center, speed), held)


def _equal_effort(inputs: PageInputs, base, racket, speed: float) -> dict:
    """With lead tape: the swing the player makes with the taped racket at the effort that
    swings the untaped one at the page's swing (:func:`racket.swing.equal_effort`, Cross
    and Bower 2006), and the exit speed at the string centre of each [mph]; {} without.
    """
    if racket is base:  # no tape
        return {}
    ball = BALLS[inputs.ball]()
    swing = page_swing(inputs, base, base.strings.center)
    taped = equal_effort(swing, base.beam.swingweight, racket.beam.swingweight)
    exits = [
        impact(r, ball, r.strings.center, speed, **s.impact_kwargs(r, r.strings.center))
        for r, s in ((base, swing), (racket, taped))
    ]  # fmt: skip
    return {
        "effort_head_untaped_mph": swing.head_speed / MPH,
        "effort_head_taped_mph": taped.head_speed / MPH,
        "effort_exit_untaped_mph": float(exits[0].ball_rebound) / MPH,
        "effort_exit_taped_mph": float(exits[1].ball_rebound) / MPH,
    }
