"""``racket-impact bat sweep|bbcor|feel`` (issue 37): the exit speed along a bat's barrel for a
swing and a pitch (:func:`studies.bat.sweep.bat_sweep`), the certification numbers
(:func:`studies.bat.certification.bbcor_test`) and the handle's motion after an impact
(:func:`studies.bat.feel.bat_feel`); positions in cm from the knob, speeds answered in the
unit typed.  One parser for the three: an option that does not apply to the question asked
is refused in one line.
"""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

from ball import DEFAULT_BASEBALL
from bat import BATS, DEFAULT_BAT
from bat.bat import BAT_SUPPORTS
from bat.pivot import CLAMP_OFFSET, PIVOT_FROM_KNOB
from common.checks import (
    S_AS_MS,
    in_range,
)
from common.units import MPH, SPEED_SUFFIXES, SPEED_UNITS
from studies.bat.certification import BBCOR_TEST_SPEED, BBCOR_UNCERTAINTY
from studies.bat.feel import FEEL_DURATION, FEEL_FROM_KNOB, HANDLE_POINTS, LEFT_OUT
from studies.bat.sweep import (
    ANGULAR_VELOCITY,
    CM_SPEED,
    PITCH_SPEED,
    SWEEP_FROM_KNOB,
    SWEEP_STEP,
    SWEET_ZONE_FRACTION,
)
from studies.cli.bat_inputs import _beyond, _clamps, _from_knob, _pitch, _pivot, _swing
from studies.cli.files import add_outputs, check_table_and_plot, say_conditions, write_outputs
from studies.cli.options import (
    _ball_arg,
    _count,
    _print_table,
    _speed_option,
    preset_or_toml,
    speed_unit,
)
from studies.config import load_ball

ACTIONS = ("sweep", "bbcor", "feel")
"""The questions ``bat`` answers."""

_ONLY = {
    "sweep": ("at", "handle", "duration_ms"),
    "bbcor": ("support", "omega", "cm_speed", "cm_speed_mph", "cm_speed_kmh", "from_", "to",
              "points", "at", "handle", "duration_ms"),
    "feel": ("from_", "to", "points"),
}  # fmt: skip
"""The options (their ``dest``) each question refuses: they belong to the others."""


def add_bat(sub) -> None:
    """The ``bat`` subcommand, on the subparsers ``sub``."""
    p = sub.add_parser("bat", help="baseball bats: exit speed along the barrel, BBCOR and the "
                       "certification numbers, the handle's vibration")  # fmt: skip
    p.add_argument("action", nargs="?", choices=ACTIONS, default="sweep",
                   help="sweep: exit speed along the barrel, its peak and sweet zone (the "
                   "default); bbcor: BBCOR, collision efficiency, BESR and BPF at the location "
                   "of maximum BBCOR, the bat pivoted as in the test; feel: the handle's motion "
                   "after one impact")  # fmt: skip
    p.add_argument("--bat", nargs="+", default=[DEFAULT_BAT], metavar="NAME_OR_TOML",
                   type=preset_or_toml(BATS, "bat"),
                   help=f"bat(s): preset (r161: Nathan's wooden R161, alloy: a hollow alloy "
                   f"what-if) or TOML file with a [bat] table (default {DEFAULT_BAT}); several "
                   "side by side (sweep, bbcor), e.g. --bat r161 alloy")  # fmt: skip
    _ball_arg(p, default=DEFAULT_BASEBALL)
    p.add_argument("--support", choices=BAT_SUPPORTS,
                   help="how the bat is held (default: the bat's, free for a preset: Nathan's "
                   "bat, whose grip does not matter during the contact)")  # fmt: skip
    _speed_option(p, "pitch", None, f"ball speed towards the bat (default {PITCH_SPEED:g} m/s, "
                  f"Nathan's; bbcor: the test's {BBCOR_TEST_SPEED / MPH:g} mph, an "
                  "assumption)")  # fmt: skip
    _speed_option(p, "cm-speed", None, f"speed of the bat's centre of mass towards the ball "
                  f"(default {CM_SPEED:g} m/s, Nathan's)")  # fmt: skip
    p.add_argument("--omega", type=float, metavar="RAD_S",
                   help=f"the bat's angular velocity [rad/s] (default {ANGULAR_VELOCITY:g}, "
                   "Nathan's); 0: the bat at rest")  # fmt: skip
    p.add_argument("--pivot-from-knob", type=float, metavar="CM",
                   help="the point the bat turns about [cm from the knob], instead of "
                   f"--cm-speed; a pivoted bat's pivot (default the rig's "
                   f"{100 * PIVOT_FROM_KNOB:g}, 6 in)")  # fmt: skip
    p.add_argument("--clamps", type=float, metavar="CM",
                   help=f"a pivoted bat's clamps either side of its pivot [cm] (default "
                   f"{100 * CLAMP_OFFSET:g}, 1 in; 0: a single pivot point)")  # fmt: skip
    p.add_argument("--from", dest="from_", type=float, metavar="CM",
                   help=f"sweep: first impact point [cm from the knob] (default "
                   f"{100 * SWEEP_FROM_KNOB:g})")  # fmt: skip
    p.add_argument("--to", type=float, metavar="CM", help="sweep: last impact point [cm from "
                   "the knob] (default the barrel's end)")  # fmt: skip
    p.add_argument("--points", type=int, metavar="N",
                   help="sweep: impact points (default one every cm)")  # fmt: skip
    p.add_argument("--at", type=float, metavar="CM",
                   help=f"feel: the impact point [cm from the knob] (default "
                   f"{100 * FEEL_FROM_KNOB:g}, Nathan's)")  # fmt: skip
    p.add_argument("--handle", type=float, nargs="+", metavar="CM",
                   help="feel: where the handle is read [cm from the knob] (default "
                   f"{' '.join(f'{100 * z:g}' for z in HANDLE_POINTS)}, Nathan's)")  # fmt: skip
    p.add_argument("--duration-ms", type=float, metavar="MS",
                   help=f"feel: how long to follow the bat [ms] (default "
                   f"{1e3 * FEEL_DURATION:g})")  # fmt: skip
    add_outputs(p, plot="plot")
    p.set_defaults(func=cmd_bat)


def cmd_bat(args) -> int:
    """``racket-impact bat``."""
    check_table_and_plot(args)
    for dest in _ONLY[args.action]:  # (``given`` would say --from as "--from-")
        if getattr(args, f"_seen_{dest}", False):
            flag = "--" + dest.rstrip("_").replace("_", "-")
            raise ValueError(f"{flag} does not apply to bat {args.action}")
    if len(args.bat) > 1 and args.action == "feel":
        raise ValueError("bat feel follows one bat: give one --bat")
    for name in args.bat:
        if args.bat.count(name) > 1:
            raise ValueError(f"--bat {name!r} is given twice; give it once")
    return {"sweep": _sweep, "bbcor": _bbcor, "feel": _feel}[args.action](args)


def _bats(args, support: str | None = None) -> list:
    """(label, Bat) of each ``--bat``, held by ``support`` or ``--support``, a pivoted one
    with ``--pivot-from-knob`` and ``--clamps``.
    """
    from studies.bat.config import load_bat

    support = support or args.support
    bats = []
    for spec in args.bat:
        bat = load_bat(spec, support)
        if bat.support == "pivoted":
            pivot = _pivot(args)
            clamps = _clamps(args)
            bat = replace(bat, **({} if pivot is None else {"pivot_from_knob": pivot}),
                          **({} if clamps is None else {"clamp_offset": clamps}))  # fmt: skip
        elif args.clamps is not None:
            raise ValueError(f"--clamps does not apply to a {bat.support} bat: give --support "
                             "pivoted")  # fmt: skip
        label = Path(spec).stem if spec.endswith(".toml") else spec
        bats.append((label, bat))
    return bats


def _say(line: str) -> None:
    """Print ``line`` wrapped at the printed tables' width (a leading blank line kept)."""
    import textwrap

    from studies.cli.show import WIDTH

    lead = "\n" if line.startswith("\n") else ""
    print(lead + textwrap.fill(line.strip("\n"), WIDTH, subsequent_indent="  "))


TRAMPOLINE = ("the trampoline effect of its thin wall, what makes a real hollow bat livelier "
              "than wood, is left out")  # fmt: skip
"""What a beam leaves out of a hollow bat's exit speed and BBCOR (``docs/guide/bats.md``;
:func:`bat.presets.alloy`: a beam model has no hoop modes)."""


def _hollow(args, bats) -> list:
    """The labels of the hollow bats among ``bats``, (label, Bat) of each ``--bat`` in order
    (:func:`studies.bat.config.is_hollow`).
    """
    from studies.bat.config import is_hollow

    return [label for spec, (label, _) in zip(args.bat, bats, strict=True) if is_hollow(spec)]


def _hollow_conditions(labels, what: str) -> str:
    """The conditions' words for the hollow bats ``labels``: ``what`` a beam leaves out."""
    return "".join(f"; {label}: hollow, without {what} (a beam)" for label in labels)


def _say_hollow(labels, said: str) -> None:
    """One line per hollow bat of ``labels``: what a beam leaves out of it and what that does
    to the answer printed above (``said``).
    """
    for label in labels:
        _say(f"\n{label}: hollow, but a beam has no wall: {said}")


def _sweep(args) -> int:
    import numpy as np
    import pandas as pd

    from studies.bat.sweep import bat_sweep

    unit = speed_unit(args, "pitch", "cm_speed")
    pitch = _pitch(args, PITCH_SPEED)
    bats, ball = _bats(args), load_ball(args.ball)
    plans = []
    for label, bat in bats:
        length = bat.beam.length
        start = SWEEP_FROM_KNOB if args.from_ is None else _from_knob("--from", args.from_,
                                                                       length)  # fmt: skip
        end = length if args.to is None else _from_knob("--to", args.to, length)
        if end <= start:
            raise ValueError(f"--to ({100 * end:g} cm) must lie beyond --from ({100 * start:g} "
                             "cm from the knob)")  # fmt: skip
        count = round((end - start) / SWEEP_STEP) + 1
        count = count if args.points is None else _count("--points", args.points, 3, 10_000)
        z = np.linspace(start, end, max(count, 3))
        swing = _swing(args, bat)
        for flag, where in (("--from", z[0]), ("--to", z[-1])):
            _beyond(flag, where, bat, swing)
        plans.append((label, bat, swing, z))
    sweeps = [bat_sweep(bat, ball, pitch, swing, z, unit, label, args.ball)
              for label, bat, swing, z in plans]  # fmt: skip
    hollow = _hollow(args, [(label, bat) for label, bat, _, _ in plans])
    joined = "; ".join(s.conditions for s in sweeps)
    conditions = say_conditions(joined + _hollow_conditions(hollow, "its wall's trampoline effect"))
    suffix = SPEED_SUFFIXES[unit]
    view = {"bat": "bat", "position_from_knob_cm": "from the knob [cm]",
            "position_from_tip_cm": "from the tip [cm]", f"bat_speed_{suffix}":
            f"bat speed [{unit}]", f"exit_speed_{suffix}": f"exit speed [{unit}]", "e": "e [-]",
            "e_A": "e_A [-]", "contact_time_ms": "contact [ms]",
            "vibration_share": "vibration share [-]"}  # fmt: skip
    table = pd.concat([s.table for s in sweeps], ignore_index=True)
    shown_view = table if len(bats) > 1 else table.drop(columns="bat")
    _print_table(shown_view[[c for c in view if c in shown_view]].rename(columns=view))
    for sweep in sweeps:
        low, high = sweep.sweet_zone
        _say(f"\n{sweep.table['bat'].iloc[0]}: peak exit speed "
              f"{sweep.peak_exit_speed / SPEED_UNITS[unit]:.4g} {unit} at "
              f"{100 * sweep.peak_from_knob:.1f} cm from the knob; sweet zone (within "
              f"{100 * SWEET_ZONE_FRACTION:g} % of it) {100 * low:.1f}-{100 * high:.1f} cm from "
              "the knob")  # fmt: skip
    _say_hollow(hollow, f"{TRAMPOLINE}; its exit speeds here are too low: a real hollow bat "
                "of this outline and mass would send the ball off faster")  # fmt: skip

    def draw():
        from studies.plots.bat import plot_exit_speed

        return plot_exit_speed(sweeps, unit=unit, conditions=conditions)

    return write_outputs(args, table, draw)


def _bbcor(args) -> int:
    import pandas as pd

    from studies.bat.certification import bbcor_test

    unit = speed_unit(args, "pitch")
    speed = _pitch(args, BBCOR_TEST_SPEED, fastest=False)
    bats, ball = _bats(args, "pivoted"), load_ball(args.ball)
    tests = [bbcor_test(bat, ball, speed, unit, label, args.ball) for label, bat in bats]
    hollow = _hollow(args, bats)
    joined = "; ".join(t.conditions for t in tests)
    conditions = say_conditions(joined + _hollow_conditions(hollow, "its wall's trampoline effect"))
    table = pd.concat([t.table for t in tests], ignore_index=True)
    view = {"bat": "bat", "method": "set-up", "position_from_knob_cm": "from the knob [cm]",
            "bbcor": "BBCOR [-]", "ball_e_A": "ball v_out/v_in [-]",
            "mass_ratio": "mass ratio [-]", "collision_efficiency": "collision efficiency [-]",
            "besr": "BESR [-]", "bpf": "BPF [-]", "verdict": "verdict"}  # fmt: skip
    shown_view = table if len(bats) > 1 else table.drop(columns="bat")
    _print_table(shown_view[[c for c in view if c in shown_view]].rename(columns=view))
    for test in tests:
        name, limit = test.along["bat"].iloc[0], test.table["limit"].iloc[0]
        said = f" {test.verdict} the limit {limit:.3f}"
        if test.verdict == "cannot call":
            margin = test.bbcor - limit
            said = (f", {abs(margin):.4f} {'above' if margin > 0 else 'below'} the limit "
                    f"{limit:.3f}: within the model's uncertainty of the limit (+/- "
                    f"{BBCOR_UNCERTAINTY:.2f}, the ball's COR at the test's speed): cannot "
                    "call")  # fmt: skip
        _say(f"\n{name}: BBCOR {test.bbcor:.4f} at {100 * test.from_knob:.1f} cm from the "
             f"knob{said} (ball's own COR {test.ball_cor:.4f})")  # fmt: skip
    _say_hollow(hollow, f"{TRAMPOLINE}; its BBCOR here is too low: a real hollow bat of this "
                "outline and mass would score higher")  # fmt: skip

    def draw():
        from studies.plots.bat import plot_bbcor

        return plot_bbcor(tests, conditions=conditions)

    return write_outputs(args, table, draw)


def _feel(args) -> int:
    import numpy as np

    from common.units import GRAVITY
    from studies.bat.feel import DURATION_RANGE, bat_feel

    unit = speed_unit(args, "pitch", "cm_speed")
    speed = _pitch(args, PITCH_SPEED)
    (label, bat), ball = _bats(args)[0], load_ball(args.ball)
    length = bat.beam.length
    swing = _swing(args, bat)
    at = FEEL_FROM_KNOB if args.at is None else _from_knob("--at", args.at, length)
    _beyond("--at", at, bat, swing)
    handle = HANDLE_POINTS if args.handle is None else [
        _from_knob("--handle", value, length) for value in args.handle]  # fmt: skip
    duration = FEEL_DURATION
    if args.duration_ms is not None:
        duration = in_range("--duration-ms", args.duration_ms, *(1e3 * np.array(DURATION_RANGE)),
                            "ms", slips=(S_AS_MS,)) / 1e3  # fmt: skip
    try:
        feel = bat_feel(bat, ball, at, speed, swing, handle, duration, unit, label, args.ball)
    except ValueError as err:  # (the contact's length is known once it has run)
        if args.duration_ms is None or not str(err).startswith("duration must"):
            raise
        raise ValueError(f"--duration-ms {args.duration_ms:g}: {err}") from None
    hollow = _hollow(args, [(label, bat)])
    conditions = say_conditions(feel.conditions + _hollow_conditions(hollow, "its wall's modes"))
    _say(f"impact {100 * feel.from_knob:.1f} cm from the knob: exit speed "
          f"{feel.exit_speed / SPEED_UNITS[unit]:.4g} {unit}, contact "
          f"{1e3 * feel.contact_time:.3g} ms, vibration energy "
          f"{feel.vibration_energy:.3g} J when the ball left")  # fmt: skip
    import pandas as pd

    rows = pd.DataFrame({
        "handle point [cm from the knob]": 100 * feel.points_from_knob,
        "largest displacement [mm]": 1e3 * np.abs(feel.displacement).max(axis=1),
        "of it vibration [mm]": 1e3 * np.abs(feel.vibration_displacement).max(axis=1),
        "largest velocity [m/s]": np.abs(feel.velocity).max(axis=1),
        "vibration acceleration [g]": np.abs(feel.vibration_acceleration).max(axis=1) / GRAVITY,
    })  # fmt: skip
    print()
    _print_table(rows)
    if feel.left_out:
        undamped, handless = (part in feel.left_out for part in LEFT_OUT)
        why = {(True, True): "the ringing never dies away here, where a real bat's wood (Van "
               "Zandt's Q of about 10) and hands damp it; these are a bare bat's motions, not "
               "what the hands feel", (True, False): "only the hands damp the ringing here, "
               "not the wood (Van Zandt's Q of about 10)", (False, True): "no hands damp or "
               "weigh down the handle here; these are a bare bat's motions, not what the "
               "hands feel"}[undamped, handless]  # fmt: skip
        _say(f"\nLeft out: {' and '.join(feel.left_out)}: {why}")
    _say_hollow(hollow, "its wall's own modes, which ring in a real hollow bat, are left out")
    print(f"\nenergy in each bending mode after {1e3 * feel.t[-1]:.3g} ms (free-free modes):")
    modes = feel.modes[["mode", "frequency_Hz", "nodes_from_knob_cm", "energy_J", "share"]]
    _print_table(modes.rename(columns={"frequency_Hz": "frequency [Hz]", "nodes_from_knob_cm":
                                       "nodes [cm from the knob]", "energy_J": "energy [J]",
                                       "share": "share [-]", "mode": "mode"}).head(8))  # fmt: skip

    def draw():
        from studies.plots.bat import plot_handle

        return plot_handle(feel, conditions=conditions)

    return write_outputs(args, feel.table, draw)
