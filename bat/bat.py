"""A bat: a free-free beam (thick, :class:`beam.ThickBeam`, or thin) struck on its own
surface, with no strings between, held free, pivoted as in the certification rig
(:mod:`bat.pivot`) or in the hands.

A bat and a racket are the two kinds of implement (:class:`racket.implement.Implement`)
the impact solver strikes (:func:`racket.impact`): each gives the solver its beam, its block
system for its support, the modal shapes at the impact points, what lies between the ball
and the beam (:attr:`contact`) and its effective mass.  On a bat the ball meets the wood itself: the
bat's local deformation under the ball is left out, as in A. M. Nathan, "Dynamics of the
baseball-bat collision", Am. J. Phys. 68, 979-990 (2000) (the ball's force law is that
on a rigid surface; N2000 p. 981).

Positions are metres from the tip, as everywhere: a bat's tip is the end of its barrel,
and N2000's z, measured from the knob, is ``length - x``.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np

from bat.pivot import CLAMP_OFFSET, PIVOT_FROM_KNOB, pivoted_system
from beam import Beam
from common.checks import finite_array, impact_positions, in_range, shown
from common.typechecks import choice, instance
from racket.hand import GRIPS, Hand
from racket.implement import Implement
from racket.system import free_system, held_system, point_shapes

BAT_SUPPORTS = ("free", "pivoted", "hand-held")
"""How a bat is held: free (N2000's bat, whose handle's grip does not matter during the
1 ms contact), pivoted (the certification rig) or in the hands (:class:`racket.Hand`)."""

PIVOT_TOLERANCE = 1e-9
"""How close [m] a pivoted bat's swing's centre must be to its pivot."""

BARREL_SHARE = 0.9
"""The barrel is the part of a bat whose sections are at least this share of its largest
(their size measured as sqrt(EI / rho A), the section's radius of gyration times the
material's wave speed): **an assumption** that puts the R161's barrel at 60-84 cm from the
knob, where its diameter exceeds 58 mm.  The certification numbers are sought there: the
rig fires at the barrel, and a 60 m/s ball on the thin handle bends it far beyond a beam's
small deflections."""

POSITION_ROUNDING = 1e-12
"""An impact point this little [m] past the barrel's end is at the end (the end's position
from the knob subtracted from the length, ``length - z``, rounds to -4e-16)."""


@dataclass(frozen=True)
class BareFace:
    """The bat's struck surface: nothing between the ball and the beam (no string bed).

    The solver's view of what is in series with the ball: infinitely stiff, lossless and
    massless, so the ball's law acts on the beam itself.

    Parameters
    ----------
    extent : (float, float)
        Where the ball may strike [m from the tip]: (start, end).
    """

    extent: tuple

    stiffness = np.inf
    """Stiffness [N/m] in series with the ball: none (inf)."""
    stiffest = np.inf
    """The largest stiffness anywhere on the face [N/m]: inf."""
    stretch = 0.0
    """No stiffening [1/m^2]."""
    loss = 0.0
    """No loss [-]."""
    moving_mass = 0.0
    """No mass of its own [kg]."""
    plain = True
    """Linear, lossless and massless."""

    @property
    def center(self) -> float:
        """Middle of the face [m from the tip]."""
        return 0.5 * (self.extent[0] + self.extent[1])

    def stiffness_at(self, x, y=0.0) -> np.ndarray:
        """Stiffness [N/m] at the points ``x`` [m from the tip] (and ``y``): inf."""
        x, _ = np.broadcast_arrays(np.asarray(x, dtype=float), np.asarray(y, dtype=float))
        return np.full(x.shape, np.inf)


@dataclass(frozen=True)
class Bat(Implement):
    """A bat: its beam (tip = the barrel's end), and how it is held.

    Parameters
    ----------
    beam : Beam
        The bat, usually a :class:`beam.ThickBeam` (:func:`bat.presets.r161` builds
        Nathan's wooden bat).
    support : str
        ``"free"`` (default), ``"pivoted"`` (the certification rig: :mod:`bat.pivot`) or
        ``"hand-held"`` (``hand`` over the handle, from the knob).
    hand : Hand
        The hands of a hand-held bat: their springs and dashpots over ``grip_length`` from
        the knob, joined to the hands' mass (default the racket's medium grip: **an
        assumption**, no bat grip was measured).
    pivot_from_knob : float
        Pivot axis of a pivoted bat [m from the knob], in [0.02, 0.5]; default 6 in
        (:data:`bat.pivot.PIVOT_FROM_KNOB`).
    clamp_offset : float
        Distance [m] of the rig's two clamps either side of the pivot, in [0, 0.05];
        default 1 in; 0 for a single pivot point (N2000's Fig. 16).
    name : str
        What the bat is called in outputs.
    """

    beam: Beam
    support: str = "free"
    hand: Hand = GRIPS["medium"]
    pivot_from_knob: float = PIVOT_FROM_KNOB
    clamp_offset: float = CLAMP_OFFSET
    name: str = "bat"

    def __post_init__(self):
        instance("beam", self.beam, Beam, "a beam.Beam (a bat's: beam.ThickBeam)")
        choice("bat support", self.support, BAT_SUPPORTS)
        instance("hand", self.hand, Hand, "a racket.Hand")
        instance("name", self.name, str, "a name")
        pivot = in_range("pivot_from_knob", self.pivot_from_knob, 0.02, 0.5, "m from the knob")
        clamp = in_range("clamp_offset", self.clamp_offset, 0.0, 0.05, "m")
        if pivot + clamp >= self.beam.length or pivot - clamp < 0.0:
            raise ValueError(
                f"the clamps must lie on the bat, within [0, {self.beam.length:g}] m from the "
                f"knob, got {pivot - clamp:g} to {pivot + clamp:g} m"
            )
        object.__setattr__(self, "pivot_from_knob", pivot)
        object.__setattr__(self, "clamp_offset", clamp)
        if self.support == "hand-held" and self.hand.grip_length >= 0.5 * self.beam.length:
            raise ValueError(
                f"grip_length must be under half the bat's length, < {0.5 * self.beam.length:g}"
                f" m, got {self.hand.grip_length!r}"
            )

    @property
    def pivot(self) -> float:
        """The pivot axis [m from the tip]."""
        return self.beam.length - self.pivot_from_knob

    @property
    def clamps(self) -> np.ndarray:
        """The rig's clamp points [m from the tip] (one point without clamp width)."""
        if self.clamp_offset == 0.0:
            return np.array([self.pivot])
        return self.pivot + np.array([-self.clamp_offset, self.clamp_offset])

    @cached_property
    def barrel(self) -> tuple:
        """Where the barrel is [m from the tip]: (0, its end), the sections from the tip on
        that are :data:`BARREL_SHARE` of the largest at least.
        """
        beam = self.beam
        size = np.sqrt(np.asarray(beam.bending_stiffness) / np.asarray(beam.mass_per_length))
        small = np.nonzero(size < BARREL_SHARE * size.max())[0]
        first = small[small > int(np.argmax(size))]
        end = beam.stations[first[0]] if first.size else beam.length
        return (0.0, float(end))

    @cached_property
    def contact(self) -> BareFace:
        """What lies between the ball and the beam: nothing (:class:`BareFace`), over the
        whole bat.
        """
        return BareFace((0.0, self.beam.length))

    @cached_property
    def system(self):
        """The bat's linear dynamics in real 2x2 blocks (:mod:`racket.system`) for its
        support; computed once.
        """
        modes = self.beam.modes
        if self.support == "pivoted":
            return pivoted_system(modes, self.clamps)
        return held_system(modes, self.hand) if self.support == "hand-held" else free_system(modes)

    face_system = None
    """A bat is struck on its axis: no roll or torsion modes."""

    def point_dynamics(self, x, y=None):
        """The block system for impacts at ``x`` [m from the tip] and their modal shapes:
        (system, phi (P, N), False).
        """
        x = np.atleast_1d(np.asarray(x, dtype=float))
        phi = point_shapes(self.system, self.beam.modes, x)
        return self.system, np.ascontiguousarray(phi), False

    def effective_mass(self, x, y=None) -> np.ndarray:
        """Rigid-body effective mass [kg] at ``x`` [m from the tip]: Eq. 20's for a free or
        hand-held bat (as for a racket), I_pivot / d**2 for a pivoted one (d the distance to
        the pivot).
        """
        if self.support != "pivoted":
            return self.beam.effective_mass(x)
        d = self.pivot - finite_array("x", x, "m from the tip")
        with np.errstate(divide="ignore"):
            return self.beam.inertia_about(self.pivot) / d**2

    @property
    def inertia_pivot(self) -> float:
        """Moment of inertia [kg m^2] about the pivot axis (the rig's; 6 in from the knob
        by default, ASTM F2398's MOI).
        """
        return self.beam.inertia_about(self.pivot)

    def check_swing(self, pivot) -> None:
        """Refuse a swing (its centre ``pivot`` [m from the tip], None for a translation)
        this bat's support cannot have: a hand-held bat's hands are at rest, and a pivoted
        bat turns about its pivot only.
        """
        if self.support == "hand-held":
            raise ValueError(
                "swing_speed must be 0 for a hand-held bat (the hands are at rest in this "
                "model); swing a free bat, as Nathan does"
            )
        if self.support == "pivoted" and (
            pivot is None or abs(pivot - self.pivot) > PIVOT_TOLERANCE
        ):
            raise ValueError(
                f"a pivoted bat turns about its pivot: pivot must be {self.pivot:.6g} m from "
                f"the tip ({self.pivot_from_knob:g} m from the knob), got {shown(pivot)}"
            )

    def check_points(self, position, offset=None):
        """Impact points [m from the tip] as a 1-D array, and None (a bat is struck on its
        axis); ValueError if there are none, if they are not numbers, if any is off the
        bat, or inside the clamps of a pivoted one.
        """
        if offset is not None and np.any(finite_array("offset", offset, "m") != 0.0):
            raise ValueError("offset must be None for a bat: it is struck on its axis")
        x = impact_positions(position)
        end = self.beam.length
        if self.support == "pivoted":
            end = self.pivot - self.clamp_offset
        elif self.support == "hand-held":
            end = self.beam.length - self.hand.grip_length
        # (a point a rounding error past the barrel's end, L - z from the knob, is at it)
        x = np.where((x < 0.0) & (x > -POSITION_ROUNDING), 0.0, x)
        off = (x < 0.0) | (x >= end)
        if np.any(off):
            where = {"pivoted": " short of the clamps", "hand-held": " short of the hands"}
            raise ValueError(
                f"position must be on the bat{where.get(self.support, '')}, in [0, "
                f"{end:g}) m from the tip (the barrel's end), got {shown(x[off][0])}"
            )
        return x, None
