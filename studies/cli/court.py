"""``racket-impact court``: does this court play fast (issue 36)?  A ball's bounce on the court
presets by name or a court of one's own, and each court's ITF pace rating; angles in degrees
and spins in rpm as typed, in SI for the core (:mod:`studies.strokes.court`).
"""

from __future__ import annotations

import math

from ball.court import (
    COR_RANGE,
    COURTS,
    CPR_ANGLE_DEG,
    CPR_SPEED,
    FASTEST_BOUNCE,
    LAB_SURFACES,
)
from ball.grip import FRICTION_RANGE
from common.checks import (
    FASTEST_STROKE,
    SPEED_RANGE,
    SPEED_SLIPS,
    finite,
    in_range,
    shown,
    suspect,
    too_fast,
)
from common.units import SPEED_SUFFIXES
from racket.stroke import RPM
from studies.cli.files import add_outputs, check_outputs, say_conditions, write_table
from studies.cli.options import _ball_arg, _print_table, _speed_option, _typed, speed_unit
from studies.cli.stroke import ask_slow_spin, ask_small_angle, check_names, presets_parser
from studies.conditions import speed_text
from studies.config import load_ball

OWN = "own court"
"""The name of a court of one's own (``--friction`` and ``--cor``) in the tables."""

SPIN_LIMIT_RPM = 1000.0 / RPM
"""The largest spin [rpm] either way :func:`ball.court.bounce` takes (1000 rad/s)."""

FASTEST_LANDING = 0.75 * FASTEST_STROKE
"""The fastest a ball is taken to come down on a court [m/s]: 54.9 m/s (123 mph), the serve
record (:data:`common.checks.FASTEST_STROKE`) less a quarter for the air on its way there.
**An ASSUMPTION**: no record of speeds at the bounce is kept (a radar reads a serve as it
leaves the racket), and the quarter is a guess on the low side of what the air takes:
filming pro matches, J. Yandell found virtually every shot, the serve included, lost at least
half its speed by the time it reached the other player, the bounce included
(tennisplayer.net, "Ball speed in pro tennis").  A ball typed faster is asked about (67 m/s:
mph typed as m/s? 67 mph is the ITF pace test's 30 m/s), not refused (:data:`FASTEST_BOUNCE`
is)."""

PERCENT_AS_FRACTION = (0.01, "percent typed as a fraction?", "%")
"""A friction or COR in percent where a fraction is asked for."""


def add_court(sub) -> None:
    """The ``court`` subcommand, on the subparsers ``sub``."""
    p = presets_parser(
        sub, "court", "a ball's bounce on a court and the court's ITF pace rating",
        f"courts: {', '.join(COURTS)} (default: all three; ball/court.py gives each number's "
        f"source or says it is an assumption), or Cross's lab surfaces "
        f"{', '.join(repr(s) for s in LAB_SURFACES)}",
    )  # fmt: skip
    p.add_argument("--friction", type=float, metavar="X", help=f"your court's sliding "
                   f"friction [-], {FRICTION_RANGE[0]:g} to {FRICTION_RANGE[1]:g} (with --cor: "
                   f"a row '{OWN}')")  # fmt: skip
    p.add_argument("--cor", type=float, metavar="E", help=f"your court's vertical COR [-], "
                   f"{COR_RANGE[0]:g} to {COR_RANGE[1]:g} (with --friction)")  # fmt: skip
    _ball_arg(p)
    _speed_option(p, "speed", None, f"ball speed before the bounce (default {CPR_SPEED:g} m/s, "
                  "the ITF pace test's)")  # fmt: skip
    p.add_argument("--angle", type=float, metavar="DEG", help=f"the ball's path above the court "
                   f"[deg], between 0 and 90 (default {CPR_ANGLE_DEG:g}, the ITF pace "
                   "test's)")  # fmt: skip
    p.add_argument("--topspin", type=float, metavar="RPM", help=f"the ball's spin before [rpm], "
                   f"within +-{SPIN_LIMIT_RPM:.0f}, negative: backspin (default none)")  # fmt: skip
    add_outputs(p)
    p.set_defaults(func=cmd_court)


def cmd_court(args) -> int:
    """``racket-impact court``."""
    from ball.court import Court
    from studies.strokes.court import court_table

    check_outputs(tables=[("--out", args.out)])
    names = list(args.names) or list(COURTS)
    check_names(names, {**COURTS, **LAB_SURFACES}, "court", f"the courts: {', '.join(COURTS)} "
                f"(and the lab surfaces: {', '.join(repr(s) for s in LAB_SURFACES)}), or your "
                "own with --friction and --cor")  # fmt: skip
    courts = list(names)
    own = _own(args)
    if own is not None:
        courts.append(Court(OWN, *own))
    speed, unit = _ball_speed(args), speed_unit(args, "speed")
    angle, spin = _angle(args.angle), _spin(args.topspin)
    if speed * math.sin(math.radians(angle)) < SPEED_RANGE[0]:
        (flag, typed, _, size), low = _typed(args, "speed"), SPEED_RANGE[0]
        said = f"{flag} {shown(typed)} {unit}" if typed is not None else f"{speed:g} m/s"
        raise ValueError(
            f"the ball must come down on the court at {low / size:.4g} {unit} at least (its "
            f"speed times the sine of its angle); {said} at --angle {shown(angle)} deg comes "
            "down slower"
        )
    ball = load_ball(args.ball)
    conditions = f"ball {args.ball} at {speed_text(speed, unit)}, {shown(angle)} deg above the "
    conditions += f"court, {_spin_words(args.topspin)}; the pace rating (CPR) from the ITF's "
    conditions += f"test bounce ({speed_text(CPR_SPEED, unit)}, {CPR_ANGLE_DEG:g} deg, no spin)"
    say_conditions(conditions)
    table = court_table(courts, speed, math.radians(angle), spin, ball, unit)
    _show(table, unit)
    if args.out:
        write_table(table, args.out)
    return 0


def _own(args) -> tuple[float, float] | None:
    """``--friction`` and ``--cor`` checked (both or neither), or None."""
    if args.friction is None and args.cor is None:
        return None
    if args.cor is None:
        raise ValueError(f"--friction needs --cor: your court's vertical COR, {COR_RANGE[0]:g} "
                         f"to {COR_RANGE[1]:g}")  # fmt: skip
    if args.friction is None:
        raise ValueError(f"--cor needs --friction: your court's sliding friction, "
                         f"{FRICTION_RANGE[0]:g} to {FRICTION_RANGE[1]:g}")  # fmt: skip
    return tuple(
        in_range(flag, value, *bounds, "", slips=_percent(value))
        for flag, value, bounds in (("--friction", args.friction, FRICTION_RANGE),
                                    ("--cor", args.cor, COR_RANGE))
    )  # fmt: skip


def _percent(value: float) -> tuple:
    """The slip of a friction or COR typed in percent, for a value that could be one (10 or
    more: **an assumption**, a court's friction and COR are tens of percent; 3 is no 0.03).
    """
    return (PERCENT_AS_FRACTION,) if abs(value) >= 10.0 else ()


def _ball_speed(args) -> float:
    """``--speed[-mph|-kmh]`` [its unit] in :func:`ball.court.bounce`'s range, in m/s (the
    ITF test's without one); one faster than the serve record asked about, and one faster
    than a ball comes down on a court (:data:`FASTEST_LANDING`).
    """
    flag, value, unit, size = _typed(args, "speed")
    if value is None:
        return CPR_SPEED
    value = in_range(flag, value, SPEED_RANGE[0] / size, FASTEST_BOUNCE / size, unit,
                     slips=SPEED_SLIPS[unit])  # fmt: skip

    def instead(typed: str) -> str:
        return f" (--speed-{SPEED_SUFFIXES[typed]} {shown(value)})"

    if abs(value * size) > FASTEST_STROKE:
        too_fast(flag, value, unit, FASTEST_STROKE, "the serve record", instead)
    else:
        limit = FASTEST_LANDING / size
        why = (f"faster than a ball comes down on a court (about {limit:.3g} {unit}: the serve "
               "record less what the air takes, estimated)")  # fmt: skip
        suspect(flag, value, (-limit, limit), unit, SPEED_SLIPS[unit], why, instead, always=True)
    return value * size


def _angle(value) -> float:
    """``--angle`` [deg] in (0, 90) (the ITF test's without one); one below
    :data:`studies.cli.stroke.SMALL_ANGLE_DEG` asked about (radians typed as degrees?).
    """
    if value is None:
        return CPR_ANGLE_DEG
    x = finite("--angle", value, "deg")
    if not 0.0 < x < 90.0:
        hint = f" (the angle is above the court, positive: --angle {shown(-x)}?)" if (
            -90.0 < x < 0.0) else ""  # fmt: skip
        raise ValueError(
            f"--angle must be in (0, 90) deg above the court, got {shown(value)}{hint}"
        )
    ask_small_angle("--angle", x, 0.0, 90.0)
    return x


def _spin(value) -> float:
    """``--topspin`` [rpm] in :func:`ball.court.bounce`'s range, in rad/s (none without one);
    one slower than :data:`studies.cli.stroke.SLOW_SPIN_RPM` asked about (rad/s typed as rpm?).
    """
    if value is None:
        return 0.0
    x = in_range("--topspin", value, -SPIN_LIMIT_RPM, SPIN_LIMIT_RPM, "rpm")
    ask_slow_spin("--topspin", x, -SPIN_LIMIT_RPM, SPIN_LIMIT_RPM)
    return x * RPM


def _spin_words(rpm) -> str:
    """The incoming spin in words: "no spin", "1500 rpm topspin", "800 rpm backspin"."""
    if not rpm:
        return "no spin"
    return f"{shown(abs(rpm))} rpm {'topspin' if rpm > 0 else 'backspin'}"


_COURTS = {"court": "court", "friction": "friction [-]", "cor": "COR [-]",
           "source": "numbers", "cpr": "CPR [-]", "pace": "ITF pace category"}  # fmt: skip
"""The printed table of the courts: its columns and their labels."""

_AFTER = {"court": "court", "speed_after": "speed after", "angle_after_deg": "angle after [deg]",
          "topspin_after_rpm": "topspin after [rpm]", "vx_ratio": "vx2/vx1 [-]",
          "e_y": "e_y [-]", "apparent_friction": "apparent friction [-]",
          "contact_time_ms": "contact time [ms]", "contact": "slid or gripped"}  # fmt: skip
"""The printed table of the ball after the bounce: its columns and their labels."""


def _show(table, unit: str) -> None:
    """Print the courts with their pace, then the ball after the bounce on each, speeds in
    ``unit``, spins to the rpm.
    """
    courts = table.assign(pace=[f"{n} {name}" for n, name in
                                zip(table["category"], table["pace"], strict=True)])  # fmt: skip
    courts = courts.assign(cpr=courts["cpr"].round(1))  # as the ITF quotes it: 29.5, 45
    _print_table(courts[list(_COURTS)].rename(columns=_COURTS))
    print()  # the ball after, apart from the courts
    suffix = SPEED_SUFFIXES[unit]
    columns = {(f"{c}_{suffix}" if c.endswith("speed_after") else c):
               (f"{name} [{unit}]" if c.endswith("speed_after") else name)
               for c, name in _AFTER.items()}  # fmt: skip
    view = table[list(columns)].rename(columns=columns)
    spin = "topspin after [rpm]"
    _print_table(view.assign(**{spin: view[spin].round().astype(int)}))
