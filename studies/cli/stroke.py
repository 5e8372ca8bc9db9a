"""``racket-impact stroke``: the ball's speed, launch and spin after a stroke (issue 36), for
the presets by name or a stroke of one's own; angles in degrees and spins in rpm as typed,
in SI for the core (:mod:`studies.strokes.stroke`).
"""

from __future__ import annotations

import math
import warnings
from dataclasses import replace

from common.checks import (
    FASTEST_HEAD,
    FASTEST_STROKE,
    SPEED_SLIPS,
    in_range,
    shown,
    slip_hints,
    too_fast,
)
from common.units import SPEED_SUFFIXES
from racket import STROKES
from racket.stroke import LIMITS, RPM, SHAFTS
from studies.cli.files import add_outputs, check_outputs, save_plot, say_conditions, write_table
from studies.cli.options import _ball_arg, _print_table, _speed_option, _typed, speed_unit
from studies.cli.racket_options import (
    _OnceTrue,
    add_racket_options,
    impact_point,
    racket_conditions,
    racket_from,
)
from studies.config import load_ball

OWN_BASE = "flat-forehand"
"""The preset a stroke of one's own starts from (stroke options and no NAME): the options
given replace its numbers, the others stay its."""

OWN = "own stroke"
"""The name of a stroke of one's own in the tables."""

SLOW_SPIN_RPM = 400.0
"""Incoming spin [rpm] below which a spin typed (not 0) is asked about: rad/s typed as rpm?
**An assumption**: balls in play spin from several hundred rpm (flat shots) to several
thousand (topspin, kick serves); the presets' 200 rad/s is 1910 rpm."""

SMALL_ANGLE_DEG = 1.0
"""An angle [deg] typed below this in size (not 0) is asked about: radians typed as degrees?
(**an assumption**: a player's angles are whole degrees or more; 0.2 rad is 11.5 deg)."""

_ANGLES = {"path": "path_angle", "face": "face_angle", "across": "swing_across",
           "ball_angle": "ball_angle"}  # fmt: skip
"""The angle options (their ``dest``) and the :class:`racket.Stroke` field each sets."""

_SPINS = {"topspin": "topspin", "sidespin": "sidespin"}
"""The incoming spin options [rpm] and the field each sets [rad/s]."""

_SPEEDS = {"head_speed": "head_speed", "ball_speed": "ball_speed"}
"""The speed options (``--NAME[-mph|-kmh]``) and the field each sets [m/s]."""

_API_WORDS = {"head_speed": "--head-speed", "ball_speed": "--ball-speed", "path_angle": "--path",
              "face_angle": "--face", "ball_angle": "--ball-angle",
              "swing_across": "--across"}  # fmt: skip
"""The Stroke's words in its refusal, as the options that set them."""


def add_stroke(sub) -> None:
    """The ``stroke`` subcommand, on the subparsers ``sub``."""
    p = presets_parser(
        sub, "stroke", "ball speed, launch and spin after a stroke",
        f"preset strokes: {', '.join(STROKES)} (default: all). The stroke options below "
        f"replace the named strokes' numbers; with no NAME they make one stroke of your own, "
        f"on the {OWN_BASE}'s numbers for those not given",
    )  # fmt: skip
    add_racket_options(p)
    _ball_arg(p)
    _speed_option(p, "head-speed", None, "racket speed at the impact point")
    _angle(p, "--path", "path_angle", "the racket path above the horizontal (+ rising)", True)
    _angle(p, "--face", "face_angle", "the face's tilt from vertical (+ open, - closed)", True)
    _angle(p, "--across", "swing_across", "the path across the aim, + to the player's left")
    _speed_option(p, "ball-speed", None, "incoming ball's speed")
    _angle(p, "--ball-angle", "ball_angle", "incoming ball's angle below the horizontal "
           "(+ descending)")  # fmt: skip
    spins = (("--topspin", "topspin"), ("--sidespin", "sidespin (+ curving it to its left)"))
    for flag, what in spins:
        high = LIMITS[flag[2:]][1] / RPM
        p.add_argument(flag, type=float, metavar="RPM", help=f"incoming ball's {what} [rpm], "
                       f"within +-{high:.0f}")  # fmt: skip
    p.add_argument(
        "--shaft",
        choices=SHAFTS,
        help="the racket's long axis in the face plane: "
        "horizontal (groundstrokes), vertical (serves)",
    )
    p.add_argument(
        "--position",
        type=float,
        metavar="CM",
        help="impact point [cm from the tip] (default: centre of the strings)",
    )
    p.add_argument("--offset", type=float, metavar="CM", help="impact point's distance from "
                   "the long axis [cm, + towards 3 o'clock] (default: on the axis)")  # fmt: skip
    p.add_argument("--lubricated", action=_OnceTrue, help="lubricated strings: mains and crosses "
                   "slide on each other more easily")  # fmt: skip
    p.add_argument("--stiff-bed", action=_OnceTrue, help="strings that never slide sideways (the "
                   "limit of a laterally rigid bed)")  # fmt: skip
    add_outputs(p, plot="exit speed against spin")
    p.set_defaults(func=cmd_stroke)


def presets_parser(sub, name: str, what: str, names: str):
    """The subparser ``name`` on the subparsers ``sub`` of a command that answers ``what``
    for presets or one's own (``stroke``, ``court``): the presets are its NAMEs (``names``:
    their help); the command adds its own options.
    """
    p = sub.add_parser(name, help=f"{what} (presets or your own)")
    p.add_argument("names", nargs="*", metavar="NAME", help=names)
    return p


def check_names(names: list[str], known, kind: str, listing: str) -> None:
    """The NAMEs given, ``names``, each among ``known`` and named once; ValueError in one line
    otherwise, naming the ``kind`` ("stroke", "court") and, for an unknown name, the ones
    there are (``listing``).
    """
    for name in names:
        if name not in known:
            raise ValueError(f"unknown {kind} {name!r}; {listing}")
        if names.count(name) > 1:
            raise ValueError(f"{kind} {name!r} is named twice; name it once")


def _angle(p, flag: str, field: str, what: str, many: bool = False) -> None:
    low, high, _ = LIMITS[field]
    p.add_argument(
        flag, type=float, nargs="+" if many else None, metavar="DEG",
        help=f"{what} [deg], {low:g} to {high:g}" + ("; several: a row for each, paths "
        "times faces" if many else ""),
    )  # fmt: skip


def cmd_stroke(args) -> int:
    """``racket-impact stroke``."""
    from racket.strings.sideways import sideways
    from studies.strokes.stroke import bed_words, spin_note, stroke_table

    check_outputs(tables=[("--out", args.out)], plots=[("--plot", args.plot)])
    racket, ball = racket_from(args), load_ball(args.ball)
    if racket.support == "clamped-head":
        raise ValueError("a stroke needs a racket that moves: --support free or hand-held, "
                         "not clamped-head")  # fmt: skip
    position, offset = impact_point(args, racket)
    strung = racket.strings.stringing
    if strung is None or strung.tension is None:
        how = (
            "give its strings and their tension, e.g. --string polyester --tension-lb 55"
            if strung is None
            else "give the strings' tension (--tension-lb) instead"
        )
        for flag in [f for f, on in (("--lubricated", args.lubricated),
                                     ("--stiff-bed", args.stiff_bed)) if on]:  # fmt: skip
            raise ValueError(
                f"{flag} does not apply to a bed given by its stiffness alone: its mains' "
                f"tension is unknown and it is stiff sideways already; {how}"
            )
    if args.lubricated and args.stiff_bed:
        raise ValueError("--lubricated does not apply with --stiff-bed: strings that "
                         "never slide do not feel each other's friction")  # fmt: skip
    unit = speed_unit(args, "head_speed", "ball_speed")
    strokes, varied = _strokes(args)
    side = sideways(racket.strings, lubricated=args.lubricated, slide=not args.stiff_bed)
    centre = position is None
    where = 100 * (racket.strings.center if centre else position)
    said = f"hit at {where:.1f} cm from the tip" + (" (the string centre)" if centre else "")
    if offset:
        said += f", {100 * offset:.1f} cm off the long axis"
    note = spin_note(strokes)
    conditions = say_conditions(
        f"{racket_conditions(args, racket)}, {said}, {bed_words(side, args.lubricated)}"
        + (f"; {note}" if note else "")
    )
    table = stroke_table(strokes, racket, ball, position, side, unit, offset)
    _show(table, unit, varied)
    if args.out:
        write_table(table, args.out)
    if args.plot:
        from studies.strokes.stroke import plot_speed_spin

        save_plot(plot_speed_spin(table, unit=unit, conditions=conditions), args.plot)
    return 0


def _strokes(args) -> tuple[list, list[str]]:
    """The strokes the command line asks for, every input checked as typed: (name, Stroke)
    pairs (each named stroke with the options given, or one of one's own, for each path and
    face), and the columns that vary within a stroke ("path_deg", "face_deg").
    """
    names = args.names or []
    check_names(names, STROKES, "stroke", f"the presets: {', '.join(STROKES)}")
    changes = {}
    for dest, field in _SPEEDS.items():
        if any(getattr(args, f"{dest}{u}") is not None for u in ("", "_mph", "_kmh")):
            changes[field] = _stroke_speed(args, dest, field)
    for dest, field in _ANGLES.items():
        values, flag = getattr(args, dest), f"--{dest.replace('_', '-')}"
        if isinstance(values, list):  # --path and --face: a row for each
            changes[field] = [_angle_value(flag, v, field) for v in values]
        elif values is not None:  # one angle (--across, --ball-angle)
            changes[field] = _angle_value(flag, values, field)
    for dest, field in _SPINS.items():
        if getattr(args, dest) is not None:
            changes[field] = _spin(f"--{dest}", getattr(args, dest), field)
    if args.shaft is not None:
        changes["shaft"] = args.shaft
    bases = {name: STROKES[name] for name in names}
    if not bases:
        bases = {OWN: STROKES[OWN_BASE]} if changes else dict(STROKES)
    paths, faces = changes.pop("path_angle", [None]), changes.pop("face_angle", [None])
    pairs = []
    for name, base in bases.items():
        for path in paths:
            for face in faces:
                grid = {
                    k: v for k, v in (("path_angle", path), ("face_angle", face)) if v is not None
                }
                pairs.append((name, _made(name, base, {**changes, **grid})))
    varied = [c for c, values in (("path_deg", paths), ("face_deg", faces)) if len(values) > 1]
    return pairs, varied


def _made(name: str, base, changes: dict):
    """``base`` with ``changes`` [SI], its refusal (the racket missing the ball) said in the
    options' words.
    """
    try:
        return replace(base, **changes)
    except ValueError as err:
        message = str(err)
        for word, option in _API_WORDS.items():
            message = message.replace(word, option)
        angles = ", ".join(f"{option[2:]} {math.degrees(changes[field]):.4g} deg"
                           for field, option in (("path_angle", "--path"), ("face_angle", "--face"))
                           if field in changes)  # fmt: skip
        raise ValueError(f"stroke {name!r}{f' ({angles})' if angles else ''}: {message}") from None


def _stroke_speed(args, dest: str, field: str) -> float:
    """``--NAME[-mph|-kmh]`` [its unit] in the Stroke's range, in m/s; one faster than a
    racket head or a serve has gone asked about.
    """
    flag, value, unit, size = _typed(args, dest)
    low, high, _ = LIMITS[field]
    value = in_range(flag, value, low / size, high / size, unit, slips=SPEED_SLIPS[unit])
    fastest, what = ((FASTEST_HEAD, "a racket head's fastest, estimated") if field == "head_speed"
                     else (FASTEST_STROKE, "the serve record"))  # fmt: skip
    base = f"--{dest.replace('_', '-')}"

    def instead(typed: str) -> str:
        return f" ({base}-{SPEED_SUFFIXES[typed]} {shown(value)})"

    too_fast(flag, value, unit, fastest, what, instead)
    return value * size


def _angle_value(flag: str, value: float, field: str) -> float:
    """An angle option [deg] in the Stroke's range, in radians; one below
    :data:`SMALL_ANGLE_DEG` asked about (radians typed as degrees?).
    """
    low, high, _ = LIMITS[field]
    value = in_range(flag, value, low, high, "deg")
    ask_small_angle(flag, value, low, high)
    return math.radians(value)


def ask_small_angle(flag: str, value: float, low: float, high: float) -> None:
    """Ask in a warning about an angle option ``value`` [deg] in [``low``, ``high``] below
    :data:`SMALL_ANGLE_DEG` in size, not 0 (radians typed as degrees?).
    """
    if 0.0 < abs(value) < SMALL_ANGLE_DEG:
        slipped = slip_hints(value, low, high, "deg", ((180 / math.pi, "radians typed as deg?",
                                                        "rad"),))  # fmt: skip
        warnings.warn(f"{flag} {shown(value)} deg is a very small angle: {slipped}", stacklevel=3)


def _spin(flag: str, value: float, field: str) -> float:
    """An incoming spin option [rpm] in the Stroke's range, in rad/s; one slower than
    :data:`SLOW_SPIN_RPM` asked about (rad/s typed as rpm?).
    """
    low, high, _ = LIMITS[field]
    value = in_range(flag, value, low / RPM, high / RPM, "rpm")
    ask_slow_spin(flag, value, low / RPM, high / RPM)
    return value * RPM


def ask_slow_spin(flag: str, value: float, low: float, high: float) -> None:
    """Ask in a warning about a spin option ``value`` [rpm] in [``low``, ``high``] slower
    than :data:`SLOW_SPIN_RPM`, not 0 (rad/s typed as rpm?).
    """
    if 0.0 < abs(value) < SLOW_SPIN_RPM:
        slipped = slip_hints(value, low, high, "rpm", ((1 / RPM, "rad/s typed as rpm?", "rad/s"),))
        warnings.warn(f"{flag} {shown(value)} rpm is slower than balls in play spin (about "
                      f"{SLOW_SPIN_RPM:g} rpm and more): {slipped}", stacklevel=3)  # fmt: skip


_INPUTS = {"stroke": "stroke", "head_speed": "head speed", "path_deg": "path [deg]",
           "face_deg": "face [deg]", "across_deg": "across [deg]", "ball_speed": "ball speed",
           "ball_angle_deg": "ball angle [deg]", "ball_topspin_rpm": "ball topspin [rpm]",
           "ball_sidespin_rpm": "ball sidespin [rpm]", "shaft": "shaft"}  # fmt: skip
"""The printed table of the strokes: its columns and their labels (a speed's unit added)."""

_AFTER = {"stroke": "stroke", "path_deg": "path [deg]", "face_deg": "face [deg]",
          "exit_speed": "exit speed", "launch_deg": "launch [deg]", "spin_rpm": "spin [rpm]",
          "topspin_rpm": "topspin [rpm]", "sidespin_rpm": "sidespin [rpm]",
          "contact_time_ms": "contact time [ms]", "contact": "slid or gripped",
          "racket_share": "racket's share [-]"}  # fmt: skip
"""The printed table of the ball after: its columns and their labels."""


def _show(table, unit: str, varied: list[str]) -> None:
    """Print the strokes (the angles swept left out) and the ball after each (with the angles
    swept), speeds in ``unit``, spins to the rpm.
    """
    suffix = SPEED_SUFFIXES[unit]
    firsts = table.drop_duplicates("stroke")
    for labels, rows, drop in ((_INPUTS, firsts, varied),
                               (_AFTER, table, [c for c in ("path_deg", "face_deg")
                                                if c not in varied])):  # fmt: skip
        columns = {(f"{c}_{suffix}" if c.endswith("speed") else c):
                   (f"{name} [{unit}]" if c.endswith("speed") else name)
                   for c, name in labels.items() if c not in drop}  # fmt: skip
        view = rows[list(columns)].rename(columns=columns)
        spins = [name for c, name in columns.items() if c.endswith("_rpm")]
        view = view.assign(**{name: view[name].round().astype(int) for name in spins})
        if rows is table:
            print()  # the ball after, apart from the strokes
        _print_table(view)
