"""The frame's bending stiffness: its profile along the racket, and the static flex test.

Profile
-------
:func:`bending_profile` gives EI along the racket up to a scale: EI = w d(x)**3, with d
the frame's depth across the string plane (the spec sheets' "beam width") and w the total
in-plane width of the members side by side, for thin-walled sections alike but for their
depth (the second moment of area of a section of fixed shape scales as its depth cubed; at a
fixed wall, as its width):

* the head: two rails whose depth runs linearly from the tip's width to the sides' width
  at the head's middle and to the throat's width at its bottom;
* the throat: two arms of the throat's width;
* the handle: one shaft of the throat's depth, as wide in the plane as the two arms
  together (assumption: the shaft inside the pallet is about 2.5 cm wide, each throat arm
  about half that), so the same EI as the throat.

The shape is then set by the beam widths alone: a thicker throat (BeamWidth3) stiffens the
throat and handle against the head; equal widths give a uniform EI.  With the sheets'
typical widths (tip 23, sides 24, throat 22.5 mm) EI varies by about 20 % along the frame.
The scale then follows from the frame stiffness given: f1 (frequencies scale as sqrt(EI)
at a fixed mass; an RA rating gives f1 by :mod:`racket.specs.ra`), or a measured flex-test
deflection (:func:`flex_test_stiffness` scales as EI).

Torsion
-------
The torsional stiffness GJ follows EI by the thin-walled tube's rule GJ = EI / (1 + nu)
(J = 2 I and G = E / (2 (1 + nu)) for a circular tube) with nu = :data:`POISSON` (an
estimate for an isotropic wall; a composite's +-45 degree plies make G, and so GJ, larger).
It gives the Pure Drive a first torsion mode at about 320 Hz.  We found no published
measured torsional frequency we could verify, so a measured value can be given instead
(``torsion_hz`` of :func:`racket.from_specs`), which scales GJ to it.

Flex test
---------

The RA rating of spec sheets comes from the Babolat RDC: "supporting the racquet at the
handle and in the throat while a force is applied to the tip; the stiffness index is a
measurement of how much the racquet tip is deflected" (Tennis Warehouse University,
"Racquet vibration explained").  :func:`flex_test_stiffness` models that test on a beam:
simple supports at :data:`HANDLE_SUPPORT` from the butt and at the throat end of the head, a
point load at the tip, and the tip stiffness F / deflection.

RA and frequency.  Babolat publishes neither the machine's load nor the scale from the
deflection to RA, so the modelled test cannot be converted to RA.  An RA rating is used
instead through the regression of f1 on RA over 622 rackets measured both ways by Tennis
Warehouse University (:mod:`racket.specs.ra`): the first free frequency it gives sets the
scale as a given f1 does.  ``racket-impact specs`` prints the modelled test stiffness of every
fitted racket.
"""

from __future__ import annotations

import numpy as np

from beam import Beam, fem
from common.checks import in_range
from common.typechecks import instance

POISSON = 0.3
"""Poisson's ratio of the tube rule GJ = EI / (1 + nu) (assumption: an isotropic wall)."""

HANDLE_SUPPORT = 0.07
"""Handle support of the modelled flex test [m from the butt] (the middle of the grip)."""

TYPICAL_BEAM_WIDTHS = (0.023, 0.024, 0.0225)
"""Beam widths [m] (tip, sides, throat) used when a sheet gives none: the medians of the
139 spec sheets of tests/data/racket_specs_sample.csv (23, 24 and 22.5 mm)."""


def bending_profile(stations, head_length: float, widths) -> np.ndarray:
    """EI of each cell between ``stations`` [m from the tip], up to a scale (see the module
    docstring): the head ends at ``head_length`` [m], and ``widths`` are the frame's depths
    (tip, sides, throat) [m].

    Parameters
    ----------
    stations : array_like
        Cell boundaries [m from the tip].
    head_length : float
        Length of the head, from the tip to the bottom of the hoop [m].
    widths : (float, float, float)
        The frame's depths across the string plane at the tip, the sides and the throat [m].
    """
    stations = np.asarray(stations, dtype=float)
    mid = 0.5 * (stations[:-1] + stations[1:])
    tip, sides, throat = widths
    return np.interp(mid, [0.0, 0.5 * head_length, head_length], [tip, sides, throat]) ** 3


def flex_test_stiffness(beam: Beam, throat: float) -> float:
    """Tip stiffness [N/m] of the beam in the modelled flex test.

    Parameters
    ----------
    beam : Beam
        The frame (tip at x = 0).
    throat : float
        The throat support [m from the tip] (the throat end of the head).
    """
    instance("beam", beam, Beam, "a beam.Beam")
    handle = beam.length - HANDLE_SUPPORT
    throat = in_range("throat", throat, 0.0, handle, "m from the tip")
    supports = np.array([throat, handle])
    extra = np.column_stack([supports, np.zeros(2)])
    nodes, k, _ = fem.assemble(
        np.asarray(beam.stations),
        beam.mass_per_length,
        beam.bending_stiffness,
        np.vstack([beam.point_array[:, :2], extra]),
        beam.elements,
    )
    fixed = [2 * int(np.argmin(np.abs(nodes - s))) for s in supports]
    free = np.setdiff1d(np.arange(k.shape[0]), fixed)
    load = np.zeros(free.size)
    load[0] = 1.0  # unit force at the tip's deflection (dof 0, which stays free)
    tip = np.linalg.solve(k[np.ix_(free, free)], load)[0]
    return float(1.0 / tip)


def torsional_profile(bending_stiffness) -> np.ndarray:
    """GJ [N m^2] of each segment from its EI [N m^2] by the tube rule EI / (1 + nu).

    Parameters
    ----------
    bending_stiffness : array_like
        Bending stiffness EI of each segment [N m^2].
    """
    return np.asarray(bending_stiffness, dtype=float) / (1.0 + POISSON)
