"""The interactive page's controls as the browser sends them, checked in one place: each
value of the page's message (whatever it holds: a number, a string, an object, a list, null,
NaN, nothing at all) becomes a field of :class:`studies.page.dashboard.PageInputs` or one line
naming the control as the page labels it (``ValueError``), which the page shows as an
error card.  Only the types are checked here; the ranges are the tool's, checked where the
numbers are used (:func:`studies.page.dashboard.page_results`).
"""

from __future__ import annotations

from common.checks import finite, shown
from racket import CATALOG
from racket.swing import WRIST_BEYOND_BUTT
from studies.config import BALLS
from studies.page.dashboard import CONTROL_LABELS, MY_SHEET, SHEET_FIELDS, PageInputs
from studies.page.strings import PAGE_STRINGS

LEAD_CLOCKS = ("3 and 9", "2 and 10", "12", "6")
"""The lead tape's clock positions the page offers (:meth:`racket.Racket.with_lead_tape`)."""

STIFFNESS = {"f1": "frequency f1", "ra": "RA"}
"""How the spec sheet gives the frame's stiffness: the choice -> its words on the page."""

LABELS = {
    "racket": "Racket A",
    "racket_b": "Racket B",
    "mass_g": SHEET_FIELDS["mass_g"],
    "balance_cm": SHEET_FIELDS["balance_cm"],
    "swingweight": SHEET_FIELDS["swingweight_kgcm2"],
    "head": SHEET_FIELDS["head_size_in2"],
    "stiffness": "Frame stiffness given as",
    "f1": SHEET_FIELDS["f1_hz"],
    "ra": SHEET_FIELDS["ra"],
    "lead_g": CONTROL_LABELS["lead_g"],
    "lead_at": "Lead at (o'clock)",
    "swing": CONTROL_LABELS["swing_mph"],
    "ball_speed": CONTROL_LABELS["ball_speed_mph"],
    "tension": CONTROL_LABELS["tension_lb"],
    "string": CONTROL_LABELS["string"],
    "played": CONTROL_LABELS["played"],
    "ball": "Ball",
    "at_wrist": f"Pivot at the wrist ({100 * WRIST_BEYOND_BUTT:g} cm beyond the butt)",
    "pivot": CONTROL_LABELS["pivot_cm_from_tip"],
}
"""The page's controls: input id -> its label (the page's and its messages')."""

_SHEET_IDS = {  # the spec sheet's inputs -> their PageInputs fields
    "mass_g": "mass_g", "balance_cm": "balance_cm", "swingweight": "swingweight_kgcm2",
    "head": "head_size_in2", "f1": "f1_hz", "ra": "ra",
}  # fmt: skip
_LONGEST = 60  # characters of a value a message quotes: a huge value is cut, not echoed


def _quoted(value) -> str:
    """``value`` as a message quotes it, cut to :data:`_LONGEST` characters."""
    said = shown(value)
    if len(said) <= _LONGEST:
        return said
    return f"{said[:_LONGEST]}... ({len(said)} characters)"


def _choice(name: str, value, choices) -> str:
    """The choice ``value`` of the control ``name``, one of ``choices``."""
    if not isinstance(value, str) or value not in choices:
        raise ValueError(f"{LABELS[name]} must be one of {list(choices)}, got {_quoted(value)}")
    return value


def _flag(name: str, value) -> bool:
    """The tick box ``value`` of the control ``name``: true or false."""
    if not isinstance(value, bool):
        raise ValueError(f"{LABELS[name]} must be true or false, got {_quoted(value)}")
    return value


def _number(name: str, value) -> float:
    """The number ``value`` of the control ``name`` (finite; its range is checked where it
    is used).
    """
    if isinstance(value, int | float) and not isinstance(value, bool):
        return finite(LABELS[name], value)
    raise ValueError(f"{LABELS[name]} must be a finite number, got {_quoted(value)}")


def page_inputs(raw: dict) -> PageInputs:
    """The page's controls from the values the browser sent, each checked for its type.

    A control the page uses and the message left out (or, for a spec-sheet field, left
    empty: null) is named in one line; so is a value of the wrong type (an object, a list,
    a string for a number, NaN, a bool) or a choice the page does not offer.  The spec
    sheet's fields are read only when :data:`studies.page.dashboard.MY_SHEET` is chosen (and of
    f1 and RA only the one its stiffness choice names); unread, they keep their defaults.

    Parameters
    ----------
    raw : dict
        Input id (:data:`LABELS`) -> the value the browser sent; an id left out is a
        control the message did not carry.

    Returns
    -------
    PageInputs
        The controls, of the types :class:`studies.page.dashboard.PageInputs` documents.
    """
    used = ["racket", "racket_b", "lead_g", "lead_at", "swing", "ball_speed", "tension"]
    used += ["string", "played"]
    used += ["ball", "at_wrist"] + (["pivot"] if raw.get("at_wrist") is False else [])
    on_sheet = MY_SHEET in (raw.get("racket"), raw.get("racket_b"))
    if raw.get("stiffness") is not None:  # "f1" or "ra": also the input it reads
        stiffness = _choice("stiffness", raw["stiffness"], STIFFNESS)
        used += [stiffness] if on_sheet else []
    if on_sheet:
        used += ["mass_g", "balance_cm", "swingweight", "head", "stiffness"]
    missing = [LABELS[name] for name in used if raw.get(name) is None]
    if missing:
        raise ValueError(
            f"the page sent no value for {', '.join(missing)} (reload the page; a spec "
            "sheet's field must not be empty)"
        )
    sheet = {}
    for name, key in _SHEET_IDS.items():
        if name in used:
            sheet[key] = _number(name, raw[name])
        elif raw.get(name) is not None:  # sent but unused: still a number
            _number(name, raw[name])
    if on_sheet:  # the stiffness not chosen is not given
        sheet[{"f1": "ra", "ra": "f1_hz"}[stiffness]] = None
    at_wrist = _flag("at_wrist", raw["at_wrist"])
    return PageInputs(
        racket=_choice("racket", raw["racket"], [*CATALOG, MY_SHEET]),
        racket_b=_choice("racket_b", raw["racket_b"], [*CATALOG, MY_SHEET]),
        lead_g=_number("lead_g", raw["lead_g"]),
        lead_at=_choice("lead_at", raw["lead_at"], LEAD_CLOCKS),
        ball=_choice("ball", raw["ball"], BALLS),
        tension_lb=_number("tension", raw["tension"]),
        string=_choice("string", raw["string"], PAGE_STRINGS),
        played=_flag("played", raw["played"]),
        ball_speed_mph=_number("ball_speed", raw["ball_speed"]),
        swing_mph=_number("swing", raw["swing"]),
        pivot_cm_from_tip=None if at_wrist else _number("pivot", raw["pivot"]),
        **sheet,
    )
