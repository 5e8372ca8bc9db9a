"""The ERT's "dynamic tension" (DT) of a string bed, as a stringer reads it: the force that
deflects the bed's centre by 1 cm, per cm [kp/cm] ("the force to deflect the bed 1 cm for a
short time", ert300.com, ``data/measurements.md`` sec. 5).

A bed pushed by w carries F = k w (1 + stretch w**2) (:class:`racket.StringBed`), so at 1 cm
the DT is k (1 + stretch (1 cm)**2) / (1 kp/cm): it depends on the material through the
bed's stretch, which grows with the strings' axial stiffness EA
(:meth:`racket.strings.stringing.Stringing.stretch`).  A stiff polyester bed reads higher
than a gut bed at the same tension and the same small-deflection stiffness k.  A measured DT
is turned back into k by solving the same relation with the bed's own stretch.
"""

from __future__ import annotations

from common.checks import positive
from common.units import KP_PER_CM
from racket.strings.bed import BED_STIFFNESS_RANGE, STRETCH_MAX

ERT_DEFLECTION = 0.01
"""The deflection [m] at which the ERT reads the bed: 1 cm (ert300.com, its definition of
DT, ``data/measurements.md`` sec. 5)."""


def dt_reading(stiffness: float, stretch: float) -> float:
    """The ERT's DT [kp/cm] of a bed of centre ``stiffness`` [N/m] and ``stretch``
    [1/m^2]: k (1 + stretch (1 cm)**2) / 980.665 N/m.

    Parameters
    ----------
    stiffness : float
        The bed's stiffness at its centre for a small deflection [N/m].
    stretch : float
        How fast it stiffens as it deflects [1/m^2] (:class:`racket.StringBed`).
    """
    return stiffness * (1.0 + stretch * ERT_DEFLECTION**2) / KP_PER_CM


def stiffness_from_dt(bed, dt_kp_cm: float, argument: str = "DT") -> float:
    """The centre stiffness k [N/m] of ``bed``'s strings that reads ``dt_kp_cm`` on the
    ERT: k (1 + stretch(k) (1 cm)**2) = DT x 980.665 N/m, stretch(k) the stretch of the bed's
    stringing at the tension that gives k (none for the paper's plain spring).  A DT no
    tension of these strings reads (a stiff string's stiffening by 1 cm alone reads a few
    kp/cm), or that gives a stiffness outside
    :data:`racket.strings.bed.BED_STIFFNESS_RANGE`, is refused in one line naming
    ``argument``.

    Parameters
    ----------
    bed : StringBed
        The bed, strung as measured (its ``stringing``, ``area``).
    dt_kp_cm : float
        The ERT's reading [kp/cm].
    argument : str, optional
        The input the DT came from, as a message names it ("--string-bed-dt").
    """
    from scipy.optimize import brentq  # here: the command line starts without scipy

    force = KP_PER_CM * positive(argument, dt_kp_cm, "kp/cm")
    strung = bed.stringing
    if strung is None:
        return force
    area = bed.area

    def misread(k: float) -> float:
        return dt_reading(k, strung.stretch(area, k)) - dt_kp_cm

    low, high = 1e-3 * force, 10.0 * force
    too_low = misread(low) > 0.0
    if too_low or misread(high) < 0.0:
        end, side = (low, "below the lowest") if too_low else (high, "above the highest")
        raise ValueError(
            f"{argument} {dt_kp_cm:g} kp/cm is {side} DT these strings "
            f"({strung.describe('')}) read at any tension on this head (about "
            f"{dt_reading(end, strung.stretch(area, end)):.3g} kp/cm): check the reading and "
            "its unit"
        )
    k = brentq(misread, low, high, xtol=1e-9 * force)
    stretch = strung.stretch(area, k)
    if not 0.0 <= stretch <= STRETCH_MAX:  # no such bed: a tension beyond EA, or next to none
        way = "past their own axial stiffness" if stretch < 0.0 else "to almost no tension"
        raise ValueError(
            f"{argument} {dt_kp_cm:g} kp/cm would need these strings ({strung.describe('')}) "
            f"pulled {way}: check the reading and its unit"
        )
    low, high = BED_STIFFNESS_RANGE
    if not low <= k <= high:  # a bed the solver does not take, said as the DT typed
        raise ValueError(
            f"{argument} {dt_kp_cm:g} kp/cm gives these strings ({strung.describe('')}) a "
            f"centre stiffness of {k:.4g} N/m, outside the {low:g}-{high:g} N/m a string bed "
            "may have: check the reading and its unit"
        )
    return k
