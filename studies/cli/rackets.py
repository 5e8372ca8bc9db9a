"""``racket-impact modes``, ``specs`` and ``feel``: a racket's modes and mass properties,
the model fitted to its spec sheet, and the handle's motion at the hand.
"""

from __future__ import annotations

import math
import sys
import textwrap

from beam.beam import MAX_MODES
from common.checks import S_AS_MS, in_range
from racket.specs.ra import ra_note
from racket.strings.ert import dt_reading
from studies.cli.files import add_outputs, check_table_and_plot, say_conditions, write_outputs
from studies.cli.options import _ball_arg, _count, _print_table, _speed
from studies.cli.racket_options import (
    add_racket_options,
    impact_parser,
    impact_point,
    modes_options,
    racket_conditions,
    racket_from,
)
from studies.cli.show import WIDTH, spots_view
from studies.conditions import PLAIN_BED
from studies.config import load_ball, racket_specs
from studies.sweeps import BALL_SPEED


def add_modes(sub) -> None:
    """The ``modes`` subcommand, on the subparsers ``sub``."""
    what = "frequencies, nodes, mass properties, swingweight"
    p = _modes_parser(sub, "modes", what, 6, "mode table: .csv, .json or .parquet")
    p.set_defaults(func=cmd_modes)


def _modes_parser(sub, name: str, what: str, count: int, table: str, ball: str | None = None):
    """The subparser of ``modes`` or ``specs`` (``name``; ``what``: its help) on the
    subparsers ``sub``: the racket's options, with ``ball`` (what the ball is for) ``--ball``,
    ``--count`` (the bending modes listed, ``count`` by default), ``--out`` (``table``: its
    help) and ``--plot`` (the mode shapes).
    """
    p = sub.add_parser(name, help=what)
    add_racket_options(p)
    if ball is not None:
        _ball_arg(p, what=ball)
    p.add_argument(
        "--count", type=int, default=count, help=f"bending modes listed (default {count})"
    )
    p.add_argument("--out", metavar="FILE", help=table)
    p.add_argument("--plot", metavar="FILE", help="mode shapes (.png, .svg, .pdf)")
    return p


def _modes_counted(args) -> int:
    """The outputs of ``modes`` or ``specs`` checked, then ``--count``: the modes listed."""
    check_table_and_plot(args)
    return _count("--count", args.count, 1, MAX_MODES)


def _modes_written(args, table, racket, count: int, conditions: str) -> int:
    """``table`` to ``--out`` and the shapes of the ``count`` first modes of ``racket`` to
    ``--plot``, as given; 0.
    """

    def draw():
        from studies.plots import plot_modes

        return plot_modes(racket, count=count, conditions=conditions)

    return write_outputs(args, table, draw)


def cmd_modes(args) -> int:
    """``racket-impact modes``."""
    import pandas as pd

    from studies.face.landmarks import hand_pivot, rigid_centre_of_percussion

    count = _modes_counted(args)
    modes_options(args)
    racket = racket_from(args)
    beam, modes = racket.beam, racket.beam.modes
    hand = hand_pivot(racket)
    centre = racket.strings.center
    conditions = say_conditions(racket_conditions(args, racket))
    print(f"length            {beam.length:.4f} m")
    print(f"mass              {beam.mass:.4f} kg")
    print(f"centre of mass    {100 * beam.center_of_mass:.2f} cm from the tip (balance "
          f"{100 * beam.balance:.2f} cm: spec sheets give it from the butt)")  # fmt: skip
    print(f"swingweight       {beam.swingweight_kgcm2:.1f} kg cm^2 (axis 10 cm from the butt, "
          "as spec sheets define it)")  # fmt: skip
    print(f"recoil weight     {1e4 * beam.inertia_cm:.1f} kg cm^2 (about the centre of mass)")
    cop = rigid_centre_of_percussion(racket, hand)
    print(
        f"centre of percussion  {100 * cop:.1f} cm from the tip (hand at {100 * hand:.1f} cm "
        "from the tip)"
    )
    print(
        f"effective mass at the string centre ({100 * centre:.1f} cm from the tip)  "
        f"{beam.effective_mass(centre):.4f} kg"
    )
    rows = []
    for k in range(1, min(count, modes.count - 2) + 1):
        nodes = modes.nodes(k)
        rows.append(
            {
                "mode": k,
                "frequency_Hz": modes.frequencies[k - 1],
                "nodes_cm_from_tip": ", ".join(f"{100 * n:.1f}" for n in nodes),
            }
        )
    table = pd.DataFrame(rows)
    print()
    _print_table(table, "{:.1f}")
    return _modes_written(args, table, racket, count, conditions)


def add_specs(sub) -> None:
    """The ``specs`` subcommand, on the subparsers ``sub``."""
    what = "the model fitted to a spec sheet: fit, masses, modes, effective mass"
    table = "effective-mass table: .csv, .json, .parquet"
    p = _modes_parser(sub, "specs", what, 4, table, ball="ball of the sweet spots")
    p.set_defaults(func=cmd_specs)


def cmd_specs(args) -> int:
    """``racket-impact specs``."""
    from studies.report import spec_report

    count = _modes_counted(args)
    racket = racket_from(args)
    specs, sources = racket_specs(args.racket)
    report = spec_report(racket, specs, count=count, ball=load_ball(args.ball))
    conditions = say_conditions(racket_conditions(args, racket))
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
    print("the racket (with any lead tape, strings and support of the file or the options):")
    _print_table(report.properties, "{:.4g}")
    print(f"\n{bed_text(racket.strings)}")
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
    print(f"\nsweet spots (ball {args.ball} at {BALL_SPEED:g} m/s on the racket at rest):")
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
    return _modes_written(args, report.effective_mass, racket, count, conditions)


def bed_text(bed) -> str:
    """The string bed as ``specs`` prints it: its stiffness [N/m] and the ERT's DT [kp/cm]
    (:func:`racket.strings.ert.dt_reading`),
    and, for a strung bed, its stretch, loss and mass (:mod:`racket.strings.stringing`).
    """
    said = (
        f"string bed: {bed.stiffness:.0f} N/m at its centre (ERT dynamic tension "
        f"{dt_reading(bed.stiffness, bed.stretch):.3g} kp/cm, the force at 1 cm)"
    )
    strung = bed.stringing
    if strung is None:
        said += f", {PLAIN_BED}: lossless and massless" if bed.plain else ""
        return textwrap.fill(said, WIDTH, subsequent_indent="  ")
    said += (
        f"; {strung.describe()}; stretch {bed.stretch:.4g} 1/m^2 ({100 * bed.stretch * 1e-4:.3g} "
        f"% stiffer at 1 cm); loss {100 * bed.loss:.3g} % of what it stores; strings "
        f"{1e3 * strung.mass(bed.area, bed.aspect):.3g} g inside the head, "
        f"{1e3 * bed.moving_mass:.2g} g moving with the ball"
    )
    return textwrap.fill(said, WIDTH, subsequent_indent="  ")


def add_feel(sub) -> None:
    """The ``feel`` subcommand, on the subparsers ``sub``."""
    from studies.feel import FEEL_SUPPORT

    p = impact_parser(sub, "feel", "the handle's motion at the hand after an impact",
                      swing=False, support_default=FEEL_SUPPORT)  # fmt: skip
    p.add_argument("--position", type=float, metavar="CM", help="impact point [cm from the "
                   "tip] (default: the string centre)")  # fmt: skip
    p.add_argument("--offset", type=float, metavar="CM", help="impact point's distance from "
                   "the long axis [cm, + towards 3 o'clock]")  # fmt: skip
    p.add_argument("--duration-ms", type=float, default=50.0, metavar="MS",
                   help="how long to follow the racket (default 50 ms)")  # fmt: skip
    add_outputs(p, "histories", "histories and spectrum")
    p.set_defaults(func=cmd_feel)


def cmd_feel(args) -> int:
    """``racket-impact feel``."""
    from racket.feel import hand_feel
    from studies.feel import feel_numbers

    check_table_and_plot(args)
    racket = racket_from(args)
    position, offset = impact_point(args, racket)
    position = racket.strings.center if position is None else position
    duration = in_range("--duration-ms", args.duration_ms, 5.0, 1000.0, "ms", slips=(S_AS_MS,))
    speed = _speed(args, "speed")
    feel = hand_feel(racket, load_ball(args.ball), position, speed, offset=offset,
                     duration=duration / 1e3)  # fmt: skip
    numbers = feel_numbers(feel, racket)
    conditions = say_conditions(racket_conditions(args, racket, speed=speed))
    where = " (the string centre)" if args.position is None else ""
    off = "" if offset is None else f", {100 * offset:+.1f} cm off the axis"
    print(f"impact {100 * position:.1f} cm from the tip{where}{off}; the handle read at "
          f"{100 * feel.grip:.1f} cm (mid-hand)")  # fmt: skip
    print(f"shock                     {numbers['feel_shock_g']:.1f} g (the handle's rigid-body "
          "jolt while the ball is on the strings)")  # fmt: skip
    print(f"vibration                 {numbers['feel_vibration_g']:.1f} g (the handle's "
          "vibration after the ball has left, largest)")  # fmt: skip
    print(f"strongest vibration       {numbers['feel_hz']:.1f} Hz ({numbers['feel_mode']})")
    print(
        f"vibration reaching the hand  {1e3 * feel.hand_vibration_energy:.2f} mJ over "
        f"{1e3 * feel.t[-1]:.0f} ms (all the hand absorbs: {1e3 * feel.hand_energy:.1f} mJ)"
    )
    print(f"vibration left in the frame  {1e3 * feel.vibration_energy_end:.2f} mJ")
    from studies.tables import feel_table

    def draw():
        from studies.plots import plot_hand_feel

        return plot_hand_feel(feel, conditions=conditions)

    return write_outputs(args, feel_table(feel), draw)
