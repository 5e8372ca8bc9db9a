"""``racket-impact validate``: the model against published measurements."""

from __future__ import annotations

import re
import textwrap

from studies.cli.files import add_outputs, check_outputs, save_plot, write_table
from studies.cli.options import _print_table
from studies.cli.show import WIDTH


def add_validate(sub) -> None:
    """The ``validate`` subcommand, on the subparsers ``sub``."""
    p = sub.add_parser("validate", help="the model against published measurements")
    add_outputs(p, plot="measured band vs model")
    p.set_defaults(func=cmd_validate)


def cmd_validate(args) -> int:
    """``racket-impact validate``."""
    from studies import validation

    check_outputs(tables=[("--out", args.out)], plots=[("--plot", args.plot)])
    table = validation.validation_table()
    band = [f"{low:.4g}-{high:.4g}" for low, high in zip(table["low"], table["high"], strict=True)]
    shown = table.reset_index(drop=True)[["quantity", "measured", "model", "agrees", "kind"]]
    shown.insert(1, "band", band)  # the values accepted, beside the measured one
    who = [re.split(r",| \(", source)[0] for source in table["source"]]  # the rest: --out
    _print_table(shown.assign(source=who))
    print()
    said = f"{validation.summary(table)} (each one's name, band, conditions and source: --out FILE)"
    print(textwrap.fill(said, WIDTH))
    missed = table[(table["kind"] == "calibration") & ~table["agrees"]]
    if len(missed):  # a calibration that does not hold is said, with why
        print("\ncalibration rows outside their band, and why:")
        for gap, rows in missed.groupby("gap", sort=False):  # one reason, its rows together
            said = f"{', '.join(rows.index)}: {gap or 'no reason given: a defect'}"
            print(textwrap.fill(said, WIDTH, initial_indent="  ", subsequent_indent="    "))
    if args.out:
        write_table(table.reset_index(), args.out)
    if args.plot:
        from studies.plots import plot_validation

        save_plot(plot_validation(table), args.plot)
    return 0
