"""The ``racket-impact`` command line.

Subcommands: ``paper``, ``sweep``, ``serve``, ``collide``, ``modes``, ``specs``, ``compare``.
Rackets and balls are presets or TOML files (:mod:`studies.config`).  Tables go to CSV,
JSON or Parquet by the file's extension, plots to PNG, SVG or PDF.  Bad input prints one
line naming the problem and exits with status 2.
"""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

import numpy as np
import pandas as pd

from ball import WALL, collide
from common.units import MPH
from racket import SUPPORTS
from studies.config import BALLS, RACKETS, load_ball, load_racket, racket_specs
from studies.tables import history_table

TABLE_FORMATS = (".csv", ".json", ".parquet")
PLOT_FORMATS = (".png", ".svg", ".pdf")


class _Parser(argparse.ArgumentParser):
    def error(self, message):  # one line, status 2, no usage dump
        self.exit(2, f"{self.prog}: error: {message}\n")


def write_table(table: pd.DataFrame, path: str) -> None:
    """Write ``table`` to ``path`` as CSV, JSON (records) or Parquet, by extension."""
    suffix = Path(path).suffix.lower()
    if suffix not in TABLE_FORMATS:
        raise ValueError(f"table file must end in {', '.join(TABLE_FORMATS)}, got {path!r}")
    if suffix == ".csv":
        table.to_csv(path, index=False)
    elif suffix == ".json":
        table.to_json(path, orient="records", indent=2)
    else:
        try:
            table.to_parquet(path, index=False)
        except ImportError:
            raise ValueError(
                "Parquet output needs pyarrow: pip install 'racket-impact[parquet]'"
            ) from None


def save_plot(axes, path: str) -> None:
    """Save the figure holding ``axes`` as PNG, SVG or PDF, by extension."""
    suffix = Path(path).suffix.lower()
    if suffix not in PLOT_FORMATS:
        raise ValueError(f"plot file must end in {', '.join(PLOT_FORMATS)}, got {path!r}")
    fig = np.atleast_1d(axes)[0].figure
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    import matplotlib.pyplot as plt

    plt.close(fig)


def _speed(args, name: str) -> float:
    mph = getattr(args, f"{name}_mph")
    return mph * MPH if mph is not None else getattr(args, name)


def _print_table(table: pd.DataFrame, floatfmt: str = "{:.4g}") -> None:
    with pd.option_context("display.width", 200, "display.max_rows", 60, "display.max_columns", 30):
        print(table.to_string(float_format=floatfmt.format))


# ----- subcommands ------------------------------------------------------------------------
def cmd_paper(args) -> int:
    from studies.paper import paper_table

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
        Path(args.json).write_text(json.dumps(records, indent=2))
    written = write_paper_figures(Path(args.out))
    print(f"figures written to {args.out}/: {', '.join(p.name for p in written)}")
    return 0 if ok else 1


def write_paper_figures(out: Path) -> list[Path]:
    """The paper's figures and the racket plots, as PNG files in ``out``."""
    import matplotlib

    matplotlib.use("Agg")
    from ball import Ball, LinearSpring, SineLaw
    from racket import impact, paper_racket, tennis_ball
    from studies import plots
    from studies.serve import serve_what_if

    out.mkdir(parents=True, exist_ok=True)
    unhappy = Ball(0.0103, SineLaw(2e4))
    racket, ball = paper_racket(), tennis_ball()
    figures = {
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
    written = []
    for name, draw in figures.items():
        save_plot(draw(), out / name)
        written.append(out / name)
    return written


def cmd_sweep(args) -> int:
    from racket import impact
    from studies.sweeps import sweep

    racket, ball = load_racket(args.racket), load_ball(args.ball)
    start = racket.strings.extent[0] if args.from_ is None else args.from_
    end = racket.strings.extent[1] if args.to is None else args.to
    if args.points < 2:
        raise ValueError(f"points must be >= 2, got {args.points}")
    positions = np.linspace(start, end, args.points)
    speeds = [s * MPH for s in args.speed_mph] if args.speed_mph else args.speed
    table = sweep(
        racket,
        ball,
        positions,
        speeds,
        string_stiffness=args.string_stiffness,
        f1=args.f1,
        support=args.support,
    )
    _print_table(
        table[
            [
                "position_from_tip_m",
                "e",
                "e_A",
                "effective_mass_kg",
                "ball_rebound_m_s",
                "vibration_energy_fraction",
            ]
            + [c for c in table.columns[11:]]
        ].iloc[:: max(1, len(table) // 25)]
    )
    best = table.loc[table["e"].idxmax()]
    print(
        f"\nlargest e = {best['e']:.4f} at {best['position_from_tip_m']:.3f} m from the tip "
        f"({len(table)} impacts)"
    )
    for path in filter(None, (args.out, args.csv, args.json)):
        write_table(table, path)
    if args.plot:
        from studies.plots import plot_cor_along_racket

        single = impact(racket, ball, positions, speeds[0])
        save_plot(plot_cor_along_racket(single, racket), args.plot)
    return 0


def cmd_serve(args) -> int:
    from studies.serve import serve_table, serve_what_if

    racket, ball = load_racket(args.racket), load_ball(args.ball)
    speed = _speed(args, "racket_speed")
    table = serve_table(racket, ball, args.position, speed, args.pivot)
    print(f"racket (impact point) speed v2 = {speed:.2f} m/s ({speed / MPH:.1f} mph)")
    _print_table(table)
    if args.what_if:
        what_if = serve_what_if(racket, ball, args.position, speed, pivot=args.pivot)
        print()
        _print_table(
            what_if[["varied", "value", "e", "serve_simulated_m_s", "reduction_simulated_percent"]]
        )
        table = what_if
        if args.plot:
            from studies.plots import plot_serve_what_if

            save_plot(plot_serve_what_if(what_if), args.plot)
    elif args.plot:
        raise ValueError("--plot needs --what-if for serve")
    if args.out:
        write_table(table.reset_index(), args.out)
    return 0


def cmd_collide(args) -> int:
    a = load_ball(args.a)
    b = WALL if args.b == "wall" else load_ball(args.b)
    r = collide(a, b, _speed(args, "va"), _speed(args, "vb"))
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


def cmd_modes(args) -> int:
    from studies.plots import HAND_FROM_BUTT, center_of_percussion

    racket = load_racket(args.racket)
    beam, modes = racket.beam, racket.beam.modes
    hand = beam.length - HAND_FROM_BUTT
    centre = racket.strings.center
    print(f"length            {beam.length:.4f} m")
    print(f"mass              {beam.mass:.4f} kg")
    print(f"balance           {100 * beam.balance:.2f} cm from the butt")
    print(f"swingweight       {beam.swingweight_kgcm2:.1f} kg cm^2 (axis 10 cm from the butt)")
    print(f"recoil weight     {1e4 * beam.inertia_cm:.1f} kg cm^2 (about the centre of mass)")
    print(
        f"centre of percussion  {100 * center_of_percussion(racket, hand):.1f} cm from the "
        f"tip (hand {100 * HAND_FROM_BUTT:.0f} cm from the butt)"
    )
    print(
        f"effective mass at the string centre ({100 * centre:.1f} cm)  "
        f"{beam.effective_mass(centre):.4f} kg"
    )
    rows = []
    for k in range(1, min(args.count, modes.count - 2) + 1):
        nodes = ", ".join(f"{100 * n:.1f}" for n in modes.nodes(k))
        rows.append(
            {"mode": k, "frequency_Hz": modes.frequencies[k - 1], "nodes_cm_from_tip": nodes}
        )
    table = pd.DataFrame(rows)
    print()
    _print_table(table, "{:.1f}")
    if args.out:
        write_table(table, args.out)
    if args.plot:
        from studies.plots import plot_modes

        save_plot(plot_modes(racket, count=args.count), args.plot)
    return 0


def cmd_specs(args) -> int:
    from studies.report import spec_report

    racket = load_racket(args.racket)
    specs, sources = racket_specs(args.racket)
    report = spec_report(racket, specs, count=args.count)
    if specs is not None:
        print("spec sheet and fitted model (f1 given on the spec sheet, not inferred from RA):")
        _print_table(report.fit, "{:.5g}")
        print()
    print("the racket (with any lead tape, strings and support of the file):")
    _print_table(report.properties, "{:.4g}")
    print(
        "\nmodes: free-free, and held by the hand (stiffness "
        f"{racket.hand.stiffness:g} N/m, damping {racket.hand.damping:g} N s/m over "
        f"{100 * racket.hand.grip_length:g} cm)"
    )
    _print_table(report.modes, "{:.4g}")
    print("\neffective mass along the strings (Eq. 20)")
    _print_table(report.effective_mass, "{:.4g}")
    if sources:
        print("\nsources:")
        for key, source in sources.items():
            print(f"  {key}: {source}")
    if args.out:
        write_table(report.effective_mass, args.out)
    if args.plot:
        from studies.plots import plot_modes

        save_plot(plot_modes(racket, count=args.count), args.plot)
    return 0


def cmd_compare(args) -> int:
    from studies.sweeps import compare

    names = args.racket or ["paper", "pure-drive-2021"]
    if len(names) < 2:
        raise ValueError(f"compare needs two or more --racket, got {len(names)}")
    rackets = {Path(n).stem if n.endswith(".toml") else n: load_racket(n) for n in names}
    if args.support:
        from dataclasses import replace

        rackets = {k: replace(r, support=args.support) for k, r in rackets.items()}
    table = compare(rackets, load_ball(args.ball), _speed(args, "speed"), args.points)
    rows = []
    for label, group in table.groupby("racket", sort=False):
        best = group.loc[group["e"].idxmax()]
        rows.append(
            {
                "racket": label,
                "largest_e": best["e"],
                "at_cm_from_tip": 100 * best["position_from_tip_m"],
                "e_at_string_centre": float(
                    np.interp(
                        rackets[label].strings.center, group["position_from_tip_m"], group["e"]
                    )
                ),
                "e_at_tip_end": group["e"].iloc[0],
            }
        )
    _print_table(pd.DataFrame(rows))
    if args.out:
        write_table(table, args.out)
    if args.plot:
        from studies.plots import plot_cor_comparison

        groups = {k: g for k, g in table.groupby("racket", sort=False)}
        save_plot(plot_cor_comparison(groups), args.plot)
    return 0


# ----- parser -----------------------------------------------------------------------------
def _racket_arg(p):
    p.add_argument(
        "--racket",
        default="paper",
        metavar="PRESET_OR_TOML",
        help=f"racket preset ({', '.join(RACKETS)}) or TOML file with a [racket] "
        "table (default: paper)",
    )


def _ball_arg(p, flag="--ball", default="tennis", what="ball"):
    p.add_argument(
        flag,
        default=default,
        metavar="PRESET_OR_TOML",
        help=f"{what}: preset ({', '.join(BALLS)}) or TOML file with a [ball] "
        f"table (default: {default})",
    )


def _speed_option(p, name: str, default, what: str, many: bool = False):
    """``--NAME`` in m/s or ``--NAME-mph`` in mph, not both."""
    group = p.add_mutually_exclusive_group()
    nargs = "+" if many else None
    group.add_argument(
        f"--{name}",
        type=float,
        nargs=nargs,
        default=default,
        metavar="M_S",
        help=f"{what} [m/s] (default {default if not many else default[0]:g})",
    )
    group.add_argument(
        f"--{name}-mph", type=float, nargs=nargs, metavar="MPH", help=f"{what} [mph]"
    )


def build_parser() -> argparse.ArgumentParser:
    parser = _Parser(prog="racket-impact", description=__doc__.split("\n\n")[0])
    sub = parser.add_subparsers(dest="command", required=True, parser_class=_Parser)

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
        "--string-stiffness",
        type=float,
        nargs="+",
        metavar="N_M",
        help="string-bed stiffness(es) [N/m] (default: the racket's)",
    )
    p.add_argument(
        "--f1",
        type=float,
        nargs="+",
        metavar="HZ",
        help="frame's first bending frequency(ies) [Hz] (default: the racket's)",
    )
    p.add_argument(
        "--support",
        nargs="+",
        choices=list(SUPPORTS),
        help="support(s) (default: the racket's)",
    )
    p.add_argument("--out", metavar="FILE", help="table file: .csv, .json or .parquet")
    p.add_argument("--csv", metavar="FILE", help="table as CSV")
    p.add_argument("--json", metavar="FILE", help="table as JSON records")
    p.add_argument("--plot", metavar="FILE", help="e along the racket: .png, .svg or .pdf")
    p.set_defaults(func=cmd_sweep)

    p = sub.add_parser("serve", help="serve speed with a normal and a zero-COR ball (Sec. VIII)")
    _racket_arg(p)
    _ball_arg(p)
    p.add_argument(
        "--position",
        type=float,
        metavar="M",
        help="impact point [m from the tip] (default: centre of the strings)",
    )
    _speed_option(p, "racket-speed", 40.0, "impact-point speed of the swung racket")
    p.add_argument(
        "--pivot",
        type=float,
        metavar="M",
        help="swing pivot [m from the tip] (default: 5 cm beyond the butt)",
    )
    p.add_argument(
        "--what-if",
        action="store_true",
        help="also sweep the reduction over string and ball stiffness",
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

    p = sub.add_parser("compare", help="e along the strings of two or more rackets")
    p.add_argument(
        "--racket",
        action="append",
        metavar="PRESET_OR_TOML",
        help="a racket (repeat; default: paper and pure-drive-2021)",
    )
    _ball_arg(p)
    _speed_option(p, "speed", 10.0, "ball speed towards the strings")
    p.add_argument("--points", type=int, default=101, help="impact points per racket")
    p.add_argument("--support", choices=list(SUPPORTS), help="support for every racket")
    p.add_argument("--out", metavar="FILE", help="table file: .csv, .json or .parquet")
    p.add_argument("--plot", metavar="FILE", help="comparison plot (.png, .svg, .pdf)")
    p.set_defaults(func=cmd_compare)
    return parser


def main(argv=None) -> int:
    """Run the CLI; returns the exit status (2 for bad input, one line on stderr)."""
    args = build_parser().parse_args(argv)
    try:
        return args.func(args)
    except (ValueError, OSError) as err:
        message = err.strerror if isinstance(err, OSError) and err.strerror else str(err)
        where = f" ({err.filename})" if isinstance(err, OSError) and err.filename else ""
        print(f"racket-impact {args.command}: error: {message}{where}", file=sys.stderr)
        return 2


if __name__ == "__main__":
    sys.exit(main())
