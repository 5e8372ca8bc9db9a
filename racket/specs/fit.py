"""A racket model that meets its spec sheet: part masses, stiffness profile, string bed.

:func:`fit_profile` builds the beam: the part masses of :mod:`racket.specs.parts` fitted to
the sheet's mass, balance and swingweight (and twistweight) by :mod:`racket.specs.mass_fit`,
the bending-stiffness profile of :mod:`racket.specs.stiffness` scaled to the sheet's f1
(given, or from its RA rating by :mod:`racket.specs.ra`) or flex test; :func:`from_specs` adds
the string bed and the support.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from beam import Beam
from racket.racket import Racket
from racket.specs.mass_fit import fit_masses
from racket.specs.parts import PARTS, Layout, layout
from racket.specs.ra import f1_from_ra
from racket.specs.sheet import SPEC_RANGES, SpecSheet, spec_sheet
from racket.specs.stiffness import (
    TYPICAL_BEAM_WIDTHS,
    bending_profile,
    flex_test_stiffness,
    torsional_profile,
)
from racket.specs.strung import LINEAR, STRUNG
from racket.strings.bed import StringBed
from racket.strings.stringing import stringing

EDGE_FRACTION = 0.02
"""A fitted part within this fraction of its range from an end is reported as at the edge
of its range."""

MISMATCH_KGCM2 = 2.0
"""A given recoil weight or twistweight that the fit misses by more than this [kg cm^2] is
reported: spec sheets print them to 1 kg cm^2, and a balance rounded to 0.1 cm moves the
recoil weight derived from a swingweight by under 1 kg cm^2 (assumption from those
roundings)."""


@dataclass(frozen=True)
class Profile:
    """The fitted model of a spec sheet.

    Attributes
    ----------
    masses : dict
        Mass of each part [kg], by the names of :data:`~racket.specs.parts.PARTS`.
    layout : Layout
        Where the parts sit (cells, hoop, string bed).
    twistweight_residual : float or None
        Fitted minus given twistweight [kg m^2], if one was given.
    recoil_weight_residual : float or None
        Fitted minus given recoil weight [kg m^2], if one was given.
    beam_widths : (float, float, float)
        The frame depths (tip, sides, throat) [m] that shaped EI (the sheet's, or
        :data:`~racket.specs.stiffness.TYPICAL_BEAM_WIDTHS`).
    """

    masses: dict
    layout: Layout
    twistweight_residual: float | None
    recoil_weight_residual: float | None
    beam_widths: tuple

    def parts(self) -> list[tuple[str, float, float, float, str]]:
        """(name, mass, low, high, source) of each part [kg]."""
        return [(p.name, self.masses[p.name], p.low, p.high, p.source) for p in PARTS]

    def at_edge(self) -> list[str]:
        """Warnings for the parts within :data:`EDGE_FRACTION` of an end of their range."""
        out = []
        for name, mass, low, high, _ in self.parts():
            margin = EDGE_FRACTION * (high - low)
            for end, bound in (("low", low), ("high", high)):
                if abs(mass - bound) <= margin:
                    out.append(
                        f"the {name} ({1e3 * mass:.1f} g) sits at the {end} end of its "
                        f"plausible range ({1e3 * low:g}-{1e3 * high:g} g): the sheet needs an "
                        f"unusual racket, or a spec-sheet number is off"
                    )
        return out

    def warnings(self) -> list[str]:
        """:meth:`at_edge`, and a given recoil weight or twistweight that the fit misses by
        more than :data:`MISMATCH_KGCM2`.
        """
        out = self.at_edge()
        for name, residual, why in (
            ("recoil_weight_kgcm2", self.recoil_weight_residual, "contradicts the swingweight"),
            ("twistweight_kgcm2", self.twistweight_residual, "cannot be met by parts in range"),
        ):
            if residual is not None and abs(1e4 * residual) > MISMATCH_KGCM2:
                out.append(
                    f"the given {name} {why}: the fitted racket's is {1e4 * residual:+.1f} "
                    f"kg cm^2 off it (mass, balance and swingweight are met)"
                )
        return out


def fit_profile(sheet: SpecSheet) -> tuple[Beam, Profile]:
    """The beam whose mass, balance, swingweight and f1 (given, or from the RA rating by
    :func:`~racket.specs.ra.f1_from_ra`, or the flex-test stiffness) equal the spec sheet's,
    and the fitted model.

    Raises ValueError, naming the quantity and the range plausible rackets reach, when no
    racket with parts in their plausible ranges meets the sheet.

    Parameters
    ----------
    sheet : SpecSheet
        The checked spec sheet, in SI (see :func:`~racket.specs.sheet.spec_sheet`).
    """
    lay = layout(sheet.length, sheet.head_area)
    fit = fit_masses(
        lay,
        sheet.mass,
        sheet.balance,
        sheet.swingweight,
        sheet.twistweight,
        recoil_given=sheet.swingweight_from_recoil,
    )
    widths = sheet.beam_widths or TYPICAL_BEAM_WIDTHS
    shape = bending_profile(lay.stations, lay.head_length, widths)
    beam = Beam(
        tuple(lay.stations),
        tuple(fit.masses @ lay.mass_shapes),
        tuple(shape),
        roll_inertia_per_length=tuple(fit.masses @ lay.roll_shapes),
    )
    if sheet.flex is None:  # f1 given, or from the RA rating by the TWU regression
        beam = beam.with_f1(sheet.f1 if sheet.ra is None else f1_from_ra(sheet.ra))
    else:  # the flex test's stiffness scales as EI, the frequencies as its square root
        deflection, load = sheet.flex
        ratio = load / deflection / flex_test_stiffness(beam, lay.head_length)
        f1 = beam.modes.frequencies[0] * np.sqrt(ratio)
        low, high, _ = SPEC_RANGES["f1_hz"]
        if not low <= f1 <= high:
            raise ValueError(
                f"flex_deflection_mm {1e3 * deflection:g} under flex_load_n {load:g} gives a "
                f"frame ringing at f1 = {f1:.4g} Hz, outside [{low:g}, {high:g}] Hz: "
                f"check the deflection and the load (a racket bends a few mm under 100-200 N)"
            )
        beam = beam.with_f1(f1)
    beam = beam.with_torsional_stiffness(torsional_profile(beam.bending_stiffness))
    if sheet.torsion_hz is not None:
        beam = beam.with_torsion_frequency(sheet.torsion_hz)
    recoil = None
    if sheet.recoil_weight is not None:
        recoil = beam.inertia_cm - sheet.recoil_weight
    profile = Profile(
        masses={p.name: float(m) for p, m in zip(PARTS, fit.masses, strict=True)},
        layout=lay,
        twistweight_residual=fit.twistweight_residual,
        recoil_weight_residual=recoil,
        beam_widths=tuple(widths),
    )
    return beam, profile


def from_specs(
    *, support: str = "free", string=None, gauge=None, pattern=None, state=None, **specs
) -> Racket:
    """A racket whose mass, balance, swingweight and frame stiffness equal a spec sheet's.

    Parameters
    ----------
    length_m : float
        Overall length [m]; default 0.6858 (27 in).
    mass_kg : float
        Strung mass [kg].
    balance_cm, balance_pts_hl : float
        Balance [cm from the butt], or points head-light (1 pt = 1/8 in from the middle;
        negative = head-heavy).  Give one.
    swingweight_kgcm2 : float
        Swingweight [kg cm^2] about the axis 10 cm from the butt (strung).
    recoil_weight_kgcm2 : float, optional
        Recoil weight [kg cm^2], the moment of inertia about the centre of mass: instead of
        the swingweight, or beside it as a check (the difference is reported).
    twistweight_kgcm2 : float, optional
        Moment of inertia about the long axis [kg cm^2]: met exactly when parts in their
        ranges can, else as closely as they can (the residual is reported).
    f1_hz, ra, flex_deflection_mm : float
        Frame stiffness: the first free-free bending frequency [Hz], the RA rating [-]
        (f1 from it by the regression on 622 rackets measured by Tennis Warehouse
        University, :func:`~racket.specs.ra.f1_from_ra`: 150 +/- 6 Hz at RA 66), or the tip
        deflection [mm] in a flex test under ``flex_load_n`` [N] at the tip (supports 7 cm
        from the butt and at the bottom of the head).  Give one.
    flex_load_n : float
        The flex test's load [N] (with ``flex_deflection_mm``).
    torsion_hz : float, optional
        Measured first torsion frequency of the free frame [Hz]; default: GJ from EI by
        the tube rule (:mod:`racket.specs.stiffness`).
    head_size_in2, head_size_cm2 : float
        Head (string-bed) area [in^2 or cm^2].  Give one.
    beam_width_mm : float or (float, float, float), optional
        Frame depth across the string plane [mm]: one value, or the tip, sides and throat
        (as "23/26/22 mm" on spec sheets).  It shapes the stiffness profile.
    tension_lb, tension_n, string_stiffness_n_m : float
        String tension [lb or N] (membrane model :func:`string_bed_stiffness`), or the
        string-plane stiffness [N/m].  Give one.
    string : str, optional
        What the racket is strung with (:func:`racket.strings.stringing.stringing`: a preset such
        as ``"polyester"``, or ``"MAINS/CROSSES"``): the bed's stiffness then follows from
        the tension, the pattern and the state, and it gains the string's stretch, loss and
        moving mass (with ``string_stiffness_n_m``, that stiffness is kept, as measured).
        Default: the rule for every racket that names no strings,
        :data:`racket.specs.strung.STRUNG` (fresh polyester 16L, 16x19, an assumption), as
        the catalogue, a TOML sheet and the page string it.  ``"linear"``
        (:data:`~racket.specs.strung.LINEAR`): the paper's linear, lossless, massless spring
        of the sheet's stiffness, by name.
    gauge : float or str, optional
        The string's gauge [m], or a name ("16L"); default the preset's (16L for the default
        string).
    pattern : str or (int, int), optional
        Mains x crosses [-], "16x19" (default).
    state : str, optional
        ``"fresh"`` (default) or ``"played"``.
    support : str
        As in :class:`~racket.Racket` ("free", "clamped-head" or "hand-held").

    Returns
    -------
    Racket
        Its beam has the fitted profile (:func:`fit_profile`), torsion included; its
        elliptical string bed has the head size and the membrane's stiffness profile (the
        sheet's stiffness at the centre, rising towards the frame, :mod:`racket.strings.membrane`).

    Raises
    ------
    ValueError
        For a missing, doubled or out-of-range spec, or a sheet no racket with plausible
        parts can meet (naming the quantity and the range such rackets reach).

    Examples
    --------
    >>> racket = from_specs(mass_kg=0.321, balance_cm=33.0, swingweight_kgcm2=325, f1_hz=150,
    ...                     head_size_in2=100, tension_lb=55)
    >>> round(racket.beam.swingweight_kgcm2, 6), round(racket.beam.twistweight_kgcm2, 1)
    (325.0, 14.8)
    """
    if string == LINEAR:
        given = [name for name, value in dict(gauge=gauge, pattern=pattern, state=state).items()
                 if value is not None]  # fmt: skip
        if given:
            raise ValueError(
                f"{given[0]} describes a string, and string={LINEAR!r} is the paper's plain "
                "spring with none: drop it, or name a string (e.g. 'polyester')"
            )
    elif string is None:  # the one rule for a racket that names no strings
        string, gauge = STRUNG["string"], STRUNG["gauge"] if gauge is None else gauge
        pattern = STRUNG["pattern"] if pattern is None else pattern
    sheet = spec_sheet(**specs)
    beam, profile = fit_profile(sheet)
    lay = profile.layout
    if string == LINEAR:
        strings = StringBed(
            sheet.string_stiffness, lay.strings_extent, lay.strings_width, profile="membrane"
        )
    else:
        strung = stringing(string, gauge, pattern, sheet.tension, state or "fresh")
        measured = None if sheet.tension is not None else sheet.string_stiffness
        strings = strung.bed(lay.strings_extent, lay.strings_width, stiffness=measured)
    return Racket(beam, strings, support)
