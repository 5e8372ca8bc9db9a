"""``racket-impact collide``, ``drop`` and ``ball``: balls on balls, walls, floors and
strings.
"""

from __future__ import annotations

import textwrap

import numpy as np

from ball import BALL_PRESETS, BASEBALL_PRESETS, WALL, collide
from ball.catalog import CALIBRATION_SPEED, ITF_DROP
from ball.collision import largest_closing_speed, too_fast_to_store
from common.checks import CM_AS_M, SPEED_RANGE, in_range, shown
from common.units import SPEED_SUFFIXES, SPEED_UNITS
from studies.cli.files import add_outputs, check_outputs, save_plot, say_conditions, write_table
from studies.cli.options import (
    _ball_arg,
    _Named,
    _print_table,
    _speed,
    _speed_option,
    _typed,
    refuse_unused,
    speed_unit,
)
from studies.cli.racket_options import STRING_OPTIONS, add_racket_options, racket_from
from studies.cli.show import WIDTH
from studies.conditions import racket_details, speed_text
from studies.config import load_ball
from studies.tables import history_table


def add_collide(sub) -> None:
    """The ``collide`` subcommand, on the subparsers ``sub``."""
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


def cmd_collide(args) -> int:
    """``racket-impact collide``."""
    import pandas as pd

    check_outputs(
        tables=[("--out", args.out), ("--history", args.history)], plots=[("--plot", args.plot)]
    )
    if args.b == "wall":
        refuse_unused(args, ("vb", "vb_mph", "vb_kmh"), "to --b wall (it cannot move)")
    v_a, v_b = _speed(args, "va", signed=True), _speed(args, "vb", signed=True)
    unit = speed_unit(args, "va", "vb")  # as typed: m/s, mph or km/h
    if v_a - v_b < SPEED_RANGE[0]:
        typed = [f"{flag} {shown(v)} {u}" for flag, v, u, _ in
                 (_typed(args, "va"), _typed(args, "vb"))]  # fmt: skip
        raise ValueError(
            f"--va must exceed --vb by at least {SPEED_RANGE[0] / SPEED_UNITS[unit]:.4g} {unit} "
            f"(the balls must approach), got {typed[0]} and {typed[1]}"
        )
    a = load_ball(args.a)
    b = WALL if args.b == "wall" else load_ball(args.b)
    fastest = largest_closing_speed(a, b)
    if v_a - v_b > fastest:  # said in the flags and units typed, not as collide's v_a
        (flag_a, typed_a, unit_a, size), (flag_b, typed_b, unit_b, _) = (
            _typed(args, "va"), _typed(args, "vb")
        )  # fmt: skip
        name, typed = flag_a, typed_a
        if v_b != 0.0:
            name = f"{flag_a} - {flag_b}"
            typed = f"{shown(typed_a)} {unit_a} - {shown(typed_b)} {unit_b}"
        raise too_fast_to_store(name, typed, fastest, unit_a, size)
    r = collide(a, b, v_a, v_b)
    rows = {
        "v_a_after_m_s": r.v_a_after,
        "v_b_after_m_s": r.v_b_after,
        "e": r.e,
        "contact_time_s": r.contact_time,
        "peak_force_N": r.peak_force,
        "energy_initial_J": r.energy_initial,
        "energy_final_J": r.energy_final,
        "energy_lost_J": energy_lost(r),
    }
    if r.x_o is not None:
        rows["x_o_m"] = r.x_o
    from studies.cli.show import label

    names = {"a": args.a, "b": args.b} if args.a != args.b else {"a": "ball a", "b": "ball b"}
    size = SPEED_UNITS[unit]
    target = "a rigid wall" if args.b == "wall" else f"ball {args.b} at {speed_text(v_b, unit)}"
    conditions = say_conditions(f"ball {args.a} at {speed_text(v_a, unit)} head on into {target}")
    said = {
        "v_a_after_m_s": f"{names['a']}'s velocity after [{unit}]",
        "v_b_after_m_s": f"{names['b']}'s velocity after [{unit}]",
        "x_o_m": "Xo of the sine law [m]",
    }
    for key, value in rows.items():
        value = value / size if key in ("v_a_after_m_s", "v_b_after_m_s") else value
        print(f"{said.get(key, label(key)):<34} {value:.6g}")
    if args.out:
        write_table(pd.DataFrame([rows]), args.out)
    if args.history:
        write_table(history_table(r.history), args.history)
    if args.plot:
        from studies.plots import plot_collision

        axes = plot_collision(r, names=(names["a"], names["b"]), unit=unit, conditions=conditions)
        save_plot(axes, args.plot)
    return 0


ROUND_OFF = 1e-9
"""How far below zero a collision's energy lost may lie [-, of the energy before] and be
round-off: the contact's integration keeps the energy to about 1e-11 of it (relative
tolerance 1e-12 a step, :mod:`ball.monotone`); **an assumption**, a hundredfold margin."""


def energy_lost(r) -> float:
    """The kinetic energy a collision ``r`` lost [J]: a value within :data:`ROUND_OFF` of zero
    given as 0 (an elastic collision loses nothing: -7e-13 J is round-off); energy gained
    beyond it is a fault of the solver (RuntimeError), never printed as a loss.

    Parameters
    ----------
    r : ball.Collision
        The collision.
    """
    lost, scale = r.energy_lost, ROUND_OFF * r.energy_initial
    if lost < -scale:
        raise RuntimeError(
            f"the collision gained {-lost:.3g} J of {r.energy_initial:.4g} J: beyond round-off"
        )
    return 0.0 if abs(lost) <= scale else lost


def add_drop(sub) -> None:
    """The ``drop`` subcommand, on the subparsers ``sub``."""
    p = sub.add_parser("drop", help="a ball dropped on the floor, on strings or on a racket")
    _ball_arg(p, "ball", nargs="?", action=_Named)
    p.add_argument(
        "--height-m",
        type=float,
        default=ITF_DROP,
        metavar="M",
        help=f"drop height [m] (default {ITF_DROP:g}, the ITF's rebound test)",
    )
    p.add_argument("--onto", choices=["floor", "strings", "racket"], default="floor",
                   help="the floor (default), the strings of --racket with its head clamped, "
                   "or --racket at its string centre, free or as --support holds it")  # fmt: skip
    add_racket_options(p)  # --support: --onto racket only (strings: a clamped head)
    p.add_argument("--out", metavar="FILE", help="force and compression against time "
                   "(.csv, .json or .parquet)")  # fmt: skip
    p.add_argument("--plot", metavar="FILE", help="force and compression (.png, .svg, .pdf)")
    p.set_defaults(func=cmd_drop)


def cmd_drop(args) -> int:
    """``racket-impact drop``."""
    import pandas as pd

    from studies.drop import HEIGHT_RANGE, drop

    check_outputs(tables=[("--out", args.out)], plots=[("--plot", args.plot)])
    if args.onto == "floor":
        refuse_unused(args, ("racket", *STRING_OPTIONS, "lead", "support", "grip"),
                      "to a drop onto the floor: add --onto strings or --onto racket")  # fmt: skip
    elif args.onto == "strings":  # the head clamped: the frame does not move
        refuse_unused(args, ("lead", "support", "grip"), "to the strings of a clamped head (the "
                      "frame does not move): --onto racket drops on the racket, free or "
                      "--support hand-held")  # fmt: skip
    height = in_range("--height-m", args.height_m, *HEIGHT_RANGE, "m", slips=(CM_AS_M,))
    ball = load_ball(args.ball)
    onto, where = None, "the floor"
    if args.onto != "floor":
        from dataclasses import replace

        if args.onto == "racket" and args.support == "clamped-head":
            raise ValueError(
                "--support clamped-head with --onto racket: --onto strings drops on the "
                "strings of a clamped head"
            )
        racket = racket_from(args)
        support = "clamped-head" if args.onto == "strings" else racket.support  # the file's too
        onto = replace(racket, support=support)
        details = racket_details(onto)
        held = {"free": "lying free", "hand-held": f"held ({details['grip']})"}
        where = (
            f"the strings of {args.racket}, its head clamped"
            if support == "clamped-head"
            else f"the string centre of {args.racket}, {held[support]}"
        ) + f" ({details['strings']})"
    result = drop(ball, height, onto)
    conditions = say_conditions(f"ball {args.ball} dropped from {result.height:g} m onto {where}")
    print(f"it arrives at {result.speed:.3g} m/s")
    print(f"bounces back at {result.rebound_speed:.3g} m/s, up to {result.bounce_height:.3g} m "
          f"({100 * result.bounce_height:.1f} cm)")  # fmt: skip
    ratio = result.rebound_ratio  # rebound / arrival speed
    if onto is None:
        print(f"e {ratio:.4f} (bounce/drop height = e\u00b2 = {ratio**2:.3f})")
    else:
        print(f"e_A {ratio:.4f} (the apparent COR: rebound / arrival speed)")
    print(f"contact {1e3 * result.contact_time:.3g} ms, peak force {result.peak_force:.4g} N, "
          f"largest compression {1e3 * float(np.max(result.compression)):.3g} mm")  # fmt: skip
    if args.out:
        table = pd.DataFrame(
            {"t_s": result.t, "force_N": result.force, "compression_m": result.compression}
        )
        write_table(table, args.out)
    if args.plot:
        from studies.plots import plot_drop

        save_plot(plot_drop(result, conditions=conditions), args.plot)
    return 0


def add_ball(sub) -> None:
    """The ``ball`` subcommand, on the subparsers ``sub``."""
    p = sub.add_parser("ball", help="a ball's bounce on a rigid surface against impact speed")
    _ball_arg(p, "ball", nargs="?", action=_Named)
    p.add_argument(
        "--list", action="store_true", help="the real-ball presets, their numbers and sources"
    )
    from studies.bounce import DEFAULT_SPEEDS

    _speed_option(p, "speeds", [round(v, 2) for v in DEFAULT_SPEEDS], "impact speeds", True)
    add_outputs(p)
    p.add_argument(
        "--plot",
        metavar="FILE",
        help="COR, contact time, peak force, compression (.png, .svg, .pdf)",
    )
    p.set_defaults(func=cmd_ball)


def cmd_ball(args) -> int:
    """``racket-impact ball``."""
    from studies.bounce import preset_table, rigid_bounce_table, static_test

    check_outputs(tables=[("--out", args.out)], plots=[("--plot", args.plot)])
    if args.list:
        refuse_unused(args, ("ball", "speeds", "speeds_mph", "speeds_kmh", "plot"),
                      "to ball --list (the presets' numbers; --out writes them): leave out "
                      "--list for one ball's bounce")  # fmt: skip
        presets = preset_table()
        band = [f"{low:.3f}-{high:.3f}" if low == low else "-" for low, high in
                zip(presets["itf_cor_low"], presets["itf_cor_high"], strict=True)]  # fmt: skip
        shown = presets[["preset", "description", "mass_g", "diameter_cm", "e0"]]
        _print_table(shown.assign(**{"ITF rebound e [-]": band}))  # the law's numbers: --out
        print("sources and assumptions: racket-impact ball --list --out presets.csv")
        if args.out:
            write_table(preset_table(), args.out)
        return 0
    speeds = _speed(args, "speeds")
    ball = load_ball(args.ball)
    fastest = largest_closing_speed(ball, WALL)
    flag, typed, unit, size = _typed(args, "speeds")
    for value, v in zip(np.atleast_1d(typed), speeds, strict=True):
        if v > fastest:  # said as typed, not as collide's v_a
            raise too_fast_to_store(flag, value, fastest, unit, size)
    table = rigid_bounce_table(ball, speeds)
    unit = speed_unit(args, "speeds")
    calibrated = (
        f"{speed_text(CALIBRATION_SPEED, unit)}, the fastest the real balls are calibrated at"
    )
    beyond = args.ball in BALL_PRESETS and bool((table["speed_m_s"] > CALIBRATION_SPEED).any())
    conditions = say_conditions(
        f"ball {args.ball} head on into a rigid wall at {speed_text(speeds, unit)}"
        + (f"; the rows above {calibrated}, extrapolated" if beyond else "")
    )
    if args.ball in BALL_PRESETS:  # a real ball's law is calibrated up to a speed
        table["calibrated"] = table["speed_m_s"] <= CALIBRATION_SPEED
    if unit != "m/s":  # mph or km/h in, mph or km/h out
        table.insert(1, f"speed_{SPEED_SUFFIXES[unit]}", table["speed_m_s"] / SPEED_UNITS[unit])
    shown_rows = table.drop(columns="speed_m_s") if unit != "m/s" else table
    if "calibrated" in table:
        shown_rows = shown_rows.assign(
            calibrated=table["calibrated"].map({True: "yes", False: "no"})
        )
    _print_table(shown_rows)
    if beyond:
        print(textwrap.fill(
            f'rows calibrated "no": above {calibrated} (the type 2 ball\'s COR there, an '
            "assumption: ball.catalog.COR_AT_30), the law is extrapolated; near the radius its "
            "force is calibrated to nothing (the hyperbola's peak force grows fast there: a "
            "real ball's walls meet and its rubber takes the load)", WIDTH,
            subsequent_indent="  ",
        ))  # fmt: skip
    if args.ball not in BASEBALL_PRESETS:  # the ITF's static test is a tennis ball's
        _print_static_test(static_test(ball, args.ball))
    if args.out:
        write_table(table, args.out)
    if args.plot:
        from studies.plots import plot_rigid_bounce

        preset = BALL_PRESETS.get(args.ball)
        axes = plot_rigid_bounce(
            table, radius=ball.radius, bands=preset and preset.bands, unit=unit,
            conditions=conditions,
        )  # fmt: skip
        save_plot(axes, args.plot)
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
              "ball is viscoelastic,\n  stiffer in a 4 ms impact than in a 5 s hold")  # fmt: skip
