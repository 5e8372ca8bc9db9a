"""``racket-impact serve``: the serve speed of one swing (Sec. VIII), and its what-ifs."""

from __future__ import annotations

from common.checks import CM_AS_M, in_range, shown
from common.units import MPH
from studies.cli.files import check_outputs, save_plot, write_table
from studies.cli.options import (
    _ball_arg,
    _check_swing,
    _Once,
    _pivot,
    _pivot_option,
    _print_table,
    _racket_arg,
    _speed,
    _speed_option,
    _typed,
)
from studies.config import load_ball, load_racket


def add_serve(sub) -> None:
    """The ``serve`` subcommand, on the subparsers ``sub``."""
    p = sub.add_parser("serve", help="serve speed for one swing (Sec. VIII), and what-ifs")
    _racket_arg(p)
    _ball_arg(p)
    p.add_argument(
        "--position",
        type=float,
        nargs="+",
        action=_Once,
        metavar="M",
        help="impact point(s) [m from the tip] (default: centre of the strings)",
    )
    _speed_option(
        p, "racket-speed", [40.0], "racket-head (string centre) speed(s) of the swing", many=True
    )
    _speed_option(p, "target-ball-speed", None, "serve speed to reach: solve for the head speed")
    _pivot_option(p)
    p.add_argument(
        "--what-if",
        action="store_true",
        help="add the zero-COR ball (Sec. VIII) and sweep its reduction over string and ball "
        "stiffness",
    )
    p.add_argument("--out", metavar="FILE", help="table file: .csv, .json or .parquet")
    p.add_argument("--plot", metavar="FILE", help="what-if plot (.png, .svg, .pdf)")
    p.set_defaults(func=cmd_serve)


def cmd_serve(args) -> int:
    """``racket-impact serve``."""
    from racket import Swing
    from studies.serve import head_speed_for, serve_reach, serve_table, serve_what_if

    check_outputs(tables=[("--out", args.out)], plots=[("--plot", args.plot)])
    if args.plot and not args.what_if:
        raise ValueError("--plot needs --what-if for serve")
    racket, ball = load_racket(args.racket), load_ball(args.ball)
    positions = [racket.strings.center] if args.position is None else args.position
    for x in positions:
        in_range("--position", x, *racket.strings.extent, "m from the tip", slips=(CM_AS_M,))
    pivot = _pivot(args)
    mph = args.racket_speed_mph is not None or args.target_ball_speed_mph is not None
    target_given = args.target_ball_speed is not None or args.target_ball_speed_mph is not None
    if target_given and (getattr(args, "_seen_racket_speed", False) or args.racket_speed_mph):
        raise ValueError(
            "give --racket-speed[-mph] or --target-ball-speed[-mph], not both (the target "
            "solves for the racket speed)"
        )
    # the pivot short of the impact points (any head speed in range will do for that)
    _check_swing(args, Swing(1.0, pivot), racket, positions, "racket_speed")
    if target_given:
        target = _speed(args, "target_ball_speed")
        flag, typed, unit, size = _typed(args, "target_ball_speed")
        heads, reach = serve_reach(racket, ball, positions[0], pivot)
        if not reach[0] < target < reach[1]:
            raise ValueError(
                f"{flag}: the target ball speed must be in ({reach[0] / size:.4g}, "
                f"{reach[1] / size:.4g}) {unit} at {100 * (racket.beam.length - positions[0]):.1f}"
                f" cm from the butt (head speeds of {heads[0] / size:.4g}-{heads[1] / size:.4g} "
                f"{unit}), got {shown(typed)}"
            )
        head = head_speed_for(racket, ball, target, positions[0], pivot)
        heads = [head]
        print(
            f"racket-head speed for a {_shown_speed(target, mph)} serve at "
            f"{100 * (racket.beam.length - positions[0]):.1f} cm from the butt: "
            f"{_shown_speed(head, mph, digits=3)}"
        )
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
    unit = "mph" if mph else "m_s"
    said = [_shown_speed(h, mph) for h in heads]
    said = ", ".join([s.split()[0] for s in said[:-1]] + said[-1:])  # the unit once
    print(
        f"{'one swing' if len(heads) == 1 else 'swings'}: racket-head (string centre) speed "
        f"{said}, pivot {abs(100 * pivot):g} cm {'beyond' if pivot <= 0 else 'inside'} the butt"
    )
    columns = [f"head_speed_{unit}"] if len(heads) > 1 else []
    columns += ["position_from_butt_cm", f"point_speed_{unit}", "e"]
    columns += [f"serve_eq22_{unit}", f"serve_simulated_{unit}"]
    if args.what_if:
        columns.append("reduction_simulated_percent")
    _print_table(table[columns])
    if args.what_if:
        head = heads[0]
        what_if = serve_what_if(racket, ball, positions[0], head, pivot_from_butt=pivot)
        print()
        view = what_if.rename(columns={"value": "stiffness_N_m"})
        _print_table(
            view[["varied", "stiffness_N_m", "e", f"serve_simulated_{unit}",
                   "reduction_simulated_percent"]]
        )  # fmt: skip
        table = what_if
        if args.plot:
            from studies.plots import plot_serve_what_if

            save_plot(plot_serve_what_if(what_if), args.plot)
    if args.out:
        write_table(table.reset_index(), args.out)
    return 0


def _shown_speed(value: float, mph: bool, digits: int = 1) -> str:
    """A speed [m/s] as the user typed speeds: mph, or m/s."""
    return f"{value / MPH:.{digits}f} mph" if mph else f"{value:.{digits + 1}f} m/s"
