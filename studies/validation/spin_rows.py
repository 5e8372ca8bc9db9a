"""The measurements of oblique impacts, spin and courts (issue 36; ``data/measurements.md``
secs. 6 and 7), each a :class:`~studies.validation.comparison.Comparison`.

Calibration: Cross's oblique bounces (Table II) set the ball's tangential stiffness and
offset (:mod:`ball.spin`) and each lab surface's friction (:data:`ball.court.LAB_SURFACES`);
Lindsey's 2 ms snapback (not a row: a time, not a spin) sets the strings' return spring
(:mod:`racket.strings.sideways`); the courts' friction and COR are the presets' own (their
CPR checks how the ITF's test reads them).  Validation: Cross's Table I bounce, TWU's spin off
a clamped racket by string (the ball sliding across the mains), TWU's lubricated fresh
strings, the tour's forehand spin against tour players' kinematics, the kick serve's spin, its
topspin and its share of sidespin, the flat serve against the tour's first serves at its own
speed, and the order of the three serves: no parameter was set from them (the kick serve's
geometry is Cross's description of the stroke, from the same article as its spins: a
description of the swing, not a number fitted to them).  Where a source states the scatter of
its inputs, the band widens by the model's spread over it
(:meth:`~studies.validation.comparison.Comparison.limits`).
"""

from __future__ import annotations

import math
from functools import cache

import numpy as np

from ball.court import COURTS, LAB_SURFACES, bounce, court_pace_rating
from common.units import LB, MPH
from racket import STROKES, hit, oblique_impact
from racket.strings.sideways import sideways
from racket.stroke import RPM
from studies.validation.comparison import Comparison
from studies.validation.conditions import _ball, clamped_racket

CROSS_2002 = "Cross, Am. J. Phys. 70 (2002) 482, as transcribed in chaehy5665/tennis-sim"

CROSS_TABLE_II = {
    "wood-20": ("wood", 20, 3.72, 19.2, 34.9, 0.84),
    "wood-45": ("wood", 45, 3.80, 50.4, 58.2, 0.60),
    "emery-20": ("emery paper", 20, 3.53, 27.2, 78.5, 0.60),
    "emery-45": ("emery paper", 45, 3.70, 51.3, 49.9, 0.63),
    "ace-20": ("Rebound Ace", 20, 3.35, 23.4, 76.7, 0.62),
    "ace-45": ("Rebound Ace", 45, 3.60, 49.3, 50.6, 0.68),
}
"""Cross 2002, Table II (``data/measurements.md`` sec. 6): a bounce without spin per row,
surface, theta1 [deg from the surface], v1 [m/s] -> theta2 [deg], omega2 [rad/s], vx2/vx1."""

CROSS_TABLE_I = {"vx1": 2.10, "vy1": 0.77, "vx2": (1.23, 0.03), "vy2": (0.61, 0.03),
                 "omega2": (52.4, 0.5), "theta2": (26.2, 1.5)}  # fmt: skip
"""Cross 2002, Table I (emery paper, a 25 cm drop): speeds [m/s], spin [rad/s], angle [deg],
each measured value with its uncertainty."""

TWU_SPIN = {
    "polyester": (1777, 1626, 1803, 1780, 1681, 1690, 1555, 1584),
    "nylon": (1452, 1531, 1207, 1422),
    "natural-gut": (1642, 1524),
}
"""TWU, "String movement and spin" (Lindsey): spin out [rpm] off a clamped racket, by
material, each string at 52 and 62 lb in turn (``data/measurements.md`` sec. 6)."""

TWU_SPIN_BAND = (1200.0, 1810.0)
"""The spin out [rpm] of every string TWU measured, rounded out (1207-1803 rpm)."""

TWU_CLAMPED = (25.0, math.radians(40.0), -3820.0 * RPM)
"""TWU's clamped-racket test: ball at 56 mph (25.0 m/s), 40 degrees from the normal, with
3820 rpm of backspin."""

TWU_LUBRICATED = (49.0 * MPH, math.radians(28.0), -3150.0 * RPM, 60.0)
"""TWU's lubrication test: 49 mph, 28 degrees from perpendicular, 3150 rpm of backspin, 16x19
rackets at 60 lb (TWU, "String lubrication and movement in spin", Lindsey 2011)."""

TWU_LUBRICATED_SCATTER = (1.0 * MPH, math.radians(1.0), 286.0 * RPM)
"""The lubrication test's stated input scatter: +/- 1 mph, +/- 1 degree, +/- 286 rpm (the
same source): its rows' band widens by the model's spread over them, dry and lubricated
shots alike (TWU compares means over shots: what is left of the scatter is the test's
setting, shared by both)."""

CROSS_TABLE_I_SCATTER = {"vx1": 0.04, "vy1": 0.014}
"""Cross 2002, Table I: the incoming speeds' uncertainties [m/s]: the band widens by the
model's spread over them."""

TOUR_FOREHANDS = (1288.0, 3331.0)
"""Men's topspin forehands at the 1997 US Open, player means [rpm] (Yandell, "Ball spin in
pro tennis", tennisplayer.net)."""

KICK_SERVES = (3270.0, 4500.0)
"""Kick serves' spin [rpm], mainly sidespin (Cross, TWU "Physics of the tennis kick serve",
2011; ``data/measurements.md`` sec. 6)."""

KICK_TOPSPIN_MAX = 1000.0
"""A kick serve's topspin is "typically below 1000 rpm" [rpm] (Cross, as :data:`KICK_SERVES`)."""

FIRST_SERVES = ((92.0, 3167.0), (120.0, 1548.0))
"""Men's first serves: (ball speed [mph], spin [rpm]), 3167 rpm at 92 mph to 1548 at 120 mph
(Yandell, "Ball spin in pro tennis")."""

FIRST_SERVE_SCATTER = 0.2
"""The band about the first serves' line at a serve's own speed, a fraction of it [-]:
**an assumption** (Yandell gives averages, no scatter)."""

_TWU_MOVEMENT = 'TWU, "String movement and spin" (Lindsey, own text)'
_TWU_LUBE = 'TWU, "String lubrication and movement in spin" (Lindsey 2011, own text)'
_YANDELL = 'Yandell, "Ball spin in pro tennis", tennisplayer.net'
_CROSS_SERVE = 'Cross, TWU "Physics of the tennis kick serve" (2011); Yandell (serves)'
_COURTS = "Cross, Sports Eng. 6 (2003); ITF court pace classification"


@cache
def _table_ii(name: str) -> tuple[float, float, float]:
    surface, theta, speed = CROSS_TABLE_II[name][:3]
    b = bounce(LAB_SURFACES[surface], speed, math.radians(theta))
    return math.degrees(b.angle_after), b.spin_after, b.vx_ratio


@cache
def _table_i(vx1: float = CROSS_TABLE_I["vx1"], vy1: float = CROSS_TABLE_I["vy1"]) -> tuple:
    b = bounce(LAB_SURFACES["emery paper"], math.hypot(vx1, vy1), math.atan2(vy1, vx1))
    return math.degrees(b.angle_after), b.vx_ratio * vx1, b.e_y * vy1, b.spin_after


def _spread(model, inputs: tuple, scatter: tuple) -> float:
    """The root-sum-square of ``model``'s half range as each input moves by its scatter, the
    others held (``model(*inputs)`` a number).
    """
    total = 0.0
    for i, delta in enumerate(scatter):
        up, down = list(inputs), list(inputs)
        up[i] += delta
        down[i] -= delta
        total += (0.5 * (model(*up) - model(*down))) ** 2
    return math.sqrt(total)


def _table_i_spread(i: int) -> float:
    inputs = (CROSS_TABLE_I["vx1"], CROSS_TABLE_I["vy1"])
    scatter = (CROSS_TABLE_I_SCATTER["vx1"], CROSS_TABLE_I_SCATTER["vy1"])
    return _spread(lambda vx1, vy1: _table_i(vx1, vy1)[i], inputs, scatter)


@cache
def twu_spin(material: str, tension_lb: float, lubricated: bool = False,
             test=TWU_CLAMPED) -> float:  # fmt: skip
    """Spin out [rpm] of a ball on the Pure Drive (2021), head clamped, strung (fresh) with
    ``material`` at ``tension_lb``, in TWU's test ``test`` (speed [m/s], angle from the
    normal [rad], spin [rad/s], backspin negative) at the string centre, the ball sliding
    across the mains (TWU films the mains moving sideways); > 0: topspin out.

    Parameters
    ----------
    material : str
        A string preset (:data:`racket.strings.stringing.STRINGS`).
    tension_lb : float
        The tension [lb].
    lubricated : bool, optional
        Lubricated strings (:data:`racket.strings.sideways.LUBRICATED_FRICTION`).
    test : tuple, optional
        The test (:data:`TWU_CLAMPED`, or the first three of :data:`TWU_LUBRICATED`).
    """
    racket = clamped_racket(None, material, tension_lb * LB)
    speed, angle, spin = test[:3]
    o = oblique_impact(
        racket, _ball(), racket.strings.center, speed * math.cos(angle),
        slip_velocity=(0.0, speed * math.sin(angle)), spin=(-spin, 0.0, 0.0),
        side=sideways(racket.strings, lubricated=lubricated),
    )  # fmt: skip
    return -float(o.spin[0, 0]) / RPM


def _material_mean(material: str) -> float:
    return float(np.mean([twu_spin(material, t) for t in (52.0, 62.0)]))


def _lubricated_gain(material: str, *test) -> float:
    """Spin gained by lubricated ``material`` [%] in TWU's lubrication test (``test``: its
    speed, angle and spin; none: the test's own), dry and lubricated shot alike.
    """
    test = test or TWU_LUBRICATED[:3]
    tension = TWU_LUBRICATED[3]
    dry = twu_spin(material, tension, False, test)
    return 100.0 * (twu_spin(material, tension, True, test) / dry - 1.0)


@cache
def _strokes(names: tuple) -> list:
    from racket import default_ball, default_racket

    return [hit(STROKES[name], default_racket(), default_ball()).flight for name in names]


def _kick_sidespin_share() -> float:
    """The kick serve's sidespin over its spin rate [-]."""
    (kick,) = _strokes(("kick-serve",))
    return abs(kick.sidespin) / kick.spin_rate


def _first_serve_line(speed_mph: float) -> float:
    """The first serves' spin [rpm] at ``speed_mph`` on :data:`FIRST_SERVES`' line."""
    (v0, w0), (v1, w1) = FIRST_SERVES
    return w0 + (w1 - w0) * (speed_mph - v0) / (v1 - v0)


def _flat_serve_against_line() -> float:
    """The flat serve's spin over the first serves' line at its own ball speed [-]."""
    (flat,) = _strokes(("flat-serve",))
    return flat.spin_rate / RPM / _first_serve_line(flat.speed / MPH)


def _serves_ordered() -> float:
    flat, slice_, kick = _strokes(("flat-serve", "slice-serve", "kick-serve"))
    speeds = flat.speed > slice_.speed > kick.speed
    spins = flat.spin_rate < slice_.spin_rate < kick.spin_rate
    return 1.0 if speeds and spins else 0.0


def spin_comparisons() -> list[Comparison]:
    """Every comparison of oblique impacts, spin and courts."""
    bounces = []
    for name, (surface, theta, speed, theta2, omega2, ratio) in CROSS_TABLE_II.items():
        said = f"{surface}, {theta} deg from the surface, {speed} m/s, no spin"
        for i, (what, value, low, high) in enumerate((
            ("rebound angle [deg]", theta2, theta2 - 3.0, theta2 + 3.0),
            ("spin after [rad/s]", omega2, 0.85 * omega2, 1.15 * omega2),
            ("vx2 / vx1 [-]", ratio, ratio - 0.07, ratio + 0.07),
        )):  # fmt: skip
            bounces.append(Comparison(
                f"bounce-{name}-{what.split()[0]}", f"bounce on {surface} at {theta} deg: {what}",
                said, value, low, high, CROSS_2002 + ", Table II", "calibration",
                "the issue's targets: 3 deg, 15 %, 0.07", lambda n=name, i=i: _table_ii(n)[i],
            ))  # fmt: skip
    table_i = [
        Comparison(
            f"bounce-table-i-{key}", f"bounce on emery paper: {what}",
            "emery paper, dropped 25 cm, vx1 2.10 m/s, vy1 0.77 m/s, no spin",
            CROSS_TABLE_I[key][0], CROSS_TABLE_I[key][0] - CROSS_TABLE_I[key][1],
            CROSS_TABLE_I[key][0] + CROSS_TABLE_I[key][1], CROSS_2002 + ", Table I",
            "validation", "the source's uncertainty, widened by the model's spread over the "
            "incoming speeds' (vx1 +/- 0.04, vy1 +/- 0.014 m/s)", lambda i=i: _table_i()[i],
            lambda i=i: _table_i_spread(i),
        )
        for i, (key, what) in enumerate((
            ("theta2", "rebound angle [deg]"), ("vx2", "vx2 [m/s]"), ("vy2", "vy2 [m/s]"),
            ("omega2", "spin after [rad/s]"),
        ))
    ]  # fmt: skip
    twu = [
        Comparison(
            f"spin-twu-{material}",
            f"spin off clamped strings, {material} [rpm]",
            "Pure Drive (2021) head clamped, 52 and 62 lb (mean), ITF type 2 at 25 m/s, 40 deg "
            "from the normal, 3820 rpm of backspin, string centre",
            float(np.mean(TWU_SPIN[material])),
            *TWU_SPIN_BAND,
            _TWU_MOVEMENT,
            "validation",
            "the issue's band: every string measured, 1207-1803 rpm",
            lambda m=material: _material_mean(m),
        )
        for material in TWU_SPIN
    ]
    twu.append(Comparison(
        "spin-twu-polyester-over-nylon", "spin off clamped strings, polyester / nylon [-]",
        "as spin-twu-*, means over both tensions", 1.202, 1.10, 1.30, _TWU_MOVEMENT,
        "validation", "the source's 'about 20 %', the issue's 10-30 %",
        lambda: _material_mean("polyester") / _material_mean("nylon"),
    ))  # fmt: skip
    lubricated = [
        Comparison(
            f"spin-lubricated-{material}",
            f"spin gained by lubricated {material} [%]",
            "Pure Drive (2021) head clamped at 60 lb, ITF type 2 at 49 mph, 28 deg from the "
            "normal, 3150 rpm of backspin",
            36.0,
            14.0,
            58.0,
            _TWU_LUBE,
            "validation",
            "the source's range over strings and conditions, +14 to +58 %, its middle as the "
            "value; widened by the model's spread over the stated input scatter (1 mph, 1 deg, "
            "286 rpm); fresh strings, as TWU's",
            lambda m=material: _lubricated_gain(m),
            lambda m=material: _spread(
                lambda *t: _lubricated_gain(m, *t), TWU_LUBRICATED[:3], TWU_LUBRICATED_SCATTER
            ),
        )
        for material in ("polyester", "nylon")
    ]
    play = [
        Comparison(
            "stroke-topspin-forehand",
            "spin of a topspin forehand [rpm]",
            "the topspin-forehand preset: tour players' kinematics (Landlinger's ATP head "
            "speed along Kwon's path, face vertical), default racket and ball",
            float(np.mean(TOUR_FOREHANDS)),
            *TOUR_FOREHANDS,
            _YANDELL,
            "validation",
            "the players' means at the 1997 US Open; the kinematics are other players'",
            lambda: _strokes(("topspin-forehand",))[0].topspin / RPM,
        ),
        Comparison(
            "stroke-kick-serve",
            "spin of a kick serve [rpm]",
            "the kick-serve preset (Gordon's head speed, Cross's geometry), default racket "
            "and ball",
            float(np.mean(KICK_SERVES)),
            *KICK_SERVES,
            _CROSS_SERVE,
            "validation",
            "Cross's range for kick serves",
            lambda: _strokes(("kick-serve",))[0].spin_rate / RPM,
        ),
        Comparison(
            "stroke-kick-serve-topspin",
            "topspin of a kick serve [rpm]",
            "as stroke-kick-serve",
            KICK_TOPSPIN_MAX,
            0.0,
            KICK_TOPSPIN_MAX,
            _CROSS_SERVE,
            "validation",
            "Cross: topspin 'typically below 1000 rpm' (a bound: measured is the bound)",
            lambda: _strokes(("kick-serve",))[0].topspin / RPM,
        ),
        Comparison(
            "stroke-kick-serve-sidespin",
            "a kick serve's sidespin over its spin [-]",
            "as stroke-kick-serve",
            0.5,
            0.5,
            1.0,
            _CROSS_SERVE,
            "validation",
            "Cross: 'mainly sidespin', read as more than half (a bound: measured is the "
            "bound; the preset's swing is his "
            "'mostly across the ball': this row checks the contact turns it into sidespin)",
            lambda: _kick_sidespin_share(),
        ),
        Comparison(
            "stroke-flat-serve",
            "a flat serve's spin over the first serves' at its speed [-]",
            "the flat-serve preset (Gordon's head speed), default racket and ball; the tour's "
            "first serves' spin on the line from 3167 rpm at 92 mph to 1548 at 120, at the "
            "preset's own ball speed",
            1.0,
            1.0 - FIRST_SERVE_SCATTER,
            1.0 + FIRST_SERVE_SCATTER,
            _YANDELL,
            "validation",
            "+/- 20 % about the line (an assumption: the source gives averages)",
            _flat_serve_against_line,
        ),
        Comparison(
            "stroke-serves-in-order",
            "flat > slice > kick in speed, < in spin [1: yes]",
            "the flat-, slice- and kick-serve presets at one head speed, default racket and ball",
            1.0,
            1.0,
            1.0,
            _CROSS_SERVE,
            "validation",
            "an order, as measured",
            _serves_ordered,
        ),
    ]
    courts = []
    for name, low, high in (("grass", 45.0, 100.0), ("clay", -100.0, 29.99)):
        court = COURTS[name]
        formula = 100.0 * (1.0 - court.friction) + 150.0 * (0.81 - court.cor)
        courts.append(Comparison(
            f"court-pace-{name}", f"ITF court pace rating, {name} [-]",
            f"the {name} preset (friction {court.friction:g}, COR {court.cor:g}), the ITF "
            "test's ball at 30 m/s, 16 deg", formula, low, high, _COURTS, "calibration",
            "the category that the preset's own friction and COR give",
            lambda c=court: court_pace_rating(c)[0],
        ))  # fmt: skip
    return [*bounces, *table_i, *twu, *lubricated, *play, *courts]
