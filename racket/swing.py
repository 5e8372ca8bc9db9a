"""A swing: the racket rotating about a fixed pivot, so that every point has its own speed."""

from __future__ import annotations

import numbers
from dataclasses import dataclass

import numpy as np

from common.checks import (
    FASTEST_HEAD,
    KGCM2_AS_KGM2,
    SPEED_RANGE,
    in_range,
    positive,
    shown,
    too_fast,
)
from common.checks import speed as check_speed
from common.typechecks import ask, asked_by_caller, instance

WRIST_BEYOND_BUTT = 0.05
"""Default swing pivot: the wrist, this far beyond the butt [m] (a hand on the grip holds
the butt against the heel of the palm; an assumption, not a measurement)."""

ARM_REACH = 1.0
"""Farthest a pivot may be beyond the butt [m]: a straight arm swung from the shoulder (an
arm is about 0.7 m long; the bound is an assumption, generous on purpose)."""

PIVOT_FROM_TIP_RANGE = (0.0, 2.5)
"""Where a pivot may be given [m from the tip], on any racket (the TOML's longest, 1.5 m,
plus :data:`ARM_REACH`); on a racket, it must also be short of the impact points and
within :data:`ARM_REACH` of its butt (:meth:`Swing.check_points`)."""


def ask_head_speed(name: str, value: float) -> None:
    """Ask (a ``UserWarning``, :func:`common.typechecks.ask`) about a racket-head speed
    ``value`` [m/s] faster than any stroke's (:data:`common.checks.FASTEST_HEAD`), naming
    the slips of unit that would explain it, as the command line asks about its own: "head_speed
    90 m/s is faster than any recorded stroke (a racket head's fastest, estimated, about
    51.2 m/s): mph typed as m/s? 90 mph would be 40.23 m/s; ...".

    Parameters
    ----------
    name : str
        The argument's name, as the message quotes it.
    value : float
        The head speed [m/s].
    """
    ask(too_fast, name, value, "m/s", FASTEST_HEAD, "a racket head's fastest, estimated")


def check_swung_support(support: str) -> None:
    """Refuse to swing a racket whose ``support`` is not ``"free"``: a hand or clamp is at
    rest in this model.

    Parameters
    ----------
    support : str
        The racket's support.
    """
    if support != "free":
        raise ValueError(
            f"swing_speed must be 0 for a {support} racket (the hand or clamp is at rest); "
            "swing a free racket, as the paper does"
        )


@dataclass(frozen=True)
class Swing:
    """The racket rotating about a fixed pivot at the moment of impact.

    Parameters
    ----------
    head_speed : float
        Racket-head speed [m/s]: the speed of the string bed's centre towards the ball, in
        [0.001, 300]; one faster than any stroke's (:data:`common.checks.FASTEST_HEAD`,
        about 51.2 m/s) is asked about in a warning, with the slips of unit that would
        explain it (90 for 90 mph).  Every other point moves in proportion to its distance
        from the pivot.
    pivot_from_tip : float or None
        The pivot [m from the tip, like every position]; default None, the wrist, 5 cm
        beyond the butt of the racket swung (:data:`WRIST_BEYOND_BUTT`), whatever its
        length.

    Notes
    -----
    The racket's speed at an impact point x [m from the tip] is omega (x_p - x), with
    x_p the pivot and omega = head_speed / (x_p - x_centre) (small
    rotations during the contact; the rigid-body motion superposes on the collision,
    :mod:`studies.serve`).

    Examples
    --------
    >>> from racket import CATALOG
    >>> racket = CATALOG["pure-drive-2021"].racket()
    >>> swing = Swing(30.0)  # head speed 30 m/s about the wrist
    >>> round(float(swing.point_speeds(racket, racket.strings.center - 0.05)), 2)
    32.67
    """

    head_speed: float
    pivot_from_tip: float | None = None

    def __post_init__(self):
        object.__setattr__(self, "head_speed", check_speed("head_speed", self.head_speed))
        ask_head_speed("head_speed", self.head_speed)
        if self.pivot_from_tip is not None:
            pivot = in_range(
                "pivot_from_tip", self.pivot_from_tip, *PIVOT_FROM_TIP_RANGE, "m from the tip"
            )
            object.__setattr__(self, "pivot_from_tip", pivot)

    def pivot(self, racket) -> float:
        """The pivot [m from the tip] on ``racket``."""
        if self.pivot_from_tip is None:
            return racket.beam.length + WRIST_BEYOND_BUTT
        return self.pivot_from_tip

    def pivot_words(self) -> str:
        """The pivot in words: "about the wrist" or "about 73.6 cm from the tip"."""
        if self.pivot_from_tip is None:
            return f"about the wrist ({100 * WRIST_BEYOND_BUTT:g} cm beyond the butt)"
        return f"about {100 * self.pivot_from_tip:.4g} cm from the tip"

    def angular_velocity(self, racket) -> float:
        """The racket's angular velocity [rad/s]."""
        return self.head_speed / (self.pivot(racket) - racket.strings.center)

    def point_speeds(self, racket, position) -> np.ndarray:
        """Speed [m/s] towards the ball of each point ``position`` [m from the tip]."""
        return self.angular_velocity(racket) * (self.pivot(racket) - np.asarray(position, float))

    def impact_kwargs(self, racket, position) -> dict:
        """The ``swing_speed`` and ``pivot`` of :func:`racket.impact` for this swing, each
        point checked first (:meth:`check_points`).
        """
        self.check_points(racket, position)
        return {"swing_speed": self.point_speeds(racket, position), "pivot": self.pivot(racket)}

    def reach(self, racket, position) -> tuple[float, float, float]:
        """What this swing may be for the impact points ``position`` [m from the tip]: the
        pivot must be short of every point and of the string centre, > the first value [m
        from the tip], so that each moves towards the ball; and the head speed between the
        second and the third [m/s], so that it and each point's speed are in
        :data:`common.checks.SPEED_RANGE` (the point nearest the tip is the fastest; both
        are ``inf`` when the pivot is not short of the points).

        Parameters
        ----------
        racket : Racket
            The racket swung.
        position : array_like
            Impact points [m from the tip].
        """
        x = np.asarray(position, dtype=float)
        nearest_butt = max(float(np.max(x, initial=-np.inf)), racket.strings.center)
        pivot_limit = nearest_butt
        if self.pivot(racket) <= pivot_limit:
            return pivot_limit, np.inf, np.inf
        ratio = (self.pivot(racket) - x) / (self.pivot(racket) - racket.strings.center)
        return (
            pivot_limit,
            SPEED_RANGE[0] / float(np.min(ratio, initial=1.0)),
            SPEED_RANGE[1] / float(np.max(ratio, initial=1.0)),
        )

    def check_points(self, racket, position, head=None, pivot=None) -> None:
        """Raise ``ValueError`` naming the pivot if it is not short of the impact points
        ``position`` [m from the tip] or is more than :data:`ARM_REACH` beyond the butt, or
        the head speed if it moves one of them out of
        :data:`common.checks.SPEED_RANGE` (:meth:`reach`).

        Parameters
        ----------
        racket, position
            As in :meth:`Swing.reach`.
        head, pivot : (str, float, str, float), optional
            How the caller's user gave the head speed and the pivot, for the message: the
            name, the value as typed, its unit and the unit's size [m/s or m], e.g.
            ``("--swing-speed-mph", 60.0, "mph", MPH)``; default ``head_speed`` [m/s] and
            ``pivot_from_tip`` [m from the tip].
        """
        pivot_limit, low, high = self.reach(racket, position)
        name, typed, unit, size = pivot or (
            "pivot_from_tip", self.pivot_from_tip, "m from the tip", 1.0
        )  # fmt: skip
        farthest = racket.beam.length + ARM_REACH
        if not pivot_limit < self.pivot(racket) <= farthest:
            raise ValueError(
                f"{name} must be in ({pivot_limit / size:.4g}, {farthest / size:.4g}] {unit}: "
                f"short of the impact points and the string centre, at most "
                f"{100 * ARM_REACH:g} cm beyond the butt (an arm), got {shown(typed)}"
            )
        name, typed, unit, size = head or ("head_speed", self.head_speed, "m/s", 1.0)
        if not low <= self.head_speed <= high:
            raise ValueError(
                f"{name} must be in [{low / size:.4g}, {high / size:.4g}] {unit} for these "
                f"impact points (each must move at {SPEED_RANGE[0] / size:.4g}-"
                f"{SPEED_RANGE[1] / size:.4g} {unit}), got {shown(typed)}"
            )


EFFORT_EXPONENT = 0.27
"""Players swing a racket of larger swingweight I0 more slowly, V = C / I0**n with
n = 0.27 (R. Cross and R. Bower, "Effects of swing-weight on swing speed and racket power",
J. Sports Sci. 24 (2006) 23-30, abstract; for I0 > 0.03 kg m^2).  I0 is taken as the
swingweight, the moment of inertia about the axis 10 cm from the butt (an assumption: the
abstract does not name the axis; a hand-held swing's axis is near it)."""

SWINGWEIGHT_RANGE = (1e-4, 2.0)
"""The swingweights [kg m^2] :func:`equal_effort` accepts: **an assumption**, generous
around the rackets racket-impact builds (strung tennis rackets 0.028-0.036 kg m^2, 280-360
kg cm^2, :data:`racket.specs.sheet.SPEC_RANGES`; a TOML frame of 0.2-1.5 m and 0.05-2 kg,
``studies.config.TOML_RANGES``, 2e-4 to 1.2 kg m^2).  A swingweight in kg cm^2, as spec
sheets give it, typed as kg m^2 (325 for 0.0325) is refused with the hint, not turned into
a head speed 12 times too fast."""


def equal_effort(swing: Swing, reference_swingweight: float, swingweight: float) -> Swing:
    """The swing a player makes with a racket of ``swingweight`` at the effort that swings a
    racket of ``reference_swingweight`` at ``swing``: the head speed scaled by
    (reference_swingweight / swingweight)**:data:`EFFORT_EXPONENT`, about the same pivot.

    Parameters
    ----------
    swing : Swing
        The reference racket's swing (a head speed alone is refused, saying how to make one:
        ``Swing(30.0)``).
    reference_swingweight, swingweight : float
        Swingweights [kg m^2] (axis 10 cm from the butt) of the reference racket and of
        the racket swung, each in :data:`SWINGWEIGHT_RANGE`.

    Examples
    --------
    >>> slower = equal_effort(Swing(30.0), 0.0320, 0.0330)
    >>> round(slower.head_speed, 3)
    29.752
    """
    number = isinstance(swing, numbers.Real) and not isinstance(swing, bool)
    hint = f" (a head speed? racket.Swing({shown(swing)}) swings about the wrist)" if number else ""
    instance("swing", swing, Swing, "a racket.Swing", hint)
    reference, swung = (
        in_range(name, positive(name, value, "kg m^2"), *SWINGWEIGHT_RANGE, "kg m^2",
                 slips=(KGCM2_AS_KGM2,))
        for name, value in (("reference_swingweight", reference_swingweight),
                            ("swingweight", swingweight))
    )  # fmt: skip
    head = swing.head_speed * (reference / swung) ** EFFORT_EXPONENT
    if not SPEED_RANGE[0] <= head <= SPEED_RANGE[1]:  # named by the swingweights, its cause
        raise ValueError(
            f"swingweight {shown(swingweight)} kg m^2 against reference_swingweight "
            f"{shown(reference_swingweight)} kg m^2 gives an equal-effort head speed of "
            f"{head:.4g} m/s, outside [{SPEED_RANGE[0]:g}, {SPEED_RANGE[1]:g}] m/s"
        )
    with asked_by_caller():  # the swing given was asked about; this one follows from it
        return Swing(head, swing.pivot_from_tip)
