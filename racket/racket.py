"""A racket: a free-free beam, a string bed on it, and how it is held."""

from __future__ import annotations

from dataclasses import dataclass, replace
from functools import cached_property

import numpy as np

from beam import Beam
from common.checks import (
    GRAMS_AS_KG,
    finite_array,
    impact_positions,
    in_range,
    non_negative,
    positive,
    shown,
)
from common.typechecks import choice, instance
from racket.hand import GRIPS, Hand
from racket.head import HEAD_ASPECT, Hoop
from racket.membrane import bed_radius, stiffness_ratio
from racket.swing import check_swung_support
from racket.system import (
    clamped_system,
    face_system,
    point_shapes,
    racket_system,
    roll_system,
)

SUPPORTS = ("free", "clamped-head", "hand-held")
STRING_PROFILES = ("uniform", "membrane")

STRETCH_MAX = 1e5
"""Largest :attr:`StringBed.stretch` [1/m^2]: the bed twice as stiff at a 3 mm deflection,
far beyond any string (a polyester bed at 20 lb, the stiffest case, has about 6e3)."""

BED_LOSS_MAX = 0.3
"""Largest :attr:`StringBed.loss` [-]: beyond a third, a stiffening bed's unloading curve
could turn back on itself; strings lose about 5 % (Kawazoe's steel ball, COR 0.97)."""

BED_MASS_MAX = 0.02
"""Largest :attr:`StringBed.moving_mass` [kg]: the whole of a 20 g string bed moving with
the ball, beyond any bed (a 16x19 bed weighs 12-20 g, of which about a quarter moves)."""

ADDED_MASS_MAX = 0.2
"""The most mass [kg] :meth:`Racket.with_mass` and :meth:`Racket.with_lead_tape` add at a
point: **an assumption**, generous on purpose (players add a few grams of lead tape; 200 g
is two thirds of a strung racket again), the TOML's ``lead_tape`` and ``--lead`` limit
too.  A mass in grams typed as kg (5 for 0.005) is refused with the hint."""


def added_mass(name: str, value) -> float:
    """A point mass added to a racket [kg], in (0, :data:`ADDED_MASS_MAX`]: ValueError
    naming ``name``, with the range and a likely slip of unit (grams typed as kg), otherwise.

    Parameters
    ----------
    name : str
        The argument's name, as the message quotes it.
    value : object
        The mass [kg].
    """
    mass = positive(name, value, "kg")
    return in_range(name, mass, 0.0, ADDED_MASS_MAX, "kg", slips=(GRAMS_AS_KG,))


@dataclass(frozen=True)
class StringBed:
    """The string plane: a spring between the ball and the frame, linear and lossless
    (the paper's) or stiffening as it deflects and losing a fraction of what it stores.

    Pushed by a force F the bed deflects by w with F = k w (1 + ``stretch`` w**2) while
    loading (k its stiffness at the point); unloading returns (1 - ``loss``) of the energy
    it stored, along a curve set back from the loading one by the deflection that leaves
    that loop's area (:mod:`racket.solver.bed_kernel`).

    Parameters
    ----------
    stiffness : float
        Stiffness of the string plane against a ball pushed into it [N/m] (about 3e4 to
        4e4 N/m for a racket strung at 55 lb; paper Secs. III and VIII).
    extent : (float, float)
        Where the strings are, as distances from the tip [m]: (start, end), start < end.
    width : float or None
        Width of the string bed across the racket [m]; None (default) for an elliptical bed
        of length / width :data:`racket.head.HEAD_ASPECT`.
    profile : str
        How the stiffness varies over the face: ``"uniform"`` (default; ``stiffness``
        everywhere, as in the paper) or ``"membrane"`` (``stiffness`` at the centre, rising
        towards the frame, :mod:`racket.membrane`).
    stretch : float
        How fast the bed stiffens as it deflects [1/m^2]: F = k w (1 + stretch w**2); 0
        (default) for the paper's linear bed.  The strings lengthen as they deflect, so
        their tension rises with their axial stiffness EA (:mod:`racket.stringing`).
    loss : float
        Fraction [-] of the energy stored in the bed that a load and unload dissipates (the
        strings' hysteresis and the friction between mains and crosses), in [0, 0.3]; 0
        (default) for the paper's lossless bed.
    stringing : object or None
        What the bed was strung with (:class:`racket.stringing.Stringing`), for the
        outputs' conditions; None for a bed given by its numbers.
    moving_mass : float
        The bed's mass that moves with the ball [kg], in [0, 0.02]: a third body between
        the ball and the frame, pushed by the ball and pushing the frame through the bed's
        law (:mod:`racket.solver.bed_mass_kernel`), whose own vibration the ball does not
        get back; 0 (default) for the paper's massless bed.  The frame keeps the whole
        strung mass as well (**an assumption**: see
        :meth:`racket.stringing.Stringing.moving_mass`).
    """

    stiffness: float
    extent: tuple
    width: float | None = None
    profile: str = "uniform"
    stretch: float = 0.0
    loss: float = 0.0
    stringing: object = None
    moving_mass: float = 0.0

    def __post_init__(self):
        object.__setattr__(self, "stiffness", positive("stiffness", self.stiffness, "N/m"))
        extent = finite_array("extent", self.extent, "m from the tip")
        if extent.shape != (2,):
            raise ValueError(
                f"extent must be (start, end) [m from the tip], got {shown(self.extent)}"
            )
        start = non_negative("extent start", extent[0], "m from the tip")
        end = positive("extent end", extent[1], "m from the tip")
        if end <= start:
            raise ValueError(f"extent must have start < end [m from the tip], got {self.extent!r}")
        object.__setattr__(self, "extent", (start, end))
        if self.width is not None:
            object.__setattr__(self, "width", positive("strings width", self.width, "m"))
        choice("string bed profile", self.profile, STRING_PROFILES)
        stretch = non_negative("string bed stretch", self.stretch, "1/m^2")
        object.__setattr__(self, "stretch", in_range("string bed stretch", stretch, 0.0,
                                                     STRETCH_MAX, "1/m^2"))  # fmt: skip
        loss = non_negative("string bed loss", self.loss, "")
        object.__setattr__(self, "loss", in_range("string bed loss", loss, 0.0, BED_LOSS_MAX, ""))
        mass = non_negative("string bed moving mass", self.moving_mass, "kg")
        object.__setattr__(self, "moving_mass", in_range("string bed moving mass", mass, 0.0,
                                                         BED_MASS_MAX, "kg",
                                                         slips=(GRAMS_AS_KG,)))  # fmt: skip
        if self.profile == "membrane":
            bed_radius(self.area)  # refuses a bed too small for the membrane model

    @property
    def plain(self) -> bool:
        """True for the paper's bed: linear, lossless and massless."""
        return self.stretch == 0.0 and self.loss == 0.0 and self.moving_mass == 0.0

    @property
    def center(self) -> float:
        """Geometric centre of the string bed [m from the tip]."""
        return 0.5 * (self.extent[0] + self.extent[1])

    @property
    def full_width(self) -> float:
        """Width of the string bed [m] (:attr:`width`, or from :data:`HEAD_ASPECT`)."""
        if self.width is not None:
            return self.width
        return (self.extent[1] - self.extent[0]) / HEAD_ASPECT

    @property
    def aspect(self) -> float:
        """Length over width of the string bed [-]."""
        return (self.extent[1] - self.extent[0]) / self.full_width

    @property
    def area(self) -> float:
        """Area of the (elliptical) string bed [m^2]."""
        return 0.25 * np.pi * (self.extent[1] - self.extent[0]) * self.full_width

    def rho2(self, x, y=0.0) -> np.ndarray:
        """Squared elliptical radius of the points (``x`` [m from the tip], ``y`` [m from
        the long axis]): 0 at the bed's centre, 1 on its edge.
        """
        half_length = 0.5 * (self.extent[1] - self.extent[0])
        dx = (np.asarray(x, dtype=float) - self.center) / half_length
        return dx**2 + (np.asarray(y, dtype=float) / (0.5 * self.full_width)) ** 2

    @property
    def stiffest(self) -> float:
        """The largest string-plane stiffness anywhere on the bed [N/m] (the solver's time
        step follows from it): :attr:`stiffness` for a uniform bed.
        """
        if self.profile == "uniform":
            return self.stiffness
        return self.stiffness * float(stiffness_ratio(1.0, self._radius))

    @property
    def _radius(self) -> float:
        """Radius [m] of the circle of the bed's area (the membrane model's)."""
        return bed_radius(self.area)

    def stiffness_at(self, x, y=0.0) -> np.ndarray:
        """String-plane stiffness [N/m] at (``x`` [m from the tip], ``y`` [m from the long
        axis]): :attr:`stiffness` for a uniform bed; the membrane's rise towards the frame
        (:func:`racket.membrane.stiffness_ratio`) for a ``"membrane"`` one.
        """
        x, y = np.broadcast_arrays(np.asarray(x, dtype=float), np.asarray(y, dtype=float))
        if self.profile == "uniform":
            return np.full(x.shape, self.stiffness)
        return self.stiffness * stiffness_ratio(self.rho2(x, y), self._radius)


@dataclass(frozen=True)
class Racket:
    """A racket frame (a free-free beam), its string bed, and its support.

    Parameters
    ----------
    beam : Beam
        The frame, tip at x = 0.
    strings : StringBed
        The string bed; it must lie on the beam.
    support : str
        ``"free"`` (default): the racket is free during the impact; a hand's impulse over
        the 4-5 ms of contact is negligible (paper Sec. VII).  ``"clamped-head"``: the head
        is rigidly held, so the strings act on an immovable support, as in head-clamped COR
        tests.  ``"hand-held"``: the handle is held by ``hand``.
    hand : Hand
        The hand of a hand-held racket (ignored otherwise).
    """

    beam: Beam
    strings: StringBed
    support: str = "free"
    hand: Hand = GRIPS["medium"]

    def __post_init__(self):
        instance("beam", self.beam, Beam, "a beam.Beam")
        instance("strings", self.strings, StringBed, "a racket.StringBed")
        choice("support", self.support, SUPPORTS)
        instance("hand", self.hand, Hand, "a racket.Hand")
        if self.strings.extent[1] > self.beam.length:
            raise ValueError(
                f"strings extent {self.strings.extent} runs past the beam's length "
                f"{self.beam.length:g} m"
            )
        if self.hand.grip_length >= self.beam.length - self.strings.extent[1]:
            raise ValueError(
                f"grip_length must end below the strings, < "
                f"{self.beam.length - self.strings.extent[1]:g} m, got {self.hand.grip_length!r}"
            )

    @cached_property
    def system(self):
        """The racket's linear dynamics in real 2x2 blocks (:mod:`racket.system`), for its
        support; computed once.
        """
        return racket_system(self.beam.modes, self.support, self.hand)

    @cached_property
    def face_system(self):
        """The block system with the roll and torsion modes beside the bending ones
        (:func:`racket.system.face_system`), for impacts off the long axis; None when the
        beam's roll inertia is not modelled.  Computed once.
        """
        roll = self.beam.roll_modes
        if roll is None:
            return None
        if self.support == "clamped-head":
            return clamped_system()
        length = self.beam.length
        return face_system(self.system, roll_system(roll, length, self.support, self.hand))

    def point_dynamics(self, x, y=None):
        """The block system for impacts at points (``x`` [m from the tip], ``y`` [m from the
        long axis] or None) and the points' modal shapes: (system, phi (P, N), face) with
        0 for a hand's coordinate (:attr:`racket.system.BlockSystem.hand_coordinate`), and
        ``face`` True when the roll and torsion modes take part (an offset given on a racket
        whose roll inertia is modelled), :attr:`face_system` then, else :attr:`system`.
        """
        x = np.atleast_1d(np.asarray(x, dtype=float))
        face = y is not None and self.face_system is not None
        system = self.face_system if face else self.system
        n = system.count
        phi = point_shapes(system, self.beam.modes, x)
        if face and n:
            phi = np.hstack([phi, self.beam.roll_modes.shape(x, y).T])
        return system, np.ascontiguousarray(phi), face

    @property
    def contact(self) -> StringBed:
        """What lies between the ball and the frame: the string bed (a bat's is its bare
        wood, :class:`racket.bat.BareFace`); the solver asks it for its stiffness.
        """
        return self.strings

    def effective_mass(self, x, y=None) -> np.ndarray:
        """The frame's rigid-body effective mass [kg] at ``x`` [m from the tip] (and ``y``
        [m from the long axis]), Eq. 20, that of the free frame whatever its support
        (:meth:`beam.Beam.effective_mass`).
        """
        return self.beam.effective_mass(x, y)

    def check_swing(self, pivot) -> None:
        """Refuse a swing (a pivot [m from the tip] or None) this racket's support cannot
        have: only a free racket is swung (:func:`racket.swing.check_swung_support`).
        """
        check_swung_support(self.support)

    @property
    def hoop(self) -> Hoop:
        """The frame's centre line around the head: an ellipse through the tip, as far
        outside the string bed at its sides as the strings' start is from the tip.
        """
        start = self.strings.extent[0]
        return Hoop(self.strings.center, 0.5 * self.strings.full_width + start)

    def with_mass(self, mass_kg: float, position_m: float) -> Racket:
        """A copy of the racket with a point mass (lead tape) of ``mass_kg`` [kg] at ``position_m``
        [m from the tip] on the long axis; mass, balance, swingweight and modes follow from
        the new beam.
        """
        mass_kg = added_mass("mass_kg", mass_kg)
        position_m = in_range("position_m", position_m, 0.0, self.beam.length, "m from the tip")
        return replace(self, beam=self.beam.with_point_masses((position_m, mass_kg)))

    def with_lead_tape(self, mass_kg: float, at: str) -> Racket:
        """A copy of the racket with lead tape of ``mass_kg`` [kg] per side at the clock position
        ``at`` of the head's hoop (``"12"``, ``"3 and 9"``, ``"2 and 10"``, ...; see
        :meth:`racket.head.Hoop.clock`).  Each piece is a point mass on the hoop: it adds to
        the mass, balance and swingweight by its position along the racket and to the roll
        inertia by m y**2.
        """
        mass_kg = added_mass("mass_kg", mass_kg)
        x, y = self.hoop.clock(at)
        points = [(float(xi), mass_kg, float(yi)) for xi, yi in zip(x, y, strict=True)]
        return replace(self, beam=self.beam.with_point_masses(*points))

    def check_points(self, position, offset=None) -> tuple[np.ndarray, np.ndarray | None]:
        """Impact points as 1-D arrays: positions [m from the tip] and offsets [m from the
        long axis, + towards 3 o'clock] broadcast together (offsets None if ``offset`` is
        None).  ValueError as :meth:`check_positions`, for an offset that is not a number or
        puts a point off the elliptical string bed, or for an offset on a racket whose roll
        inertia is not modelled.
        """
        if offset is None:
            return self.check_positions(position), None
        x = finite_array("position", position, "m from the tip")
        y = finite_array("offset", offset, "m from the long axis")
        if y.size == 0:
            raise ValueError("offset must be a number or one per impact point [m], got none")
        try:
            x, y = np.broadcast_arrays(x, y)
        except ValueError:
            raise ValueError(
                f"position and offset must broadcast together, got shapes "
                f"{np.shape(position)} and {np.shape(offset)}"
            ) from None
        x = self.check_positions(x)
        y = np.atleast_1d(y).astype(float).ravel()
        if self.beam.roll_inertia is None and np.any(y != 0.0):
            raise ValueError(
                "offset must be 0 on this racket: its roll inertia is not modelled (use a "
                "spec-sheet racket, from_specs or a catalogue name, or a Beam with "
                f"roll_inertia_per_length); got {shown(y[y != 0.0][0])}"
            )
        if not self.beam.is_mirror_symmetric:
            raise ValueError(
                "offset needs a racket symmetric about its long axis: its point masses off "
                "the axis must come in mirrored pairs (x, m, y) and (x, m, -y), as lead tape "
                "by clock position does; one side alone would couple bending and twisting, "
                "which the model leaves out"
            )
        off = self.strings.rho2(x, y) > 1.0 + 1e-12
        if np.any(off):
            i = np.nonzero(off)[0][0]
            half = 0.5 * self.strings.full_width * np.sqrt(max(1.0 - self.strings.rho2(x[i]), 0))
            raise ValueError(
                f"offset must put the impact point on the strings: at {x[i]:g} m from the tip "
                f"they span [{-half:.4g}, {half:.4g}] m, got {shown(y[i])}"
            )
        return x, y

    def check_positions(self, position) -> np.ndarray:
        """Impact positions [m from the tip] as a 1-D array; ValueError if there are none,
        if they are not a number or a flat sequence, or if any is off the strings.
        """
        x = impact_positions(position)
        start, end = self.strings.extent
        off = (x < start) | (x > end)
        if np.any(off):
            raise ValueError(
                f"position must be on the strings, in [{start:g}, {end:g}] m from "
                f"the tip, got {shown(x[off][0])}"
            )
        return x
