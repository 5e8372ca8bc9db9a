"""``racket-impact strings``: one racket strung with each string in turn, for a stringer
(:mod:`studies.strings.table`).
"""

from __future__ import annotations

from studies.cli.files import add_outputs, check_outputs, say_conditions, write_table
from studies.cli.options import (
    _ball_arg,
    _print_table,
    _speed,
    _speed_option,
    in_speed_unit,
    speed_unit,
)
from studies.cli.racket_options import add_racket_options, racket_conditions, racket_from
from studies.cli.serve import DEFAULT_HEAD_SPEED
from studies.conditions import speed_text
from studies.config import load_ball
from studies.sweeps import BALL_SPEED


def add_strings(sub) -> None:
    """The ``strings`` subcommand, on the subparsers ``sub``."""
    from racket.strings.stringing import STRING_CHOICES

    what = ("one racket strung with each string in turn: the bed's stiffness (DT), stretch "
            "and loss, power, dwell time and the serve")  # fmt: skip
    p = sub.add_parser("strings", help=what)
    add_racket_options(p)
    _ball_arg(p)
    _speed_option(p, "speed", BALL_SPEED, "ball speed onto the racket at rest")
    _speed_option(p, "racket-speed", DEFAULT_HEAD_SPEED, "racket-head (string centre) speed "
                  "of the serve")  # fmt: skip
    p.add_argument("--strings", nargs="+", metavar="NAME", default=list(STRING_CHOICES),
                   help="strings to compare: presets or MAINS/CROSSES hybrids (default: "
                   f"{', '.join(STRING_CHOICES)})")  # fmt: skip
    add_outputs(p)
    p.set_defaults(func=cmd_strings)


def cmd_strings(args) -> int:
    """``racket-impact strings``."""
    from racket.strings.stringing import stringing
    from studies.strings.table import string_table

    check_outputs(tables=[("--out", args.out)])
    for name in args.strings:
        stringing(name, argument="--strings")  # refused before any work: one line naming it
    racket = racket_from(args)
    speed, head = _speed(args, "speed"), _speed(args, "racket_speed")
    unit = speed_unit(args, "racket_speed", "speed")
    say_conditions(f"{racket_conditions(args, racket, speed=speed)}; serves at a head speed of "
                   f"{speed_text(head, unit)}")  # fmt: skip
    table = in_speed_unit(string_table(racket, load_ball(args.ball), speed, head, args.strings),
                          unit)  # fmt: skip
    # printed: the bed by its DT and moving mass (its stiffness in kN/m and the strings' whole
    # mass are in --out), the serve in the unit typed
    hidden = ["stiffness_kN_m", "bed_mass_g"] + (["serve_m_s"] if unit != "m/s" else [])
    _print_table(table.drop(columns=hidden))
    if args.out:
        write_table(table, args.out)
    return 0
