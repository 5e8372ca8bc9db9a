"""Impact-position sweeps over any grid of parameters, as tidy tables.

Each combination of the grid runs all its impact positions together (one vectorized call
of :func:`racket.impact`); the rows are gathered into one pandas DataFrame, one row per
impact, SI columns (:func:`sweep`), or into its columns, without pandas
(:func:`sweep_columns`: the command line's).
"""

from __future__ import annotations

import inspect
import itertools
import re
import warnings
from collections.abc import Mapping, Sequence
from concurrent.futures import Executor
from dataclasses import replace
from typing import TYPE_CHECKING

import numpy as np

from ball import Ball
from ball.catalog import TWU_SPEED
from common.checks import finite_array, in_range, whole
from common.checks import speed as check_speed
from common.typechecks import choice, flag, instance
from racket import SUPPORTS, Racket, Swing
from racket.solver import F1_MIN
from racket.specs.restring import with_tension
from racket.specs.sheet import SPEC_RANGES
from racket.strings.bed import BED_STIFFNESS_RANGE
from racket.strings.stringing import restrung
from racket.swing import check_swung_support
from racket.swing import equal_effort as same_effort
from studies.arguments import ball_argument, racket_argument, swing_argument
from studies.scale import impacts_of, run_calls
from studies.tables import frame, impact_columns

if TYPE_CHECKING:
    import pandas as pd

BALL_SPEED = TWU_SPEED
"""The ball speed [m/s] towards the strings of every study of a racket at rest when none is
given (``sweep``, ``compare``, ``map``, ``sweetspots``, ``feel``; not ``paper``, which uses
the paper's own speeds).  TWU's test speed (16.5 +/- 1 m/s, "Racquet Control" part 1;
:data:`ball.catalog.TWU_SPEED`), so that e_A and the sweet area can be read beside
the published maps.  An assumption for play, labelled as such: a groundstroke meets the
racket faster, 30-45 m/s relative to it (the ball's 15-25 m/s plus the head's 15-20 m/s;
:data:`studies.validation.STROKE_SPEEDS`); e falls only a little with speed over that
range (the ball's COR), and a swing (``--swing-speed``) gives the stroke's own speeds."""

TENSION_RANGE = SPEC_RANGES["tension_n"][:2]
"""String tension [N] a sweep accepts: 20-80 lb (strung rackets: 40-65 lb), the spec sheets'
range (:data:`racket.specs.sheet.SPEC_RANGES`, which :func:`with_tension` checks too)."""

STRING_STIFFNESS_RANGE = BED_STIFFNESS_RANGE
"""String-bed stiffness [N/m] a sweep accepts (a strung racket's is 2e4-5e4; paper Secs. III
and VIII): the bed's own (:data:`racket.strings.bed.BED_STIFFNESS_RANGE`)."""

F1_MAX = 2000.0
"""Highest f1 [Hz] a sweep accepts (a racket's is 100-200 Hz; Taraborrelli et al. 2019)."""

MAX_IMPACTS = 5_000_000
"""Most impacts a sweep or a comparison runs.  The README's benchmark (2-core machine) runs
1e6 impacts through :func:`sweep` in 16 s and holds 0.12-0.17 GiB of table at the peak, so
5e6 take about a minute and a half and under 1 GiB; 1e8 (say 1000 positions times 1e5
parameter values) would take half an hour and 17 GiB.  Larger studies are run in parts."""

_SECONDS_PER_IMPACT = 16e-6  # through sweep (README benchmark: 1e6 impacts in 16 s)
_GIB_PER_IMPACT = 0.17e-6  # the table's peak (README benchmark: 0.12-0.17 GiB per 1e6)


def check_impacts(count: int, what: str) -> None:
    """Raise ``ValueError`` if ``count`` impacts are more than :data:`MAX_IMPACTS`.

    Parameters
    ----------
    count : int
        The impacts asked for [-].
    what : str
        What asks for them, as the message quotes it (e.g. "positions x speed").
    """
    if count > MAX_IMPACTS:
        raise ValueError(
            f"{what} ask for {count:,} impacts, more than one run takes, {MAX_IMPACTS:,} "
            f"(about {MAX_IMPACTS * _SECONDS_PER_IMPACT:.0f} s and "
            f"{MAX_IMPACTS * _GIB_PER_IMPACT:.2g} GiB); split the study"
        )


COLUMNS = (
    "position_from_tip_cm",
    "position_from_tip_m",
    "offset_m",
    "e",
    "e_A",
    "effective_mass_kg",
    "v_cm_m_s",
    "omega_rad_s",
    "roll_rate_rad_s",
    "swing_speed_m_s",
    "ball_rebound_m_s",
    "exit_speed_mph",
    "vibration_energy_fraction",
    "contact_time_s",
    "peak_force_N",
    "e_van_zandt",
    "self_consistent",
    "recontacts",
)
"""The columns every sweep returns, in order (:func:`studies.tables.impact_table`); one
column per varying parameter follows."""

PARAMETERS = {
    "speed": "speed_m_s",
    "string_stiffness": "string_stiffness_N_m",
    "tension": "tension_N",
    "f1": "f1_Hz",
    "support": "support",
    "ball": "ball",
}
"""Sweepable parameters and their column names."""


def _variant(racket: Racket, string_stiffness=None, tension=None, f1=None, support=None):
    if tension is not None:
        racket = with_tension(racket, tension)
    beam = racket.beam if f1 is None else racket.beam.with_f1(f1)
    strings = (
        racket.strings
        if string_stiffness is None
        else restrung(racket.strings, stiffness=string_stiffness)  # a string's stretch follows
    )
    return replace(
        racket, beam=beam, strings=strings, support=racket.support if support is None else support
    )


def _as_list(name, value):
    if isinstance(value, Mapping):
        values = list(value.items())
    elif isinstance(value, (str, Ball)) or np.ndim(value) == 0:
        return [value]
    else:
        values = list(value)
    if not values:
        raise ValueError(f"{name} must not be empty")
    return values


def _ball_label(item) -> tuple[str, Ball]:
    if isinstance(item, tuple) and len(item) == 2:
        return item[0], ball_argument(item[1])
    return repr(ball_argument(item).law), item


def sweep(*args, **kwargs) -> pd.DataFrame:
    """Impacts at ``positions`` for every combination of the parameters given as lists.

    Parameters
    ----------
    racket : Racket
        The racket; the grid parameters replace its values.
    ball : Ball, sequence of Ball, or mapping label -> Ball
        The ball(s); a mapping names them in the ``ball`` column.
    positions : array_like, optional
        Impact points [m from the tip]; default 101 points across the string bed.
    speed : float or sequence
        Ball speed towards the strings [m/s] (default :data:`BALL_SPEED`).
    string_stiffness : float or sequence, optional
        String-bed stiffness [N/m], in [1e3, 1e7].
    tension : float or sequence, optional
        String tension [N], in [88.96, 355.9] (20-80 lb): the string bed's stiffness from the
        membrane model on the racket's head (:func:`racket.string_bed_stiffness`); not with
        ``string_stiffness``.
    f1 : float or sequence, optional
        First bending frequency of the frame [Hz], in [20, 2000] (EI scaled, mode shapes
        kept).
    support : str or sequence, optional
        ``"free"``, ``"clamped-head"`` or ``"hand-held"``.
    offset : float or array_like, optional
        Distance of the impact points from the long axis [m, + towards 3 o'clock],
        broadcast with ``positions`` (:func:`racket.impact`); None: on the axis, the
        bending modes only.
    swing : Swing, optional
        The racket swung about a pivot (a free racket): each impact point moves at its own
        speed, :meth:`racket.Swing.point_speeds`; ``speed`` may then be 0 (a serve: the
        ball at rest).  The ball's exit speed is ``ball_rebound_m_s`` (and
        ``exit_speed_mph``).
    progress : bool, optional
        Show a progress bar; default: when standard error is a terminal.
    executor : concurrent.futures.Executor, optional
        Run the impacts on it, in chunks of at most :data:`studies.scale.TASK_IMPACTS`
        (e.g. a ``ProcessPoolExecutor``, or a Dask cluster's ``client.get_executor()``;
        :func:`studies.scale.executor_for` makes either): each worker's kernel on one
        thread, each racket's caches computed once and sent with it; bit-identical to the
        run in this process.  Default: one grid point after the other in this process.

    Returns
    -------
    DataFrame
        One row per impact: :data:`COLUMNS`, then one column per parameter that varies.
        At most :data:`MAX_IMPACTS` rows (positions times the combinations).
    """
    try:
        sweep.__signature__.bind(*args, **kwargs)  # its own name in a misuse's message
    except TypeError as err:
        raise TypeError(f"sweep(): {err}") from None
    return frame(sweep_columns(*args, **kwargs))


def sweep_columns(
    racket: Racket,
    ball: Ball | Sequence[Ball] | Mapping[str, Ball],
    positions=None,
    speed: float | Sequence[float] = BALL_SPEED,
    *,
    string_stiffness=None,
    tension=None,
    f1=None,
    support=None,
    offset=None,
    swing: Swing | None = None,
    progress: bool | None = None,
    executor: Executor | None = None,
) -> dict:
    """The table of :func:`sweep` as its columns, without pandas (the command line's).

    Parameters
    ----------
    racket, ball, positions, speed
        As for :func:`sweep`.
    string_stiffness, tension, f1, support, offset, swing, progress, executor
        As for :func:`sweep`.

    Returns
    -------
    dict
        Column name -> 1-D array, in :func:`sweep`'s order; a parameter that varies in
        words (``support``, ``ball``) is an array of str (dtype object), which
        :func:`studies.tables.frame` makes the DataFrame's categorical column.
    """
    racket, swing = racket_argument(racket), swing_argument(swing)
    if positions is None:
        positions = np.linspace(*racket.strings.extent, 101)
    elif finite_array("positions", positions, "m from the tip").size == 0:
        raise ValueError("positions must give at least one impact point, got none")
    grid = {
        "speed": _as_list("speed", speed),
        "string_stiffness": _as_list("string_stiffness", string_stiffness),
        "tension": _as_list("tension", tension),
        "f1": _as_list("f1", f1),
        "support": _as_list("support", support),
        "ball": [_ball_label(b) for b in _as_list("ball", ball)],
    }
    varying = [name for name, values in grid.items() if len(values) > 1]
    # Every value checked before any impact runs.
    racket.check_points(positions, offset)
    points = np.broadcast(np.asarray(positions), np.asarray(0.0 if offset is None else offset))
    sizes = {"positions": points.size}
    sizes.update((name, len(values)) for name, values in grid.items() if len(values) > 1)
    check_impacts(int(np.prod(list(sizes.values()))), " x ".join(sizes))
    for sp in grid["speed"]:
        check_speed("speed", sp, allow_zero=swing is not None)
    if swing is not None:
        swing.check_points(racket, positions)
    for sup in grid["support"]:
        if sup is not None:
            choice("support", sup, SUPPORTS)
        if swing is not None:
            check_swung_support(racket.support if sup is None else sup)
    for freq in grid["f1"]:
        if freq is not None:
            in_range("f1", freq, F1_MIN, F1_MAX, "Hz")
    if string_stiffness is not None and tension is not None:
        raise ValueError("give string_stiffness or tension, not both")
    for t in grid["tension"]:
        if t is not None:
            in_range("tension", t, *TENSION_RANGE, "N")
    for k_s in grid["string_stiffness"]:
        if k_s is not None:
            in_range("string_stiffness", k_s, *STRING_STIFFNESS_RANGE, "N/m")
    variants = {}  # each racket built once (its modes and flexibility computed once)
    combos = []
    for sp, ks, tn, freq, sup, (label, b) in itertools.product(*grid.values()):
        if (ks, tn, freq, sup) not in variants:
            variants[ks, tn, freq, sup] = _variant(racket, ks, tn, freq, sup)
        combos.append((sp, variants[ks, tn, freq, sup], label, b, tn))
    calls = [impacts_of(v, b, positions, sp, offset, swing) for sp, v, _, b, _ in combos]
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        parts = run_calls(calls, impact_columns, executor, progress, "sweep")
    _first_of_each_kind(caught)
    columns = {name: [part[name] for part in parts] for name in COLUMNS}
    del parts
    labels = {name: [] for name in varying}
    for sp, variant, label, _, tn in combos:
        values = {
            "speed": sp,
            "string_stiffness": variant.strings.stiffness,
            "tension": tn,
            "f1": variant.beam.modes.frequencies[0],
            "support": variant.support,
            "ball": label,
        }
        for name in varying:
            labels[name].append(values[name])
    # One column at a time, each joined and its parts let go: the peak memory is the table
    # and one column more (a study of 1e6 impacts stays near 150 MB).
    count = np.array([part.size for part in columns[COLUMNS[0]]])
    table = {}
    for name in COLUMNS:
        table[name] = np.concatenate(columns.pop(name))
    for name in varying:
        values = labels[name]
        kind = object if isinstance(values[0], str) else float  # words: an array of str
        table[PARAMETERS[name]] = np.repeat(np.asarray(values, dtype=kind), count)
    return table


sweep.__signature__ = inspect.signature(sweep_columns).replace(return_annotation="pd.DataFrame")


def _first_of_each_kind(caught) -> None:
    """Emit again the first of the warnings ``caught`` of each kind (the same text but for
    its numbers): a grid would repeat a warning once per grid point.
    """
    seen = set()
    for w in caught:
        kind = (w.category, re.sub(r"[-+0-9.e]+", "#", str(w.message)))
        if kind not in seen:
            seen.add(kind)
            warnings.warn_explicit(w.message, w.category, w.filename, w.lineno)


def compare(
    rackets: Mapping[str, Racket],
    ball: Ball,
    speed: float = BALL_SPEED,
    points: int = 101,
    swing: Swing | None = None,
    tension: float | None = None,
    equal_effort: bool = False,
    *,
    progress: bool | None = False,
    executor: Executor | None = None,
) -> pd.DataFrame:
    """Impacts across the string bed of each racket: one sweep table, a ``racket`` column.

    Parameters
    ----------
    rackets : mapping label -> Racket
    ball : Ball
    speed : float
        Ball speed towards the strings [m/s] (0 allowed with a swing; default
        :data:`BALL_SPEED`).
    points : int
        Impact points across each racket's string bed, in [2, 100000]; times the rackets,
        at most :data:`MAX_IMPACTS`.
    swing : Swing, optional
        The same swing for every racket (as in :func:`sweep`).
    tension : float, optional
        Every racket strung at this tension [N], in [88.96, 355.9] (20-80 lb, as in :func:`sweep`).
    equal_effort : bool
        With a swing: ``swing`` is the first racket's, and each other racket is swung at the
        same effort, its head speed scaled by its swingweight
        (:func:`racket.swing.equal_effort`, Cross and Bower 2006).  The table gets a
        ``head_speed_m_s`` column with a swing.
    progress : bool, optional
        Show a progress bar (default False; None: when standard error is a terminal).
    executor : concurrent.futures.Executor, optional
        Run the impacts on it, in chunks, as :func:`sweep` does; bit-identical to the run in
        this process (the default).
    """
    import pandas as pd

    instance("rackets", rackets, Mapping, "a dict of label -> racket.Racket")
    if not rackets:
        raise ValueError("rackets must name one racket at least, got none")
    for label, racket in rackets.items():
        racket_argument(racket, f"rackets[{label!r}]")
    ball, swing = ball_argument(ball), swing_argument(swing)
    if flag("equal_effort", equal_effort) and swing is None:
        raise ValueError("equal_effort needs a swing (the first racket's)")
    if tension is not None:
        tension = in_range("tension", tension, *TENSION_RANGE, "N")
        rackets = {label: with_tension(r, tension) for label, r in rackets.items()}
    points = whole("points", points, 2, 100_000)
    check_impacts(points * len(rackets), "points x rackets")
    check_speed("speed", speed, allow_zero=swing is not None)
    reference = next(iter(rackets.values())).beam.swingweight
    swings, calls = [], []
    for racket in rackets.values():
        x = np.linspace(*racket.strings.extent, int(points))
        own = swing
        if equal_effort:
            own = same_effort(swing, reference, racket.beam.swingweight)
        swings.append(own)
        calls.append(impacts_of(racket, ball, x, speed, swing=own))
    parts = run_calls(calls, impact_columns, executor, progress, "compare")
    frames = []
    for label, own, part in zip(rackets, swings, parts, strict=True):
        frame = pd.DataFrame(part)
        frame.insert(0, "racket", label)
        if own is not None:
            frame["head_speed_m_s"] = own.head_speed
        frames.append(frame)
    return pd.concat(frames, ignore_index=True)
