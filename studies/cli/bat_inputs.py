"""The ``bat`` command's inputs checked in the units they were typed in: the pitch, the
swing (``--omega``, ``--cm-speed``, ``--pivot-from-knob``), a pivoted bat's clamps and the
points along the bat (cm from the knob), each refused or asked about in one line naming the
option, with the slip of unit that would explain it.
"""

from __future__ import annotations

from functools import partial

from bat import BatSwing
from bat.swing import (
    ANGULAR_VELOCITY_RANGE,
    CENTRE_BEYOND_KNOB,
    CM_SPEED_RANGE,
    DEG_S_AS_RAD_S,
    FASTEST_CM_SPEED,
)
from common.checks import (
    INCH_AS_CM,
    M_AS_CM,
    MM_AS_CM,
    RPM_AS_RAD_S,
    SPEED_RANGE,
    SPEED_SLIPS,
    ends,
    in_range,
    shown,
    slip_hints,
    suspect,
    too_fast,
)
from common.units import MPH, SPEED_SUFFIXES
from studies.bat.certification import BBCOR_CANNON_SPEED, BBCOR_TEST_SPEED
from studies.bat.sweep import (
    ANGULAR_VELOCITY,
    CM_SPEED,
    FASTEST_PITCH,
)
from studies.cli.options import (
    _typed,
    refuse_unused,
)

NEAREST_KNOB_CM = 1.0
"""A point typed closer to the knob than this [cm] is refused as a length in m typed as cm
(**an assumption**: no ball is hit, nor a handle read, within 1 cm of the knob's end)."""


def _pivot(args) -> float | None:
    """``--pivot-from-knob`` [cm] checked (the rig's range, :class:`bat.Bat`), in m."""
    if args.pivot_from_knob is None:
        return None
    return in_range("--pivot-from-knob", args.pivot_from_knob, 2.0, 50.0, "cm from the knob",
                    slips=(M_AS_CM, INCH_AS_CM)) / 100  # fmt: skip


def _clamps(args) -> float | None:
    """``--clamps`` [cm] checked (:class:`bat.Bat`'s range; one under 0.5 cm, an assumption,
    asked about as m typed as cm), in m.
    """
    if args.clamps is None:
        return None
    value = in_range("--clamps", args.clamps, 0.0, 5.0, "cm", slips=(MM_AS_CM,))
    suspect("--clamps", value, (0.5, 5.0), "cm", (M_AS_CM,), "closer than clamps hold a bat")
    return value / 100


def _instead(name: str, value, typed: str) -> str:
    """The option giving ``value`` in the unit it was ``typed`` in: " (--pitch-mph 136)"."""
    return f" (--{name}-{SPEED_SUFFIXES[typed]} {shown(value)})"


def _pitch(args, default: float, fastest: bool = True) -> float:
    """``--pitch[-mph|-kmh]`` [its unit] in m/s (``default`` [m/s] without one), in the
    speed range; one faster than the fastest pitch on record asked about (``fastest``), or
    else one outside the BBCOR test's speeds (the certification's ball, fired by a cannon).
    """
    flag, value, unit, size = _typed(args, "pitch")
    if value is None:
        return default
    value = in_range(flag, value, SPEED_RANGE[0] / size, SPEED_RANGE[1] / size, unit,
                     slips=SPEED_SLIPS[unit])  # fmt: skip
    instead = partial(_instead, "pitch", value)
    if fastest:
        too_fast(flag, value, unit, FASTEST_PITCH, "the fastest on record", instead, "pitch")
    else:
        test = (BBCOR_TEST_SPEED / size, BBCOR_CANNON_SPEED / size)
        why = (f"not the BBCOR test's speed ({ends(*test).replace(', ', '-')} {unit}: from "
               f"the {BBCOR_TEST_SPEED / MPH:g} mph often cited to the cannon's "
               f"{BBCOR_CANNON_SPEED / MPH:g} mph), so the verdict is not the "
               "standard's")  # fmt: skip
        suspect(flag, value, test, unit, SPEED_SLIPS[unit], why, instead, always=True)
    return value * size


def _swing(args, bat) -> BatSwing | None:
    """The swing of ``--omega``, ``--cm-speed[-mph|-kmh]`` and ``--pivot-from-knob``, each
    checked as typed, for ``bat``: None for a bat at rest (``--omega 0``, or a hand-held bat,
    whose hands are at rest in this model); a pivoted bat turns about its pivot.
    """
    speeds = ("cm_speed", "cm_speed_mph", "cm_speed_kmh")
    if bat.support == "hand-held":
        refuse_unused(
            args,
            ("omega", *speeds, "pivot_from_knob"),
            "to a hand-held bat: the "
            "hands are at rest in this model (swing a free bat, as Nathan does)",
        )
        return None
    omega = ANGULAR_VELOCITY
    if args.omega is not None:
        omega = in_range("--omega", args.omega, *ANGULAR_VELOCITY_RANGE, "rad/s",
                         slips=(RPM_AS_RAD_S, DEG_S_AS_RAD_S))  # fmt: skip
    if bat.support == "pivoted":
        refuse_unused(args, speeds, "to a pivoted bat: it turns about its pivot "
                      "(--pivot-from-knob)")  # fmt: skip
    elif args.pivot_from_knob is not None:
        refuse_unused(args, speeds, "with --pivot-from-knob: give the point the bat turns "
                      "about or its centre of mass's speed, not both")  # fmt: skip
    if omega == 0.0:
        refuse_unused(args, speeds, "with --omega 0: the bat at rest does not move")
        return None
    if bat.support == "pivoted" or args.pivot_from_knob is not None:
        return BatSwing(omega, pivot_from_knob=bat.pivot_from_knob if bat.support == "pivoted"
                        else _pivot(args))  # fmt: skip
    flag, value, unit, size = _typed(args, "cm_speed")
    cm = CM_SPEED
    if value is not None:
        speed = in_range(flag, value, CM_SPEED_RANGE[0] / size, CM_SPEED_RANGE[1] / size,
                         unit, slips=SPEED_SLIPS[unit])  # fmt: skip
        limit = FASTEST_CM_SPEED / size
        why = (f"faster than batters swing a bat's centre of mass (about {limit:.3g} {unit}, "
               "estimated)")  # fmt: skip
        suspect(flag, speed, (0.0, limit), unit, SPEED_SLIPS[unit], why,
                partial(_instead, "cm-speed", speed), always=True)  # fmt: skip
        cm = speed * size
    swing = BatSwing(omega, cm_speed=cm)
    beyond = swing.pivot(bat) - bat.beam.length  # the turn's centre beyond the knob [m]
    if beyond > CENTRE_BEYOND_KNOB:
        typed = flag if value is not None else "the default --cm-speed"
        raise ValueError(
            f"--omega {omega:g} rad/s with {typed} {cm / size:g} {unit} turns the bat about a "
            f"point {100 * beyond:.4g} cm beyond the knob, farther than "
            f"{100 * CENTRE_BEYOND_KNOB:g} cm: a faster --omega or a slower --cm-speed"
        )
    return swing


def _from_knob(flag: str, value: float, length: float) -> float:
    """A point typed [cm from the knob] on a bat ``length`` [m] long, in m from the knob; one
    within :data:`NEAREST_KNOB_CM` of the knob refused as a length in m typed as cm.
    """
    value = in_range(flag, value, 0.0, 100 * length, "cm from the knob",
                     slips=(M_AS_CM, INCH_AS_CM))  # fmt: skip
    if 0.0 < value < NEAREST_KNOB_CM:
        slipped = slip_hints(value, 0.0, 100 * length, "cm", (M_AS_CM,))
        raise ValueError(f"{flag} {shown(value)} cm is on the knob: {slipped}")
    return value / 100


def _beyond(flag: str, z: float, bat, swing) -> None:
    """A point ``z`` [m from the knob] the bat can be hit at: beyond the swing's centre, short
    of a pivoted bat's clamps or of the hands (ValueError in the option's words).
    """
    length = bat.beam.length
    if swing is not None:
        centre = length - swing.pivot(bat)
        if z <= centre:
            raise ValueError(f"{flag} {100 * z:g} cm is not beyond the point the bat turns "
                             f"about, {100 * centre:.3g} cm from the knob: hit it towards the "
                             "barrel")  # fmt: skip
    try:
        bat.check_points(length - z)
    except ValueError:
        near = {"pivoted": bat.pivot_from_knob + bat.clamp_offset,
                "hand-held": bat.hand.grip_length}.get(bat.support, 0.0)  # fmt: skip
        raise ValueError(f"{flag} {100 * z:g} cm must lie beyond the {bat.support} bat's "
                         f"{'clamps' if bat.support == 'pivoted' else 'hands'}, "
                         f"{100 * near:.3g} cm from the knob") from None  # fmt: skip
