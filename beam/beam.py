"""A free-free Euler-Bernoulli beam: its profile, mass properties and modes.

Positions along the beam are distances from the tip [m] everywhere (the racket's tip is
x = 0 and its butt is x = length).
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from functools import cached_property

import numpy as np

from beam import fem, uniform
from beam.modes import Modes
from beam.torsion import RollModes, roll_modes
from common.checks import finite, finite_array, in_range, positive, shown, whole
from common.typechecks import instance

DEFAULT_DAMPING = 0.005
"""Default modal damping ratio of every bending mode.  A freely suspended graphite racket
rings for about a second at its 100-150 Hz fundamental (R. Cross, Sports Eng. 1, 1998;
H. Brody, Tennis Science for Tennis Players, 1987), i.e. a damping ratio of a few tenths of
a percent; 0.5 % is used.  Over a 5 ms impact it changes e by less than 1e-3."""

DEFAULT_MODES = 12
"""Default number of bending modes.  The modes left out count quasi-statically (the static
correction), which is exact for a free frame; a hand-held one's grip couples them to the
hand's mass through stiff springs (:data:`racket.GRIPS`), which the correction does not
follow: with 8 modes the held paper racket's e was 5.4e-5 from a 64-mode solution, with 12
1.2e-5 (measured, issue 25; issue 10's target is 2e-5).  The eighth free-free mode of the
paper's racket is at 3.8 kHz, far above what a 4-5 ms impact excites; 12 modes cost about
15 % more time than 8 (200 impacts 3.3 -> 3.85 ms)."""

MAX_MODES = 200
"""Most bending modes a beam may keep (the analytic shapes overflow above about 225)."""

MAX_ELEMENTS = 20_000
"""Most finite elements along a beam (an assumption: 240 resolve a racket's modes; each
element more costs time, and 20 000 are far past any use)."""

MAX_PROFILE_RATIO = 1e4
"""Largest ratio between the segments' largest and smallest EI (or mass per length): a
racket's varies by a few times; beyond this the finite-element eigenproblem loses accuracy."""

DEFAULT_TORSION_MODES = 12
"""Default number of torsion modes (beyond the rigid roll) of a beam whose torsional
stiffness is given; the ones left out count quasi-statically (static correction).  Twist
compliance falls off only as 1/n**2 per mode (bending as 1/n**4), and a flexible frame's
fifth torsion mode rings near 750 Hz, not far above a 4 ms contact: with 4 modes e off the
axis was up to 8.8e-5 from the converged value; with 12, 5.2e-6 (Pure Drive, 21 points 8-26 cm
from the tip and 3-9 cm off the axis, 16.5 m/s; against 96 modes; measured, issue 23)."""

SWINGWEIGHT_AXIS = 0.10
"""Swingweight is the moment of inertia about an axis this far from the butt [m]."""


@dataclass(frozen=True)
class Beam:
    """A free-free beam with a piecewise-constant profile.

    Parameters
    ----------
    stations : sequence of float
        Segment boundaries [m from the tip], increasing from 0 to the beam length.
    mass_per_length : sequence of float
        Mass per length of each segment [kg/m], > 0.
    bending_stiffness : sequence of float
        Bending stiffness EI of each segment [N m^2], > 0.
    point_masses : sequence of (position, mass) or (position, mass, offset)
        Concentrated masses (e.g. lead tape): position [m from the tip], mass [kg] and
        lateral offset from the long axis [m] (default 0; it counts only in the roll
        inertia, the bending modes are of the long axis).
    damping : float or sequence of float
        Modal damping ratio [-] of each bending mode, in [0, 1): one value for all, or one per
        mode.  Default :data:`DEFAULT_DAMPING`.
    n_modes : int
        Number of bending modes, in [1, :data:`MAX_MODES`].  Default :data:`DEFAULT_MODES`.
    elements : int
        Finite elements along a non-uniform beam (about), in [20, :data:`MAX_ELEMENTS`].
    roll_inertia_per_length : sequence of float or None
        Moment of inertia about the long axis per length of each segment [kg m] (the
        frame's width: hoop, strings, throat arms), >= 0; None (default) when the beam's
        width is not modelled, and then :attr:`roll_inertia` is None.
    torsional_stiffness : sequence of float or None
        Torsional stiffness GJ of each segment [N m^2], > 0, for the torsion modes
        (:attr:`roll_modes`); needs ``roll_inertia_per_length``.  None (default): the frame
        is torsionally rigid (its roll is the rigid roll only).
    n_torsion_modes : int
        Torsion modes kept beyond the rigid roll, in [1, :data:`MAX_MODES`]; default
        :data:`DEFAULT_TORSION_MODES`.

    Notes
    -----
    A tabulated profile is given as many short segments.  Uniform beams without point
    masses use the analytic modes (:mod:`beam.uniform`), others finite elements
    (:mod:`beam.fem`).
    """

    stations: tuple
    mass_per_length: tuple
    bending_stiffness: tuple
    point_masses: tuple = ()
    damping: float | tuple = DEFAULT_DAMPING
    n_modes: int = DEFAULT_MODES
    elements: int = field(default=240, compare=False)
    roll_inertia_per_length: tuple | None = None
    torsional_stiffness: tuple | None = None
    n_torsion_modes: int = DEFAULT_TORSION_MODES

    def __post_init__(self):
        st = finite_array("stations", self.stations, "m").ravel()
        rho = finite_array("mass_per_length", self.mass_per_length, "kg/m").ravel()
        ei = finite_array("bending_stiffness", self.bending_stiffness, "N m^2").ravel()
        if st.size < 2 or st[0] != 0.0 or np.any(np.diff(st) <= 0):
            raise ValueError(f"stations must increase from 0 to the beam length [m], got {st}")
        for name, values in (("mass_per_length", rho), ("bending_stiffness", ei)):
            if values.size != st.size - 1:
                raise ValueError(
                    f"{name} needs one value per segment ({st.size - 1}), got {values.size}"
                )
            if np.any(values <= 0):
                raise ValueError(
                    f"{name} must be > 0 on every segment, got {float(values.min())!r}"
                )
            if values.max() > MAX_PROFILE_RATIO * values.min():
                raise ValueError(
                    f"{name} must vary by at most {MAX_PROFILE_RATIO:g} times along the beam, "
                    f"got {float(values.min()):g} to {float(values.max()):g}"
                )
        points = "a sequence of (position, mass[, offset]) [m, kg, m]"
        instance("point_masses", self.point_masses, tuple | list, points)
        pm = np.zeros((len(self.point_masses), 3))
        for i, point in enumerate(self.point_masses):
            values = finite_array("point_masses", point).ravel()
            if values.size not in (2, 3):
                raise ValueError(
                    "each of point_masses must be (position [m], mass [kg]) or (position, mass, "
                    f"offset [m]), got {shown(point)}"
                )
            pm[i, : values.size] = values
            in_range("point mass position", values[0], 0.0, st[-1], "m from the tip")
            positive("point mass", values[1], "kg")
        if self.roll_inertia_per_length is not None:
            roll = finite_array("roll_inertia_per_length", self.roll_inertia_per_length, "kg m")
            roll = roll.ravel()
            if roll.size != st.size - 1 or np.any(roll < 0):
                raise ValueError(
                    f"roll_inertia_per_length needs one value >= 0 per segment "
                    f"({st.size - 1}) [kg m], got {shown(self.roll_inertia_per_length)}"
                )
            object.__setattr__(self, "roll_inertia_per_length", tuple(roll))
        if self.torsional_stiffness is not None:
            if self.roll_inertia_per_length is None:
                raise ValueError(
                    "torsional_stiffness needs roll_inertia_per_length (the twist's inertia)"
                )
            if np.any(np.asarray(self.roll_inertia_per_length) <= 0):
                raise ValueError(
                    "roll_inertia_per_length must be > 0 on every segment [kg m] with a "
                    f"torsional_stiffness, got {shown(self.roll_inertia_per_length)}"
                )
            gj = finite_array("torsional_stiffness", self.torsional_stiffness, "N m^2").ravel()
            if gj.size != st.size - 1 or np.any(gj <= 0):
                raise ValueError(
                    f"torsional_stiffness needs one value > 0 per segment ({st.size - 1}) "
                    f"[N m^2], got {shown(self.torsional_stiffness)}"
                )
            object.__setattr__(self, "torsional_stiffness", tuple(gj))
        n_torsion = in_range("n_torsion_modes", self.n_torsion_modes, 1, MAX_MODES)
        if n_torsion != int(n_torsion):
            raise ValueError(
                f"n_torsion_modes must be a whole number, got {shown(self.n_torsion_modes)}"
            )
        object.__setattr__(self, "n_torsion_modes", int(n_torsion))
        n_modes = in_range("n_modes", self.n_modes, 1, MAX_MODES)
        if n_modes != int(n_modes):
            raise ValueError(f"n_modes must be a whole number, got {shown(self.n_modes)}")
        n_modes = int(n_modes)
        damping = np.atleast_1d(finite_array("damping", self.damping))
        if damping.size not in (1, n_modes):
            raise ValueError(
                f"damping must be one value or {n_modes} (one per mode), got {damping.size}"
            )
        if np.any((damping < 0) | (damping >= 1)):
            raise ValueError(f"damping must be in [0, 1), got {damping}")
        object.__setattr__(self, "elements", whole("elements", self.elements, 20, MAX_ELEMENTS))
        object.__setattr__(self, "stations", tuple(st))
        object.__setattr__(self, "mass_per_length", tuple(rho))
        object.__setattr__(self, "bending_stiffness", tuple(ei))
        object.__setattr__(self, "point_masses", tuple(map(tuple, pm)))
        object.__setattr__(
            self, "damping", float(damping[0]) if damping.size == 1 else tuple(damping)
        )
        object.__setattr__(self, "n_modes", n_modes)

    @classmethod
    def uniform(
        cls,
        length: float,
        mass: float,
        f1: float,
        damping=DEFAULT_DAMPING,
        n_modes: int = DEFAULT_MODES,
    ) -> Beam:
        """A uniform beam whose first free-free bending frequency is ``f1``.

        Parameters
        ----------
        length : float
            Beam length [m].
        mass : float
            Total mass [kg].
        f1 : float
            First free-free bending frequency [Hz]: EI = (m/L) L**4 (2 pi f1 / 4.730**2)**2.
        """
        length = positive("length", length, "m")
        mass = positive("mass", mass, "kg")
        f1 = positive("f1", f1, "Hz")
        rho = mass / length
        beta_l = uniform.free_free_roots(1)[0]
        ei = rho * length**4 * (2.0 * np.pi * f1 / beta_l**2) ** 2
        return cls((0.0, length), (rho,), (ei,), damping=damping, n_modes=n_modes)

    # ----- mass properties -------------------------------------------------------------
    @property
    def length(self) -> float:
        """Length [m]."""
        return self.stations[-1]

    @cached_property
    def _segments(self):
        st = np.asarray(self.stations)
        lengths = np.diff(st)
        masses = np.asarray(self.mass_per_length) * lengths
        return 0.5 * (st[:-1] + st[1:]), lengths, masses, self.point_array[:, :2]

    @property
    def point_array(self) -> np.ndarray:
        """The point masses as an array (P, 3): position [m from the tip], mass [kg],
        lateral offset [m].
        """
        return np.asarray(self.point_masses, dtype=float).reshape(-1, 3)

    @cached_property
    def mass(self) -> float:
        """Total mass [kg]."""
        _, _, masses, pm = self._segments
        return float(masses.sum() + pm[:, 1].sum())

    @cached_property
    def center_of_mass(self) -> float:
        """Centre of mass [m from the tip]."""
        mid, _, masses, pm = self._segments
        return float((masses @ mid + pm[:, 1] @ pm[:, 0]) / self.mass)

    @property
    def balance(self) -> float:
        """Balance point [m from the butt] (the spec sheets' 'balance')."""
        return self.length - self.center_of_mass

    def inertia_about(self, x: float) -> float:
        """Moment of inertia [kg m^2] about a transverse axis at ``x`` [m from the tip]."""
        x = finite("x", x, "m from the tip")
        mid, lengths, masses, pm = self._segments
        return float(masses @ (lengths**2 / 12.0 + (mid - x) ** 2) + pm[:, 1] @ (pm[:, 0] - x) ** 2)

    @cached_property
    def inertia_cm(self) -> float:
        """Moment of inertia about the centre of mass, I_cm [kg m^2] (the 'recoil weight')."""
        return self.inertia_about(self.center_of_mass)

    @property
    def recoil_weight_kgcm2(self) -> float:
        """Recoil weight: the moment of inertia about the centre of mass [kg cm^2]."""
        return self.inertia_cm * 1e4

    @cached_property
    def roll_inertia(self) -> float | None:
        """Moment of inertia about the long axis [kg m^2] (the 'twistweight'): the
        segments' roll inertia plus m y**2 of each point mass; None when the beam's width is
        not modelled (``roll_inertia_per_length`` is None).
        """
        if self.roll_inertia_per_length is None:
            return None
        pm = self.point_array
        lengths = np.diff(np.asarray(self.stations))
        return float(np.asarray(self.roll_inertia_per_length) @ lengths + pm[:, 1] @ pm[:, 2] ** 2)

    @cached_property
    def is_mirror_symmetric(self) -> bool:
        """True when the point masses off the long axis come in mirrored pairs (x, m, y)
        and (x, m, -y): the beam is then symmetric about its long axis, and bending and
        twisting are uncoupled (:mod:`beam.torsion`).
        """
        pm = self.point_array
        off = pm[np.abs(pm[:, 2]) > 1e-15]  # on the axis but for round-off [m]: no coupling
        plus = off[off[:, 2] > 0]
        minus = off[off[:, 2] < 0] * np.array([1.0, 1.0, -1.0])
        if plus.shape != minus.shape:
            return False
        key = lambda a: a[np.lexsort(a.T[::-1])]  # noqa: E731
        return bool(np.allclose(key(plus), key(minus), rtol=1e-12, atol=1e-15))

    @property
    def twistweight_kgcm2(self) -> float | None:
        """:attr:`roll_inertia` in the spec sheets' unit [kg cm^2] (None if not modelled)."""
        roll = self.roll_inertia
        return None if roll is None else roll * 1e4

    @property
    def swingweight(self) -> float:
        """Moment of inertia about the axis 10 cm from the butt [kg m^2]."""
        return self.inertia_about(self.length - SWINGWEIGHT_AXIS)

    @property
    def swingweight_kgcm2(self) -> float:
        """Swingweight in the spec sheets' unit [kg cm^2]."""
        return self.swingweight * 1e4

    def effective_mass(self, x, y=None) -> np.ndarray:
        """Rigid-body effective mass [kg] at ``x`` [m from the tip] (Eq. 20): 1/m2 = 1/M +
        b**2 / I_cm, with b = x_cm - x the distance from the centre of mass; with an offset
        ``y`` [m from the long axis] the roll adds y**2 / I_roll (needs :attr:`roll_inertia`).

        References
        ----------
        .. [1] R. Cross, Am. J. Phys. 68, 1025-1031 (2000), doi:10.1119/1.1285945.

        Examples
        --------
        >>> beam = Beam.uniform(0.68, 0.34, 120.0)
        >>> round(float(beam.effective_mass(0.16)), 4)  # the paper racket's string centre
        0.1847
        """
        b = self.center_of_mass - (x := finite_array("x", x, "m from the tip"))
        if y is None and x.shape == (1,):  # one point (an impact's): in numbers, same bits
            return np.array([1.0 / (1.0 / self.mass + b.item() * b.item() / self.inertia_cm)])
        flexibility = 1.0 / self.mass + b**2 / self.inertia_cm
        if y is not None:
            if self.roll_inertia is None:
                raise ValueError(
                    "an offset from the long axis needs the beam's roll inertia "
                    "(roll_inertia_per_length; a spec-sheet racket has it)"
                )
            y = finite_array("y", y, "m from the long axis")
            flexibility = flexibility + y**2 / self.roll_inertia
        return 1.0 / flexibility

    def with_f1(self, f1: float) -> Beam:
        """A copy of the beam with every bending stiffness scaled so its first frequency is ``f1``
        [Hz].  Frequencies scale as sqrt(EI), so scaling EI by (f1 / f1_now)**2 keeps the
        mode shapes.  The torsional stiffness GJ is left as it is (a spec-sheet fit derives
        it from EI once, :func:`racket.from_specs`; :meth:`with_torsion_frequency` sets it).
        """
        scale = (positive("f1", f1, "Hz") / self.modes.frequencies[0]) ** 2
        beam = replace(self, bending_stiffness=tuple(scale * np.asarray(self.bending_stiffness)))
        # Same shapes, frequencies times sqrt(scale), flexibility over scale: no recomputing.
        modes = self.modes
        beam.__dict__["modes"] = replace(modes, omega=modes.omega * np.sqrt(scale))
        if "roll_modes" in self.__dict__:  # twisting does not depend on EI
            beam.__dict__["roll_modes"] = self.roll_modes
        if "_flexibility" in self.__dict__:
            flex = self._flexibility
            beam.__dict__["_flexibility"] = replace(flex, blocks=flex.blocks / scale)
        return beam

    def with_point_masses(self, *masses) -> Beam:
        """A copy of the beam with more point masses (lead tape): (position [m from the tip],
        mass [kg]) or (position, mass, lateral offset [m]).
        """
        points = (tuple(finite_array("point_masses", m).ravel()) for m in masses)
        return replace(self, point_masses=(*self.point_masses, *points))

    def with_torsion_frequency(self, frequency: float) -> Beam:
        """A copy of the beam with every torsional stiffness scaled so that its first torsion mode
        rings at ``frequency`` [Hz] (frequencies scale as sqrt(GJ); the shapes stay).
        """
        modes = self.roll_modes
        if modes is None or modes.count < 2:
            raise ValueError("with_torsion_frequency needs a beam with torsional_stiffness")
        scale = (positive("torsion frequency", frequency, "Hz") / modes.frequencies[0]) ** 2
        beam = self.with_torsional_stiffness(scale * np.asarray(self.torsional_stiffness))
        beam.__dict__["roll_modes"] = replace(
            modes,
            omega=modes.omega * np.sqrt(scale),
            residual=modes.residual / scale,
            element_flexibility=modes.element_flexibility / scale,
        )
        return beam

    def with_torsional_stiffness(self, torsional_stiffness) -> Beam:
        """A copy of the beam with the torsional stiffness GJ [N m^2] of each segment (its bending
        modes and flexibility are kept, not computed again).
        """
        beam = replace(self, torsional_stiffness=tuple(np.ravel(torsional_stiffness)))
        for name in ("modes", "_flexibility"):
            if name in self.__dict__:
                beam.__dict__[name] = self.__dict__[name]
        return beam

    @cached_property
    def roll_modes(self) -> RollModes | None:
        """The rigid roll and the torsion modes about the long axis (:mod:`beam.torsion`);
        None when the roll inertia is not modelled.  Without ``torsional_stiffness`` the
        rigid roll alone.
        """
        if self.roll_inertia_per_length is None:
            return None
        return roll_modes(
            np.asarray(self.stations),
            self.roll_inertia_per_length,
            self.torsional_stiffness,
            self.point_array,
            self.n_torsion_modes,
            self.damping if np.ndim(self.damping) == 0 else self.damping[0],
            self.elements,
        )

    # ----- modes -----------------------------------------------------------------------
    @property
    def is_uniform(self) -> bool:
        """True for a uniform profile without point masses (analytic modes)."""
        return (
            len(set(self.mass_per_length)) == 1
            and len(set(self.bending_stiffness)) == 1
            and not self.point_masses
        )

    @cached_property
    def modes(self) -> Modes:
        """Rigid-body and bending modes (analytic when uniform, else finite elements)."""
        return self.compute_modes("analytic" if self.is_uniform else "fem")

    @cached_property
    def _flexibility(self) -> fem.FemFlexibility:
        return fem.static_flexibility(
            np.asarray(self.stations),
            self.mass_per_length,
            self.bending_stiffness,
            self.point_array[:, :2],
            self.elements,
        )

    def static_flexibility(self, x) -> np.ndarray:
        """Deflection per unit force [m/N] of the free beam's bending at x [m from the tip]
        for a force at x, all bending modes included: sum_k phi_k(x)**2 / omega_k**2.
        """
        return self._flexibility(np.atleast_1d(np.asarray(x, dtype=float)))

    def residual_flexibility(self, x, shapes=None) -> np.ndarray:
        """The part [m/N] of :meth:`static_flexibility` from the bending modes not kept
        (beyond ``n_modes``): sum_{k > n_modes} phi_k(x)**2 / omega_k**2, >= 0.

        ``shapes``, if given, are ``self.modes.shape(x)`` (to spare computing them again). The
        impact solver adds it in series with the strings: the modes left out, far above what
        an impact excites, respond to the force quasi-statically (the static correction, or
        mode acceleration method).
        """
        modes = self.modes
        phi = modes.shape(x) if shapes is None else shapes
        kept = np.add.reduce(phi[2:] ** 2 / modes.bending_omega_squared)  # (.sum, unwrapped)
        return np.maximum(self.static_flexibility(x) - kept, 0.0)

    def compute_modes(self, method: str = "fem") -> Modes:
        """The modes by ``method`` = "analytic" (uniform beams only) or "fem"."""
        if method == "analytic":
            if not self.is_uniform:
                raise ValueError("method 'analytic' needs a uniform beam without point masses")
            beta_l = uniform.free_free_roots(self.n_modes)
            rho, ei, length = self.mass_per_length[0], self.bending_stiffness[0], self.length
            omega_b = beta_l**2 * np.sqrt(ei / (rho * length**4))
            bending = uniform.UniformShapes(beta_l, length, 1.0 / np.sqrt(self.mass))
        elif method == "fem":
            omega_b, bending = fem.bending_modes(
                np.asarray(self.stations),
                self.mass_per_length,
                self.bending_stiffness,
                self.point_array[:, :2],
                self.n_modes,
                self.elements,
            )
        else:
            raise ValueError(f"method must be 'analytic' or 'fem', got {method!r}")
        return self._modes(omega_b, bending)

    def _modes(self, omega_b: np.ndarray, bending) -> Modes:
        """The :class:`Modes` of bending frequencies ``omega_b`` [rad/s] and shapes
        ``bending``, with the two rigid-body modes and this beam's damping and mass.
        """
        zeta = np.broadcast_to(np.asarray(self.damping, dtype=float), (self.n_modes,))
        return Modes(
            omega=np.concatenate([[0.0, 0.0], omega_b]),
            damping=np.concatenate([[0.0, 0.0], zeta]),
            mass=self.mass,
            center_of_mass=self.center_of_mass,
            inertia_cm=self.inertia_cm,
            length=self.length,
            bending_shapes=bending,
        )
