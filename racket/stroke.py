"""The geometry of a tennis stroke: where the racket and the ball go, seen from the face.

Pure kinematics: no physics of the contact.  A :class:`Stroke` gives the racket point's and
the incoming ball's velocities and spin; :meth:`Stroke.face_frame` resolves them on the face
(:class:`FaceFrame`), where a model of the contact works; :meth:`Stroke.to_world` turns that
model's answer back into a :class:`Flight`.

Conventions (SI throughout: angles in radians, speeds in m/s, spin in rad/s):

* World frame: X forward (towards the net, where the player hits), Y to the player's left,
  Z up.
* A ball's spin is split on its horizontal flight direction d (unit; +X for a vertical
  flight): **topspin** about Z x d (for a ball flying +X the axis is +Y, and the top of the
  ball moves forwards), **sidespin** about +Z (counter-clockwise seen from above: it curves
  the ball to its left), **rifle spin** about d itself.  The three axes are orthonormal.
* Face frame: e_n, the face normal, points forward (where the ball goes); e_along is the
  racket's long axis, e_across = e_n x e_along; components are ordered (along, across,
  normal).  With the shaft ``"horizontal"`` (groundstrokes, volleys) e_along = unit(Z x n)
  = +Y (towards the player's left) and e_across points up the face; with the shaft
  ``"vertical"`` (serves) e_along = unit(Z - (Z.n) n) points up the face (the tip up) and
  e_across = -Y (towards the player's right).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ball.spin import ask_spin
from common.checks import (
    FASTEST_STROKE,
    KMH_AS_M_S,
    MPH_AS_M_S,
    RPM_AS_RAD_S,
    finite,
    finite_array,
    in_range,
    too_fast,
)
from common.typechecks import ask
from common.units import MPH
from racket.swing import ask_head_speed

RPM = 2.0 * math.pi / 60.0
"""One revolution per minute [rad/s] (spin is quoted in rpm)."""

LIMITS = {
    "head_speed": (0.0, 60.0, "m/s"),
    "path_angle": (-60.0, 80.0, "deg"),
    "face_angle": (-60.0, 60.0, "deg"),
    "ball_speed": (0.0, 80.0, "m/s"),
    "ball_angle": (-60.0, 60.0, "deg"),
    "swing_across": (-60.0, 60.0, "deg"),
    "topspin": (-1000.0, 1000.0, "rad/s"),
    "sidespin": (-1000.0, 1000.0, "rad/s"),
}
"""The range of each input of a :class:`Stroke` and its unit (angles are given in radians,
their ranges here in degrees): head speeds from 0 (a block) to above the fastest serves, ball
speeds to above the serve record (73 m/s), spins to +-9549 rpm, twice the most measured.
Inside them, a head speed above :data:`common.checks.FASTEST_HEAD`, a ball speed above
:data:`common.checks.FASTEST_STROKE` and a spin above :data:`ball.spin.MOST_SPIN` are asked
about in a warning, with the slips of unit that would explain them (mph or km/h typed as m/s,
rpm typed as rad/s)."""

# The slips of unit (common.checks.slip_hints) a message names, by the unit asked for
_DEG_AS_RAD = (math.pi / 180.0, "degrees typed as radians?", "deg")
_SLIPS = {"m/s": (MPH_AS_M_S, KMH_AS_M_S), "deg": (_DEG_AS_RAD,), "rad/s": (RPM_AS_RAD_S,)}

SHAFTS = ("horizontal", "vertical")
"""How the racket's long axis lies in the face plane: groundstrokes and volleys, serves."""

_X, _Z = np.array([1.0, 0.0, 0.0]), np.array([0.0, 0.0, 1.0])


def rpm(omega):
    """A spin [rad/s] in revolutions per minute [rpm] (a float, or an array for an array).

    Parameters
    ----------
    omega : float or array_like
        Spin [rad/s].
    """
    return np.asarray(omega, dtype=float) / RPM if np.ndim(omega) else float(omega) / RPM


def rad_per_s(rpm):
    """A spin [rpm] in radians per second [rad/s] (a float, or an array for an array).

    Parameters
    ----------
    rpm : float or array_like
        Spin [rpm].
    """
    return np.asarray(rpm, dtype=float) * RPM if np.ndim(rpm) else float(rpm) * RPM


def _checked(name: str, value) -> float:
    """``value`` in its range of :data:`LIMITS` (an angle in radians), as a float."""
    low, high, unit = LIMITS[name]
    if unit != "deg":
        return in_range(name, value, low, high, unit, slips=_SLIPS[unit])
    x, bounds = finite(name, value, "rad"), (math.radians(low), math.radians(high))
    if abs(x) > 2.0 * math.pi:  # likely degrees: say what they would be in radians
        return in_range(name, x, *bounds, "rad", slips=_SLIPS[unit])
    hint = f" (that is {math.degrees(x):.4g} deg; the range is {low:g} to {high:g} deg)"
    return in_range(name, x, *bounds, "rad", hint)


def _horizontal_direction(velocity: np.ndarray) -> np.ndarray:
    """The unit horizontal direction of ``velocity`` [m/s]; +X for a vertical one."""
    size = math.hypot(velocity[0], velocity[1])
    if size <= 1e-12 * float(np.linalg.norm(velocity)):  # vertical, or no flight at all
        return _X.copy()
    return np.array([velocity[0] / size, velocity[1] / size, 0.0])


def _frozen(a: np.ndarray) -> np.ndarray:
    a = np.array(a, dtype=float)
    a.setflags(write=False)
    return a


def _vector(name: str, value, size: int, unit: str) -> np.ndarray:
    a = finite_array(name, value, unit)
    if a.shape != (size,):
        raise ValueError(f"{name} must hold {size} numbers [{unit}], got shape {a.shape}")
    return a


@dataclass(frozen=True, eq=False)
class FaceFrame:
    """A stroke seen from the face, just before the impact.

    Attributes
    ----------
    closing_speed : float
        Speed [m/s] at which the ball and the racket point approach along the normal,
        (v_racket - v_ball) . n, > 0.
    ball_normal_speed : float
        The ball's speed towards the face [m/s], -v_ball . n (< 0 if the ball moves away
        from a face that catches up with it).
    racket_normal_speed : float
        The racket point's speed along the normal [m/s], v_racket . n.
    slip_velocity : ndarray
        Tangential velocity [m/s] of the ball's centre relative to the racket point,
        (along, across), shape (2,).
    spin : ndarray
        The ball's spin vector [rad/s] in (along, across, normal) components, shape (3,).
    basis : ndarray
        The rows e_along, e_across, e_n in world coordinates [-], shape (3, 3);
        ``basis @ world`` gives face components, ``basis.T @ face`` world ones.
    """

    closing_speed: float
    ball_normal_speed: float
    racket_normal_speed: float
    slip_velocity: np.ndarray
    spin: np.ndarray
    basis: np.ndarray


@dataclass(frozen=True, eq=False)
class Flight:
    """A ball's flight just after the impact, in the world frame.

    Parameters
    ----------
    velocity : array_like
        The ball's velocity [m/s] (X forward, Y left, Z up), shape (3,).
    spin : array_like
        The ball's spin vector [rad/s], shape (3,).

    Attributes
    ----------
    speed : float
        ``|velocity|`` [m/s].
    launch_angle : float
        The flight's angle above the horizontal [rad].
    direction : float
        The horizontal angle of the flight from +X [rad], + to the left (0 for a vertical
        flight).
    topspin, sidespin, rifle_spin : float
        The spin's components [rad/s] about Z x d, Z and d, d the horizontal flight
        direction (+X for a vertical flight).
    spin_rate : float
        ``|spin|`` [rad/s].
    """

    velocity: np.ndarray
    spin: np.ndarray
    speed: float = field(init=False)
    launch_angle: float = field(init=False)
    direction: float = field(init=False)
    topspin: float = field(init=False)
    sidespin: float = field(init=False)
    rifle_spin: float = field(init=False)
    spin_rate: float = field(init=False)

    def __post_init__(self):
        v = _vector("velocity", self.velocity, 3, "m/s")
        w = _vector("spin", self.spin, 3, "rad/s")
        d = _horizontal_direction(v)
        values = {
            "velocity": _frozen(v),
            "spin": _frozen(w),
            "speed": float(np.linalg.norm(v)),
            "launch_angle": math.atan2(v[2], math.hypot(v[0], v[1])),
            "direction": math.atan2(d[1], d[0]),
            "topspin": float(w @ np.cross(_Z, d)),
            "sidespin": float(w[2]),
            "rifle_spin": float(w @ d),
            "spin_rate": float(np.linalg.norm(w)),
        }
        for name, value in values.items():
            object.__setattr__(self, name, value)


@dataclass(frozen=True)
class Stroke:
    """A stroke at the moment of impact: the racket point's and the ball's motion.

    Parameters
    ----------
    head_speed : float
        Speed of the racket at the impact point [m/s], in [0, 60].
    path_angle : float
        The racket path's angle above the horizontal [rad] (+ rising), in [-60, 80] deg.
    face_angle : float
        The face's tilt from vertical [rad]: + open (the normal points upward), - closed;
        in [-60, 60] deg.  The normal is n = (cos f, 0, sin f).
    ball_speed : float
        The incoming ball's speed [m/s], in [0, 80].
    ball_angle : float
        The incoming ball's direction below the horizontal [rad] (+ descending), in
        [-60, 60] deg; it flies towards the player: v = ball_speed (-cos b, 0, -sin b).
    swing_across : float, optional
        Horizontal angle [rad] of the racket path from the face's aim, + towards the player's
        left; in [-60, 60] deg.  The racket point moves at
        head_speed (cos a cos g, cos a sin g, sin a), a the path angle, g this angle.
    topspin, sidespin : float, optional
        The incoming ball's spin [rad/s] in its own flight frame (its horizontal flight
        direction d = -X: topspin about Z x d = -Y, sidespin about +Z), each in [-1000, 1000]
        (one above :data:`ball.spin.MOST_SPIN`, 523.6 rad/s, is asked about: rpm typed as
        rad/s?).
    shaft : str, optional
        ``"horizontal"`` (groundstrokes, volleys) or ``"vertical"`` (serves): how the long
        axis lies in the face plane (the module's docstring).

    Raises
    ------
    ValueError
        For an input out of its range, or a racket that does not close on the ball.

    Examples
    --------
    >>> s = Stroke(20.0, 0.0, 0.0, 15.0, 0.0)
    >>> s.face_frame().closing_speed
    35.0
    """

    head_speed: float
    path_angle: float
    face_angle: float
    ball_speed: float
    ball_angle: float
    swing_across: float = 0.0
    topspin: float = 0.0
    sidespin: float = 0.0
    shaft: str = "horizontal"

    def __post_init__(self):
        for name in LIMITS:
            object.__setattr__(self, name, _checked(name, getattr(self, name)))
        ask_head_speed("head_speed", self.head_speed)  # in range, but faster than any stroke?
        ask(too_fast, "ball_speed", self.ball_speed, "m/s", FASTEST_STROKE, "the serve record")
        for name in ("topspin", "sidespin"):
            ask_spin(name, getattr(self, name))
        if not isinstance(self.shaft, str) or self.shaft not in SHAFTS:
            raise ValueError(f"shaft must be 'horizontal' or 'vertical', got {self.shaft!r}")
        closing = float((self.racket_velocity() - self.ball_velocity()) @ self.normal())
        if closing <= 0.0:
            raise ValueError(
                f"the racket misses the ball: they close at {closing:.4g} m/s along the face "
                "normal (must be > 0); raise head_speed or ball_speed, or bring path_angle "
                "and ball_angle nearer face_angle"
            )

    def normal(self) -> np.ndarray:
        """The face normal n [-], pointing forward: (cos f, 0, sin f)."""
        f = self.face_angle
        return np.array([math.cos(f), 0.0, math.sin(f)])

    def basis(self) -> np.ndarray:
        """The face axes [-] as rows e_along, e_across, e_n in world coordinates (3, 3)."""
        n = self.normal()
        along = np.cross(_Z, n) if self.shaft == "horizontal" else _Z - n[2] * n
        along /= np.linalg.norm(along)
        return np.array([along, np.cross(n, along), n])

    def racket_velocity(self) -> np.ndarray:
        """The racket point's velocity [m/s] before the impact, world frame (3,)."""
        a, g = self.path_angle, self.swing_across
        direction = [math.cos(a) * math.cos(g), math.cos(a) * math.sin(g), math.sin(a)]
        return self.head_speed * np.array(direction)

    def ball_velocity(self) -> np.ndarray:
        """The incoming ball's velocity [m/s], world frame (3,)."""
        b = self.ball_angle
        return self.ball_speed * np.array([-math.cos(b), 0.0, -math.sin(b)])

    def ball_spin(self) -> np.ndarray:
        """The incoming ball's spin vector [rad/s], world frame (3,): topspin about
        Z x (-X) = -Y, sidespin about Z.
        """
        return np.array([0.0, -self.topspin, self.sidespin])

    def face_frame(self) -> FaceFrame:
        """The stroke resolved on the face, just before the impact (:class:`FaceFrame`)."""
        basis = self.basis()
        n = basis[2]
        v_racket, v_ball = self.racket_velocity(), self.ball_velocity()
        relative = basis @ (v_ball - v_racket)
        return FaceFrame(
            closing_speed=float(-relative[2]),
            ball_normal_speed=float(-v_ball @ n),
            racket_normal_speed=float(v_racket @ n),
            slip_velocity=_frozen(relative[:2]),
            spin=_frozen(basis @ self.ball_spin()),
            basis=_frozen(basis),
        )

    def to_world(
        self, tangential_velocity, normal_velocity, spin_face, racket_velocity_change=None
    ) -> Flight:
        """The ball's :class:`Flight` after the impact, from a contact model's face answer.

        Its world velocity is v_racket + racket_velocity_change + the relative velocity
        given: relative to the racket point as it moves after the contact (with no change,
        as before it).  How much the racket point slows is the caller's to say.

        Parameters
        ----------
        tangential_velocity : array_like
            The ball's velocity relative to the racket point along the face [m/s],
            (along, across), shape (2,).
        normal_velocity : float
            Its velocity relative to the racket point along the normal [m/s]: > 0 for a
            ball leaving the face (a negative one, a ball still closing, is accepted: the
            incoming ball's components return the incoming ball).
        spin_face : array_like
            The ball's spin [rad/s] in (along, across, normal) components, shape (3,).
        racket_velocity_change : array_like, optional
            The racket point's change of velocity during the contact [m/s], in (along,
            across, normal) components, shape (3,); default zeros.
        """
        tangential = _vector("tangential_velocity", tangential_velocity, 2, "m/s")
        normal = finite("normal_velocity", normal_velocity, "m/s")
        spin = _vector("spin_face", spin_face, 3, "rad/s")
        change = np.zeros(3)
        if racket_velocity_change is not None:
            change = _vector("racket_velocity_change", racket_velocity_change, 3, "m/s")
        basis = self.basis()
        relative = np.array([tangential[0], tangential[1], normal])
        velocity = self.racket_velocity() + basis.T @ (relative + change)
        return Flight(velocity, basis.T @ spin)


_SERVE_HEAD = 38.0  # [m/s] Gordon: "slightly more than 85 mph" 0.01 s before contact
_TOSS = {"ball_speed": 1.5, "ball_angle": math.radians(60.0)}  # the tossed ball (assumption)
_KNUDSON = {"head_speed": 49 * MPH, "ball_speed": 45 * MPH}  # a forehand (sources below)
_RALLY = {"ball_angle": math.radians(10.0), "topspin": 200.0}  # incoming ball (assumption)
_DEG = math.radians
_KWON_PATH = _DEG(18.6)  # [rad] Kwon et al. 2017: head path 18.6 +/- 4.3 deg above horizontal
_TOUR_FOREHAND = {
    # Landlinger et al. 2010: ATP forehands' peak horizontal racket speed 33.1 m/s, taken as
    # the head's horizontal speed at impact; along Kwon's path, its speed is that / cos(path)
    "head_speed": 33.1 / math.cos(_KWON_PATH),
    "path_angle": _KWON_PATH,
    "face_angle": 0.0,  # vertical: an assumption (Kwon's 80.4 deg has no stated reference)
    "ball_speed": 20.0,  # Landlinger's ball machine, "about 20 m/s"
    "ball_angle": _DEG(10.0),  # descending: an assumption
}

STROKES = {
    "flat-serve": Stroke(_SERVE_HEAD, 0.0, _DEG(-7.0), **_TOSS, shaft="vertical"),
    "slice-serve": Stroke(
        _SERVE_HEAD, _DEG(5.0), _DEG(-8.0), **_TOSS, swing_across=_DEG(-25.0), shaft="vertical"
    ),
    "kick-serve": Stroke(
        _SERVE_HEAD, _DEG(5.0), 0.0, **_TOSS, swing_across=_DEG(-45.0), shaft="vertical"
    ),
    "topspin-forehand": Stroke(**_TOUR_FOREHAND),
    "flat-forehand": Stroke(path_angle=_DEG(5.0), face_angle=_DEG(4.0), **_KNUDSON, **_RALLY),
    "slice-backhand": Stroke(15.0, _DEG(-15.0), _DEG(12.0), 45 * MPH, **_RALLY),
    "volley": Stroke(5.0, 0.0, _DEG(5.0), 20.0, _DEG(5.0), topspin=200.0),
}
"""Typical strokes of a right-handed player, by name (:data:`STROKE_SOURCES` says where each
number comes from: the serves' head speed is Gordon's, the topspin forehand's Landlinger's
tour players' along Kwon's measured path, the kick serve's geometry Cross's description).
Where no measurement exists the face angles are assumptions, each chosen so that a crude
estimate launches the ball as the stroke would (serves from 2.7 m a few degrees below
horizontal): the ball leaving along n at 0.4 times its incoming normal speed plus 1.4 times
the racket's (an apparent COR of 0.4, TWU "Racquet Control"), its sliding velocity on the
face cut to half; the topspin forehand's and the kick serve's faces are vertical, the
neutral choice (their sources describe the path, not the face)."""

STROKE_SOURCES = {
    "flat-serve": "head speed 38 m/s: Gordon, 'The serve and tennis science', "
    "tennisplayer.net ('slightly more than 85 mph' 0.01 s before contact, nine NCAA Division I "
    "servers); path 0, toss 1.5 m/s falling at 60 deg, face 7 deg closed: assumptions.",
    "slice-serve": "the flat serve's head speed and toss; path +5 deg, swing_across -25 deg "
    "(the racket brushes the ball's back to the right: sidespin curving it to the left, a "
    "right-hander's slice), face 8 deg closed: assumptions.",
    "kick-serve": "the flat serve's head speed and toss; Cross, 'Physics of the tennis kick "
    "serve' (TWU 2011, Sports Technology 2012): the racket near the top of its arc (face "
    "vertical: an assumption), an upward approach 'much smaller than' a forehand's (+5 deg "
    "against Kwon's 18.6: an assumption), mostly across the ball (swing_across -45 deg, the "
    "least angle at which it moves as much across as forward: an assumption).",
    "topspin-forehand": "tour players' kinematics: head's horizontal speed 33.1 m/s "
    "(Landlinger et al., J. Sports Sci. Med. 9 (2010): ATP players' peak horizontal racket "
    "speed) along a path rising 18.6 deg (Kwon et al., J. Sports Sci. Med. 16 (2017), "
    "collegiate players), 34.9 m/s along it; ball from Landlinger's machine at about 20 m/s, "
    "descending at 10 deg, no spin: assumptions (the machine's spin is not stated); face "
    "vertical: an assumption (Kwon's 80.4 +/- 3.6 deg 'impact angle' has a reference not in "
    "the stored text).",
    "flat-forehand": "Knudson's head and ball speeds (teaching pros: head 49 mph, 21.9 m/s; "
    "ball 45 mph, 20.1 m/s; Knudson as summarised by Yandell, 'Comparing the open and closed "
    "stances', tennisplayer.net); path +5 deg, face 4 deg open, ball descending at 10 deg "
    "with 200 rad/s of topspin: assumptions.",
    "slice-backhand": "ball at 45 mph (Knudson's forehands); head 15 m/s falling at 15 deg, "
    "face 12 deg open, ball descending at 10 deg with 200 rad/s of topspin: assumptions.",
    "volley": "head 5 m/s, path 0, face 5 deg open, ball at 20 m/s descending at 5 deg with "
    "200 rad/s of topspin: assumptions.",
}
"""Where each number of :data:`STROKES` comes from, or that it is an assumption."""
