"""The interactive page's strokes with spin (issue 36): a flat and a kick serve at the page's
racket-head speed, and a topspin forehand following it in the presets' ratio, hit by each
racket as ``racket-impact stroke`` hits them (:func:`studies.strokes.stroke.stroke_table`:
at the string centre, the racket free, its mains and crosses sliding on dry crossings), and
the line saying what each card of them was computed for.
"""

from __future__ import annotations

import math
from dataclasses import replace

from common.checks import shown
from common.units import MPH
from racket import STROKES
from racket.strings.sideways import sideways
from racket.stroke import LIMITS, RPM
from studies.page.conditions import page_conditions
from studies.strokes.stroke import bed_words, spin_note, stroke_table

PAGE_SERVES = ("flat-serve", "kick-serve")
"""The serves the page hits with spin (:data:`racket.STROKES`), each at the page's head
speed (``racket-impact stroke flat-serve kick-serve --head-speed-mph``), its path, face and
toss the preset's."""

PAGE_GROUNDSTROKE = "topspin-forehand"
"""The groundstroke the page hits with spin: the preset, its head speed following the page's
in :data:`GROUNDSTROKE_RATIO` (``racket-impact stroke topspin-forehand --head-speed-mph``)."""

GROUNDSTROKE_RATIO = STROKES[PAGE_GROUNDSTROKE].head_speed / STROKES[PAGE_SERVES[0]].head_speed
"""The page's groundstroke's head speed over its serves' [-] (the page's swing): the
presets' own ratio, the tour forehand's over the serve's (0.92), so that at the serve
preset's head speed the page hits the forehand preset as it is."""

STROKE_HEAD_MAX = LIMITS["head_speed"][1]
"""The fastest racket-head speed the page takes [m/s] (134 mph): a :class:`racket.Stroke`'s
(:data:`racket.stroke.LIMITS`), above the fastest assumed for any stroke
(:data:`common.checks.FASTEST_HEAD`, the slider's end)."""

STROKE_KEYS = {"flat_serve": "flat-serve", "kick_serve": "kick-serve",
               "forehand": PAGE_GROUNDSTROKE}  # fmt: skip
"""The page's name of each of its strokes (``<key>_mph``, ``<key>_spin_rpm``,
``<key>_launch_deg`` in a racket's summary) and the preset it is."""

STROKE_COMPARED = (
    "flat_serve_mph", "flat_serve_spin_rpm", "kick_serve_mph", "kick_serve_spin_rpm",
    "forehand_mph", "forehand_spin_rpm", "forehand_launch_deg",
)  # fmt: skip
"""The strokes' numbers the page's cards show for A, B and B - A."""


def page_strokes(swing_mph: float) -> dict:
    """The page's strokes, by preset name: :data:`PAGE_SERVES` at ``swing_mph``,
    :data:`PAGE_GROUNDSTROKE` at :data:`GROUNDSTROKE_RATIO` times it.

    Parameters
    ----------
    swing_mph : float
        The page's racket-head speed [mph] (the string centre's).
    """
    serves = {name: replace(STROKES[name], head_speed=swing_mph * MPH) for name in PAGE_SERVES}
    ground = replace(STROKES[PAGE_GROUNDSTROKE], head_speed=GROUNDSTROKE_RATIO * swing_mph * MPH)
    return serves | {PAGE_GROUNDSTROKE: ground}


def stroke_summary(racket, ball, swing_mph: float) -> dict:
    """The ball after each of :func:`page_strokes` with ``racket`` (at the string centre, the
    bed's mains and crosses sliding on dry crossings: the defaults of
    :func:`studies.strokes.stroke.stroke_table` and of ``racket-impact stroke``).

    Parameters
    ----------
    racket : Racket
        The racket (free or hand-held).
    ball : Ball
        The ball.
    swing_mph : float
        The page's racket-head speed [mph], the serves'.

    Returns
    -------
    dict
        For each key of :data:`STROKE_KEYS`: ``<key>_mph`` (the ball's speed [mph]),
        ``<key>_spin_rpm`` (its spin rate [rpm], signed as its topspin: < 0 backspin) and
        ``<key>_launch_deg`` (its launch above
        the horizontal [deg]).
    """
    table = stroke_table(page_strokes(swing_mph), racket, ball, unit="mph").set_index("stroke")
    summary = {}
    for key, name in STROKE_KEYS.items():
        row = table.loc[name]
        summary[f"{key}_mph"] = float(row["exit_speed_mph"])
        summary[f"{key}_spin_rpm"] = float(row["spin_rpm"])
        summary[f"{key}_launch_deg"] = float(row["launch_deg"])
    return summary


def _degrees(angle: float) -> str:
    """The size of an angle [rad] in degrees, as typed: "7°", not "7.000000000000001°"."""
    return f"{shown(abs(round(math.degrees(angle), 6)))}°"


def _angle(angle: float, up: str, down: str) -> str:
    """An angle [rad] in degrees and words: "0°", "30° up", "7° closed"."""
    return _degrees(angle) + (f" {up if angle > 0 else down}" if _degrees(angle) != "0°" else "")


def stroke_words(name: str, stroke, head: str = "") -> str:
    """A stroke's numbers that shape its spin, in words: "kick-serve at 70 mph head speed,
    path 30° up, 35° across to the right, face 12° closed".

    Parameters
    ----------
    name : str
        The stroke's name.
    stroke : Stroke
        The stroke.
    head : str
        Said after its head speed ("(the preset's)").
    """
    speed = f"{shown(round(stroke.head_speed / MPH, 6))} mph head speed"
    words = [f"{name} at {speed}{f' {head}' if head else ''}"]
    words.append(f"path {_angle(stroke.path_angle, 'up', 'down')}")
    if stroke.swing_across:
        words.append(_angle(stroke.swing_across, "across to the left", "across to the right"))
    words.append(f"face {_angle(stroke.face_angle, 'open', 'closed')}")
    return ", ".join(words)


def _incoming(stroke) -> str:
    """The incoming ball of ``stroke`` in words: "at 45 mph falling at 10° with 1910 rpm of
    topspin".
    """
    way = "falling" if stroke.ball_angle >= 0 else "rising"
    at = f"at {stroke.ball_speed / MPH:.3g} mph {way} at {_degrees(stroke.ball_angle)}"
    return at + (f" with {stroke.topspin / RPM:.0f} rpm of topspin" if stroke.topspin else "")


def stroke_conditions(inputs, a, b) -> dict:
    """The conditions lines of the page's cards with spin; {} with no racket built.
    ``serve_spin``, the serve card's: the flat and kick serves' (the serve head-on, without
    spin, is the serve plot's: :func:`studies.page.conditions.page_conditions`);
    ``groundstroke``, the topspin forehand's.  Each names the rackets as the other cards do,
    the ball, each stroke's head speed, path and face, the incoming ball, where it is hit and
    how the racket moves, and what the bed does sideways (:func:`studies.strokes.stroke.bed_words`).

    Parameters
    ----------
    inputs : PageInputs
        The page's controls (:class:`studies.page.dashboard.PageInputs`).
    a, b : RacketResults or None
        Rackets A and B, None for one not built.
    """
    built = {side: one for side, one in (("A", a), ("B", b)) if one is not None}
    if not built:
        return {}
    lines = page_conditions(inputs, a, b)
    beds = {side: bed_words(sideways(one.racket.strings)) for side, one in built.items()}
    bed = next(iter(beds.values()))
    if len(set(beds.values())) > 1:
        bed = "; ".join(f"{side} {said}" for side, said in beds.items())
    how = ("as racket-impact stroke hits it: at the string centre, the racket moving with it "
           f"(no pivot); {bed}")  # fmt: skip
    strokes = page_strokes(inputs.swing_mph)
    flat, kick = (strokes[name] for name in PAGE_SERVES)
    page = "(the page's)"
    serves = (
        f"{stroke_words(PAGE_SERVES[0], flat, page)}; {stroke_words(PAGE_SERVES[1], kick, page)}"
    )
    forehand = strokes[PAGE_GROUNDSTROKE]
    ground = stroke_words(PAGE_GROUNDSTROKE, forehand, f"(the page's times "
                          f"{GROUNDSTROKE_RATIO:.2f}, the presets' ratio)")  # fmt: skip
    notes = {
        key: spin_note({name: strokes[name] for name in names})
        for key, names in (("serve", PAGE_SERVES), ("ground", (PAGE_GROUNDSTROKE,)))
    }
    return {
        "serve_spin": f"{lines['racket']}, ball {inputs.ball} tossed {_incoming(flat)}, "
        f"{serves}, {how}" + (f"; {notes['serve']}" if notes["serve"] else ""),
        "groundstroke": f"{lines['racket']}, ball {inputs.ball} {_incoming(forehand)}, "
        f"{ground}, {how}" + (f"; {notes['ground']}" if notes["ground"] else ""),
    }
