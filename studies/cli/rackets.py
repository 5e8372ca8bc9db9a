"""``racket-impact modes``, ``specs`` and ``feel``: a racket's modes and mass properties,
the model fitted to its spec sheet, and the handle's motion at the hand.
"""

from __future__ import annotations

import math
import sys
import textwrap

from beam.beam import MAX_MODES
from common.checks import CM_AS_M, S_AS_MS, in_range
from common.units import GRAVITY
from racket import GRIPS
from racket.specs.ra import ra_note
from studies.cli.files import check_outputs, save_plot, write_table
from studies.cli.options import _ball_arg, _count, _print_table, _racket_arg, _speed, _speed_option
from studies.cli.show import WIDTH, spots_view
from studies.config import RACKETS, default_ball, load_ball, load_racket, racket_specs
from studies.landmarks import HAND_FROM_BUTT
from studies.sweeps import BALL_SPEED


def add_modes(sub) -> None:
    """The ``modes`` subcommand, on the subparsers ``sub``."""
    p = sub.add_parser("modes", help="frequencies, nodes, mass properties, swingweight")
    _racket_arg(p)
    p.add_argument("--count", type=int, default=6, help="bending modes listed (default 6)")
    p.add_argument("--out", metavar="FILE", help="mode table: .csv, .json or .parquet")
    p.add_argument("--plot", metavar="FILE", help="mode shapes (.png, .svg, .pdf)")
    p.set_defaults(func=cmd_modes)


def cmd_modes(args) -> int:
    """``racket-impact modes``."""
    import pandas as pd

    from studies.landmarks import rigid_centre_of_percussion

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
    cop = rigid_centre_of_percussion(racket, hand)
    print(
        f"centre of percussion  {100 * (beam.length - cop):.1f} cm from the butt "
        f"({100 * cop:.1f} cm from the tip; hand {100 * HAND_FROM_BUTT:.0f} cm from the butt)"
    )
    print(
        f"effective mass at the string centre ({100 * (beam.length - centre):.1f} cm from "
        f"the butt, {100 * centre:.1f} cm from the tip)  "
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


def add_specs(sub) -> None:
    """The ``specs`` subcommand, on the subparsers ``sub``."""
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
        "\nmodes: free-free, and held by the hand\n(stiffness "
        f"{racket.hand.stiffness:g} N/m, damping {racket.hand.damping:g} N s/m over "
        f"{100 * racket.hand.grip_length:g} cm, "
        + (
            f"to a hand of {racket.hand.mass:g} kg)"
            if math.isfinite(racket.hand.mass)
            else "to a hand held still)"
        )
    )
    _print_table(report.modes, "{:.4g}")
    print(f"\nsweet spots (ball {ball_name} at {BALL_SPEED:g} m/s on the racket at rest):")
    _print_table(spots_view(report.sweet_spots), "{:.4g}")
    print("\neffective mass along the strings (Eq. 20)")
    _print_table(report.effective_mass, "{:.4g}")
    if sources:
        print("\nsources:")
        for key, source in sources.items():
            print(textwrap.fill(f"{key}: {source}", WIDTH, initial_indent="  ",
                                subsequent_indent="    "))  # fmt: skip
    if specs is not None:
        print("\nsources of the parts' ranges:")
        for part in report.parts.itertuples():
            print(textwrap.fill(f"{part.part}: {part.source}", WIDTH, initial_indent="  ",
                                subsequent_indent="    "))  # fmt: skip
    if args.out:
        write_table(report.effective_mass, args.out)
    if args.plot:
        from studies.plots import plot_modes

        save_plot(plot_modes(racket, count=count), args.plot)
    return 0


def add_feel(sub) -> None:
    """The ``feel`` subcommand, on the subparsers ``sub``."""
    p = sub.add_parser("feel", help="the handle's motion at the hand after an impact")
    _racket_arg(p, default="pure-drive-2021")
    _ball_arg(p)
    _speed_option(p, "speed", BALL_SPEED, "ball speed towards the strings")
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


def cmd_feel(args) -> int:
    """``racket-impact feel``."""
    from racket.feel import hand_feel

    check_outputs(tables=[("--out", args.out)], plots=[("--plot", args.plot)])
    from dataclasses import replace

    racket = replace(load_racket(args.racket), support=args.support)  # always given (default)
    if args.grip:
        racket = replace(racket, hand=GRIPS[args.grip])
    position = racket.strings.center if args.position is None else args.position
    in_range("--position", position, *racket.strings.extent, "m from the tip", slips=(CM_AS_M,))
    if args.offset is not None and racket.beam.roll_inertia is not None:
        half = 0.5 * racket.strings.full_width
        in_range("--offset", args.offset, -half, half, "m from the long axis", slips=(CM_AS_M,))
    duration = in_range("--duration-ms", args.duration_ms, 5.0, 1000.0, "ms", slips=(S_AS_MS,))
    duration /= 1e3
    feel = hand_feel(
        racket, load_ball(args.ball), position, _speed(args, "speed"), offset=args.offset,
        duration=duration,
    )  # fmt: skip
    length = racket.beam.length
    print(
        f"impact {100 * (length - position):.1f} cm from the butt ({100 * position:.1f} cm from "
        f"the tip){'' if args.offset is None else f', {100 * args.offset:+.1f} cm off the axis'}"
        f"; handle read {100 * feel.grip_from_butt:.1f} cm from the butt ({racket.support})"
    )
    print(f"peak handle velocity      {feel.peak_velocity:.3f} m/s")
    print(f"peak handle acceleration  {feel.peak_acceleration:.0f} m/s^2 "
          f"({feel.peak_acceleration / GRAVITY:.0f} g)")  # fmt: skip
    dominant, of_mode = feel.strongest()
    bins = f"{feel.frequencies[1]:.0f} Hz"
    print(f"strongest vibration       {dominant:.1f} Hz " + (
        f"(the {racket.support} racket's mode; the spectrum's bins: {bins})"
        if of_mode else f"(the spectrum's peak, to +/- {bins}: its bins' width)"))  # fmt: skip
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
