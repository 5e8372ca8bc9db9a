"""``racket-impact compare``: e along the strings of two or more rackets."""

from __future__ import annotations

from common.checks import shown
from common.units import KP_PER_CM
from racket import DEFAULT_RACKET
from studies.cli.files import check_table_and_plot, say_conditions, write_outputs
from studies.cli.options import (
    _check_swing,
    _count,
    _labels,
    _print_table,
    _scale,
    _scale_options,
    _swing_options,
    speed_unit,
    swing_and_speed,
)
from studies.cli.racket_options import (
    add_ball_speed,
    add_racket_options,
    racket_conditions,
    racket_from,
)
from studies.cli.show import compare_view
from studies.config import load_ball

SECOND_RACKET = "pro-staff-97l-cv"
"""The racket ``compare`` sets beside the default one when none is named."""


def add_compare(sub) -> None:
    """The ``compare`` subcommand, on the subparsers ``sub``."""
    p = sub.add_parser("compare", help="e along the strings of two or more rackets")
    add_racket_options(p, many=True, racket=False)
    p.add_argument(
        "--racket",
        action="append",
        metavar="PRESET_OR_TOML",
        help="a racket, as PRESET_OR_TOML or LABEL=PRESET_OR_TOML (repeat; default: "
        f"{DEFAULT_RACKET} and {SECOND_RACKET})",
    )
    add_ball_speed(p)
    p.add_argument("--points", type=int, default=101, help="impact points per racket")
    _swing_options(p)
    p.add_argument(
        "--equal-effort",
        action="store_true",
        help="the swing is the first racket's; every other racket is swung at the same "
        "effort, slower the larger its swingweight: head speed x (I_first / I)^0.27 (Cross "
        "and Bower 2006)",
    )
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
    from dataclasses import replace

    from studies.face.maps import compare_summary
    from studies.sweeps import check_impacts, compare

    check_table_and_plot(args)
    scale = _scale(args)
    points = _count("--points", args.points, 2, 100_000)
    swing, speed = swing_and_speed(args)
    names = args.racket or [DEFAULT_RACKET, SECOND_RACKET]
    if len(names) < 2:
        raise ValueError(f"compare needs two or more --racket, got {len(names)}")
    if args.long and not args.out:
        raise ValueError("--long needs --out (the file of the long table)")
    if args.equal_effort and swing is None:
        raise ValueError("--equal-effort needs a swing: --swing-speed (or -mph, -kmh)")
    labelled = _labels(names)
    supports = args.support or [None]
    strings = _strings_grid(args)
    variants = len(supports) * len(strings)
    check_impacts(points * len(names) * variants, f"--points {points} x {len(names)} --racket")
    rackets = {}
    for label, spec in labelled:  # every racket at every support and tension
        base = racket_from(args, spec, grid=True)
        for support in supports:
            for value in strings:
                racket = base if support is None else replace(base, support=support)
                racket = _strung(args, racket, value[0])
                extra = [support] if len(supports) > 1 else []
                extra += [value[1]] if len(strings) > 1 else []
                rackets[" ".join([label, *extra])] = racket
    for racket in rackets.values():  # the points span each racket's strings
        _check_swing(args, swing, racket, racket.strings.extent)
    ball = load_ball(args.ball)
    with scale as executor:
        table = compare(
            rackets, ball, speed, points, swing=swing,
            equal_effort=args.equal_effort, executor=executor,
        )  # fmt: skip
    summary = compare_summary(rackets, table, ball, speed)
    first = next(iter(rackets.values()))
    said = racket_conditions(
        args, first, " vs ".join(rackets), speed=speed, swing=swing, each=rackets
    )
    conditions = say_conditions(said + (" (equal effort)" if args.equal_effort else ""))
    unit = speed_unit(args, "speed", "swing_speed")
    _print_table(compare_view(summary, unit, swung=swing is not None))
    for note in summary.attrs["notes"]:  # each "-" of the table said
        print(note)

    def draw():
        from studies.plots import plot_cor_comparison

        groups = {k: g for k, g in table.groupby("racket", sort=False)}
        return plot_cor_comparison(groups, conditions=conditions)

    return write_outputs(args, table if args.long else summary, draw)


def _strings_grid(args) -> list:
    """The tensions, stiffnesses or ERT readings to string every racket at, each ((kind,
    value [N, N/m or kp/cm]), its label as typed: "58 lb", "26 kg", "3e+04 N/m", "35
    kp/cm"); [((None, None), "")] for none.
    """
    from studies.cli.racket_options import stiffnesses, tensions

    typed = {"tension_lb": "lb", "tension_kg": "kg", "string_stiffness": "N/m",
             "string_bed_dt": "kp/cm"}  # fmt: skip
    for dest, unit in typed.items():
        if getattr(args, dest, None) is not None:
            values = tensions(args) if dest.startswith("tension") else stiffnesses(args)
            kind = "tension" if dest.startswith("tension") else "stiffness"
            if dest == "string_bed_dt":  # read on each racket's strings (_strung)
                kind, values = "dt", [v / KP_PER_CM for v in values]
            said = [f"{shown(v)} {unit}" for v in getattr(args, dest)]
            return [((kind, v), s) for v, s in zip(values, said, strict=True)]
    return [((None, None), "")]


def _strung(args, racket, value):
    """``racket`` strung at ``value``, (its kind: "tension", "stiffness" or "dt", the
    tension [N], stiffness [N/m] or ERT reading [kp/cm]); as it is for None.
    """
    from dataclasses import replace

    kind, number = value
    if number is None:
        return racket
    if kind == "tension":
        from racket.specs.restring import with_tension

        return with_tension(racket, number)
    from racket.strings.ert import stiffness_from_dt
    from racket.strings.stringing import restrung

    if kind == "dt":
        number = stiffness_from_dt(racket.strings, number, "--string-bed-dt")
    return replace(racket, strings=restrung(racket.strings, stiffness=number))
