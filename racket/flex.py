"""The static flex test of racket diagnostic machines, on the beam model.

The RA rating of spec sheets comes from the Babolat RDC: "supporting the racquet at the
handle and in the throat while a force is applied to the tip; the stiffness index is a
measurement of how much the racquet tip is deflected" (Tennis Warehouse University,
"Racquet vibration explained").  :func:`flex_test_stiffness` models that test on a beam:
simple supports at :data:`HANDLE_SUPPORT` from the butt and at the throat end of the head, a
point load at the tip, and the tip stiffness F / deflection.

Calibration status.  Babolat publishes neither the machine's load nor the scale from the
deflection to RA.  The one public analysis found (Sten Solli, racquetTune, on the Tennis
Warehouse forum thread "Racquet stiffness - RDC/RA and frame frequency") shows RA rising with
the beam-theory stiffness 4 M f1^2 over the TWU frequency database, with a scatter too large
to compute one from the other.  Without paired (RA, f1 or deflection) data the RA -> stiffness
scale cannot be calibrated, so :func:`racket.from_specs` asks for f1 and refuses an RA-only
spec sheet with that reason; ``racket-impact specs`` prints the modelled test stiffness of
every fitted racket so that such data can calibrate it.
"""

from __future__ import annotations

import numpy as np

from beam import Beam, fem

HANDLE_SUPPORT = 0.07
"""Handle support of the modelled flex test [m from the butt] (the middle of the grip)."""

RA_UNCALIBRATED = (
    "ra cannot be used yet: the RA scale has no public calibration against a measurable "
    "stiffness (see racket.flex); give f1_hz, the frame's first free-free frequency [Hz]"
)


def flex_test_stiffness(beam: Beam, throat: float) -> float:
    """Tip stiffness [N/m] of the beam in the modelled flex test.

    Parameters
    ----------
    beam : Beam
        The frame (tip at x = 0).
    throat : float
        The throat support [m from the tip] (the throat end of the head).
    """
    supports = np.array([throat, beam.length - HANDLE_SUPPORT])
    extra = np.column_stack([supports, np.zeros(2)])
    nodes, k, _ = fem.assemble(
        np.asarray(beam.stations),
        beam.mass_per_length,
        beam.bending_stiffness,
        np.vstack([np.asarray(beam.point_masses).reshape(-1, 2), extra]),
        beam.elements,
    )
    fixed = [2 * int(np.argmin(np.abs(nodes - s))) for s in supports]
    free = np.setdiff1d(np.arange(k.shape[0]), fixed)
    load = np.zeros(free.size)
    load[0] = 1.0  # unit force at the tip's deflection (dof 0, which stays free)
    tip = np.linalg.solve(k[np.ix_(free, free)], load)[0]
    return float(1.0 / tip)
