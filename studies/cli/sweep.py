"""``racket-impact sweep``, ``map``, ``sweetspots`` and ``compare``: impacts along the
strings and over the face.
"""

from __future__ import annotations

import textwrap
from pathlib import Path

import numpy as np

from common.checks import CM_AS_M, KN_AS_N, in_range, shown
from racket import SUPPORTS
from racket.specs.ra import f1_from_ra, ra_note
from racket.specs.sheet import SPEC_RANGES
from studies.cli.files import check_outputs, save_plot, write_table
from studies.cli.options import (
    _ball_arg,
    _check_swing,
    _count,
    _labels,
    _print_table,
    _racket_arg,
    _scale,
    _scale_options,
    _speed,
    _speed_option,
    _swing,
    _swing_options,
    _tension,
    _tension_option,
    _tensions,
    _typed,
)
from studies.cli.show import WIDTH, compare_view, spots_view
from studies.config import RACKETS, load_ball, load_racket
from studies.landmarks import HAND_FROM_BUTT
from studies.sweeps import BALL_SPEED


def add_sweep(sub) -> None:
    """The ``sweep`` subcommand, on the subparsers ``sub``."""
    p = sub.add_parser("sweep", help="impacts along the strings, over any parameter grid")
    _racket_arg(p)
    _ball_arg(p)
    _speed_option(p, "speed", [BALL_SPEED], "ball speed(s) towards the strings", many=True)
    p.add_argument(
        "--from",
        dest="from_",
        type=float,
        metavar="M",
        help="first impact point [m from the tip] (default: start of the strings)",
    )
    p.add_argument(
        "--to",
        type=float,
        metavar="M",
        help="last impact point [m from the tip] (default: end of the strings)",
    )
    p.add_argument("--points", type=int, default=101, help="impact points (default 101)")
    p.add_argument(
        "--offset",
        type=float,
        metavar="M",
        help="impact points' distance from the long axis [m, + towards 3 o'clock]; given "
        "(even 0), the roll and torsion modes take part (a spec-sheet racket)",
    )
    p.add_argument(
        "--string-stiffness",
        type=float,
        nargs="+",
        metavar="N_M",
        help="string-bed stiffness(es) [N/m] (default: the racket's)",
    )
    stiffness = p.add_mutually_exclusive_group()
    stiffness.add_argument(
        "--f1",
        type=float,
        nargs="+",
        metavar="HZ",
        help="frame's first bending frequency(ies) [Hz] (default: the racket's)",
    )
    stiffness.add_argument(
        "--ra",
        type=float,
        nargs="+",
        metavar="RA",
        help="or RA rating(s), f1 from the TWU regression (racket.specs.ra; +/- 6 Hz)",
    )
    p.add_argument(
        "--support",
        nargs="+",
        choices=list(SUPPORTS),
        help="support(s) (default: the racket's)",
    )
    _swing_options(p)
    _tension_option(p, many=True)
    p.add_argument("--out", metavar="FILE", help="table file: .csv, .json or .parquet")
    p.add_argument("--csv", metavar="FILE", help="table as CSV")
    p.add_argument("--json", metavar="FILE", help="table as JSON records")
    p.add_argument("--plot", metavar="FILE", help="e along the racket: .png, .svg or .pdf")
    _scale_options(p)
    p.set_defaults(func=cmd_sweep)


def cmd_sweep(args) -> int:
    """``racket-impact sweep``."""
    from racket.solver import F1_MIN
    from studies.sweeps import COLUMNS, F1_MAX, STRING_STIFFNESS_RANGE, check_impacts, sweep

    check_outputs(
        tables=[("--out", args.out), ("--csv", args.csv), ("--json", args.json)],
        plots=[("--plot", args.plot)],
    )
    for flag, path, kind in (("--csv", args.csv, ".csv"), ("--json", args.json, ".json")):
        if path is not None and Path(path).suffix.lower() != kind:
            raise ValueError(f"{flag} must be a file ending in {kind}, got {path!r}")
    scale = _scale(args)
    points = _count("--points", args.points, 2, 100_000)
    speeds = _speed(args, "speed", allow_zero=args.swing_speed or args.swing_speed_mph)
    for k_s in args.string_stiffness or ():
        in_range("--string-stiffness", k_s, *STRING_STIFFNESS_RANGE, "N/m", slips=(KN_AS_N,))
    for f1 in args.f1 or ():
        in_range("--f1", f1, F1_MIN, F1_MAX, "Hz")
    for ra in args.ra or ():
        in_range("--ra", ra, *SPEC_RANGES["ra"][:2])
    grid = {f"--{name.replace('_', '-')}": getattr(args, name) or () for name in
            ("speed" if args.speed_mph is None else "speed_mph", "string_stiffness",
             "tension_lb", "f1", "ra", "support")}  # fmt: skip
    sizes = [f"--points {points}"] + [f"{len(v)} {f} values" for f, v in grid.items() if len(v) > 1]
    check_impacts(points * int(np.prod([max(len(v), 1) for v in grid.values()])), " x ".join(sizes))
    swing = _swing(args)
    racket, ball = load_racket(args.racket), load_ball(args.ball)
    ends = _ends(args, racket)
    _check_swing(args, swing, racket, ends)
    for ra in args.ra or ():
        print(ra_note(ra))
    with scale as executor:
        table = sweep(
            racket,
            ball,
            np.linspace(*ends, points),
            speeds,
            string_stiffness=args.string_stiffness,
            tension=_tensions(args),
            f1=args.f1 or ([f1_from_ra(ra) for ra in args.ra] if args.ra else None),
            support=args.support,
            offset=args.offset,
            swing=swing,
            executor=executor,
        )
    mph = args.speed_mph is not None or args.swing_speed_mph is not None
    grid = list(table.columns[len(COLUMNS) :])  # the parameters that vary
    table = _in_units(table, mph, args.tension_lb is not None)
    swung = bool(table["swing_speed_m_s"].any())
    speed = "mph" if mph else "m_s"
    shown = ["position_from_butt_cm", "e", "e_A"]  # the rest: --out
    shown += ["recontacts"] if table["recontacts"].any() else []
    shown += [f"ball_rebound_{speed}", "vibration_energy_fraction"]
    shown += [f"swing_speed_{speed}"] if swung else []  # the rebound is the exit speed
    units = {"speed_m_s": f"speed_{speed}", "tension_N": "tension_lb" if args.tension_lb else None}
    shown += [units.get(c, c) or c for c in grid]
    _print_table(table[list(dict.fromkeys(shown))].iloc[:: max(1, len(table) // 25)])
    _say_recontacts(table)
    best = table.loc[table["e"].idxmax()]
    print(
        f"\nlargest e = {best['e']:.4f} at {best['position_from_butt_cm']:.1f} cm from the butt "
        f"({100 * best['position_from_tip_m']:.1f} cm from the tip) "
        f"({len(table)} impacts)"
    )
    for path in filter(None, (args.out, args.csv, args.json)):
        write_table(table, path)
    if args.plot:
        from studies.plots import plot_cor_along_racket

        save_plot(plot_cor_along_racket(table, racket), args.plot)
    return 0


def _ends(args, racket) -> list[float]:
    """The first and last impact points [m from the tip] of ``sweep``: ``--from``/``--to``
    (on the strings; a value in cm caught), by default the ends of the strings, or with
    ``--offset`` the ends of the strings that far off the axis (the bed is an ellipse: said
    in one line).
    """
    extent = racket.strings.extent
    half = 0.5 * racket.strings.full_width
    offset = None  # (an offset on a racket without roll inertia: refused by the sweep)
    if args.offset is not None and racket.beam.roll_inertia is not None:
        offset = in_range(
            "--offset", args.offset, -half, half, "m from the long axis", slips=(CM_AS_M,)
        )
    span = list(extent)
    if offset:
        shrink = np.sqrt(max(1.0 - (args.offset / half) ** 2, 0.0))
        middle, reach = racket.strings.center, 0.5 * (extent[1] - extent[0]) * shrink
        span = [middle - reach, middle + reach]
    ends = list(span)
    for k, (flag, value) in enumerate((("--from", args.from_), ("--to", args.to))):
        if value is not None:
            ends[k] = in_range(
                flag, value, *extent, "m from the tip (the strings)", slips=(CM_AS_M,)
            )
            if not span[0] <= ends[k] <= span[1]:
                raise ValueError(
                    f"{flag} {shown(value)} is off the strings at --offset {shown(args.offset)}: "
                    f"there they span {span[0]:.4g}-{span[1]:.4g} m from the tip (the bed is an "
                    "ellipse); narrow --from/--to to that"
                )
    if offset and (args.from_ is None or args.to is None):
        print(
            f"at --offset {shown(args.offset)} m the strings span {span[0]:.4g}-{span[1]:.4g} m "
            "from the tip\n(the bed is an ellipse): the sweep is clipped to them"
        )
    return ends


def _in_units(table, mph: bool, lb: bool):
    """``table`` with its speeds also in mph (``mph``: the user typed mph) and its tensions
    also in lb (``lb``): columns ``*_mph`` and ``tension_lb`` beside the SI ones.
    """
    from common.units import LB, MPH

    extra = {}
    if mph:
        for name in ("speed_m_s", "ball_rebound_m_s", "swing_speed_m_s", "v_cm_m_s"):
            if name in table:
                extra[name.replace("_m_s", "_mph")] = table[name] / MPH
    if lb and "tension_N" in table:
        extra["tension_lb"] = table["tension_N"] / LB
    return table.assign(**extra)


def _say_recontacts(table) -> None:
    """One line under a printed table when some impacts touched the strings again."""
    count = int((table["recontacts"] > 0).sum())
    if count:
        where = 100 * table.loc[table["recontacts"] > 0, "position_from_tip_m"]
        print(
            textwrap.fill(
                f"re-contacts: at {count} of the {len(table)} impacts ({where.min():.1f}-"
                f"{where.max():.1f} cm from the tip) the ball left the strings and was caught "
                "again by the vibrating frame: e there sums both contacts, and the contact "
                "lasts longer",
                WIDTH,
            )
        )


def add_map(sub) -> None:
    """The ``map`` subcommand, on the subparsers ``sub``."""
    p = sub.add_parser("map", help="e, e_A, exit speed, vibration and twist over the face")
    _racket_arg(p, default="pure-drive-2021")
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
    p.add_argument("--support", choices=list(SUPPORTS), help="support (default: the racket's)")
    _tension_option(p)
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
    from studies.maps import FIELDS, check_map_points, face_map, face_points

    check_outputs(tables=[("--out", args.out)], plots=[("--plot", args.plot)])
    scale = _scale(args)
    if args.field not in FIELDS:
        raise ValueError(f"--field must be one of {list(FIELDS)}, got {args.field!r}")
    grid = tuple(_count("--grid", n, 4, 1000) for n in args.grid)
    check_map_points(*grid, f"--grid {grid[0]} {grid[1]}")
    speed = _speed(args, "speed")
    swing = _swing(args)
    if args.field == "exit_speed_swung" and swing is None:
        raise ValueError("--field exit_speed_swung needs --swing-speed (or --swing-speed-mph)")
    racket = load_racket(args.racket)
    if args.support:
        from dataclasses import replace

        racket = replace(racket, support=args.support)
    if args.tension_lb is not None:
        from racket.specs.strings import with_tension

        racket = with_tension(racket, _tension(args.tension_lb))
    ball = load_ball(args.ball)
    _check_swing(args, swing, racket, face_points(racket, grid, ball.radius)[0])
    with scale as executor:
        result = face_map(racket, ball, speed, swing=swing, grid=grid, executor=executor)
    mph = args.speed_mph is not None or args.swing_speed_mph is not None
    for line in result.summary(mph):
        said = textwrap.fill(line.replace(" o'clock", "_o'clock"), WIDTH, subsequent_indent="  ")
        print(said.replace("_o'clock", " o'clock"))  # "3 o'clock" kept on one line
    if args.out:
        write_table(result.to_frame(), args.out)
    if args.plot:
        from studies.plots import plot_face_map

        save_plot(plot_face_map(result, args.field), args.plot)
    return 0


def add_sweetspots(sub) -> None:
    """The ``sweetspots`` subcommand, on the subparsers ``sub``."""
    p = sub.add_parser("sweetspots", help="nodes, centre of percussion, power spots, sweet area")
    p.add_argument(
        "racket",
        metavar="PRESET_OR_TOML",
        help=f"racket preset ({', '.join(RACKETS)}) or TOML file with a [racket] table",
    )
    _ball_arg(p)
    _speed_option(p, "speed", BALL_SPEED, "ball speed towards the strings")
    _swing_options(p)
    p.add_argument(
        "--grip-cm-from-butt",
        type=float,
        default=100 * HAND_FROM_BUTT,
        metavar="CM",
        help="where the hand pivots, for the centre of percussion (default "
        f"{100 * HAND_FROM_BUTT:g})",
    )
    p.add_argument("--out", metavar="FILE", help="table file: .csv, .json or .parquet")
    p.set_defaults(func=cmd_sweetspots)


def cmd_sweetspots(args) -> int:
    """``racket-impact sweetspots``."""
    from studies.sweetspots import sweet_spots

    check_outputs(tables=[("--out", args.out)])
    swing = _swing(args)
    speed = _speed(args, "speed", allow_zero=swing is not None)
    grip = in_range("--grip-cm-from-butt", args.grip_cm_from_butt, 0.0, 30.0, "cm") / 100
    racket, ball = load_racket(args.racket), load_ball(args.ball)
    _check_swing(args, swing, racket, racket.strings.extent)  # the points span the strings
    table = sweet_spots(racket, ball, speed, swing, grip)
    _flag, typed, unit, _ = _typed(args, "speed")
    print(f"sweet spots of {args.racket} on its strings (ball {args.ball} at {shown(typed)} {unit}"
          f"{', the racket at rest' if swing is None else ''}):")  # fmt: skip
    if swing is not None and _typed(args, "swing_speed")[2] == "mph":  # mph in, mph out
        from common.units import MPH

        fastest = table["spot"] == "largest exit speed"
        table.loc[fastest, "said"] = [f"fastest exit, {v / MPH:.1f} mph" for v in
                                      table.loc[fastest, "value"]]  # fmt: skip
        table.loc[fastest, "meaning"] = f"swung at {swing.head_speed / MPH:.4g} mph head speed"
    _print_table(spots_view(table), "{:.4g}")
    if args.out:
        write_table(table, args.out)
    return 0


def add_compare(sub) -> None:
    """The ``compare`` subcommand, on the subparsers ``sub``."""
    p = sub.add_parser("compare", help="e along the strings of two or more rackets")
    p.add_argument(
        "--racket",
        action="append",
        metavar="PRESET_OR_TOML",
        help="a racket, as PRESET_OR_TOML or LABEL=PRESET_OR_TOML (repeat; default: paper "
        "and pure-drive-2021)",
    )
    _ball_arg(p)
    _speed_option(p, "speed", BALL_SPEED, "ball speed towards the strings")
    p.add_argument("--points", type=int, default=101, help="impact points per racket")
    p.add_argument("--support", choices=list(SUPPORTS), help="support for every racket")
    _swing_options(p)
    p.add_argument(
        "--equal-effort",
        action="store_true",
        help="the swing is the first racket's; every other racket is swung at the same "
        "effort, slower the larger its swingweight: head speed x (I_first / I)^0.27 (Cross "
        "and Bower 2006)",
    )
    _tension_option(p, many=True)
    p.add_argument("--out", metavar="FILE", help="the summary printed: .csv, .json or .parquet")
    p.add_argument(
        "--long",
        action="store_true",
        help="--out writes the long table instead: every impact of every racket",
    )
    p.add_argument("--plot", metavar="FILE", help="comparison plot (.png, .svg, .pdf)")
    _scale_options(p)
    p.set_defaults(func=cmd_compare)


def cmd_compare(args) -> int:
    """``racket-impact compare``."""
    from studies.maps import compare_summary
    from studies.sweeps import check_impacts, compare

    check_outputs(tables=[("--out", args.out)], plots=[("--plot", args.plot)])
    scale = _scale(args)
    points = _count("--points", args.points, 2, 100_000)
    swing = _swing(args)
    speed = _speed(args, "speed", allow_zero=swing is not None)
    names = args.racket or ["paper", "pure-drive-2021"]
    if len(names) < 2:
        raise ValueError(f"compare needs two or more --racket, got {len(names)}")
    labelled = _labels(names)
    check_impacts(points * len(names), f"--points {points} x {len(names)} --racket")
    rackets = {label: load_racket(spec) for label, spec in labelled}
    for racket in rackets.values():  # the points span each racket's strings
        _check_swing(args, swing, racket, racket.strings.extent)
    if args.support:
        from dataclasses import replace

        rackets = {k: replace(r, support=args.support) for k, r in rackets.items()}
    ball = load_ball(args.ball)
    if args.long and not args.out:
        raise ValueError("--long needs --out (the file of the long table)")
    if args.tension_lb is not None:  # every racket at every tension
        from racket.specs.strings import with_tension

        tensions = [(lb, _tension(lb)) for lb in args.tension_lb]
        rackets = {
            label if len(tensions) == 1 else f"{label} {shown(lb)} lb": with_tension(racket, n)
            for label, racket in rackets.items()
            for lb, n in tensions
        }
    if args.equal_effort and swing is None:
        raise ValueError("--equal-effort needs a swing: --swing-speed or --swing-speed-mph")
    with scale as executor:
        table = compare(
            rackets, ball, speed, points, swing=swing,
            equal_effort=args.equal_effort, executor=executor,
        )  # fmt: skip
    summary = compare_summary(rackets, table, ball, speed)
    _flag, typed, unit, _ = _typed(args, "speed")
    said = f"ball {args.ball} at {shown(typed)} {unit}, the rackets at rest"
    if swing is not None:
        _flag, head, head_unit, _ = _typed(args, "swing_speed")
        said = f"ball {args.ball} at {shown(typed)} {unit}, the rackets swung at {shown(head)} "
        said += f"{head_unit} head speed" + (" (equal effort)" if args.equal_effort else "")
    print(said)
    mph = args.speed_mph is not None or args.swing_speed_mph is not None
    _print_table(compare_view(summary, mph, swung=swing is not None))
    if args.out:
        write_table(table if args.long else summary, args.out)
    if args.plot:
        from studies.plots import plot_cor_comparison

        groups = {k: g for k, g in table.groupby("racket", sort=False)}
        save_plot(plot_cor_comparison(groups), args.plot)
    return 0
