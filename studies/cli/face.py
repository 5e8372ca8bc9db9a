"""``racket-impact map`` and ``sweetspots``: impacts over the face, and the sweet spots."""

from __future__ import annotations

import textwrap

from common.checks import M_AS_CM, in_range
from studies.cli.files import (
    add_outputs,
    check_outputs,
    check_table_and_plot,
    say_conditions,
    write_outputs,
)
from studies.cli.options import (
    _check_swing,
    _count,
    _print_table,
    _scale,
    _scale_options,
    _speed,
    _swing,
    refuse_unused,
    speed_unit,
    swing_and_speed,
)
from studies.cli.racket_options import impact_parser, racket_conditions, racket_from
from studies.cli.show import WIDTH, spots_view
from studies.config import load_ball


def add_map(sub) -> None:
    """The ``map`` subcommand, on the subparsers ``sub``."""
    p = impact_parser(sub, "map", "e, e_A, exit speed, vibration and twist over the face")
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
    add_outputs(p, plot="the map")
    _scale_options(p)
    p.set_defaults(func=cmd_map)


def cmd_map(args) -> int:
    """``racket-impact map``."""
    from studies.face.maps import FIELDS, check_map_points, face_map, face_points

    check_table_and_plot(args)
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

    def draw():
        from studies.plots import plot_face_map

        return plot_face_map(result, args.field, unit=unit, conditions=conditions)

    return write_outputs(args, result.to_frame(), draw)


def add_sweetspots(sub) -> None:
    """The ``sweetspots`` subcommand, on the subparsers ``sub``."""
    p = impact_parser(sub, "sweetspots", "nodes, centre of percussion, power spots, sweet area")
    p.add_argument(
        "--hand-cm-from-tip",
        type=float,
        metavar="CM",
        help="where the hand pivots, for the centre of percussion [cm from the tip] (default: "
        "the middle of the racket's grip)",
    )
    add_outputs(p)
    p.set_defaults(func=cmd_sweetspots)


def cmd_sweetspots(args) -> int:
    """``racket-impact sweetspots``."""
    from studies.face.landmarks import HANDLE_REACH
    from studies.face.sweetspots import sweet_spots

    check_outputs(tables=[("--out", args.out)])
    swing, speed = swing_and_speed(args)
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
    return write_outputs(args, table)
