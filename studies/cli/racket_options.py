"""The options that describe the racket, the same on every command that takes one:
``--racket``, ``--support``, ``--grip``, what it is strung with (``--string``, ``--gauge``,
``--pattern``, ``--tension-lb`` or ``--tension-kg``, ``--played``; or the bed's stiffness,
``--string-stiffness`` or the ERT's ``--string-bed-dt``) and ``--lead GRAMS@CLOCK``; the
racket made from them, and the conditions line of a run.
"""

from __future__ import annotations

import re
from dataclasses import replace

from common.checks import KG_AS_G, KN_AS_N, M_AS_CM, in_range, shown, suspect
from common.units import GRAVITY, KP_PER_CM
from racket import DEFAULT_RACKET, GRIPS, STRINGS, SUPPORTS
from racket.strings.sizes import GAUGE_RANGE, GAUGES, diameter, parse_pattern
from racket.strings.stringing import LINEAR, restrung, stringing
from studies.cli.options import (
    _ball_arg,
    _Once,
    _speed_option,
    _swing_options,
    _tension,
    given,
    preset_or_toml,
    refuse_unused,
    speed_unit,
)
from studies.conditions import PLAIN_BED, conditions_line, racket_details
from studies.config import LEAD_GRAMS, RACKETS, load_racket, read_toml
from studies.strings.inputs import (
    DT_RANGE,
    LB_AS_KG,
    N_M_AS_KP_CM,
    TENSION_KG_RANGE,
    stiff_dt,
)
from studies.sweeps import BALL_SPEED, STRING_STIFFNESS_RANGE

_LEAD = re.compile(r"^\s*(\d+(?:\.\d*)?|\.\d+)\s*(?:g)?\s*@\s*(.+?)\s*$")

STRING_OPTIONS = (
    "string", "gauge", "pattern", "played", "tension_lb", "tension_kg", "string_stiffness",
    "string_bed_dt",
)  # fmt: skip
"""The options (their ``dest``) that say what a racket is strung with."""

GAUGE_MM = tuple(1e3 * g for g in GAUGE_RANGE)
"""The gauges ``--gauge`` takes [mm]."""

NEAR_AXIS_CM = 1.0
"""An ``--offset`` typed nearer the long axis than this [cm] (but not on it) that is one in m
typed as cm is asked about (**an assumption**: a player's off-centre hits are centimetres
off the axis; 0.05 is more likely 5 cm than half a millimetre)."""

HAND_READERS = ("specs", "modes", "map", "sweetspots", "feel")
"""The commands that read the racket's hand whatever holds it (its held modes, the pivot of
the centre of percussion, the grip the feel is read at): elsewhere a ``[racket.hand]`` table
on a racket no hand holds is refused, as nothing would read it."""

FREE_ONLY = {"serve": "serve swings a free racket", "strings": "strings serves a free racket"}
"""The commands that take a free racket only, and why (the hand has no place there)."""


def add_racket_options(
    p, many: bool = False, support: bool = True, support_default=None, racket: bool = True
):
    """The racket's options on the subparser ``p``: ``--racket`` (with ``racket``: compare
    takes several, its own way), ``--support`` and ``--grip`` (with ``support``),
    ``--string``, ``--gauge``, ``--pattern``, ``--played``, ``--tension-lb`` or
    ``--tension-kg``, ``--string-stiffness`` or ``--string-bed-dt``, and ``--lead``;
    ``many``: several tensions, stiffnesses and supports (a grid).
    """
    if racket:
        _racket_option(p)
    nargs = "+" if many else None
    if support:
        said = support_default or "the racket's, free for a preset"
        p.add_argument(
            "--support", choices=list(SUPPORTS), nargs=nargs, action=_Once,
            default=support_default, help=f"support{'(s)' if many else ''} (default: {said})",
        )  # fmt: skip
        p.add_argument(
            "--grip", choices=list(GRIPS), action=_Once,
            help="how the hand holds a hand-held racket (default: the racket's hand, the "
            "medium grip unless its file says otherwise)",
        )  # fmt: skip
    p.add_argument(
        "--string", action=_Once, metavar="NAME",
        help=f"what the racket is strung with: {', '.join(STRINGS)}, or MAINS/CROSSES for a "
        "hybrid, e.g. natural-gut/polyester, or linear for the paper's plain spring (default: "
        "the racket's; give one of --string, --gauge, --pattern, --played and the others "
        "stay the racket's)",
    )  # fmt: skip
    p.add_argument(
        "--gauge", action=_Once, metavar="MM_OR_NAME",
        help=f"the string's gauge [mm, {GAUGE_MM[0]:g}-{GAUGE_MM[1]:g}], or a name: "
        f"{', '.join(GAUGES)} (default: the string's own)",
    )  # fmt: skip
    p.add_argument(
        "--pattern", action=_Once, metavar="MxC",
        help="string pattern, mains x crosses, e.g. 16x19 or 18x20 (default: the racket's)",
    )  # fmt: skip
    p.add_argument(
        "--played", action=_OnceTrue,
        help="played strings: the tension lost in TWU's impact test (default: fresh)",
    )  # fmt: skip
    p.add_argument(
        "--tension-lb", type=float, nargs=nargs, action=_Once, metavar="LB",
        help=f"string tension{'(s)' if many else ''} [lb]: the string bed's stiffness from the "
        "membrane model (default: the racket's)",
    )  # fmt: skip
    p.add_argument(
        "--tension-kg", type=float, nargs=nargs, action=_Once, metavar="KG",
        help=f"or the tension{'(s)' if many else ''} in kg, as stringing machines show it",
    )  # fmt: skip
    p.add_argument(
        "--string-stiffness", type=float, nargs=nargs, action=_Once, metavar="N_M",
        help=f"string-bed stiffness{'(es)' if many else ''} [N/m] (default: the racket's)",
    )  # fmt: skip
    p.add_argument(
        "--string-bed-dt", type=float, nargs=nargs, action=_Once, metavar="KP_CM",
        help="or the measured string-bed stiffness as the ERT's dynamic tension [kp/cm] "
        "(1 kp/cm = 980.7 N/m; players' beds read 28-46)",
    )  # fmt: skip
    p.add_argument(
        "--lead", nargs="+", action=_Once, metavar="GRAMS@CLOCK",
        help="lead tape: grams per side at a clock position of the head, e.g. 3@12 (the "
        "tip), 2@3/9 (both sides), 4@6 (the throat)",
    )  # fmt: skip


def add_ball_speed(p, many: bool = False) -> None:
    """``--ball`` and its speed towards the strings, ``--speed`` (or ``--speed-mph``,
    ``--speed-kmh``; default :data:`studies.sweeps.BALL_SPEED`), on the subparser ``p``;
    ``many``: several speeds (a grid).
    """
    _ball_arg(p)
    if many:
        _speed_option(p, "speed", [BALL_SPEED], "ball speed(s) towards the strings", many=True)
    else:
        _speed_option(p, "speed", BALL_SPEED, "ball speed towards the strings")


def impact_parser(
    sub, name: str, what: str, swing: bool = True, support_default=None, many: bool = False
):
    """The subparser ``name`` (``what``: its help) on the subparsers ``sub`` of a command of
    impacts on a racket: the racket's options (:func:`add_racket_options`; ``many`` and
    ``support_default`` as there), the ball and its speed (:func:`add_ball_speed`) and, with
    ``swing``, the racket's swing (``--swing-speed``, ``--pivot-cm-from-tip``); the command
    adds its own.
    """
    p = sub.add_parser(name, help=what)
    add_racket_options(p, many=many, support_default=support_default)
    add_ball_speed(p, many=many)
    if swing:
        _swing_options(p)
    return p


class _OnceTrue(_Once):
    """A flag (``--played``): True when given, refused twice, its ``given`` said."""

    def __init__(self, option_strings, dest, **kwargs):
        super().__init__(option_strings, dest, nargs=0, default=False, **kwargs)

    def __call__(self, parser, namespace, values, option_string=None):
        super().__call__(parser, namespace, True, option_string)


def _racket_option(p) -> None:
    p.add_argument(
        "--racket",
        default=DEFAULT_RACKET,
        type=preset_or_toml(RACKETS, "racket"),
        metavar="PRESET_OR_TOML",
        help=f"racket: preset ({', '.join(RACKETS)}; 'paper' is the paper's uniform racket) "
        f"or TOML file with a [racket] table (default: {DEFAULT_RACKET})",
    )


def tensions(args) -> list[float] | None:
    """``--tension-lb`` or ``--tension-kg`` values in N (a list), None if not given; one of
    them, and not with a stiffness (``--string-stiffness``, ``--string-bed-dt``).
    """
    typed = given(args, "tension_lb", "tension_kg", "string_stiffness", "string_bed_dt")
    if len(typed) > 1:
        raise ValueError(f"give one of {' or '.join(typed)}, not both: each sets the bed's "
                         "stiffness")  # fmt: skip
    if getattr(args, "tension_kg", None) is not None:
        kg = [in_range("--tension-kg", t, *TENSION_KG_RANGE, "kg", slips=(LB_AS_KG,))
              for t in _many(args.tension_kg)]  # fmt: skip
        return [t * GRAVITY for t in kg]
    if args.tension_lb is None:
        return None
    return [_tension(t) for t in _many(args.tension_lb)]


def stiffnesses(args, bed=None) -> list[float] | None:
    """``--string-stiffness`` [N/m] or ``--string-bed-dt`` [kp/cm] values as the bed's
    centre stiffness in N/m, checked (a list), None if neither was given; a DT is read on
    ``bed``'s strings, as an ERT reads it (:func:`racket.strings.ert.stiffness_from_dt`:
    their stretch counts), or at face value (x 980.665 N/m) without a bed (the ranges'
    check before any work).
    """
    if getattr(args, "string_bed_dt", None) is not None:
        from racket.strings.ert import stiffness_from_dt

        hint, slips = "; in N/m: --string-stiffness", (N_M_AS_KP_CM,)
        dts = [in_range("--string-bed-dt", dt, *DT_RANGE, "kp/cm", hint, slips)
               for dt in _many(args.string_bed_dt)]  # fmt: skip
        for dt in dts:  # (N/cm typed as kp/cm?)
            stiff_dt("--string-bed-dt", dt)
        return [KP_PER_CM * dt if bed is None else stiffness_from_dt(bed, dt, "--string-bed-dt")
                for dt in dts]  # fmt: skip
    if args.string_stiffness is None:
        return None
    return [
        in_range("--string-stiffness", k, *STRING_STIFFNESS_RANGE, "N/m", slips=(KN_AS_N,))
        for k in _many(args.string_stiffness)
    ]


def restring(racket, args):
    """``racket`` strung as ``--string``, ``--gauge``, ``--pattern`` and ``--played`` say
    (:func:`racket.strings.stringing.restrung`: what is given replaces the racket's); each
    option checked and refused as typed.
    """
    gauge = args.gauge and diameter(args.gauge, "--gauge", "mm")
    pattern = args.pattern and parse_pattern(args.pattern, "--pattern")
    if args.string not in (None, LINEAR):
        stringing(args.string, gauge, argument="--string")  # refused as typed before any work
    elif args.string == LINEAR or racket.strings.stringing is None:
        plain = "--string linear is" if args.string else "this racket's bed is"
        for flag in given(args, "gauge", "pattern", "played"):
            raise ValueError(
                f"{flag} describes a string, and {plain} a plain spring with none: name a "
                "string, e.g. --string polyester"
            )
    state = "played" if args.played else None
    return replace(racket, strings=restrung(racket.strings, args.string, gauge, pattern, state))


def _many(value) -> list:
    return list(value) if isinstance(value, list | tuple) else [value]


def lead_tape(racket, words):
    """``racket`` with the ``--lead GRAMS@CLOCK`` pieces ``words`` (None: none)."""
    for word in words or ():
        match = _LEAD.match(word)
        if not match:
            raise ValueError(
                f"--lead {word!r} must be GRAMS@CLOCK, e.g. 3@12, 2@3/9 or 4@6 (grams per side)"
            )
        grams = in_range("--lead", float(match.group(1)), *LEAD_GRAMS, "g per side",
                         slips=(KG_AS_G,))  # fmt: skip
        at = match.group(2)
        try:
            racket = racket.with_lead_tape(grams / 1e3, at.replace("/", " and "))
        except ValueError:
            raise ValueError(f"--lead {word!r} {_clock_hint(match.group(1), at)}") from None
    return racket


def _clock_hint(grams: str, at: str) -> str:
    """What to type instead of the clock position ``at`` of ``--lead`` that the head refused,
    in the option's own spelling (GRAMS@H/K, not the API's 'H and K').
    """
    if at.isdigit() and 1 <= int(at) <= 11:  # one side (12 and 6 are on the axis, accepted)
        return (
            f"puts lead on one side only: give both sides, {grams}@{int(at)}/{12 - int(at)} "
            "(the racket model is symmetric about its long axis)"
        )
    return (
        f"must be at 12 (the tip), 6 (the throat) or a mirrored pair H/K with H + K = 12, "
        f"e.g. {grams}@12, {grams}@6, {grams}@3/9, {grams}@2/10"
    )


def racket_from(args, spec: str | None = None, grid: bool = False):
    """The racket of a command: ``--racket`` (or ``spec``) with its ``--lead``, and, unless
    ``grid`` (a sweep varies them itself), its ``--support``, ``--tension-lb`` and
    ``--string-stiffness``; ``--grip`` for a hand-held racket (refused on another).
    """
    racket = lead_tape(load_racket(spec or args.racket), args.lead)
    supports = _many(getattr(args, "support", None) or [racket.support])
    check_hand(args, spec or args.racket, supports)
    newtons, _ = tensions(args), stiffnesses(args)  # checked before any work
    measured = given(args, "string_stiffness", "string_bed_dt")
    if getattr(args, "played", False) and measured:
        raise ValueError(
            f"--played lowers the strings' tension, and {measured[0]} sets the bed as measured "
            "(played or not): give one"
        )
    racket = restring(racket, args)
    if not grid:
        stiffness = stiffnesses(args, racket.strings)  # a DT read on the strings as strung
        racket = replace(racket, support=supports[0])
        if stiffness:
            racket = replace(racket, strings=restrung(racket.strings, stiffness=stiffness[0]))
        if newtons:
            from racket.specs.restring import with_tension

            racket = with_tension(racket, newtons[0])
    if getattr(args, "grip", None):
        if "hand-held" not in supports:
            raise ValueError(
                f"--grip {args.grip} holds a hand-held racket; this one is {supports[0]}: "
                "add --support hand-held"
            )
        racket = replace(racket, hand=GRIPS[args.grip])
    return racket


def check_hand(args, spec, supports) -> None:
    """A ``[racket.hand]`` table in the racket's TOML file ``spec`` refused in one line where
    no hand holds the racket (none of ``supports`` is hand-held) and the command does not
    read the hand otherwise (:data:`HAND_READERS`): it would be ignored in silence.
    """
    command = getattr(args, "command", None)
    if spec in RACKETS or "hand-held" in supports or command in HAND_READERS:
        return
    table = read_toml(spec).get("racket", {})  # (a file load_racket has read)
    if "hand" not in table:
        return
    support = table.get("support")
    typed = given(args, "support")
    held = " / ".join(supports)
    said = (f"{typed[0]} {held}" if typed else f'its support = "{support}"' if support
            else f"its preset's support, {held}")  # fmt: skip
    what = (f"{FREE_ONLY[command]}: leave the table out" if command in FREE_ONLY
            else "give --support hand-held, or leave the table out")  # fmt: skip
    raise ValueError(f"[racket.hand] in {spec} does not apply to a {held} racket ({said}): only "
                     f"a hand-held racket has a hand; {what}")  # fmt: skip


def offset_cm(value, half: float) -> float:
    """``--offset`` [cm from the long axis] checked on strings ``half`` [cm] wide either side
    (one in m typed as cm refused with the hint beyond them, asked about within
    :data:`NEAR_AXIS_CM` of the axis), in cm.
    """
    unit = "cm from the long axis"
    x = in_range("--offset", value, -half, half, unit, slips=(M_AS_CM,))
    if x != 0.0:
        usual = (NEAR_AXIS_CM, half) if x > 0 else (-half, -NEAR_AXIS_CM)
        suspect("--offset", x, usual, unit, (M_AS_CM,),
                f"within {NEAR_AXIS_CM:g} cm of it")  # fmt: skip
    return x


def check_offset(args, racket) -> None:
    """``--offset`` refused in one line on a racket whose roll inertia is not modelled (its
    impacts are all on the long axis), the racket named as ``--racket`` gave it.
    """
    if racket.beam.roll_inertia is None:
        refuse_unused(args, ("offset",), f"to the racket {args.racket!r}: its roll inertia is "
                      "not modelled, every impact is on the long axis (a spec-sheet racket, "
                      f"such as {DEFAULT_RACKET}, has it)")  # fmt: skip


def impact_point(args, racket) -> tuple[float | None, float | None]:
    """The impact point of ``--position`` [cm from the tip] and ``--offset`` [cm from the
    long axis, + towards 3 o'clock], each checked on the strings, in m; None where not
    given (the string centre, the long axis).
    """
    position = offset = None
    if args.position is not None:
        low, high = (100 * end for end in racket.strings.extent)
        position = in_range("--position", args.position, low, high, "cm from the tip",
                            slips=(M_AS_CM,)) / 100  # fmt: skip
    check_offset(args, racket)
    if args.offset is not None:
        offset = offset_cm(args.offset, 50 * racket.strings.full_width) / 100
    return position, offset


def modes_options(args) -> None:
    """The racket's options that ``modes`` does not take refused in one line: its modes are
    the free frame's, whatever holds or strings it.
    """
    refuse_unused(args, ("support", "grip", *STRING_OPTIONS), "to modes (the free frame's modes "
                  "and mass properties, whatever holds or strings it): racket-impact specs "
                  "gives the modes held by the hand")  # fmt: skip


def racket_conditions(
    args, racket, name: str | None = None, speed=None, swing=None, each: dict | None = None
) -> str:
    """The conditions line of a run (:func:`studies.conditions.conditions_line`): the racket
    as named (``name``, default ``--racket``), its support, grip and strings (as typed), the
    ball (``--ball``) at ``speed`` [m/s] in the unit the user typed, the ``swing`` (a
    :class:`racket.Swing`, said with its head speed); ``each``: several rackets (label ->
    racket), each with its own hand unless the options set it, and its strings named (once
    when they are all strung alike).
    """
    typed = {
        unit: ", ".join(shown(v) for v in _many(value))
        for unit, value in (("lb", getattr(args, "tension_lb", None)),
                            ("kg", getattr(args, "tension_kg", None)),
                            ("N/m", getattr(args, "string_stiffness", None)),
                            ("kp/cm", getattr(args, "string_bed_dt", None)))
        if value is not None
    }  # fmt: skip
    tension = next((f"{v} {u}" for u, v in typed.items() if u in ("lb", "kg")), None)
    stiffness = next((f"{v} {u}" for u, v in typed.items() if u in ("N/m", "kp/cm")), None)
    details = racket_details(racket, tension)
    strung = racket.strings.stringing
    if each:
        said = {label: racket_details(r)["strings"] for label, r in each.items()}
        alike = len(set(said.values())) == 1
        details["strings"] = (
            next(iter(said.values())) if alike
            else "; ".join(f"{label}: {words}" for label, words in said.items())
        )  # fmt: skip
        details["grip"] = "each its own grip" if details["grip"] else None
        if stiffness:  # as typed: each racket's is said above
            details["strings"] += f"; set by {'DT ' if 'kp/cm' in stiffness else ''}{stiffness}"
    elif stiffness:  # as typed (several: a grid's), the ERT's DT said as such
        stiffness = f"DT {stiffness}" if stiffness.endswith("kp/cm") else stiffness
        details["strings"] = (
            f"{strung.describe('')}, {stiffness}" if strung else f"{PLAIN_BED}, {stiffness}"
        )
    elif tension and (strung is None or "," in tension):  # a grid's: no one stiffness
        details["strings"] = strung.describe(tension) if strung else f"{PLAIN_BED} at {tension}"
    supports = getattr(args, "support", None)
    if isinstance(supports, list) and supports:  # sweep's grid: one support or several
        details["support"] = " / ".join(supports)
        if "hand-held" in supports:  # the grid holds the racket in its own hand
            details["grip"] = racket_details(replace(racket, support="hand-held"))["grip"]
    if args.lead:
        details["strings"] += f", lead {' '.join(args.lead)}"
    speeds = ("speed", "swing_speed", "racket_speed", "target_ball_speed")
    unit = speed_unit(args, *(name for name in speeds if hasattr(args, name)))
    moved = None
    if swing is not None:
        from studies.conditions import speed_text

        moved = f"swung at {speed_text(swing.head_speed, unit)} head speed {swing.pivot_words()}"
    return conditions_line(
        name or args.racket, getattr(args, "ball", None), speed, unit, moved, **details
    )
