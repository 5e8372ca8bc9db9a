"""The options the commands share: the parser that refuses an option given twice, the racket,
ball, speed, swing and tension options, and their values checked in the unit typed.
"""

from __future__ import annotations

import argparse
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from ball import DEFAULT_BALL
from common.checks import (
    FASTEST_HEAD,
    FASTEST_STROKE,
    M_AS_CM,
    N_AS_LB,
    SPEED_RANGE,
    in_range,
    loose_tension,
    shown,
    slip_hints,
    too_fast,
)
from common.units import SPEED_SUFFIXES, SPEED_UNITS
from racket.specs.sheet import SPEC_RANGES
from racket.swing import WRIST_BEYOND_BUTT
from studies.config import BALLS
from studies.scheduler import SCHEDULER_TIMEOUT
from studies.toml_files import unknown_preset

if TYPE_CHECKING:
    import pandas as pd


class _Once(argparse.Action):
    """Store an option, refusing it twice (the last would silently win)."""

    def __call__(self, parser, namespace, values, option_string=None):
        if getattr(namespace, f"_seen_{self.dest}", False):
            once = f"all its values after one {option_string}" if self.nargs == "+" else "it once"
            parser.error(f"{option_string} given twice; give {once}")
        setattr(namespace, f"_seen_{self.dest}", True)
        setattr(namespace, self.dest, values)


class _Named(argparse.Action):
    """Store an optional positional (``ball [PRESET_OR_TOML]``), noting whether it was typed:
    argparse hands an absent one its default, the very object (as argparse itself tells).
    """

    def __call__(self, parser, namespace, values, option_string=None):
        if values is not self.default:  # said as typed by :func:`given`
            setattr(namespace, f"_seen_{self.dest}", f"the {self.dest} {values!r}")
        setattr(namespace, self.dest, values)


def given(args, *dests: str) -> list[str]:
    """The options among ``dests`` (their ``dest``: ``"tension_lb"``) that the command line
    gave, as their flags (``"--tension-lb"``; a positional as :class:`_Named` says it).

    Parameters
    ----------
    args : argparse.Namespace
        The parsed command line.
    *dests : str
        The options' ``dest``.
    """
    seen = [(dest, getattr(args, f"_seen_{dest}", False)) for dest in dests]
    return [
        said if isinstance(said, str) else f"--{dest.replace('_', '-')}"
        for dest, said in seen
        if said
    ]


def refuse_unused(args, dests, why: str) -> None:
    """ValueError in one line for the first option among ``dests`` the command line gave
    (:func:`given`): it does not apply ``why`` (what it would take, or what to do instead),
    and would otherwise be ignored in silence.

    Parameters
    ----------
    args : argparse.Namespace
        The parsed command line.
    dests : sequence of str
        The options' ``dest`` that do not apply.
    why : str
        Where they do not apply and what to do, after "does not apply ".
    """
    for flag in given(args, *dests):
        raise ValueError(f"{flag} does not apply {why}")


class _Parser(argparse.ArgumentParser):
    """Options in full only (a recorded command means one thing); an option whose metavar
    is FILE or DIR names a file the command writes, listed in the parsed ``_writes``.
    """

    def __init__(self, *args, **kwargs):
        super().__init__(*args, allow_abbrev=False, **kwargs)

    def error(self, message):  # one line, status 2, no usage dump
        self.exit(2, f"{self.prog}: error: {message}\n")

    def add_argument(self, *args, **kwargs):
        action = super().add_argument(*args, **_once(args, kwargs))
        if action.option_strings and action.metavar in ("FILE", "DIR"):
            self.set_defaults(_writes=(*(self.get_default("_writes") or ()), action.dest))
        return action

    def add_mutually_exclusive_group(self, **kwargs):
        group = _OnceGroup(self, **kwargs)
        self._mutually_exclusive_groups.append(group)
        return group


class _OnceGroup(argparse._MutuallyExclusiveGroup):
    """A group of mutually exclusive options, each refused twice as on the parser."""

    def add_argument(self, *args, **kwargs):
        return super().add_argument(*args, **_once(args, kwargs))


def _once(args: tuple, kwargs: dict) -> dict:
    """``kwargs`` of an option ``--NAME`` with :class:`_Once` as its action unless it says
    another (``store_true``, ``append``): on the parser and in its groups alike.
    """
    if args and args[0].startswith("--") and "action" not in kwargs:
        return {**kwargs, "action": _Once}
    return kwargs


class _Replay(_Parser):
    """The parser of a command recorded in a sidecar: its errors are the sidecar's."""

    def error(self, message):
        raise ValueError(f"the sidecar's command: {message}")


_HEADS = ("swing_speed", "racket_speed")
"""The speed options that are a racket head's (checked against
:data:`common.checks.FASTEST_HEAD`); the others are a ball's (against
:data:`common.checks.FASTEST_STROKE`)."""

_UNITS = {"": "m/s", "_mph": "mph", "_kmh": "km/h"}
"""The unit of each speed option by the ending of its name: ``--NAME`` [m/s],
``--NAME-mph`` [mph], ``--NAME-kmh`` [km/h]."""


def _speed(args, name: str, allow_zero: bool = False, signed: bool = False):
    """The speed option ``--NAME`` [m/s], ``--NAME-mph`` [mph] or ``--NAME-kmh`` [km/h] in
    m/s (a list for a many-valued option), each value checked in the unit it was typed in;
    one faster than any recorded stroke asked about, in that unit (a racket head's speed, of
    :data:`_HEADS`, against :data:`common.checks.FASTEST_HEAD`).
    """
    flag, values, unit, scale = _typed(args, name)
    low, high = (v / scale for v in SPEED_RANGE)
    fastest, what = (
        (FASTEST_HEAD, "a racket head's fastest, estimated")
        if name in _HEADS
        else (FASTEST_STROKE, "the serve record")
    )
    base, checked = f"--{name.replace('_', '-')}", []
    for value in np.atleast_1d(values):
        if signed:
            checked.append(in_range(flag, value, -high, high, unit) * scale)
        elif allow_zero and value == 0.0:
            checked.append(0.0)
        else:
            checked.append(in_range(flag, value, low, high, unit) * scale)

        def instead(typed: str, v=value) -> str:  # the option a slip of unit would have meant
            return f" ({base}-{SPEED_SUFFIXES[typed]} {shown(v)})"

        too_fast(flag, value, unit, fastest, what, instead)  # allowed, but asked about
    return checked if isinstance(values, list) else checked[0]


def _typed(args, name: str) -> tuple[str, object, str, float]:
    """The speed option ``--NAME``, ``--NAME-mph`` or ``--NAME-kmh`` as the user typed it:
    the flag, the value(s), the unit and its size [m/s] (``--NAME`` when none was given).
    """
    flag = f"--{name.replace('_', '-')}"
    for ending, unit in _UNITS.items():
        values = getattr(args, f"{name}{ending}", None) if ending else None
        if values is not None:
            return f"{flag}{ending.replace('_', '-')}", values, unit, SPEED_UNITS[unit]
    return flag, getattr(args, name), "m/s", 1.0


def speed_unit(args, *names: str) -> str:
    """The unit the user typed the speed options ``names`` in ("m/s", "mph" or "km/h"), for
    the answer to be in it: the first of them given in mph or km/h, else m/s.

    Parameters
    ----------
    args : argparse.Namespace
        The parsed command line.
    *names : str
        The speed options, as their ``dest`` (``"speed"``, ``"swing_speed"``).
    """
    for name in names:
        unit = _typed(args, name)[2]
        if unit != "m/s":
            return unit
    return "m/s"


def with_columns(table, added: dict):
    """``table`` with the ``added`` columns after its own (one of the same name replaced
    where it is), as ``DataFrame.assign`` makes it.

    Parameters
    ----------
    table : DataFrame or dict
        The table, or its columns (name -> 1-D array: the sweep's, without pandas).
    added : dict
        Column name -> values.
    """
    return {**table, **added} if isinstance(table, dict) else table.assign(**added)


def in_speed_unit(table, unit: str):
    """``table`` with each speed column [m/s] (``*_m_s``) also in ``unit``, the unit the user
    typed (``*_mph`` or ``*_kmh`` beside it, unless there already); as it is for m/s.

    Parameters
    ----------
    table : DataFrame or dict
        A table whose speed columns are in m/s, or its columns (:func:`with_columns`).
    unit : str
        "m/s", "mph" or "km/h".
    """
    if unit == "m/s":
        return table
    suffix, size = SPEED_SUFFIXES[unit], SPEED_UNITS[unit]
    return with_columns(table, {
        c.replace("_m_s", f"_{suffix}"): table[c] / size for c in list(table)
        if c.endswith("_m_s") and c.replace("_m_s", f"_{suffix}") not in table
    })  # fmt: skip


def _count(flag: str, value: int, low: int, high: int) -> int:
    """A whole-number option in [low, high]."""
    return int(in_range(flag, value, low, high))


def _print_table(table: pd.DataFrame | dict, floatfmt: str = "{:.4g}") -> None:
    """Print ``table`` with human labels and units, at most 100 characters wide
    (:func:`studies.cli.show.print_table`).
    """
    from studies.cli.show import print_table

    print_table(table, floatfmt)


def _tension(value_lb: float) -> float:
    """``--tension-lb`` [lb] checked in lb (the spec sheets' range, 20-80 lb; a value in N
    refused with a hint, one below :data:`common.checks.STRUNG_AT_LB` that is one in kg asked
    about, :func:`common.checks.loose_tension`) and given in N.
    """
    from common.units import LB

    low, high, unit = SPEC_RANGES["tension_lb"]
    value = in_range("--tension-lb", value_lb, low, high, unit, slips=(N_AS_LB,))
    loose_tension("--tension-lb", value)
    return value * LB


def _swing(args):
    """The ``--swing-speed[-mph|-kmh]`` and ``--pivot-cm-from-tip`` options as a Swing, or
    None without a swing speed.
    """
    from racket import Swing

    if all(getattr(args, f"swing_speed{u}", None) is None for u in ("", "_mph", "_kmh")):
        if args.pivot_cm_from_tip is not None:
            raise ValueError("--pivot-cm-from-tip needs --swing-speed (or -mph, -kmh)")
        return None
    return Swing(_speed(args, "swing_speed"), _pivot(args))


def swing_and_speed(args) -> tuple:
    """The racket's swing (:func:`_swing`: a Swing, or None) and the ball's ``--speed`` [m/s]
    (a list for a many-valued option), checked in that order: a swung racket may meet a
    ball at rest (0).

    Parameters
    ----------
    args : argparse.Namespace
        The parsed command line.
    """
    swing = _swing(args)
    return swing, _speed(args, "speed", allow_zero=swing is not None)


def _check_swing(args, swing, racket, positions, name: str = "swing_speed") -> None:
    """``swing`` (of the speed option ``--NAME[-mph|-kmh]`` and ``--pivot-cm-from-tip``)
    checked for the impact points ``positions`` [m from the tip], the message quoting the
    options as typed (:meth:`racket.Swing.check_points`), and refused on a racket that
    ``--support`` (or the racket's own file) holds at rest; nothing without a swing.
    """
    if swing is not None:
        typed = getattr(args, "support", None)
        supports = typed or [racket.support]
        held = [s for s in (supports if isinstance(supports, list) else [supports]) if s != "free"]
        if held:
            flag, value, *_ = _typed(args, name)
            holder = f"--support {held[0]}" if typed else f"the racket's file ({held[0]})"
            raise ValueError(
                f"{flag} {shown(value)} swings a free racket, and {holder} holds it at rest "
                "(the hand or the clamp does not move in this model): drop one"
            )
        typed = args.pivot_cm_from_tip
        pivot = ("--pivot-cm-from-tip", 100 * swing.pivot(racket) if typed is None else typed,
                 "cm", 0.01)  # fmt: skip
        swing.check_points(racket, positions, head=_typed(args, name), pivot=pivot)


def _pivot(args) -> float | None:
    """``--pivot-cm-from-tip`` [cm] checked in cm (:data:`racket.swing.PIVOT_FROM_TIP_RANGE`),
    in m; None (not given): the wrist, 5 cm beyond the butt.  A pivot below 2.5 cm that is
    one in m is refused with the hint (m typed as cm?).
    """
    from racket.swing import PIVOT_FROM_TIP_RANGE

    if args.pivot_cm_from_tip is None:
        return None
    low, high = (100 * end for end in PIVOT_FROM_TIP_RANGE)
    value = in_range("--pivot-cm-from-tip", args.pivot_cm_from_tip, low, high, "cm")
    slipped = slip_hints(value, low, high, "cm", (M_AS_CM,)) if 0 < abs(value) < 2.5 else ""
    if slipped:
        raise ValueError(f"--pivot-cm-from-tip {shown(value)} cm is at the tip: {slipped}")
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
def preset_or_toml(presets, kind: str):
    """An argparse ``type``: the text given where it names one of ``presets`` or a .toml
    file (read later), else refused naming the option (argparse prefixes it).

    Parameters
    ----------
    presets : iterable of str
        The presets' names.
    kind : str
        "racket", "ball", "bat", ...
    """
    names = tuple(presets)

    def preset_or_file(text: str) -> str:
        if text in names or text.endswith(".toml"):
            return text
        raise argparse.ArgumentTypeError(unknown_preset(text, names, kind))

    preset_or_file.names = names  # (what the option takes, for a caller to pick from)
    return preset_or_file


def _ball_arg(p, flag="--ball", default=DEFAULT_BALL, what="ball", **extra):
    if flag.startswith("--"):  # (a positional's bad word may be an option's, said later)
        extra["type"] = preset_or_toml(BALLS, "ball")
    p.add_argument(
        flag,
        default=default,
        metavar="PRESET_OR_TOML",
        help=f"{what}: preset ({', '.join(BALLS)}; 'paper' is the paper's linear ball) or TOML "
        f"file with a [ball] table (default: {default})",
        **extra,
    )


def _speed_option(p, name: str, default, what: str, many: bool = False):
    """``--NAME`` in m/s, ``--NAME-mph`` in mph or ``--NAME-kmh`` in km/h, one of them."""
    group = p.add_mutually_exclusive_group()
    said = "" if default is None else f" (default {default if not many else default[0]:g})"
    for ending, unit in _UNITS.items():
        group.add_argument(
            f"--{name}{ending.replace('_', '-')}",
            action=_Once,
            type=float,
            nargs="+" if many else None,
            default=default if not ending else None,
            metavar={"m/s": "M_S", "mph": "MPH", "km/h": "KMH"}[unit],
            help=f"{what} [{unit}]" + (said if not ending else ""),
        )


def _pivot_option(p):
    p.add_argument(
        "--pivot-cm-from-tip",
        type=float,
        action=_Once,
        metavar="CM",
        help="swing pivot [cm from the tip, like every position] (default: the wrist, "
        f"{100 * WRIST_BEYOND_BUTT:g} cm beyond the butt)",
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
        help="run the impacts on N local processes, at most this machine's cores "
        "(bit-identical results)",
    )
    group.add_argument(
        "--scheduler",
        action=_Once,
        metavar="ADDRESS",
        help="run the impacts on the Dask cluster at [tcp://]HOST:PORT (needs "
        "racket-impact[scale]; bit-identical results), refused unless a Dask scheduler "
        f"answers there within {SCHEDULER_TIMEOUT:g} s",
    )


def _scale(args):
    """The ``--workers`` or ``--scheduler`` option checked (before any work: the number of
    workers cut to the cores, a Dask scheduler answering at the address), as a context that yields
    the executor (None: this process), :func:`studies.scale.executor_for`.
    """
    from studies.scale import check_workers, executor_for
    from studies.scheduler import check_answers, check_scheduler

    workers = None if args.workers is None else check_workers(args.workers, "--workers")
    if args.scheduler is not None:
        check_answers(check_scheduler(args.scheduler, "--scheduler"), "--scheduler")
    return executor_for(workers, args.scheduler, flags=("--workers", "--scheduler"))
