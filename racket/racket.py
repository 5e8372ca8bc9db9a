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
    positive,
    shown,
)
from common.typechecks import choice, instance
from racket.hand import GRIPS, Hand
from racket.implement import Implement
from racket.strings.bed import StringBed
from racket.strings.head import Hoop
from racket.swing import check_swung_support
from racket.system import (
    clamped_system,
    face_system,
    point_shapes,
    racket_system,
    roll_system,
)

SUPPORTS = ("free", "clamped-head", "hand-held")

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


def check_strings_fit(beam: Beam, strings: StringBed, hand: Hand, name: str = "strings extent"):
    """Refuse a string bed that does not fit its frame: one that runs past the frame's end,
    or into its handle (the last ``hand.grip_length`` of it, where the hand holds a hand-held
    racket and the handle is on any other).  The message names what was typed: the bed's
    extent as ``name`` (a TOML key: "[racket.strings] extent") when the hand is a preset
    grip (:data:`racket.hand.GRIPS`, a hand no one typed), the grip's length for a hand of
    one's own; each with the frame and what would fit.

    Parameters
    ----------
    beam : Beam
        The frame.
    strings : StringBed
        Its string bed.
    hand : Hand
        The hand (its grip's length is the handle's).
    name : str, optional
        The bed's extent as the user gave it, as the message quotes it.
    """
    start, end = strings.extent
    said = f"{name} ({start:g}, {end:g}) m from the tip"
    if end > beam.length:
        raise ValueError(f"{said} runs past the end of the {beam.length:g} m frame: the strings "
                         f"must end at most {beam.length:g} m from the tip")  # fmt: skip
    handle = beam.length - hand.grip_length
    if end < handle:
        return
    if hand not in GRIPS.values():  # a grip of one's own: its length was typed
        raise ValueError(
            f"grip_length must end below the strings (they end {end:g} m from the tip of the "
            f"{beam.length:g} m frame), < {beam.length - end:.4g} m, got {hand.grip_length:g}"
        )
    raise ValueError(
        f"{said} runs into the handle: on this {beam.length:g} m frame the strings must end "
        f"before its grip (grip_length {hand.grip_length:g} m from the butt), < {handle:.4g} m "
        "from the tip"
    )


@dataclass(frozen=True)
class Racket(Implement):
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
        check_strings_fit(self.beam, self.strings, self.hand)

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
        wood, :class:`bat.bat.BareFace`); the solver asks it for its stiffness.
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
        :meth:`racket.strings.head.Hoop.clock`).  Each piece is a point mass on the hoop: it adds to
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
        start, end = self.strings.extent
        if isinstance(position, float) and start <= position <= end:  # (one, on the strings)
            return np.array([position])
        x = impact_positions(position)
        off = (x < start) | (x > end)
        if off.any():
            raise ValueError(
                f"position must be on the strings, in [{start:g}, {end:g}] m from "
                f"the tip, got {shown(x[off][0])}"
            )
        return x
