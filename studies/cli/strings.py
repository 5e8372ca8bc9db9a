"""``racket-impact strings``: one racket strung with each string in turn, for a stringer
(:mod:`studies.strings.table`).
"""

from __future__ import annotations

import textwrap

from studies.cli.files import add_outputs, check_outputs, say_conditions, write_table
from studies.cli.options import (
    _ball_arg,
    _print_table,
    _speed,
    _speed_option,
    in_speed_unit,
    refuse_unused,
    speed_unit,
)
from studies.cli.racket_options import add_racket_options, racket_conditions, racket_from
from studies.cli.serve import DEFAULT_HEAD_SPEED
from studies.cli.show import WIDTH
from studies.conditions import speed_text
from studies.config import load_ball
from studies.sweeps import BALL_SPEED

NOT_MODELLED = (
    "not modelled: control (where the ball goes for a given swing), the strings' wear and "
    "their loss of tension in play beyond --played"
)
"""What ``strings`` leaves out, said under its table."""


def add_strings(sub) -> None:
    """The ``strings`` subcommand, on the subparsers ``sub``."""
    from racket.strings.stringing import STRING_CHOICES

    what = ("one racket strung with each string in turn: the bed's stiffness (DT), stretch "
            "and loss, power, dwell time, the serve, the forehand's spin and the feel")  # fmt: skip
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
    from racket.strings.sizes import diameter
    from racket.strings.stringing import stringing
    from studies.strings.table import SPIN_STROKE, string_table

    check_outputs(tables=[("--out", args.out)])
    if args.string is not None:
        raise ValueError(
            f"--string {args.string}: strings compares the strings of --strings, each in "
            "turn; name them there (e.g. --strings nylon natural-gut)"
        )
    for name in args.strings:
        stringing(name, argument="--strings")  # refused before any work: one line naming it
    refuse_unused(args, ("grip",), "to strings, which serves a free racket and reads the feel "
                  "in the medium grip (racket-impact feel --grip for another)")  # fmt: skip
    racket = racket_from(args)
    if racket.support != "free":
        raise ValueError(
            f"{f'--support {args.support}' if args.support else f'--racket {args.racket}'} "
            f"holds the racket ({racket.support}), and strings serves a free one and reads the "
            "feel in the hand: "
            "racket-impact sweep --support for the held racket's power"
        )
    if racket.strings.stringing is None:
        raise ValueError(
            f"--racket {args.racket} has the paper's plain spring, no string to compare: "
            "strings compares strung rackets (e.g. --racket pure-drive-2021)"
        )
    gauge = args.gauge and diameter(args.gauge, "--gauge", "mm")
    speed, head = _speed(args, "speed"), _speed(args, "racket_speed")
    unit = speed_unit(args, "racket_speed", "speed")
    say_conditions(f"{racket_conditions(args, racket, speed=speed)}; serves at a head speed of "
                   f"{speed_text(head, unit)}; spin: the {SPIN_STROKE} stroke's own swing; "
                   f"feel: held in the hand")  # fmt: skip
    table = string_table(racket, load_ball(args.ball), speed, head, args.strings, gauge,
                         args.string_bed_dt)  # each row reads the DT typed  # fmt: skip
    table = in_speed_unit(table, unit)
    # printed: the bed by its DT and moving mass, the power by e_A, the serve by its ratio
    # (the stiffness in kN/m, the strings' whole mass, e and the serve's speed are in --out)
    speeds = [c for c in table.columns if c.startswith("serve_") and c != "serve_ratio"]
    hidden = ["stiffness_kN_m", "bed_mass_g", "e", *speeds]
    _print_table(table.drop(columns=hidden))
    print(textwrap.fill(NOT_MODELLED, WIDTH))
    if args.out:
        write_table(table, args.out)
    return 0
