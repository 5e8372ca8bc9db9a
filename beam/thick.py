"""A free-free Timoshenko (thick) beam: :class:`~beam.Beam` with shear deformation and
rotary inertia (:mod:`beam.timoshenko`), and one built from a round profile
(:meth:`ThickBeam.round`: a bat from its diameters, solid or hollow).
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from functools import cached_property

import numpy as np

from beam import timoshenko
from beam.beam import Beam
from beam.modes import Modes
from common.checks import finite_array, in_range, positive, shown

SHEAR_COEFFICIENT = 1.0
"""Default shear coefficient kappa [-] of :meth:`ThickBeam.round`: 1, as in Nathan's model,
whose shear force is S A times the shear strain (N2000 eqs. 1-2, his S an assumed value
"not very sensitive"); a solid circle's is about 0.89 (G. R. Cowper, J. Appl. Mech. 33,
335 (1966)), which a user may give."""


@dataclass(frozen=True)
class ThickBeam(Beam):
    """A free-free Timoshenko beam: a :class:`~beam.Beam` whose sections also shear and
    turn (rotary inertia).  Its modes always come from finite elements
    (:mod:`beam.timoshenko`); its moment of inertia about a transverse axis includes the
    sections' own, the sum of rho I over the length.

    Parameters
    ----------
    stations, mass_per_length, bending_stiffness, point_masses, damping, n_modes, elements
        As for :class:`~beam.Beam`.
    roll_inertia_per_length, torsional_stiffness, n_torsion_modes
        As for :class:`~beam.Beam` (a bat's are not modelled: None).
    shear_stiffness : sequence of float
        Shear stiffness kappa G A of each segment [N], > 0.
    rotary_inertia_per_length : sequence of float
        Rotary inertia rho I of each segment about its transverse axis, per length
        [kg m], >= 0.
    """

    shear_stiffness: tuple = ()
    rotary_inertia_per_length: tuple = ()

    def __post_init__(self):
        super().__post_init__()
        segments = len(self.stations) - 1
        for name, unit, low in (("shear_stiffness", "N", 0.0),
                                ("rotary_inertia_per_length", "kg m", None)):  # fmt: skip
            values = finite_array(name, getattr(self, name), unit).ravel()
            if values.size != segments:
                raise ValueError(
                    f"{name} needs one value per segment ({segments}) [{unit}], got {values.size}"
                )
            bad = values <= 0 if low is not None else values < 0
            if np.any(bad):
                sign = "> 0" if low is not None else ">= 0"
                raise ValueError(f"{name} must be {sign} on every segment [{unit}], got "
                                 f"{float(values[bad][0])!r}")  # fmt: skip
            object.__setattr__(self, name, tuple(values))

    @classmethod
    def round(
        cls,
        stations,
        diameters,
        density: float,
        youngs_modulus: float,
        shear_modulus: float,
        bore=None,
        shear_coefficient: float = SHEAR_COEFFICIENT,
        **kwargs,
    ) -> ThickBeam:
        """A beam of round sections: solid, or hollow with a bore.

        A = pi (R**2 - r**2), I = pi (R**4 - r**4) / 4 (N2000 p. 980; ACOR p. 3), rho A the
        mass per length, rho I the rotary inertia per length, E I and kappa G A.

        Parameters
        ----------
        stations : sequence of float
            Segment boundaries [m from the tip], increasing from 0.
        diameters : sequence of float
            Outer diameter of each segment [m].
        density : float
            Density of the material [kg/m^3], in [50, 20000].
        youngs_modulus, shear_modulus : float
            Young's modulus E and shear modulus G [Pa], in [1e8, 1e13].
        bore : sequence of float or None
            Inner diameter of each segment [m] (0 solid), below the outer; None: solid.
        shear_coefficient : float
            kappa [-], in (0, 1]; default :data:`SHEAR_COEFFICIENT`.
        **kwargs
            Passed to :class:`ThickBeam` (``n_modes``, ``damping``, ``elements``,
            ``point_masses``).
        """
        outer = finite_array("diameters", diameters, "m").ravel()
        segments = np.size(finite_array("stations", stations, "m")) - 1
        if segments < 1:
            raise ValueError(f"stations must increase from 0 to the beam length [m], got "
                             f"{shown(stations)}")  # fmt: skip
        if outer.size != segments:
            raise ValueError(
                f"diameters needs one value per segment ({segments}) [m], got {outer.size}"
            )
        if np.any(outer <= 0):
            raise ValueError(f"diameters must be > 0 [m], got {float(outer.min())!r}")
        inner = np.zeros_like(outer) if bore is None else finite_array("bore", bore, "m").ravel()
        if inner.shape != outer.shape or np.any(inner < 0) or np.any(inner >= outer):
            raise ValueError("bore must give one inner diameter per segment, >= 0 and below "
                             "the outer diameter [m]")  # fmt: skip
        rho = in_range("density", density, 50.0, 2e4, "kg/m^3")
        e = in_range("youngs_modulus", youngs_modulus, 1e8, 1e13, "Pa")
        g = in_range("shear_modulus", shear_modulus, 1e8, 1e13, "Pa")
        kappa = in_range("shear_coefficient", shear_coefficient, 0.0, 1.0, "")
        positive("shear_coefficient", kappa, "")
        area = 0.25 * np.pi * (outer**2 - inner**2)
        second = np.pi * (outer**4 - inner**4) / 64.0
        return cls(
            stations=stations,
            mass_per_length=tuple(rho * area),
            bending_stiffness=tuple(e * second),
            shear_stiffness=tuple(kappa * g * area),
            rotary_inertia_per_length=tuple(rho * second),
            **kwargs,
        )

    @property
    def _profile(self) -> tuple:
        return (self.mass_per_length, self.rotary_inertia_per_length,
                self.bending_stiffness, self.shear_stiffness)  # fmt: skip

    @property
    def is_uniform(self) -> bool:
        """False: a thick beam's modes come from finite elements (no analytic shapes)."""
        return False

    def inertia_about(self, x: float) -> float:
        """Moment of inertia [kg m^2] about a transverse axis at ``x`` [m from the tip]: the
        sections' mass about it plus their own rotary inertia.
        """
        own = np.asarray(self.rotary_inertia_per_length) @ np.diff(np.asarray(self.stations))
        return super().inertia_about(x) + float(own)

    def compute_modes(self, method: str = "fem") -> Modes:
        """The modes by finite elements (``method`` must be "fem")."""
        if method != "fem":
            raise ValueError(f"a thick beam's modes come from method 'fem', got {method!r}")
        omega_b, bending = timoshenko.bending_modes(
            np.asarray(self.stations), self._profile, self.point_array[:, :2], self.n_modes,
            self.elements,
        )  # fmt: skip
        return self._modes(omega_b, bending)

    @cached_property
    def _flexibility(self):
        return timoshenko.static_flexibility(
            np.asarray(self.stations), self._profile, self.point_array[:, :2], self.elements
        )

    def with_f1(self, f1: float) -> ThickBeam:
        """A copy with E and G scaled together so that the first frequency is ``f1`` [Hz]
        (EI and kappa G A by the same factor: the shapes stay, the frequencies scale as its
        square root).
        """
        scale = (positive("f1", f1, "Hz") / self.modes.frequencies[0]) ** 2
        return self.stiffened(scale)

    def stiffened(self, factor: float) -> ThickBeam:
        """A copy with EI and kappa G A times ``factor`` [-] (> 0): the same shapes, every
        frequency times sqrt(factor), the flexibility over it.
        """
        factor = positive("factor", factor, "")
        beam = replace(
            self,
            bending_stiffness=tuple(factor * np.asarray(self.bending_stiffness)),
            shear_stiffness=tuple(factor * np.asarray(self.shear_stiffness)),
        )
        modes = self.modes
        beam.__dict__["modes"] = replace(modes, omega=modes.omega * np.sqrt(factor))
        flex = self._flexibility
        beam.__dict__["_flexibility"] = replace(flex, blocks=flex.blocks / factor)
        return beam
