"""``racket-impact map`` and ``sweetspots``: impacts over the face, and the sweet spots."""

from __future__ import annotations

import textwrap

from common.checks import M_AS_CM, in_range
from studies.cli.files import check_outputs, save_plot, say_conditions, write_table
from studies.cli.options import (
    _ball_arg,
    _check_swing,
    _count,
    _print_table,
    _scale,
    _scale_options,
    _speed,
    _speed_option,
    _swing,
    _swing_options,
    refuse_unused,
    speed_unit,
)
from studies.cli.racket_options import add_racket_options, racket_conditions, racket_from
from studies.cli.show import WIDTH, spots_view
from studies.config import load_ball
from studies.sweeps import BALL_SPEED


def add_map(sub) -> None:
    """The ``map`` subcommand, on the subparsers ``sub``."""
    p = sub.add_parser("map", help="e, e_A, exit speed, vibration and twist over the face")
    add_racket_options(p)
    _ball_arg(p)
    _speed_option(p, "speed", BALL_SPEED, "ball speed towards the strings")
    _swing_options(p)
    p.add_argument(
        "--grid",
        type=int,
        nargs=2,
        default=[15, 9],
        metavar=("ALONG", "ACROSS"),
        help="grid points along and across the racket (default 15 9)",
    )
    p.add_argument(
        "--field", default="e_A", help="what the plot shows: e, e_A, exit_speed, "
        "exit_speed_swung, vibration_energy or roll_rate (default e_A)",
    )  # fmt: skip
    p.add_argument("--out", metavar="FILE", help="table file: .csv, .json or .parquet")
    p.add_argument("--plot", metavar="FILE", help="the map (.png, .svg, .pdf)")
    _scale_options(p)
    p.set_defaults(func=cmd_map)


def cmd_map(args) -> int:
    """``racket-impact map``."""
    from studies.face.maps import FIELDS, check_map_points, face_map, face_points

    check_outputs(tables=[("--out", args.out)], plots=[("--plot", args.plot)])
    scale = _scale(args)
    if args.field not in FIELDS:
        raise ValueError(f"--field must be one of {list(FIELDS)}, got {args.field!r}")
    if args.plot is None:
        refuse_unused(args, ("field",), "without --plot (it chooses what the plot shows; the "
                      "table has every field): add --plot FILE")  # fmt: skip
    grid = tuple(_count("--grid", n, 4, 1000) for n in args.grid)
    check_map_points(*grid, f"--grid {grid[0]} {grid[1]}")
    speed = _speed(args, "speed")
    swing = _swing(args)
    if args.field == "exit_speed_swung" and swing is None:
        raise ValueError("--field exit_speed_swung needs --swing-speed (or -mph, -kmh)")
    racket, ball = racket_from(args), load_ball(args.ball)
    _check_swing(args, swing, racket, face_points(racket, grid, ball.radius)[0])
    with scale as executor:
        result = face_map(racket, ball, speed, swing=swing, grid=grid, executor=executor)
    unit = speed_unit(args, "speed", "swing_speed")
    conditions = say_conditions(racket_conditions(args, racket, speed=speed, swing=swing))
    for line in result.summary(unit):
        said = textwrap.fill(line.replace(" o'clock", "_o'clock"), WIDTH, subsequent_indent="  ")
        print(said.replace("_o'clock", " o'clock"))  # "3 o'clock" kept on one line
    if args.out:
        write_table(result.to_frame(), args.out)
    if args.plot:
        from studies.plots import plot_face_map

        save_plot(plot_face_map(result, args.field, unit=unit, conditions=conditions), args.plot)
    return 0


def add_sweetspots(sub) -> None:
    """The ``sweetspots`` subcommand, on the subparsers ``sub``."""
    p = sub.add_parser("sweetspots", help="nodes, centre of percussion, power spots, sweet area")
    add_racket_options(p)
    _ball_arg(p)
    _speed_option(p, "speed", BALL_SPEED, "ball speed towards the strings")
    _swing_options(p)
    p.add_argument(
        "--hand-cm-from-tip",
        type=float,
        metavar="CM",
        help="where the hand pivots, for the centre of percussion [cm from the tip] (default: "
        "the middle of the racket's grip)",
    )
    p.add_argument("--out", metavar="FILE", help="table file: .csv, .json or .parquet")
    p.set_defaults(func=cmd_sweetspots)


def cmd_sweetspots(args) -> int:
    """``racket-impact sweetspots``."""
    from studies.face.landmarks import HANDLE_REACH
    from studies.face.sweetspots import sweet_spots

    check_outputs(tables=[("--out", args.out)])
    swing = _swing(args)
    speed = _speed(args, "speed", allow_zero=swing is not None)
    racket, ball = racket_from(args), load_ball(args.ball)
    if racket.support == "clamped-head":
        refuse_unused(args, ("hand_cm_from_tip",), "to a racket with its head clamped (no "
                      "centre of percussion): --support free or hand-held")  # fmt: skip
    hand = None
    if args.hand_cm_from_tip is not None:
        length = 100 * racket.beam.length
        low = length - 100 * HANDLE_REACH
        hand = in_range("--hand-cm-from-tip", args.hand_cm_from_tip, low, length, "cm",
                        slips=(M_AS_CM,)) / 100  # fmt: skip
    _check_swing(args, swing, racket, racket.strings.extent)  # the points span the strings
    table = sweet_spots(racket, ball, speed, swing, hand)
    unit = speed_unit(args, "speed", "swing_speed")
    say_conditions(racket_conditions(args, racket, speed=speed, swing=swing))
    if swing is not None and unit != "m/s":  # mph or km/h in, the same out
        from common.units import SPEED_UNITS
        from studies.conditions import speed_text

        fastest = table["spot"] == "largest exit speed"
        table.loc[fastest, "said"] = [f"fastest exit, {speed_text(v, unit)}" for v in
                                      table.loc[fastest, "value"]]  # fmt: skip
        table.loc[fastest, "value"] = table.loc[fastest, "value"] / SPEED_UNITS[unit]
        table.loc[fastest, "unit"] = unit
        table.loc[fastest, "meaning"] = f"swung at {speed_text(swing.head_speed, unit)} head speed"
    _print_table(spots_view(table), "{:.4g}")
    if args.out:
        write_table(table, args.out)
    return 0
