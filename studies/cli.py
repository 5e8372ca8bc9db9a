"""The ``racket-impact`` command line.

Subcommands: ``paper``, ``sweep``, ``serve``, ``collide``, ``modes``, ``specs``, ``compare``.
Rackets and balls are presets or TOML files (:mod:`studies.config`).  Tables go to CSV,
JSON or Parquet by the file's extension, plots to PNG, SVG or PDF.  Bad input prints one
line naming the problem and exits with status 2.
"""

from __future__ import annotations

import argparse
import contextlib
import json
import os
import re
import sys
import warnings
from pathlib import Path

import numpy as np
import pandas as pd

from ball import BALL_PRESETS, DEFAULT_BALL, WALL, collide
from beam.beam import MAX_MODES
from common.checks import CM_AS_M, FASTEST_STROKE, KN_AS_N, SPEED_RANGE, in_range, shown
from common.units import GRAVITY, MPH
from racket import GRIPS, SUPPORTS
from racket.specs.ra import f1_from_ra, ra_note
from racket.specs.sheet import SPEC_RANGES
from racket.swing import WRIST_BEYOND_BUTT
from studies import outputs
from studies.config import (
    BALLS,
    PAPER_BALL,
    RACKETS,
    default_ball,
    load_ball,
    load_racket,
    racket_specs,
)
from studies.entry import interrupted
from studies.landmarks import HAND_FROM_BUTT
from studies.maps import MAP_SPEED
from studies.provenance import sidecar_path
from studies.tables import history_table

TABLE_FORMATS = (".csv", ".json", ".parquet")
PLOT_FORMATS = (".png", ".svg", ".pdf")


class _Once(argparse.Action):
    """Store a single-valued option, refusing it twice (the last would silently win)."""

    def __call__(self, parser, namespace, values, option_string=None):
        if getattr(namespace, f"_seen_{self.dest}", False):
            parser.error(f"{option_string} given twice; give it once")
        setattr(namespace, f"_seen_{self.dest}", True)
        setattr(namespace, self.dest, values)


class _Parser(argparse.ArgumentParser):
    """Options in full only (a recorded command means one thing); an option whose metavar
    is FILE or DIR names a file the command writes, listed in the parsed ``_writes``.
    """

    def __init__(self, *args, **kwargs):
        super().__init__(*args, allow_abbrev=False, **kwargs)

    def error(self, message):  # one line, status 2, no usage dump
        self.exit(2, f"{self.prog}: error: {message}\n")

    def add_argument(self, *args, **kwargs):
        if args and args[0].startswith("--") and "action" not in kwargs:
            kwargs["action"] = _Once
        action = super().add_argument(*args, **kwargs)
        if action.option_strings and action.metavar in ("FILE", "DIR"):
            self.set_defaults(_writes=(*(self.get_default("_writes") or ()), action.dest))
        return action


class _Replay(_Parser):
    """The parser of a command recorded in a sidecar: its errors are the sidecar's."""

    def error(self, message):
        raise ValueError(f"the sidecar's command: {message}")


TABLE_COMMANDS = (
    "sweep", "map", "serve", "collide", "ball", "modes", "specs", "feel", "sweetspots", "compare",
    "validate", "drop",
)  # fmt: skip
"""The commands that write tables (with sidecars): the only ones ``rerun`` replays."""


def check_outputs(tables=(), plots=(), directories=()) -> None:
    """Check every output path before any work: a known extension, an existing, writable
    directory, a name the directory can hold, nothing there but a regular file, not a
    symbolic link (for a table, its sidecar too), and no file named twice.  ValueError
    naming the path otherwise.
    """
    seen = {}
    for paths, kinds, what in ((tables, TABLE_FORMATS, "table"), (plots, PLOT_FORMATS, "plot")):
        for flag, path in paths:
            if path is None:
                continue
            if Path(path).suffix.lower() not in kinds:
                raise ValueError(
                    f"{flag} must be a {what} file ending in {', '.join(kinds)}, got {path!r}"
                )
            _check_directory(flag, Path(path).parent, path)
            files = [(flag, Path(path))]
            if what == "table":
                files.append((f"{flag}'s sidecar", sidecar_path(path)))
            for name, file in files:
                _check_file(name, file)
                key = file.resolve()
                if key in seen:
                    raise ValueError(f"{name} and {seen[key]} name the same file {str(file)!r}")
                seen[key] = name
    for flag, path in directories:
        if not str(path).strip():
            raise ValueError(f"{flag} must name a directory, got {str(path)!r}")
        target = Path(path)
        if target.exists() and not target.is_dir():
            raise ValueError(f"{flag} must be a directory, got the file {str(path)!r}")
        existing = next((p for p in [target, *target.parents] if p.exists()), Path("."))
        _check_directory(flag, existing, path)


def _check_file(flag: str, path: Path) -> None:
    """An output file that can be replaced: a name its directory can hold, and nothing there
    yet but a writable regular file (not a directory, FIFO or device; never opened), nor a
    symbolic link (the rename would replace the link and leave the file it names stale).
    """
    try:
        longest = os.pathconf(path.parent, "PC_NAME_MAX")
    except (AttributeError, ValueError, OSError):  # no pathconf (Windows), or no such limit
        longest = -1
    if longest > 0 and len(os.fsencode(path.name)) > longest:
        raise ValueError(
            f"{flag}: the name of {str(path)!r} is longer than its directory allows "
            f"({longest} bytes)"
        )
    if path.is_symlink():
        raise ValueError(f"{flag}: {str(path)!r} is a symbolic link; name the file it links to")
    if path.exists() and not path.is_file():
        raise ValueError(f"{flag}: {str(path)!r} exists and is not a regular file")
    if path.exists() and not os.access(path, os.W_OK):
        raise ValueError(f"{flag}: {str(path)!r} is read-only")


def _check_directory(flag: str, directory: Path, path) -> None:
    directory = directory if str(directory) else Path(".")
    if not directory.is_dir():
        raise ValueError(f"{flag}: directory {str(directory)!r} of {str(path)!r} does not exist")
    if not os.access(directory, os.W_OK):
        raise ValueError(f"{flag}: directory {str(directory)!r} of {str(path)!r} is not writable")


_RUN = {}  # the command line being run (main sets it), for the tables' sidecars


def write_table(table: pd.DataFrame, path: str) -> None:
    """Write ``table`` to ``path`` as CSV, JSON (records) or Parquet, by extension, and,
    when the command line writes it, its sidecar (:mod:`studies.provenance`); both are
    put in place with the run's other files (:mod:`studies.outputs`).
    """
    suffix = Path(path).suffix.lower()
    if suffix not in TABLE_FORMATS:
        raise ValueError(f"table file must end in {', '.join(TABLE_FORMATS)}, got {path!r}")

    def writer(temp: str) -> None:
        if suffix == ".csv":
            table.to_csv(temp, index=False)
        elif suffix == ".json":
            table.to_json(temp, orient="records", indent=2)
        else:
            try:
                table.to_parquet(temp, index=False)
            except ImportError:
                raise ValueError(
                    "Parquet output needs pyarrow: pip install 'racket-impact[parquet]'"
                ) from None

    outputs.write(path, writer)
    _sidecar(path)


def _sidecar(path) -> None:
    """The sidecar of a table the command line wrote (:mod:`studies.provenance`); the
    description is built once per command run, however many tables it writes.
    """
    if _RUN:
        from studies.provenance import describe, write_sidecar

        if "description" not in _RUN:
            _RUN["description"] = describe(
                _RUN["argv"], _RUN["command"], _RUN["options"], _RUN.get("originals")
            )
        write_sidecar(path, _RUN["description"])


def save_plot(axes, path: str) -> None:
    """Save the figure holding ``axes`` as PNG, SVG or PDF, by extension, put in place with
    the run's other files (:mod:`studies.outputs`).
    """
    import matplotlib.pyplot as plt

    suffix = Path(path).suffix.lower()
    if suffix not in PLOT_FORMATS:
        raise ValueError(f"plot file must end in {', '.join(PLOT_FORMATS)}, got {path!r}")
    fig = np.atleast_1d(axes)[0].figure
    try:
        fig.tight_layout()
        outputs.write(path, lambda temp: fig.savefig(temp, dpi=120, format=suffix[1:]))
    finally:
        plt.close(fig)


def _speed(args, name: str, allow_zero: bool = False, signed: bool = False):
    """The speed option ``--NAME`` [m/s] or ``--NAME-mph`` [mph] in m/s (a list for a
    many-valued option), each value checked in the unit it was typed in.
    """
    flag, values, unit, scale = _typed(args, name)
    low, high = (v / scale for v in SPEED_RANGE)
    checked = []
    for value in np.atleast_1d(values):
        if signed:
            checked.append(in_range(flag, value, -high, high, unit) * scale)
        elif allow_zero and value == 0.0:
            checked.append(0.0)
        else:
            checked.append(in_range(flag, value, low, high, unit) * scale)
        if unit == "m/s" and abs(checked[-1]) > FASTEST_STROKE:  # allowed, but likely a slip
            warnings.warn(
                f"{flag} {shown(value)} m/s is faster than any recorded stroke (about "
                f"{FASTEST_STROKE:g} m/s): mph typed as m/s? {shown(value)} mph would be "
                f"{value * MPH:.3g} m/s ({flag}-mph {shown(value)})",
                stacklevel=2,
            )
    return checked if isinstance(values, list) else checked[0]


def _typed(args, name: str) -> tuple[str, object, str, float]:
    """The speed option ``--NAME`` or ``--NAME-mph`` as the user typed it: the flag, the
    value(s), the unit and its size [m/s].
    """
    mph = getattr(args, f"{name}_mph")
    flag = f"--{name.replace('_', '-')}"
    if mph is not None:
        return f"{flag}-mph", mph, "mph", MPH
    return flag, getattr(args, name), "m/s", 1.0


def _count(flag: str, value: int, low: int, high: int) -> int:
    """A whole-number option in [low, high]."""
    return int(in_range(flag, value, low, high))


def _print_table(table: pd.DataFrame, floatfmt: str = "{:.4g}") -> None:
    with pd.option_context("display.width", 200, "display.max_rows", 60, "display.max_columns", 30):
        print(table.to_string(float_format=floatfmt.format))


# ----- subcommands ------------------------------------------------------------------------
def cmd_paper(args) -> int:
    """``racket-impact paper``."""
    from studies.paper import paper_table

    check_outputs(directories=[("--out", args.out)])
    if args.json is not None and Path(args.json).suffix.lower() != ".json":
        raise ValueError(f"--json must be a file ending in .json, got {args.json!r}")
    out, figures = Path(args.out), paper_figures()
    check_outputs(
        tables=[("--json", args.json)],
        plots=[("--out", out / name) for name in figures] if out.is_dir() else [],
    )
    table = paper_table()
    _print_table(table[["claim", "paper", "simulated", "tolerance", "ok"]])
    ok = bool(table["ok"].all())
    print(f"\n{int(table['ok'].sum())} of {len(table)} claims reproduced within tolerance.")
    if args.json:
        records = [
            {
                "claim": r.claim,
                "paper": r.paper,
                "simulated": r.simulated,
                "tolerance": r.tolerance,
                "ok": bool(r.ok),
            }
            for r in table.itertuples()
        ]
        text = json.dumps(records, indent=2)
        outputs.write(args.json, lambda temp: Path(temp).write_text(text))
        _sidecar(args.json)
    outputs.directory(out)
    for name, draw in figures.items():
        save_plot(draw(), out / name)
    print(f"figures written to {args.out}/: {', '.join(figures)}")
    return 0 if ok else 1


def paper_figures() -> dict:
    """The paper's figures and the racket plots: each PNG file's name, and what draws it."""
    import matplotlib

    matplotlib.use("Agg")
    from ball import Ball, LinearSpring, SineLaw
    from racket import impact, paper_racket, tennis_ball
    from studies import plots
    from studies.serve import serve_what_if

    unhappy = Ball(0.0103, SineLaw(2e4))
    racket, ball = paper_racket(), tennis_ball()
    return {
        "fig2_unhappy_on_wall.png": lambda: plots.plot_collision(
            collide(unhappy, WALL, 4.0), title="Fig. 2: unhappy ball on a rigid wall"
        ),
        "fig3_soft_happy_ball.png": lambda: plots.plot_collision(
            collide(unhappy, Ball(0.0103, LinearSpring(2e4)), 4.0), title="Fig. 3: k2 = 2e4 N/m"
        ),
        "fig4_stiff_happy_ball.png": lambda: plots.plot_collision(
            collide(unhappy, Ball(0.0103, LinearSpring(1e5)), 4.0), title="Fig. 4: k2 = 1e5 N/m"
        ),
        "cor_vs_stiffness.png": plots.plot_cor_vs_stiffness,
        "cor_along_racket.png": lambda: plots.plot_cor_along_racket(
            impact(racket, ball, np.linspace(0, 0.32, 161), 10.0), racket
        ),
        "impact_near_tip.png": lambda: plots.plot_impact(
            impact(racket, ball, 0.03, 10.0, histories=True)
        ),
        "modes.png": lambda: plots.plot_modes(racket),
        "serve_what_if.png": lambda: plots.plot_serve_what_if(serve_what_if(racket, ball)),
    }


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
    ends = list(racket.strings.extent)
    for k, (flag, value) in enumerate((("--from", args.from_), ("--to", args.to))):
        if value is not None:
            ends[k] = in_range(flag, value, *racket.strings.extent, "m from the tip (the strings)")
    _check_swing(args, swing, racket, ends)
    for ra in args.ra or ():
        print(ra_note(ra))
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
    )
    _print_table(
        table[
            [
                "position_from_butt_cm",
                "position_from_tip_m",
                "e",
                "e_A",
                "effective_mass_kg",
                "ball_rebound_m_s",
                "vibration_energy_fraction",
            ]
            + (["swing_speed_m_s", "exit_speed_mph"] if table["swing_speed_m_s"].any() else [])
            + [c for c in table.columns[len(COLUMNS) :]]
        ].iloc[:: max(1, len(table) // 25)]
    )
    best = table.loc[table["e"].idxmax()]
    print(
        f"\nlargest e = {best['e']:.4f} at {best['position_from_butt_cm']:.1f} cm from the butt "
        f"({best['position_from_tip_m']:.3f} m from the tip) "
        f"({len(table)} impacts)"
    )
    for path in filter(None, (args.out, args.csv, args.json)):
        write_table(table, path)
    if args.plot:
        from studies.plots import plot_cor_along_racket

        save_plot(plot_cor_along_racket(table, racket), args.plot)
    return 0


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
        in_range("--position", x, *racket.strings.extent, "m from the tip")
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
        print(
            f"racket-head speed for a {_shown_speed(target, mph)} serve at "
            f"{100 * (racket.beam.length - positions[0]):.1f} cm from the butt: "
            f"{_shown_speed(head, mph, digits=3)}"
        )
    else:
        head = _speed(args, "racket_speed")
        _check_swing(args, Swing(head, pivot), racket, positions, "racket_speed")
    table = serve_table(racket, ball, positions, head, pivot, zero_cor=args.what_if)
    unit = "mph" if mph else "m_s"
    print(
        f"one swing: racket-head (string centre) speed {_shown_speed(head, mph)}, pivot "
        f"{abs(100 * pivot):g} cm {'beyond' if pivot <= 0 else 'inside'} the butt"
    )
    columns = ["position_from_butt_cm", "position_from_tip_m", f"point_speed_{unit}", "e"]
    columns += [f"serve_eq22_{unit}", f"serve_simulated_{unit}"]
    if args.what_if:
        columns.append("reduction_simulated_percent")
    _print_table(table[columns])
    if args.what_if:
        what_if = serve_what_if(racket, ball, positions[0], head, pivot_from_butt=pivot)
        print()
        _print_table(
            what_if[["varied", "value", "e", "serve_simulated_m_s", "reduction_simulated_percent"]]
        )
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


def cmd_collide(args) -> int:
    """``racket-impact collide``."""
    check_outputs(
        tables=[("--out", args.out), ("--history", args.history)], plots=[("--plot", args.plot)]
    )
    v_a, v_b = _speed(args, "va", signed=True), _speed(args, "vb", signed=True)
    if v_a - v_b < SPEED_RANGE[0]:
        typed = [
            f"--{n}-mph {shown(getattr(args, n + '_mph'))} mph"
            if getattr(args, n + "_mph") is not None
            else f"--{n} {shown(getattr(args, n))} m/s"
            for n in ("va", "vb")
        ]
        raise ValueError(
            f"--va must exceed --vb by at least {SPEED_RANGE[0]:g} m/s (the balls must "
            f"approach), got {typed[0]} and {typed[1]}"
        )
    a = load_ball(args.a)
    b = WALL if args.b == "wall" else load_ball(args.b)
    r = collide(a, b, v_a, v_b)
    rows = {
        "v_a_after_m_s": r.v_a_after,
        "v_b_after_m_s": r.v_b_after,
        "e": r.e,
        "contact_time_s": r.contact_time,
        "peak_force_N": r.peak_force,
        "energy_initial_J": r.energy_initial,
        "energy_final_J": r.energy_final,
        "energy_lost_J": r.energy_lost,
    }
    if r.x_o is not None:
        rows["x_o_m"] = r.x_o
    for key, value in rows.items():
        print(f"{key:<18} {value:.6g}")
    if args.out:
        write_table(pd.DataFrame([rows]), args.out)
    if args.history:
        write_table(history_table(r.history), args.history)
    if args.plot:
        from studies.plots import plot_collision

        save_plot(plot_collision(r), args.plot)
    return 0


def cmd_drop(args) -> int:
    """``racket-impact drop``."""
    from studies.drop import HEIGHT_RANGE, drop

    check_outputs(tables=[("--out", args.out)], plots=[("--plot", args.plot)])
    height = in_range("--height-m", args.height_m, *HEIGHT_RANGE, "m", slips=(CM_AS_M,))
    ball = load_ball(args.ball)
    onto, where = None, "the floor"
    if args.onto != "floor":
        from dataclasses import replace

        support = "clamped-head" if args.onto == "strings" else "free"
        onto = replace(load_racket(args.racket), support=support)
        where = (
            f"the strings of {args.racket}, its head clamped"
            if args.onto == "strings"
            else f"the string centre of {args.racket}, lying free"
        )
    result = drop(ball, height, onto)
    print(f"ball {args.ball} dropped from {result.height:g} m onto {where}: it arrives at "
          f"{result.speed:.3g} m/s")  # fmt: skip
    print(f"bounces back at {result.rebound_speed:.3g} m/s, up to {result.bounce_height:.3g} m "
          f"({100 * result.bounce_height:.1f} cm)")  # fmt: skip
    meaning = "the ball's COR, bounce/drop = e^2" if onto is None else "the apparent COR e_A"
    print(f"rebound ratio {result.rebound_ratio:.4f} ({meaning})")
    print(f"contact {1e3 * result.contact_time:.3g} ms, peak force {result.peak_force:.4g} N, "
          f"largest compression {1e3 * float(np.max(result.compression)):.3g} mm")  # fmt: skip
    if args.out:
        table = pd.DataFrame(
            {"t_s": result.t, "force_N": result.force, "compression_m": result.compression}
        )
        write_table(table, args.out)
    if args.plot:
        from studies.plots import plot_drop

        save_plot(plot_drop(result), args.plot)
    return 0


def cmd_ball(args) -> int:
    """``racket-impact ball``."""
    from studies.bounce import preset_table, rigid_bounce_table, static_test

    check_outputs(tables=[("--out", args.out)], plots=[("--plot", args.plot)])
    if args.list:
        _print_table(preset_table().drop(columns="sources").set_index("preset"))
        print("sources and assumptions: racket-impact ball --list --out presets.csv")
        if args.out:
            write_table(preset_table(), args.out)
        return 0
    speeds = _speed(args, "speeds")
    ball = load_ball(args.ball)
    table = rigid_bounce_table(ball, speeds)
    _print_table(table)
    _print_static_test(static_test(ball, args.ball))
    if args.out:
        write_table(table, args.out)
    if args.plot:
        from studies.plots import plot_rigid_bounce

        preset = BALL_PRESETS.get(args.ball)
        axes = plot_rigid_bounce(table, radius=ball.radius, bands=preset and preset.bands)
        save_plot(axes, args.plot)
    return 0


def cmd_validate(args) -> int:
    """``racket-impact validate``."""
    from studies import validation

    check_outputs(tables=[("--out", args.out)], plots=[("--plot", args.plot)])
    table = validation.validation_table()
    with pd.option_context("display.max_colwidth", 80):
        _print_table(table.drop(columns="conditions"))
    print(f"\n{validation.summary(table)} (each one's conditions: --out FILE)")
    if args.out:
        write_table(table.reset_index(), args.out)
    if args.plot:
        from studies.plots import plot_validation

        save_plot(plot_validation(table), args.plot)
    return 0


def _print_static_test(test: dict) -> None:
    """The ITF's static deformation test beside the dynamic law (:func:`studies.bounce.
    static_test`), on its own lines.
    """
    force, dynamic, band = test["force_N"], test["dynamic_compression_m"], test["itf_forward_m"]
    print(f"\nstatic test (ITF, quasi-static, apart from the bounce above), {force:.2f} N:")
    if band is not None:
        print(f"  ITF forward deformation of this type: {1e3 * band[0]:.1f}-{1e3 * band[1]:.1f} "
              f"mm ({force / band[1] / 1e3:.1f}-{force / band[0] / 1e3:.1f} kN/m)")  # fmt: skip
    if dynamic is not None:
        stiffness = force / dynamic / 1e3
        print(f"  this ball's dynamic law: {1e3 * dynamic:.2f} mm ({stiffness:.1f} kN/m): a "
              "ball is viscoelastic, stiffer in a 4 ms impact than in a 5 s hold")  # fmt: skip


def cmd_modes(args) -> int:
    """``racket-impact modes``."""
    from studies.landmarks import center_of_percussion

    check_outputs(tables=[("--out", args.out)], plots=[("--plot", args.plot)])
    count = _count("--count", args.count, 1, MAX_MODES)
    racket = load_racket(args.racket)
    beam, modes = racket.beam, racket.beam.modes
    hand = beam.length - HAND_FROM_BUTT
    centre = racket.strings.center
    print(f"length            {beam.length:.4f} m")
    print(f"mass              {beam.mass:.4f} kg")
    print(f"balance           {100 * beam.balance:.2f} cm from the butt")
    print(f"swingweight       {beam.swingweight_kgcm2:.1f} kg cm^2 (axis 10 cm from the butt)")
    print(f"recoil weight     {1e4 * beam.inertia_cm:.1f} kg cm^2 (about the centre of mass)")
    cop = center_of_percussion(racket, hand)
    print(
        f"centre of percussion  {100 * (beam.length - cop):.1f} cm from the butt "
        f"({100 * cop:.1f} from the tip; hand {100 * HAND_FROM_BUTT:.0f} cm from the butt)"
    )
    print(
        f"effective mass at the string centre ({100 * (beam.length - centre):.1f} cm from "
        f"the butt, {100 * centre:.1f} from the tip)  "
        f"{beam.effective_mass(centre):.4f} kg"
    )
    rows = []
    for k in range(1, min(count, modes.count - 2) + 1):
        nodes = modes.nodes(k)
        rows.append(
            {
                "mode": k,
                "frequency_Hz": modes.frequencies[k - 1],
                "nodes_cm_from_butt": ", ".join(f"{100 * (beam.length - n):.1f}" for n in nodes),
                "nodes_cm_from_tip": ", ".join(f"{100 * n:.1f}" for n in nodes),
            }
        )
    table = pd.DataFrame(rows)
    print()
    _print_table(table, "{:.1f}")
    if args.out:
        write_table(table, args.out)
    if args.plot:
        from studies.plots import plot_modes

        save_plot(plot_modes(racket, count=count), args.plot)
    return 0


def cmd_specs(args) -> int:
    """``racket-impact specs``."""
    from studies.report import spec_report

    check_outputs(tables=[("--out", args.out)], plots=[("--plot", args.plot)])
    count = _count("--count", args.count, 1, MAX_MODES)
    racket = load_racket(args.racket)
    specs, sources = racket_specs(args.racket)
    ball_name = default_ball(args.racket)
    report = spec_report(racket, specs, count=count, ball=load_ball(ball_name))
    if specs is not None and specs.get("ra") is not None:
        print(f"{ra_note(specs['ra'])}\nspec sheet and fitted model:")
    elif specs is not None:
        print("spec sheet and fitted model (frame stiffness as given, not inferred from RA):")
    if specs is not None:
        _print_table(report.fit, "{:.5g}")
        print("\nfitted parts and their plausible ranges:")
        _print_table(report.parts.drop(columns="source"), "{:.4g}")
        for warning in report.warnings:
            print(f"warning: {warning}", file=sys.stderr)
        print()
    print("the racket (with any lead tape, strings and support of the file):")
    _print_table(report.properties, "{:.4g}")
    print(
        "\nmodes: free-free, and held by the hand (stiffness "
        f"{racket.hand.stiffness:g} N/m, damping {racket.hand.damping:g} N s/m over "
        f"{100 * racket.hand.grip_length:g} cm, to a hand of {racket.hand.mass:g} kg)"
    )
    _print_table(report.modes, "{:.4g}")
    print(f"\nsweet spots (ball {ball_name} at {MAP_SPEED:g} m/s on the racket at rest):")
    _print_table(report.sweet_spots, "{:.4g}")
    print("\neffective mass along the strings (Eq. 20)")
    _print_table(report.effective_mass, "{:.4g}")
    if sources:
        print("\nsources:")
        for key, source in sources.items():
            print(f"  {key}: {source}")
    if specs is not None:
        print("\nsources of the parts' ranges:")
        for part in report.parts.itertuples():
            print(f"  {part.part}: {part.source}")
    if args.out:
        write_table(report.effective_mass, args.out)
    if args.plot:
        from studies.plots import plot_modes

        save_plot(plot_modes(racket, count=count), args.plot)
    return 0


def cmd_app(args) -> int:
    """``racket-impact app``."""
    port = int(_count("--port", args.port, 1024, 65535))
    try:
        from studies.app import run
    except ImportError:
        raise ValueError("the page needs Shiny: pip install 'racket-impact[app]'") from None
    print(f"racket-impact: the page is at http://{args.host}:{port} (Ctrl-C stops it)")
    run(args.host, port)
    return 0


def cmd_rerun(args) -> int:
    """``racket-impact rerun``: the command recorded in a table's sidecar (checked as
    untrusted input), made again from the sidecar alone (the recorded TOML texts), a
    table-making command only, every file it writes put in the table's own directory.
    """
    import shlex

    from studies.provenance import _restored, rerun_argv, temporary_directory

    folder, moved = Path(args.sidecar).parent, {}
    with temporary_directory() as workdir:
        argv, originals = rerun_argv(args.sidecar, workdir)
        if argv[0] not in TABLE_COMMANDS:
            raise ValueError(
                f"{args.sidecar!r}: command {argv[0]!r} makes no table; rerun replays only "
                f"{', '.join(TABLE_COMMANDS)}"
            )
        if "-h" in argv or "--help" in argv:
            raise ValueError(f"{args.sidecar!r}: command asks for help, not a table")
        replay = build_parser(_Replay).parse_args(argv)
        for dest in replay._writes:
            value = getattr(replay, dest)
            if value is None:
                continue
            if Path(value).name in ("", ".", ".."):
                raise ValueError(f"the sidecar's command: --{dest} {value!r} names no file")
            moved[value] = str(folder / Path(value).name)
            setattr(replay, dest, moved[value])
        replay.debug = args.debug
        shown = shlex.join(_restored(word, originals) for word in argv)
        into = "" if folder == Path(".") else f"  (files written into {folder}/)"
        print(f"racket-impact {shown}{into}")  # stdout: stderr is for one line of trouble
        # the new sidecars record where the files went
        return _start(replay, [_restored(word, moved) for word in argv], originals)


def cmd_feel(args) -> int:
    """``racket-impact feel``."""
    from racket.feel import hand_feel

    check_outputs(tables=[("--out", args.out)], plots=[("--plot", args.plot)])
    from dataclasses import replace

    racket = replace(load_racket(args.racket), support=args.support)  # always given (default)
    if args.grip:
        racket = replace(racket, hand=GRIPS[args.grip])
    position = racket.strings.center if args.position is None else args.position
    in_range("--position", position, *racket.strings.extent, "m from the tip")
    duration = in_range("--duration-ms", args.duration_ms, 5.0, 1000.0, "ms") / 1e3
    feel = hand_feel(
        racket, load_ball(args.ball), position, _speed(args, "speed"), offset=args.offset,
        duration=duration,
    )  # fmt: skip
    length = racket.beam.length
    print(
        f"impact {100 * (length - position):.1f} cm from the butt ({100 * position:.1f} from "
        f"the tip){'' if args.offset is None else f', {100 * args.offset:+.1f} cm off the axis'}"
        f"; the handle read {100 * feel.grip_from_butt:.1f} cm from the butt ({racket.support})"
    )
    print(f"peak handle velocity      {feel.peak_velocity:.3f} m/s")
    print(f"peak handle acceleration  {feel.peak_acceleration:.0f} m/s^2 "
          f"({feel.peak_acceleration / GRAVITY:.0f} g)")  # fmt: skip
    above = feel.frequencies > 20.0
    dominant = feel.frequencies[above][np.argmax(feel.spectrum[above])]
    print(f"strongest vibration       {dominant:.0f} Hz")
    print(
        f"vibration reaching the hand  {1e3 * feel.hand_vibration_energy:.2f} mJ over "
        f"{1e3 * feel.t[-1]:.0f} ms (all the hand absorbs: {1e3 * feel.hand_energy:.1f} mJ)"
    )
    print(f"vibration left in the frame  {1e3 * feel.vibration_energy_end:.2f} mJ")
    if args.out:
        from studies.tables import feel_table

        write_table(feel_table(feel), args.out)
    if args.plot:
        from studies.plots import plot_hand_feel

        save_plot(plot_hand_feel(feel), args.plot)
    return 0


def cmd_sweetspots(args) -> int:
    """``racket-impact sweetspots``."""
    from studies.landmarks import sweet_spots

    check_outputs(tables=[("--out", args.out)])
    swing = _swing(args)
    speed = _speed(args, "speed", allow_zero=swing is not None)
    grip = in_range("--grip-cm-from-butt", args.grip_cm_from_butt, 0.0, 30.0, "cm") / 100
    racket, ball = load_racket(args.racket), load_ball(args.ball)
    _check_swing(args, swing, racket, racket.strings.extent)  # the points span the strings
    table = sweet_spots(racket, ball, speed, swing, grip)
    _print_table(table, "{:.4g}")
    if args.out:
        write_table(table, args.out)
    return 0


def cmd_compare(args) -> int:
    """``racket-impact compare``."""
    from studies.maps import compare_summary
    from studies.sweeps import check_impacts, compare

    check_outputs(tables=[("--out", args.out)], plots=[("--plot", args.plot)])
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
    tension = None if args.tension_lb is None else _tension(args.tension_lb)
    if args.equal_effort and swing is None:
        raise ValueError("--equal-effort needs a swing: --swing-speed or --swing-speed-mph")
    table = compare(
        rackets, ball, speed, points, swing=swing, tension=tension, equal_effort=args.equal_effort
    )
    _print_table(compare_summary(rackets, table, ball, speed))
    if args.out:
        write_table(table, args.out)
    if args.plot:
        from studies.plots import plot_cor_comparison

        groups = {k: g for k, g in table.groupby("racket", sort=False)}
        save_plot(plot_cor_comparison(groups), args.plot)
    return 0


def cmd_map(args) -> int:
    """``racket-impact map``."""
    from studies.maps import FIELDS, check_map_points, face_map, face_points

    check_outputs(tables=[("--out", args.out)], plots=[("--plot", args.plot)])
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
    result = face_map(racket, ball, speed, swing=swing, grid=grid)
    for line in result.summary():
        print(line)
    if args.out:
        write_table(result.to_frame(), args.out)
    if args.plot:
        from studies.plots import plot_face_map

        save_plot(plot_face_map(result, args.field), args.plot)
    return 0


def _tensions(args):
    """``--tension-lb`` values in N (a list), None if not given; not with the stiffness."""
    if args.tension_lb is None:
        return None
    if args.string_stiffness is not None:
        raise ValueError("give --string-stiffness or --tension-lb, not both")
    return [_tension(t) for t in args.tension_lb]


def _tension(value_lb: float) -> float:
    """``--tension-lb`` [lb] checked in lb (the spec sheets' range, 20-80 lb) and given in
    N.
    """
    from common.units import LB

    low, high, unit = SPEC_RANGES["tension_lb"]
    return in_range("--tension-lb", value_lb, low, high, unit) * LB


def _tension_option(p, many: bool = False):
    p.add_argument(
        "--tension-lb",
        type=float,
        nargs="+" if many else None,
        action=_Once,
        metavar="LB",
        help="string tension(s) [lb]: the string bed's stiffness from the membrane model "
        "(default: the racket's)",
    )


def _swing(args):
    """The ``--swing-speed[-mph]`` and ``--pivot-cm-from-butt`` options as a Swing, or None
    without a swing speed.
    """
    from racket import Swing

    if args.swing_speed is None and args.swing_speed_mph is None:
        if getattr(args, "_seen_pivot_cm_from_butt", False):
            raise ValueError("--pivot-cm-from-butt needs --swing-speed (or --swing-speed-mph)")
        return None
    return Swing(_speed(args, "swing_speed"), _pivot(args))


def _check_swing(args, swing, racket, positions, name: str = "swing_speed") -> None:
    """``swing`` (of the speed option ``--NAME[-mph]`` and ``--pivot-cm-from-butt``) checked
    for the impact points ``positions`` [m from the tip], the message quoting the options as
    typed (:meth:`racket.Swing.check_points`); nothing without a swing.
    """
    if swing is not None:
        pivot = ("--pivot-cm-from-butt", args.pivot_cm_from_butt, "cm", 0.01)
        swing.check_points(racket, positions, head=_typed(args, name), pivot=pivot)


def _pivot(args) -> float:
    """``--pivot-cm-from-butt`` [cm] checked in cm (:data:`racket.swing.PIVOT_RANGE`), in m."""
    from racket.swing import PIVOT_RANGE

    low, high = (100 * end for end in PIVOT_RANGE)
    return in_range("--pivot-cm-from-butt", args.pivot_cm_from_butt, low, high, "cm") / 100


def _labels(names: list[str]) -> list[tuple[str, str]]:
    """(label, preset or file) of each ``--racket``: ``LABEL=SPEC`` as given; otherwise the
    preset, or the file's name without .toml, or its path where two files share a name.
    """
    pairs = []
    for name in names:
        label, sep, spec = name.partition("=")
        pairs.append((label, spec) if sep and label else (None, name))
    stems = [Path(spec).stem if spec.endswith(".toml") else spec for _, spec in pairs]
    labelled = [
        (label or (stem if stems.count(stem) == 1 else spec), spec)
        for (label, spec), stem in zip(pairs, stems, strict=True)
    ]
    seen = [label for label, _ in labelled]
    for label in seen:
        if seen.count(label) > 1:
            raise ValueError(
                f"--racket {label!r} is given twice; name the rackets apart with "
                "LABEL=PRESET_OR_TOML"
            )
    return labelled


# ----- parser -----------------------------------------------------------------------------
def _racket_arg(p, default="paper"):
    p.add_argument(
        "--racket",
        default=default,
        metavar="PRESET_OR_TOML",
        help=f"racket preset ({', '.join(RACKETS)}) or TOML file with a [racket] "
        f"table (default: {default})",
    )


def _ball_arg(p, flag="--ball", default=None, what="ball", **extra):
    shown_default = default or (
        f"{DEFAULT_BALL}, a real ball; with the paper's racket the paper's ball, {PAPER_BALL}"
    )
    p.add_argument(
        flag,
        default=default,
        metavar="PRESET_OR_TOML",
        help=f"{what}: preset ({', '.join(BALLS)}) or TOML file with a [ball] "
        f"table (default: {shown_default})",
        **extra,
    )


def _speed_option(p, name: str, default, what: str, many: bool = False):
    """``--NAME`` in m/s or ``--NAME-mph`` in mph, not both."""
    group = p.add_mutually_exclusive_group()
    nargs = "+" if many else None
    group.add_argument(
        f"--{name}",
        action=_Once,
        type=float,
        nargs=nargs,
        default=default,
        metavar="M_S",
        help=f"{what} [m/s]"
        + ("" if default is None else f" (default {default if not many else default[0]:g})"),
    )
    group.add_argument(
        f"--{name}-mph",
        action=_Once,
        type=float,
        nargs=nargs,
        metavar="MPH",
        help=f"{what} [mph]",
    )


def _pivot_option(p):
    p.add_argument(
        "--pivot-cm-from-butt",
        type=float,
        action=_Once,
        default=-100 * WRIST_BEYOND_BUTT,
        metavar="CM",
        help="swing pivot [cm from the butt, negative beyond it] (default "
        f"{-100 * WRIST_BEYOND_BUTT:g}, the wrist)",
    )


def _swing_options(p):
    """A swing about a pivot: the racket-head (string centre) speed and the pivot."""
    _speed_option(
        p, "swing-speed", None, "racket-head (string centre) speed of a swing of the free racket"
    )
    _pivot_option(p)


def build_parser(parser_class=_Parser) -> argparse.ArgumentParser:
    """The ``racket-impact`` argument parser, one subcommand per study (``parser_class``:
    :class:`_Replay` for a command recorded in a sidecar).
    """
    parser = parser_class(prog="racket-impact", description=__doc__.split("\n\n")[0])
    parser.add_argument(
        "--debug", action="store_true", help="show the traceback of an error (for reports)"
    )
    sub = parser.add_subparsers(dest="command", required=True, parser_class=parser_class)

    p = sub.add_parser("paper", help="reproduce every number of the paper, write its figures")
    p.add_argument(
        "--out",
        metavar="DIR",
        default="paper-figures",
        help="directory for the figures (PNG; default: paper-figures)",
    )
    p.add_argument(
        "--json",
        metavar="FILE",
        help="write the rows as JSON: claim, paper, simulated, tolerance, ok",
    )
    p.set_defaults(func=cmd_paper)

    p = sub.add_parser("sweep", help="impacts along the strings, over any parameter grid")
    _racket_arg(p)
    _ball_arg(p)
    _speed_option(p, "speed", [10.0], "ball speed(s) towards the strings", many=True)
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
    p.set_defaults(func=cmd_sweep)

    p = sub.add_parser("map", help="e, e_A, exit speed, vibration and twist over the face")
    _racket_arg(p, default="pure-drive-2021")
    _ball_arg(p)
    _speed_option(p, "speed", MAP_SPEED, "ball speed towards the strings")
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
    p.set_defaults(func=cmd_map)

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
    _speed_option(p, "racket-speed", 40.0, "racket-head (string centre) speed of the swing")
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

    p = sub.add_parser("collide", help="head-on collision of two balls (or a ball and a wall)")
    _ball_arg(p, "--a", "unhappy", "ball a")
    p.add_argument(
        "--b",
        default="happy",
        metavar="PRESET_OR_TOML",
        help="ball b: preset, TOML file, or 'wall' (default: happy)",
    )
    _speed_option(p, "va", 4.0, "velocity of a towards b")
    _speed_option(p, "vb", 0.0, "velocity of b, same direction as a's")
    p.add_argument("--out", metavar="FILE", help="summary file: .csv, .json or .parquet")
    p.add_argument("--history", metavar="FILE", help="time history: .csv, .json or .parquet")
    p.add_argument("--plot", metavar="FILE", help="history plot (.png, .svg, .pdf)")
    p.set_defaults(func=cmd_collide)

    p = sub.add_parser("drop", help="a ball dropped on the floor, on strings or on a racket")
    _ball_arg(p, "ball", nargs="?")
    p.add_argument("--height-m", type=float, default=2.54, metavar="M",
                   help="drop height [m] (default 2.54, the ITF rebound test)")  # fmt: skip
    p.add_argument("--onto", choices=["floor", "strings", "racket"], default="floor",
                   help="the floor (default), the strings of --racket with its head clamped, "
                   "or --racket lying free (at its string centre)")  # fmt: skip
    _racket_arg(p, default="pure-drive-2021")
    p.add_argument("--out", metavar="FILE", help="force and compression against time "
                   "(.csv, .json or .parquet)")  # fmt: skip
    p.add_argument("--plot", metavar="FILE", help="force and compression (.png, .svg, .pdf)")
    p.set_defaults(func=cmd_drop)

    p = sub.add_parser("ball", help="a ball's bounce on a rigid surface against impact speed")
    _ball_arg(p, "ball", nargs="?")
    p.add_argument(
        "--list", action="store_true", help="the real-ball presets, their numbers and sources"
    )
    from studies.bounce import DEFAULT_SPEEDS

    _speed_option(p, "speeds", [round(v, 2) for v in DEFAULT_SPEEDS], "impact speeds", True)
    p.add_argument("--out", metavar="FILE", help="table file: .csv, .json or .parquet")
    p.add_argument(
        "--plot",
        metavar="FILE",
        help="COR, contact time, peak force, compression (.png, .svg, .pdf)",
    )
    p.set_defaults(func=cmd_ball)

    p = sub.add_parser("modes", help="frequencies, nodes, mass properties, swingweight")
    _racket_arg(p)
    p.add_argument("--count", type=int, default=6, help="bending modes listed (default 6)")
    p.add_argument("--out", metavar="FILE", help="mode table: .csv, .json or .parquet")
    p.add_argument("--plot", metavar="FILE", help="mode shapes (.png, .svg, .pdf)")
    p.set_defaults(func=cmd_modes)

    p = sub.add_parser(
        "specs", help="the model fitted to a spec sheet: fit, masses, modes, effective mass"
    )
    p.add_argument(
        "racket",
        metavar="PRESET_OR_TOML",
        help=f"racket preset ({', '.join(RACKETS)}) or TOML file with a [racket] table "
        "(a [racket.specs] spec sheet, or any racket)",
    )
    p.add_argument("--count", type=int, default=4, help="bending modes listed (default 4)")
    p.add_argument("--out", metavar="FILE", help="effective-mass table: .csv, .json, .parquet")
    p.add_argument("--plot", metavar="FILE", help="mode shapes (.png, .svg, .pdf)")
    p.set_defaults(func=cmd_specs)

    p = sub.add_parser("app", help="the interactive page, served on this machine")
    p.add_argument("--host", default="127.0.0.1", help="address to serve on (default 127.0.0.1)")
    p.add_argument("--port", type=int, default=8000, help="port (default 8000)")
    p.set_defaults(func=cmd_app)

    p = sub.add_parser("rerun", help="make a table again from its sidecar (*.meta.json)")
    p.add_argument("sidecar", metavar="FILE", help="a table's sidecar, or the table itself")
    p.set_defaults(func=cmd_rerun)

    p = sub.add_parser("feel", help="the handle's motion at the hand after an impact")
    _racket_arg(p, default="pure-drive-2021")
    _ball_arg(p)
    _speed_option(p, "speed", 20.0, "ball speed towards the strings")
    p.add_argument("--position", type=float, metavar="M", help="impact point [m from the tip] "
                   "(default: the string centre)")  # fmt: skip
    p.add_argument("--offset", type=float, metavar="M", help="impact point's distance from "
                   "the long axis [m, + towards 3 o'clock]")  # fmt: skip
    p.add_argument("--support", choices=["free", "hand-held"], default="hand-held",
                   help="support (default hand-held)")  # fmt: skip
    p.add_argument("--grip", choices=list(GRIPS), help="how the hand holds it (default: the "
                   "racket's hand, the medium grip unless its file says otherwise)")  # fmt: skip
    p.add_argument("--duration-ms", type=float, default=50.0, metavar="MS",
                   help="how long to follow the racket (default 50 ms)")  # fmt: skip
    p.add_argument("--out", metavar="FILE", help="histories: .csv, .json or .parquet")
    p.add_argument("--plot", metavar="FILE", help="histories and spectrum (.png, .svg, .pdf)")
    p.set_defaults(func=cmd_feel)

    p = sub.add_parser("sweetspots", help="nodes, centre of percussion, power spots, sweet area")
    p.add_argument(
        "racket",
        metavar="PRESET_OR_TOML",
        help=f"racket preset ({', '.join(RACKETS)}) or TOML file with a [racket] table",
    )
    _ball_arg(p)
    _speed_option(p, "speed", MAP_SPEED, "ball speed towards the strings")
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

    p = sub.add_parser("compare", help="e along the strings of two or more rackets")
    p.add_argument(
        "--racket",
        action="append",
        metavar="PRESET_OR_TOML",
        help="a racket, as PRESET_OR_TOML or LABEL=PRESET_OR_TOML (repeat; default: paper "
        "and pure-drive-2021)",
    )
    _ball_arg(p)
    _speed_option(p, "speed", 10.0, "ball speed towards the strings")
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
    _tension_option(p)
    p.add_argument("--out", metavar="FILE", help="table file: .csv, .json or .parquet")
    p.add_argument("--plot", metavar="FILE", help="comparison plot (.png, .svg, .pdf)")
    p.set_defaults(func=cmd_compare)

    p = sub.add_parser("validate", help="the model against published measurements")
    p.add_argument("--out", metavar="FILE", help="table file: .csv, .json or .parquet")
    p.add_argument("--plot", metavar="FILE", help="measured band vs model (.png, .svg, .pdf)")
    p.set_defaults(func=cmd_validate)
    return parser


class _Stdout:
    """``sys.stdout`` while the command line runs: when its reader has gone (``| head``),
    the rest of the output goes to ``os.devnull``, as Python's documentation advises for
    SIGPIPE, and the run goes on to write its files.

    Parameters
    ----------
    stream : file
        The standard output.
    """

    def __init__(self, stream):
        self._stream = stream

    def write(self, text: str) -> int:
        """Write ``text``, or nothing once the reader has gone; returns its length."""
        try:
            return self._stream.write(text)
        except BrokenPipeError:
            self._gone()
            return len(text)

    def flush(self) -> None:
        """Flush, or nothing once the reader has gone."""
        try:
            self._stream.flush()
        except BrokenPipeError:
            self._gone()

    def _gone(self) -> None:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, self._stream.fileno())  # what is still buffered goes there too
        os.close(devnull)

    def __getattr__(self, name):
        return getattr(self._stream, name)


@contextlib.contextmanager
def _reader_may_go():
    """Inside the block, ``sys.stdout`` is a :class:`_Stdout`, flushed at its end (a reader
    gone shows there, not as Python exits).
    """
    stream = sys.stdout
    if stream is None:  # no standard output at all (``>&-``): print writes nothing
        yield
        return
    sys.stdout = _Stdout(stream)
    try:
        yield
    finally:
        sys.stdout.flush()
        sys.stdout = stream


def main(argv=None) -> int:
    """Run the CLI; returns the exit status: 0, 1 if ``paper`` finds a claim out of
    tolerance or on an internal error, 2 for bad input, 130 when interrupted (Ctrl-C), 143
    or 129 when stopped by SIGTERM or SIGHUP: one line on stderr each.  Every file a run
    writes is put in place only when it succeeds (:mod:`studies.outputs`).  A reader of the
    output that goes (``racket-impact modes | head -3``) stops nothing.
    """
    argv = sys.argv[1:] if argv is None else list(argv)
    words = [a for a in argv if a != "--debug"]
    with _reader_may_go():
        try:
            args = build_parser().parse_args(words)
            args.debug = len(words) < len(argv)  # before or after the subcommand
            return _start(args, words)
        except KeyboardInterrupt as err:  # before the run (a run reports its own)
            if "--debug" in argv:
                raise
            return interrupted("racket-impact", err, written=False)


def _start(args, words: list[str], originals: dict | None = None) -> int:
    """Run the parsed ``args`` as the command line ``words``, which its tables' sidecars
    record (``originals``: a rerun's copies of TOML inputs -> the paths first given).
    """
    if getattr(args, "ball", "") is None:  # the real ball, the paper's with the paper's racket
        rackets = getattr(args, "racket", None)
        args.ball = default_ball(
            *(rackets if isinstance(rackets, list) else [rackets] * bool(rackets))
        )
    options = {k: v for k, v in vars(args).items() if k != "func" and not k.startswith("_")}
    outer = dict(_RUN)  # a rerun's own run, restored afterwards
    _RUN.clear()
    _RUN.update(argv=words, command=args.command, options=options, originals=originals or {})
    try:
        return _run(args, f"racket-impact {args.command}")
    finally:
        _RUN.clear()
        _RUN.update(outer)


def _run(args, prefix: str) -> int:
    """Run the parsed command, its files put in place together when it returns: warnings
    one line each, said when it has succeeded, bad input status 2 (one line, the warnings
    before it left unsaid), Ctrl-C status 130 and SIGTERM or SIGHUP
    128 + its number (one line; its files removed, as :func:`studies.outputs.stoppable`).
    """
    said = {}  # kind -> line: the first warning of each kind, said when the run succeeds

    def one_line(message, category, filename, lineno, file=None, line=None):
        kind = re.sub(r"\d[\d.eE+-]*", "#", str(message))  # a grid repeats them, new numbers
        said.setdefault(kind, f"{prefix}: warning: {message}")

    with warnings.catch_warnings(), outputs.stoppable():
        warnings.showwarning = one_line
        files = None
        try:
            with outputs.transaction() as files:
                status = args.func(args)
            for line in said.values():  # (a run refused says one line: its error)
                print(line, file=sys.stderr)
            return status
        except KeyboardInterrupt as err:  # Stopped too: SIGTERM, SIGHUP
            if args.debug:
                raise
            return interrupted(prefix, err, written=files is not None and files.committed)
        except (ValueError, OSError) as err:
            if args.debug:
                raise
            message = err.strerror if isinstance(err, OSError) and err.strerror else str(err)
            where = f" ({err.filename})" if isinstance(err, OSError) and err.filename else ""
            line = f"{prefix}: error: {message}{where}"
            for copy, original in _RUN.get("originals", {}).items():  # a rerun's TOML copies
                line = line.replace(copy, original)
            print(line, file=sys.stderr)
            return 2
        except Exception as err:
            if args.debug:
                raise
            print(
                f"{prefix}: internal error ({type(err).__name__}: {err}); please report it, "
                "with the command; --debug shows the traceback",
                file=sys.stderr,
            )
            return 1


if __name__ == "__main__":
    sys.exit(main())
