"""The options the commands share: the parser that refuses an option given twice, the racket,
ball, speed, swing and tension options, and their values checked in the unit typed.
"""

from __future__ import annotations

import argparse
import warnings
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from ball import DEFAULT_BALL
from common.checks import (
    FASTEST_STROKE,
    KG_AS_LB,
    M_AS_CM,
    MPH_AS_M_S,
    N_AS_LB,
    SPEED_RANGE,
    in_range,
    shown,
    slip_hints,
    suspect,
)
from common.units import MPH
from racket.specs.sheet import SPEC_RANGES
from racket.swing import WRIST_BEYOND_BUTT
from studies.config import BALLS, PAPER_BALL, RACKETS

if TYPE_CHECKING:
    import pandas as pd


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
        # allowed, but asked about (mph typed as m/s?).  FASTEST_STROKE is the serve's
        # ball-speed record; as the limit of a racket head's (or swing's) speed it is an
        # assumption, a generous bound: a racket head is slower than the ball it serves.
        if unit == "m/s":
            suspect(flag, abs(value), (0.0, FASTEST_STROKE), "m/s", (MPH_AS_M_S,),
                    f"faster than any recorded stroke (about {FASTEST_STROKE:g} m/s)",
                    f" ({flag}-mph {shown(value)})", always=True)  # fmt: skip
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
    """Print ``table`` with human labels and units, at most 100 characters wide
    (:func:`studies.cli.show.print_table`).
    """
    from studies.cli.show import print_table

    print_table(table, floatfmt)


def _tensions(args):
    """``--tension-lb`` values in N (a list), None if not given; not with the stiffness."""
    if args.tension_lb is None:
        return None
    if args.string_stiffness is not None:
        raise ValueError("give --string-stiffness or --tension-lb, not both")
    return [_tension(t) for t in args.tension_lb]


STRUNG_AT_LB = (40.0, 65.0)
"""What rackets are usually strung at [lb]: an assumption, not a measurement (the project's
measurements give none; :data:`racket.specs.strings.TENSION_RANGE_LB` accepts 20-80 lb).  A
tension below it that is one in kg is asked about."""


def _tension(value_lb: float) -> float:
    """``--tension-lb`` [lb] checked in lb (the spec sheets' range, 20-80 lb; a value in N
    refused with a hint, one below :data:`STRUNG_AT_LB` that is one in kg asked about) and
    given in N.
    """
    from common.units import LB

    low, high, unit = SPEC_RANGES["tension_lb"]
    value = in_range("--tension-lb", value_lb, low, high, unit, slips=(N_AS_LB,))
    low, high = STRUNG_AT_LB
    why = f"below what rackets are strung at ({low:g}-{high:g} lb)"
    suspect("--tension-lb", value, STRUNG_AT_LB, unit, (KG_AS_LB,), why)
    return value * LB


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
    """``--pivot-cm-from-butt`` [cm] checked in cm (:data:`racket.swing.PIVOT_RANGE`), in m;
    one within 1 cm of the butt that is a pivot in m is asked about (m typed as cm?).
    """
    from racket.swing import PIVOT_RANGE

    low, high = (100 * end for end in PIVOT_RANGE)
    value = in_range("--pivot-cm-from-butt", args.pivot_cm_from_butt, low, high, "cm")
    slipped = slip_hints(value, low, high, "cm", (M_AS_CM,)) if 0 < abs(value) < 1 else ""
    if slipped:
        warnings.warn(f"--pivot-cm-from-butt {shown(value)} cm is within 1 cm of the butt: "
                      f"{slipped}", stacklevel=2)  # fmt: skip
    return value / 100


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


def _scale_options(p):
    """Where the impacts run: ``--workers N`` (a local process pool) or ``--scheduler
    ADDRESS`` (a Dask cluster), not both; default this process (:mod:`studies.scale`).
    """
    group = p.add_mutually_exclusive_group()
    group.add_argument(
        "--workers",
        action=_Once,
        type=int,
        metavar="N",
        help="run the impacts on N local processes (bit-identical results)",
    )
    group.add_argument(
        "--scheduler",
        action=_Once,
        metavar="ADDRESS",
        help="run the impacts on the Dask cluster at [tcp://]HOST:PORT (needs "
        "racket-impact[scale]; bit-identical results)",
    )


def _scale(args):
    """The ``--workers`` or ``--scheduler`` option checked (before any work), as a context
    that yields the executor (None: this process), :func:`studies.scale.executor_for`.
    """
    from studies.scale import check_scheduler, check_workers, executor_for

    if args.workers is not None:
        check_workers(args.workers, "--workers")
    if args.scheduler is not None:
        check_scheduler(args.scheduler, "--scheduler")
    return executor_for(args.workers, args.scheduler)
