"""``racket-impact sweep``, ``map``, ``sweetspots`` and ``compare``: impacts along the
strings and over the face.
"""

from __future__ import annotations

import textwrap
from pathlib import Path

import numpy as np

from common.checks import M_AS_CM, in_range, shown
from common.units import SPEED_SUFFIXES
from racket.specs.ra import f1_from_ra, ra_note
from racket.specs.sheet import SPEC_RANGES
from studies.cli.files import check_outputs, save_plot, say_conditions, write_table
from studies.cli.options import (
    _check_swing,
    _count,
    _print_table,
    _scale,
    _scale_options,
    _swing_options,
    _typed,
    in_speed_unit,
    speed_unit,
    swing_and_speed,
    with_columns,
)
from studies.cli.racket_options import (
    check_offset,
    impact_parser,
    offset_cm,
    racket_conditions,
    racket_from,
    stiffnesses,
    tensions,
)
from studies.cli.show import WIDTH, label
from studies.config import load_ball


def add_sweep(sub) -> None:
    """The ``sweep`` subcommand, on the subparsers ``sub``."""
    what = "impacts along the strings, over any parameter grid"
    p = impact_parser(sub, "sweep", what, swing=False, many=True)  # (the swing: further down)
    p.add_argument(
        "--from",
        dest="from_",
        type=float,
        metavar="CM",
        help="first impact point [cm from the tip] (default: start of the strings)",
    )
    p.add_argument(
        "--to",
        type=float,
        metavar="CM",
        help="last impact point [cm from the tip] (default: end of the strings)",
    )
    p.add_argument("--points", type=int, default=101, help="impact points (default 101)")
    p.add_argument(
        "--offset",
        type=float,
        metavar="CM",
        help="impact points' distance from the long axis [cm, + towards 3 o'clock]; given "
        "(even 0), the roll and torsion modes take part (a spec-sheet racket)",
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
    _swing_options(p)
    p.add_argument("--out", metavar="FILE", help="table file: .csv, .json or .parquet")
    p.add_argument("--csv", metavar="FILE", help="table as CSV")
    p.add_argument("--json", metavar="FILE", help="table as JSON records")
    p.add_argument("--plot", metavar="FILE", help="e along the racket: .png, .svg or .pdf")
    _scale_options(p)
    p.set_defaults(func=cmd_sweep)


SHOWN_ROWS = 25
"""About how many rows of a sweep are printed (--out writes them all)."""


def cmd_sweep(args) -> int:
    """``racket-impact sweep``."""
    from racket.solver import F1_MIN
    from studies.sweeps import COLUMNS, F1_MAX, check_impacts, sweep_columns

    check_outputs(
        tables=[("--out", args.out), ("--csv", args.csv), ("--json", args.json)],
        plots=[("--plot", args.plot)],
    )
    for flag, path, kind in (("--csv", args.csv, ".csv"), ("--json", args.json, ".json")):
        if path is not None and Path(path).suffix.lower() != kind:
            raise ValueError(f"{flag} must be a file ending in {kind}, got {path!r}")
    scale = _scale(args)
    points = _count("--points", args.points, 2, 100_000)
    swing, speeds = swing_and_speed(args)
    for f1 in args.f1 or ():
        in_range("--f1", f1, F1_MIN, F1_MAX, "Hz")
    for ra in args.ra or ():
        in_range("--ra", ra, *SPEC_RANGES["ra"][:2])
    unit = speed_unit(args, "speed", "swing_speed")
    speed_flag = _typed(args, "speed")[0]
    grid = {speed_flag: speeds} | {f"--{name.replace('_', '-')}": getattr(args, name) or () for
            name in ("string_stiffness", "tension_lb", "f1", "ra", "support")}  # fmt: skip
    sizes = [f"--points {points}"] + [f"{len(v)} {f} values" for f, v in grid.items() if len(v) > 1]
    check_impacts(points * int(np.prod([max(len(v), 1) for v in grid.values()])), " x ".join(sizes))
    racket, ball = racket_from(args, grid=True), load_ball(args.ball)
    ends, clipped = _ends(args, racket)
    _check_swing(args, swing, racket, ends)
    measured = stiffnesses(args, racket.strings)  # a DT read on the strings, before any print
    conditions = say_conditions(racket_conditions(args, racket, speed=speeds, swing=swing))
    for note in [clipped, *(ra_note(ra) for ra in args.ra or ())]:
        if note:
            print(note)
    with scale as executor:
        table = sweep_columns(  # its columns: no pandas, unless a plot or a JSON asks for it
            racket,
            ball,
            np.linspace(*ends, points),
            speeds,
            string_stiffness=measured,
            tension=tensions(args),
            f1=args.f1 or ([f1_from_ra(ra) for ra in args.ra] if args.ra else None),
            support=args.support,
            offset=None if args.offset is None else args.offset / 100,
            swing=swing,
            executor=executor,
        )
    varying = list(table)[len(COLUMNS) :]  # the parameters that vary
    tension_unit = "kg" if getattr(args, "tension_kg", None) is not None else (
        "lb" if args.tension_lb is not None else None)  # fmt: skip
    table = _in_units(table, unit, tension_unit)
    suffix = SPEED_SUFFIXES[unit]
    shown = ["position_from_tip_cm", "e", "e_A"]  # the rest: --out
    shown += ["recontacts"] if table["recontacts"].any() else []
    shown += [f"ball_rebound_{suffix}", "vibration_energy_fraction"]
    shown += [f"swing_speed_{suffix}"] if swing is not None else []  # the rebound: exit speed
    units = {"speed_m_s": f"speed_{suffix}",
             "tension_N": f"tension_{tension_unit}" if tension_unit else None}  # fmt: skip
    shown_grid = [units.get(c, c) or c for c in varying]
    rows = _every_group_alike(table, varying)
    _print_table({c: rows[c] for c in dict.fromkeys(shown + shown_grid)})
    _say_recontacts(table)
    top = np.nanargmax(table["e"])  # the first of the largest, as pandas' idxmax
    best = {c: values[top] for c, values in table.items()}
    at = ", ".join(f"{label(c)} {_value(best[c])}" for c in shown_grid)
    print(
        f"\nlargest e = {best['e']:.4f} at {best['position_from_tip_cm']:.1f} cm from the tip"
        f"{f' ({at})' if at else ''} ({table['e'].size} impacts)"
    )
    for path in filter(None, (args.out, args.csv, args.json)):
        write_table(table, path)
    if args.plot:
        from studies.plots import plot_cor_along_racket
        from studies.tables import frame

        save_plot(plot_cor_along_racket(frame(table), racket, conditions=conditions), args.plot)
    return 0


def _value(value) -> str:
    """A grid value as printed beside the largest e."""
    return f"{value:.4g}" if isinstance(value, float | np.floating) else str(value)


def _every_group_alike(table: dict, varying: list[str]) -> dict:
    """The rows of a sweep (its columns) to print: at most about :data:`SHOWN_ROWS`, the
    same impact points for every combination of the ``varying`` parameters; a line says so
    when rows are left out.
    """
    positions = np.unique(table["position_from_tip_m"])
    count = table["position_from_tip_m"].size
    groups = max(1, count // len(positions))
    keep = max(2, SHOWN_ROWS // groups)
    if len(positions) <= keep:
        return table
    chosen = positions[np.unique(np.linspace(0, len(positions) - 1, keep).round().astype(int))]
    kept = np.isin(table["position_from_tip_m"], chosen)
    each = " and ".join(label(c).split(" [")[0] for c in varying)
    print(
        f"({np.count_nonzero(kept)} of {count} rows shown: the same {len(chosen)} of "
        f"{len(positions)} impact points{f' for each {each}' if each else ''}; --out writes all)"
    )
    return {name: values[kept] for name, values in table.items()}


def _ends(args, racket) -> tuple[list[float], str]:
    """The first and last impact points [m from the tip] of ``sweep``: ``--from``/``--to``
    [cm from the tip] (on the strings; a value in m caught), by default the ends of the
    strings, or with ``--offset`` [cm] the ends of the strings that far off the axis (the bed
    is an ellipse: said in the note returned with them, "" if none).
    """
    extent = [100 * end for end in racket.strings.extent]  # cm from the tip
    half = 50 * racket.strings.full_width
    check_offset(args, racket)
    offset = None
    if args.offset is not None:
        offset = offset_cm(args.offset, half)
    span = list(extent)
    if offset:
        shrink = np.sqrt(max(1.0 - (offset / half) ** 2, 0.0))
        middle, reach = 100 * racket.strings.center, 0.5 * (extent[1] - extent[0]) * shrink
        span = [middle - reach, middle + reach]
    ends = list(span)
    for k, (flag, value) in enumerate((("--from", args.from_), ("--to", args.to))):
        if value is not None:
            ends[k] = in_range(
                flag, value, *extent, "cm from the tip (the strings)", slips=(M_AS_CM,)
            )
            if not span[0] <= ends[k] <= span[1]:
                raise ValueError(
                    f"{flag} {shown(value)} is off the strings at --offset {shown(offset)}: "
                    f"there they span {span[0]:.4g}-{span[1]:.4g} cm from the tip (the bed is "
                    "an ellipse); narrow --from/--to to that"
                )
    note = ""
    if offset and (args.from_ is None or args.to is None):
        note = (
            f"at --offset {shown(offset)} cm the strings span {span[0]:.4g}-{span[1]:.4g} cm "
            "from the tip\n(the bed is an ellipse): the sweep is clipped to them"
        )
    return [end / 100 for end in ends], note


def _in_units(table: dict, unit: str, tension_unit: str | None) -> dict:
    """A sweep's columns ``table`` with its speeds also in ``unit`` (as the user typed
    them: :func:`studies.cli.options.in_speed_unit`) and its tensions also in
    ``tension_unit`` ("lb" or "kg", as typed; None: N only).
    """
    from common.units import GRAVITY, LB

    table = in_speed_unit(table, unit)
    if tension_unit is None or "tension_N" not in table:
        return table
    size = {"lb": LB, "kg": GRAVITY}[tension_unit]
    return with_columns(table, {f"tension_{tension_unit}": table["tension_N"] / size})


def _say_recontacts(table: dict) -> None:
    """One line under a printed sweep (its columns ``table``) when some impacts touched the
    strings again.
    """
    again = table["recontacts"] > 0
    count = int(again.sum())
    if count:
        where = 100 * table["position_from_tip_m"][again]
        print(
            textwrap.fill(
                f"re-contacts: at {count} of the {again.size} impacts ({where.min():.1f}-"
                f"{where.max():.1f} cm from the tip) the ball left the strings and was caught "
                "again by the vibrating frame: e there sums both contacts, and the contact "
                "lasts longer",
                WIDTH,
            )
        )
