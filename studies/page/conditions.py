"""What each output of the interactive page was computed for, one line each, as every table
and plot of the command line says it (:func:`studies.conditions.conditions_line`): the
rackets (support, grip, what they are strung with), the ball and its speed, the swing.
"""

from __future__ import annotations

from common.checks import shown
from common.units import MPH
from racket import Swing
from studies.conditions import conditions_line, racket_details


def page_conditions(inputs, a, b) -> dict:
    """The conditions line of each of the page's outputs, by output: ``serve``, ``power``,
    ``sweet``, ``feel``, ``racket`` (the cards), ``exit``, ``e_A`` (the plots along the
    racket), ``spots`` (where to hit), ``face_a`` and ``face_b`` (the face maps; absent for
    a racket not built).

    Parameters
    ----------
    inputs : PageInputs
        The page's controls (:class:`studies.page.dashboard.PageInputs`).
    a, b : RacketResults or None
        Rackets A and B (:class:`studies.page.dashboard.RacketResults`), None for one not built:
        the lines name only the rackets built.
    """
    named = {"A": a, "B": b}
    built = {side: one for side, one in named.items() if one is not None}
    if not built:
        return {}
    tape = ""
    if inputs.lead_g > 0:
        tape = f" with {shown(inputs.lead_g)} g of lead tape per side at {inputs.lead_at}"
    names = {"A": f"A {inputs.racket}{tape}", "B": f"B {inputs.racket_b}"}
    rackets = " and ".join(names[side] for side in built)
    strung = {side: racket_details(one.racket)["strings"] for side, one in built.items()}
    strings = next(iter(strung.values()))
    if len(set(strung.values())) > 1:
        strings = "; ".join(f"{side} {said}" for side, said in strung.items())
    pivot = None if inputs.pivot_cm_from_tip is None else inputs.pivot_cm_from_tip / 100
    swing = (
        f"swung at {shown(inputs.swing_mph)} mph head speed (the string centre's) "
        f"{Swing(inputs.swing_mph * MPH, pivot).pivot_words()}"
    )
    speed = inputs.ball_speed_mph * MPH

    def line(who=rackets, at=speed, moving=None, **held):
        held = {"support": "free", "strings": strings, **held}
        return conditions_line(who, inputs.ball, at, "mph", swing=moving, **held)

    lines = {
        "serve": line(at=None, moving=f"the ball at rest at the string centre, {swing}"),
        "power": line(moving=f"e_A with the racket at rest, the exit speed {swing}"),
        "sweet": line(),
        "racket": conditions_line(rackets, None, support="free", strings=strings),
        "exit": line(moving=swing),
        "e_A": line(),
        "spots": line(moving=f"the racket at rest, the largest exit speed {swing}"),
    }
    held = {key: built[next(iter(built))].summary.get(f"feel_{key}") for key in ("support", "grip")}
    lines["feel"] = line(moving="at the string centre", **held)
    for side in built:
        lines[f"face_{side.lower()}"] = line(who=names[side], strings=strung[side])
    return lines
