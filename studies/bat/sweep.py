"""Bats (issue 37): the exit (batted-ball) speed along the barrel for a swing and a pitch, its
peak and the sweet zone (:func:`bat_sweep`), and what every bat answer shares: the one
default pitch and swing, the bat taken by name or as a :class:`bat.Bat`, and its
conditions in one line.  The certification numbers: :mod:`studies.bat.certification`; the
vibration reaching the hands: :mod:`studies.bat.feel`; a bat of one's own from TOML:
:mod:`studies.bat.config`.

The defaults are A. M. Nathan's high-speed case (N2000 = A. M. Nathan, "Dynamics of the
baseball-bat collision", Am. J. Phys. 68, 979-990 (2000), Sec. III C; ``data/bats.md``
section 3 B): a 40 m/s ball onto the R161 (:data:`bat.DEFAULT_BAT`) swung with its
centre of mass at 24 m/s and turning at 51 rad/s, the baseball of e0 0.50
(:data:`ball.DEFAULT_BASEBALL`).  Positions: the bat answers count them from the knob, as
Nathan and bat makers do, and also from the tip (the barrel's end: the core's convention,
``position_from_tip_cm``); a function's ``from_knob`` is in metres from the knob.

Wood against hollow metal: :func:`bat_sweep` of :func:`bat.presets.alloy` beside the R161
(``racket-impact bat sweep --bat r161 alloy`` draws both); no comparison helper of its own.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass, replace
from typing import TYPE_CHECKING

import numpy as np

from ball import Ball
from bat import BATS, Bat, BatSwing
from bat.bat import BAT_SUPPORTS
from common.checks import finite, finite_array, shown
from common.typechecks import choice, instance
from common.units import MPH, SPEED_UNITS
from racket import impact
from racket.hand import GRIPS
from studies.arguments import ball_argument
from studies.conditions import speed_text
from studies.face.maps import SWEET_FRACTION

if TYPE_CHECKING:
    import pandas as pd

PITCH_SPEED = 40.0
"""The ball's speed towards the bat [m/s] of every bat answer: N2000's high-speed case,
"40 m/s (90 mph)" (p. 986)."""

CM_SPEED = 24.0
"""Speed [m/s] of the bat's centre of mass towards the ball: N2000's high-speed case
(p. 986)."""

ANGULAR_VELOCITY = 51.0
"""The bat's angular velocity [rad/s]: N2000's high-speed case (p. 986)."""

DEFAULT_SWING = BatSwing(ANGULAR_VELOCITY, cm_speed=CM_SPEED)
"""The swing of every bat answer: :data:`CM_SPEED` and :data:`ANGULAR_VELOCITY`, a turn about
a point about 9 cm from the R161's knob."""

SWEEP_FROM_KNOB = 0.40
"""Where a sweep starts [m from the knob]: N2000 Figs. 10-12 span 40-84 cm (read from their
axes, ``data/bats.md`` section 3 B); it runs to the barrel's end."""

SWEEP_STEP = 0.01
"""Spacing of a sweep's points [m]: N2000's 1-cm slices (p. 984)."""

SWEET_ZONE_FRACTION = SWEET_FRACTION
"""The sweet zone is where the exit speed is within this fraction of its peak [-]: 5 %,
the sweet area's of a racket's face map (:data:`studies.face.maps.SWEET_FRACTION`).  **An
ASSUMPTION**: no standard width was found; D. A. Russell lists a sweet spot's definitions
(the most batted-ball speed is one), and puts it "approximately 4-7 inches from the end of
the barrel" (as quoted by infomobilityforum.com, "The sweet spot and the perfect baseball
bat")."""

FASTEST_PITCH = 105.1 * MPH
"""The fastest pitch on record [m/s]: 105.1 mph, Aroldis Chapman, 2010 (PITCHf/x), tied in
2016 (Statcast) (ESPN, "Aroldis Chapman falls 0.1 mph shy of tying own MLB record",
m.espn.go.com/mlb/story?storyId=17103543).  A pitch typed faster is asked about (a unit
slip?), not refused."""

SPEED_COLUMNS = ("bat_speed", "exit_speed")
"""The speeds of a sweep table (``*_m_s``, and ``*_mph`` or ``*_kmh`` with ``unit``): the
impact point's before, the ball's after."""


def bat_argument(bat, support: str | None = None) -> Bat:
    """``bat`` as a :class:`bat.Bat`: a preset's name of :data:`bat.BATS` built with
    ``support`` (free without one), or a Bat (held by ``support`` if given).

    Parameters
    ----------
    bat : str or Bat
        A preset's name, or a bat.
    support : str, optional
        "free", "pivoted" or "hand-held"; None: the bat's own (a preset's: free).
    """
    if support is not None:
        choice("support", support, BAT_SUPPORTS)
    if isinstance(bat, str):
        if bat not in BATS:
            raise ValueError(
                f"unknown bat {bat!r}; presets: {', '.join(BATS)} (a TOML file? "
                f"studies.bat.config.load_bat({bat!r}) makes one)"
            )
        return _preset(bat) if support in (None, "free") else replace(_preset(bat), support=support)
    instance("bat", bat, Bat, "a bat.Bat or a preset's name", f" ({', '.join(BATS)})")
    return bat if support in (None, bat.support) else replace(bat, support=support)


@functools.cache
def _preset(name: str) -> Bat:
    """The preset ``name`` of :data:`bat.BATS`, free, built once (its modes, a few seconds,
    computed once; a Bat is frozen, so one object serves every caller).
    """
    return BATS[name]("free")


def swing_argument(bat: Bat, swing) -> BatSwing | None:
    """``swing`` checked for ``bat``: a :class:`bat.BatSwing` or None (the bat at rest); a
    hand-held bat is at rest, a pivoted one turns about its pivot (:meth:`bat.Bat.check_swing`).
    The default swing (:data:`DEFAULT_SWING`, a free bat's) becomes, as on the command line,
    None for a hand-held bat and a turn about the pivot at :data:`ANGULAR_VELOCITY` for a
    pivoted one.

    Parameters
    ----------
    bat : Bat
        The bat.
    swing : BatSwing or None
        Its swing.
    """
    instance("swing", swing, BatSwing | type(None), "a bat.BatSwing or None (at rest)")
    if swing is DEFAULT_SWING and bat.support == "hand-held":
        return None
    if swing is DEFAULT_SWING and bat.support == "pivoted":
        return BatSwing(ANGULAR_VELOCITY, pivot_from_knob=bat.pivot_from_knob)
    if swing is not None:
        try:
            bat.check_swing(swing.pivot(bat))
            swing.check(bat)
        except ValueError as err:
            raise ValueError(f"swing does not suit this bat: {err}") from None
    return swing


def swing_kwargs(bat: Bat, swing: BatSwing | None, x) -> dict:
    """The swing's ``swing_speed`` and ``pivot`` for :func:`racket.impact` at the points ``x``
    [m from the tip] (nothing for a bat at rest; a single point's speed as a number).

    Parameters
    ----------
    bat, swing
        As in :func:`swing_argument`.
    x : float or ndarray
        The impact points [m from the tip].
    """
    if swing is None:
        return {}
    kwargs = swing.impact_kwargs(bat, np.atleast_1d(x))
    if np.ndim(x) == 0:
        kwargs["swing_speed"] = float(kwargs["swing_speed"][0])
    return kwargs


def tip_positions(bat: Bat, z, name: str = "from_knob") -> np.ndarray:
    """Points ``z`` [m from the knob] as metres from the tip (the core's), each checked to lie
    on the bat.

    Parameters
    ----------
    bat : Bat
        The bat.
    z : float or array_like
        The points [m from the knob].
    name : str
        The argument's name, as a message quotes it.
    """
    z = finite_array(name, z, "m from the knob")
    length = bat.beam.length
    z = np.where(np.abs(z - length) < 1e-9, length, z)  # round-off at the barrel's end
    off = (z < 0.0) | (z > length)
    if np.any(off):
        bad = z[off].ravel()[0]
        hint = f" (cm typed as m? {shown(bad)} cm would be {bad / 100:g} m)" if (
            length < bad <= 100 * length) else ""  # fmt: skip
        raise ValueError(
            f"{name} must be on the bat, in [0, {length:g}] m from the knob, got {shown(bad)}{hint}"
        )
    return length - z


def bat_words(bat: Bat, bat_name: str | None = None) -> str:
    """The bat as a conditions line says it: "bat r161 (R161 (wood), 0.869 kg, 84 cm; free)",
    "...; pivoted 15.24 cm from the knob, clamps 2.54 cm either side)".

    Parameters
    ----------
    bat : Bat
        The bat.
    bat_name : str, optional
        The name the user gave it (a preset or a file); default its own.
    """
    said = f"bat {bat_name or bat.name} ("
    said += f"{bat.name}, " if bat_name and bat_name != bat.name else ""
    said += f"{bat.beam.mass:.3g} kg, {100 * bat.beam.length:.4g} cm; {bat.support}"
    if bat.support == "pivoted":
        clamps = (f"clamps {100 * bat.clamp_offset:.3g} cm either side" if bat.clamp_offset
                  else "a single pivot point")  # fmt: skip
        said += f" {100 * bat.pivot_from_knob:.4g} cm from the knob, {clamps}"
    elif bat.support == "hand-held":
        grips = [name for name, hand in GRIPS.items() if hand == bat.hand]
        said += f", {grips[0] if grips else 'own'} grip"
    return said + ")"


def swing_words(bat: Bat, swing: BatSwing | None, unit: str = "m/s") -> str:
    """The swing in words: "the bat swung at 24 m/s (its centre of mass) and 51 rad/s, about
    9.3 cm from the knob", "the bat turning at 56 rad/s about 15 cm from the knob", "the bat
    at rest".

    Parameters
    ----------
    bat, swing
        As in :func:`swing_argument`.
    unit : str
        The unit of the speeds: "m/s", "mph" or "km/h".
    """
    if swing is None:
        return "the bat at rest"
    about = f"about {100 * (bat.beam.length - swing.pivot(bat)):.3g} cm from the knob"
    if swing.cm_speed is None:
        return f"the bat turning at {shown(swing.angular_velocity)} rad/s {about}"
    return (f"the bat swung at {speed_text(swing.cm_speed, unit)} (its centre of mass) and "
            f"{shown(swing.angular_velocity)} rad/s, {about}")  # fmt: skip


def bat_conditions(bat: Bat, ball: Ball, speed, swing, unit: str = "m/s", bat_name=None,
                   ball_name=None) -> str:  # fmt: skip
    """One line naming what a bat answer was computed for: the bat, the ball and its speed,
    the swing.

    Parameters
    ----------
    bat : Bat
        The bat.
    ball : Ball
        The ball.
    speed : float
        The ball's speed towards the bat [m/s].
    swing : BatSwing or None
        The bat's swing (None: at rest).
    unit : str
        The unit the speeds are said in.
    bat_name, ball_name : str, optional
        The names the user gave them (a preset or a file).
    """
    ball_said = ball_name or f"of {1e3 * ball.mass:.4g} g"
    return (f"{bat_words(bat, bat_name)}, ball {ball_said} at {speed_text(speed, unit)}, "
            f"{swing_words(bat, swing, unit)}")  # fmt: skip


def sweep_points(bat: Bat, start: float = SWEEP_FROM_KNOB, step: float = SWEEP_STEP):
    """A sweep's default points [m from the knob]: every ``step`` from ``start`` to the
    barrel's end.

    Parameters
    ----------
    bat : Bat
        The bat.
    start : float
        The first point [m from the knob].
    step : float
        The spacing [m].
    """
    count = int(np.floor((bat.beam.length - start) / step + 1e-9)) + 1
    return np.round(start + step * np.arange(count), 12)


@dataclass(frozen=True)
class BatSweep:
    """The exit speed along the barrel (built by :func:`bat_sweep`).

    Attributes
    ----------
    table : DataFrame
        One row per impact point: ``bat``, ``position_from_knob_cm``,
        ``position_from_tip_cm`` (the barrel's end), ``bat_speed_m_s`` (the point's speed
        towards the ball before), ``exit_speed_m_s`` (the batted ball's), ``e`` (the COR of
        the bat's rigid motion, Eq. 21), ``e_A`` (the collision efficiency e_a in the frame
        of the swing: exit speed = e_a v_pitch + (1 + e_a) v_bat), ``contact_time_ms``,
        ``peak_force_N``, ``vibration_energy_J`` and ``vibration_share`` (of the energy the
        impact shares out), ``recontacts`` (times the bat caught the ball again: near the
        handle, where a beam bent this far is out of its depth), ``sweet_zone`` (bool); the
        speeds also in ``unit``.
    peak_from_knob : float
        Where the exit speed peaks [m from the knob], refined between the points.
    peak_exit_speed : float
        The peak exit speed [m/s].
    sweet_zone : (float, float)
        Where the exit speed is within :data:`SWEET_ZONE_FRACTION` of its peak [m from the
        knob], its ends interpolated between the points (an end at the sweep's own: the zone
        may go on beyond it).
    conditions : str
        What it was computed for (:func:`bat_conditions`).
    unit : str
        The unit of the speeds shown: "m/s", "mph" or "km/h".
    """

    table: pd.DataFrame
    peak_from_knob: float
    peak_exit_speed: float
    sweet_zone: tuple
    conditions: str
    unit: str = "m/s"

    def exit_speed_at(self, z: float) -> float:
        """The exit speed [m/s] at ``z`` [m from the knob], interpolated between the points.

        Parameters
        ----------
        z : float
            The point [m from the knob].
        """
        table = self.table
        return float(np.interp(100 * finite("z", z, "m"), table["position_from_knob_cm"],
                               table["exit_speed_m_s"]))  # fmt: skip


def bat_sweep(
    bat=None,
    ball=None,
    pitch_speed: float = PITCH_SPEED,
    swing=DEFAULT_SWING,
    from_knob=None,
    unit: str = "m/s",
    bat_name: str | None = None,
    ball_name: str | None = None,
) -> BatSweep:
    """The exit (batted-ball) speed along the bat, its peak and the sweet zone.

    Parameters
    ----------
    bat : Bat or str, optional
        The bat, or a preset's name (built free); default :data:`bat.DEFAULT_BAT`, free.
    ball : Ball, optional
        The ball; default :data:`ball.DEFAULT_BASEBALL` (e0 0.50).
    pitch_speed : float
        The ball's speed towards the bat [m/s]; default :data:`PITCH_SPEED`.
    swing : BatSwing or None
        The bat's swing; default :data:`DEFAULT_SWING`; None: the bat at rest (a hand-held
        bat's hands are at rest; a pivoted bat turns about its pivot).
    from_knob : array_like, optional
        The impact points [m from the knob], at least three; default
        :func:`sweep_points` (every cm from 40 cm to the barrel's end).
    unit : str
        "m/s", "mph" or "km/h": the speeds also in this unit, the one the user typed.
    bat_name, ball_name : str, optional
        Their names as the user gave them, for the conditions.

    Returns
    -------
    BatSweep

    Examples
    --------
    >>> result = bat_sweep()
    >>> 0.6 < result.peak_from_knob < 0.8
    True
    """
    from studies.tables import speeds_in

    bat, ball = _bat_and_ball(bat, ball)
    pitch_speed = _speed("pitch_speed", pitch_speed)
    swing = swing_argument(bat, swing)
    choice("unit", unit, tuple(SPEED_UNITS))
    if from_knob is not None:
        from_knob = np.sort(np.ravel(finite_array("from_knob", from_knob, "m from the knob")))
    z = sweep_points(bat) if from_knob is None else from_knob
    x = _points(bat, z)
    r = impact(bat, ball, x, pitch_speed, **swing_kwargs(bat, swing, x))
    exit_speed = np.asarray(r.ball_rebound)
    peak_z, peak = _refined_peak(bat, ball, pitch_speed, swing, z, exit_speed)
    zone = _zone(z, exit_speed, peak_z, peak)
    import pandas as pd

    table = pd.DataFrame({
        "bat": bat_name or bat.name,
        "position_from_knob_cm": 100 * z,
        "position_from_tip_cm": 100 * x,
        "bat_speed_m_s": np.broadcast_to(r.swing_speed, x.shape).astype(float),
        "exit_speed_m_s": exit_speed,
        "e": r.e,
        "e_A": r.e_A,
        "contact_time_ms": 1e3 * np.asarray(r.contact_time),
        "peak_force_N": r.peak_force,
        "vibration_energy_J": r.vibration_energy,
        "vibration_share": np.divide(r.vibration_energy, r.closing_energy),
        "recontacts": np.asarray(r.recontacts),
        "sweet_zone": (z >= zone[0] - 1e-12) & (z <= zone[1] + 1e-12),
    })  # fmt: skip
    conditions = bat_conditions(bat, ball, pitch_speed, swing, unit, bat_name, ball_name)
    return BatSweep(speeds_in(table, unit, SPEED_COLUMNS), peak_z, peak, zone, conditions, unit)


def _bat_and_ball(bat, ball, support: str | None = None) -> tuple[Bat, Ball]:
    """The bat (default the R161) and the ball (default Nathan's baseball), checked."""
    from ball import BASEBALL_PRESETS, DEFAULT_BASEBALL
    from bat import DEFAULT_BAT

    bat = bat_argument(DEFAULT_BAT if bat is None else bat, support)
    ball = BASEBALL_PRESETS[DEFAULT_BASEBALL].ball() if ball is None else ball_argument(ball)
    return bat, ball


def _speed(name: str, value) -> float:
    """A ball's speed [m/s] in :data:`common.checks.SPEED_RANGE`."""
    from common.checks import speed

    return speed(name, value)


def _points(bat: Bat, z: np.ndarray) -> np.ndarray:
    """Sweep points ``z`` [m from the knob], at least three, distinct: metres from the tip."""
    x = tip_positions(bat, z)
    if z.size < 3 or np.unique(z).size != z.size:
        raise ValueError(
            f"from_knob must give three distinct points or more [m from the knob], got "
            f"{shown(list(z))}"
        )
    return x


REFINE_POINTS = 41
"""Points of the fine sweep between a sweep's best point's neighbours (0.05 cm apart for
1-cm points), where the peak is found."""


def _refined_peak(bat, ball, speed, swing, z, speeds) -> tuple[float, float]:
    """The peak [m from the knob] and its exit speed [m/s]: a fine sweep between the best
    point's neighbours (:data:`REFINE_POINTS`), then the parabola through its best three.
    """
    k = int(np.argmax(speeds))
    fine = np.linspace(z[max(k - 1, 0)], z[min(k + 1, z.size - 1)], REFINE_POINTS)
    x = bat.beam.length - fine
    found = np.asarray(impact(bat, ball, x, speed, **swing_kwargs(bat, swing, x)).ball_rebound)
    return parabola_peak(fine, found)


def parabola_peak(z, values) -> tuple[float, float]:
    """The largest of ``values`` at the points ``z`` [m], refined by the parabola through it
    and its neighbours (the point itself at an end): (where [m], the value [SI]).

    Parameters
    ----------
    z : ndarray
        Evenly spaced points [m].
    values : ndarray
        The values there [SI].
    """
    k = int(np.argmax(values))
    if k in (0, len(values) - 1):
        return float(z[k]), float(values[k])
    a, b, c = values[k - 1], values[k], values[k + 1]
    curve = a - 2.0 * b + c
    shift = 0.5 * (a - c) / curve if curve < 0.0 else 0.0
    h = z[k + 1] - z[k]
    return float(z[k] + shift * h), float(b - 0.25 * (a - c) * shift)


def _zone(z, speeds, peak_z: float, peak: float) -> tuple[float, float]:
    """The ends [m from the knob] of the run of points around the refined peak (``peak_z``,
    ``peak`` [m/s], put among the points ``z`` and ``speeds``) whose speed is within
    :data:`SWEET_ZONE_FRACTION` of the peak, each interpolated linearly to where the speed
    crosses that (or at the sweep's end).
    """
    floor = (1.0 - SWEET_ZONE_FRACTION) * peak
    k = int(np.searchsorted(z, peak_z))
    z = np.insert(np.asarray(z, dtype=float), k, peak_z)
    speeds = np.insert(np.asarray(speeds, dtype=float), k, peak)
    inside = speeds >= floor
    lo = k
    while lo > 0 and inside[lo - 1]:
        lo -= 1
    hi = k
    while hi < z.size - 1 and inside[hi + 1]:
        hi += 1

    def crossing(a: int, b: int) -> float:  # between the points a (inside) and b (outside)
        fraction = (speeds[a] - floor) / (speeds[a] - speeds[b])
        return float(z[a] + fraction * (z[b] - z[a]))

    start = float(z[lo]) if lo == 0 else crossing(lo, lo - 1)
    end = float(z[hi]) if hi == z.size - 1 else crossing(hi, hi + 1)
    return (start, end)
