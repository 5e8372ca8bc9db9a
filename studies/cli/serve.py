"""``racket-impact serve``: the serve speed of one swing (Sec. VIII), and its what-ifs."""

from __future__ import annotations

from common.checks import M_AS_CM, in_range, shown
from common.units import SPEED_SUFFIXES, SPEED_UNITS
from studies.cli.files import add_outputs, check_outputs, save_plot, say_conditions, write_table
from studies.cli.options import (
    _ball_arg,
    _check_swing,
    _Once,
    _pivot,
    _pivot_option,
    _print_table,
    _speed,
    _speed_option,
    _typed,
    given,
    in_speed_unit,
    refuse_unused,
    speed_unit,
)
from studies.cli.racket_options import add_racket_options, racket_conditions, racket_from
from studies.conditions import speed_text
from studies.config import load_ball

DEFAULT_HEAD_SPEED = 40.0
"""The racket-head speed of ``serve`` when none is given [m/s]: the paper's serve (Sec. VIII,
40 m/s at the string centre)."""


def add_serve(sub) -> None:
    """The ``serve`` subcommand, on the subparsers ``sub``."""
    p = sub.add_parser("serve", help="serve speed for one swing (Sec. VIII), and what-ifs")
    add_racket_options(p)  # --support and --grip: refused in words (a served racket is free)
    _ball_arg(p)
    p.add_argument(
        "--position",
        type=float,
        nargs="+",
        action=_Once,
        metavar="CM",
        help="impact point(s) [cm from the tip] (default: centre of the strings)",
    )
    _speed_option(
        p, "racket-speed", [DEFAULT_HEAD_SPEED], "racket-head (string centre) speed(s) of the "
        "swing", many=True,
    )  # fmt: skip
    _speed_option(p, "target-ball-speed", None, "serve speed to reach: solve for the head speed")
    _pivot_option(p)
    p.add_argument(
        "--what-if",
        action="store_true",
        help="add the zero-COR ball (Sec. VIII) and sweep its reduction over string and ball "
        "stiffness",
    )
    add_outputs(p, plot="what-if plot")
    p.set_defaults(func=cmd_serve)


def cmd_serve(args) -> int:
    """``racket-impact serve``."""
    from racket import Swing
    from studies.serve import head_speed_for, serve_reach, serve_table, serve_what_if

    check_outputs(tables=[("--out", args.out)], plots=[("--plot", args.plot)])
    if args.plot and not args.what_if:
        raise ValueError("--plot needs --what-if for serve")
    if args.support not in (None, "free"):
        raise ValueError(
            f"--support {args.support}: serve swings a free racket (Sec. VIII; the hand is not "
            "swung in this model): racket-impact stroke flat-serve swings a hand-held one"
        )
    refuse_unused(args, ("grip",), "to serve, which swings a free racket: racket-impact stroke "
                  "flat-serve --support hand-held takes a grip")  # fmt: skip
    racket, ball = racket_from(args), load_ball(args.ball)
    if racket.support != "free":  # a file's own support
        raise ValueError(
            f"--racket {args.racket} is {racket.support} in its file, and serve swings a free "
            "racket (Sec. VIII): racket-impact stroke flat-serve swings a hand-held one"
        )
    low, high = (100 * end for end in racket.strings.extent)
    positions = [racket.strings.center] if args.position is None else [
        in_range("--position", x, low, high, "cm from the tip", slips=(M_AS_CM,)) / 100
        for x in args.position
    ]  # fmt: skip
    pivot = _pivot(args)
    unit = speed_unit(args, "racket_speed", "target_ball_speed")
    size = SPEED_UNITS[unit]
    target_given = given(args, *_UNITS_OF["target_ball_speed"])
    if target_given and given(args, *_UNITS_OF["racket_speed"]):
        raise ValueError(
            "give --racket-speed[-mph|-kmh] or --target-ball-speed[-mph|-kmh], not both (the "
            "target solves for the racket speed)"
        )
    # the pivot short of the impact points (any head speed in range will do for that)
    _check_swing(args, Swing(1.0, pivot), racket, positions, "racket_speed")
    at = f"{100 * positions[0]:.1f} cm from the tip"
    if target_given:
        target = _speed(args, "target_ball_speed")
        flag, typed, _, _ = _typed(args, "target_ball_speed")
        heads, reach = serve_reach(racket, ball, positions[0], pivot)
        if not reach[0] < target < reach[1]:
            raise ValueError(
                f"{flag}: the target ball speed must be in ({reach[0] / size:.4g}, "
                f"{reach[1] / size:.4g}) {unit} at {at} (head speeds of {heads[0] / size:.4g}-"
                f"{heads[1] / size:.4g} {unit}), got {shown(typed)}"
            )
        heads = [head_speed_for(racket, ball, target, positions[0], pivot)]
        print(f"racket-head speed for a {speed_text(target, unit)} serve at {at}: "
              f"{speed_text(heads[0], unit)}")  # fmt: skip
    else:
        heads = _speed(args, "racket_speed")
        if args.what_if and len(heads) > 1:
            raise ValueError("--what-if takes one racket speed, got several")
        for head in heads:
            _check_swing(args, Swing(head, pivot), racket, positions, "racket_speed")
    import pandas as pd

    table = pd.concat(
        [serve_table(racket, ball, positions, h, pivot, zero_cor=args.what_if) for h in heads]
    )
    table = _named(in_speed_unit(table, unit), args.ball)
    swing = Swing(heads[0], pivot)
    said = f"swung at {speed_text(heads, unit)} head speed {swing.pivot_words()}"
    conditions = say_conditions(racket_conditions(args, racket, speed=None) + f" at rest, {said}")
    suffix = SPEED_SUFFIXES[unit]
    columns = [f"head_speed_{suffix}"] if len(heads) > 1 else []
    columns += ["ball", "position_from_tip_cm", f"point_speed_{suffix}", "e"]
    columns += [f"serve_eq22_{suffix}", f"serve_simulated_{suffix}"]
    if args.what_if:
        columns.append("reduction_simulated_percent")
    _print_table(table[columns])
    if args.what_if:
        what_if = serve_what_if(racket, ball, positions[0], heads[0], pivot_from_tip=pivot)
        what_if = in_speed_unit(what_if, unit)
        print()
        view = what_if.rename(columns={"value": "stiffness_N_m"})
        _print_table(
            view[["varied", "stiffness_N_m", "e", f"serve_simulated_{suffix}",
                   "reduction_simulated_percent"]]
        )  # fmt: skip
        table = what_if
        if args.plot:
            from studies.plots import plot_serve_what_if

            save_plot(plot_serve_what_if(what_if, conditions=conditions), args.plot)
    if args.out:
        write_table(table.reset_index(drop="ball" in table.columns), args.out)
    return 0


_UNITS_OF = {name: (name, f"{name}_mph", f"{name}_kmh") for name in
             ("racket_speed", "target_ball_speed")}  # fmt: skip
"""A speed option's ``dest`` in each unit."""


def _named(table, ball_name: str):
    """The serve table with its ball named: the ball as given, and its zero-COR twin."""
    names = {"normal": ball_name, "zero-COR": f"zero-COR twin of {ball_name}"}
    return table.rename(index=names).rename_axis("ball").reset_index()
