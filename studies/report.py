"""What a fitted racket model is: the tables ``racket-impact specs`` prints.

:func:`spec_report` compares a racket with the spec sheet it was fitted to and lists its
mass properties, mass split, modes (free and hand-held), centre of percussion, flex-test
stiffness and effective mass along the strings.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pandas as pd

from ball import BALL_PRESETS, DEFAULT_BALL, Ball
from beam import Beam
from beam.beam import MAX_MODES
from common.checks import whole
from common.typechecks import instance
from racket import Racket, flex_test_stiffness
from racket.specs import Profile, SpecSheet, fit_profile, spec_sheet
from racket.specs.ra import RA_ROWS, RA_SCATTER, f1_from_ra
from racket.system import held_mode, held_system
from studies.arguments import ball_argument, racket_argument
from studies.face.sweetspots import sweet_spots


@dataclass(frozen=True)
class SpecReport:
    """Tables describing a racket model (each a DataFrame).

    Each table's columns name their units.

    Parameters
    ----------
    fit : DataFrame
        The spec sheet against the fitted model (empty without a spec sheet); an RA rating
        appears as the f1 it gives (:func:`racket.specs.ra.f1_from_ra`) with the scatter.
    properties : DataFrame
        Mass properties, centre of percussion, string bed and flex-test stiffness.
    modes : DataFrame
        Free-free bending modes and the hand-held racket's coupled modes [Hz].
    effective_mass : DataFrame
        Effective mass [kg] along the strings.
    parts : DataFrame
        Fitted part masses [g] beside their plausible ranges (empty without a spec sheet).
    sweet_spots : DataFrame
        The sweet spots (:func:`studies.face.sweetspots.sweet_spots`).
    warnings : tuple of str, optional
        A warning for each fitted part at the edge of its range.
    """

    fit: pd.DataFrame
    properties: pd.DataFrame
    modes: pd.DataFrame
    effective_mass: pd.DataFrame
    parts: pd.DataFrame
    sweet_spots: pd.DataFrame
    warnings: tuple = ()


def _fit_table(sheet: SpecSheet, beam: Beam, throat: float) -> pd.DataFrame:
    """The spec sheet against the fitted model (before lead tape or other changes)."""
    rows = [
        ("mass", 1e3 * sheet.mass, 1e3 * beam.mass, "g"),
        ("balance", 100 * sheet.balance, 100 * beam.balance, "cm from the butt"),
        ("swingweight", 1e4 * sheet.swingweight, beam.swingweight_kgcm2, "kg cm^2"),
    ]
    if sheet.recoil_weight is not None:
        rows.append(
            ("recoil weight", 1e4 * sheet.recoil_weight, beam.recoil_weight_kgcm2, "kg cm^2")
        )
    if sheet.twistweight is not None:
        rows.append(("twistweight", 1e4 * sheet.twistweight, beam.twistweight_kgcm2, "kg cm^2"))
    if sheet.f1 is not None:
        rows.append(("f1 (free-free)", sheet.f1, beam.modes.frequencies[0], "Hz"))
    elif sheet.ra is not None:
        rows.append(
            (
                f"f1 from RA {sheet.ra:g}",
                f1_from_ra(sheet.ra),
                beam.modes.frequencies[0],
                f"Hz (+/- {RA_SCATTER:.1f}, TWU regression of {RA_ROWS} rackets)",
            )
        )
    else:
        deflection, load = sheet.flex
        rows.append(
            (
                "flex-test deflection",
                1e3 * deflection,
                1e3 * load / flex_test_stiffness(beam, throat),
                f"mm under {load:g} N",
            )
        )
    table = pd.DataFrame(rows, columns=["quantity", "spec_sheet", "fitted_model", "unit"])
    difference = table["fitted_model"] / table["spec_sheet"] - 1.0
    # an exact fit's round-off (a few 1e-16) is no difference: 0, not -2.2e-16
    table["relative_difference"] = difference.where(difference.abs() > 1e-12, 0.0)
    return table


def _parts(profile: Profile) -> pd.DataFrame:
    """The fitted part masses beside their plausible ranges and the ranges' sources."""
    return pd.DataFrame(
        [
            (name, 1e3 * mass, 1e3 * low, 1e3 * high, source)
            for name, mass, low, high, source in profile.parts()
        ],
        columns=["part", "mass_g", "low_g", "high_g", "source"],
    )


def _properties(racket: Racket, spots: pd.DataFrame) -> pd.DataFrame:
    beam = racket.beam
    throat = 2.0 * racket.hoop.center
    cop = spots.set_index("spot").loc["centre of percussion"]  # simulated (sweet_spots)
    rows = [
        ("length", 100 * beam.length, "cm"),
        ("mass", 1e3 * beam.mass, "g"),
        ("centre of mass", 100 * beam.center_of_mass, "cm from the tip"),
        ("balance", 100 * beam.balance, "cm (spec sheets give it from the butt)"),
        ("swingweight", beam.swingweight_kgcm2, "kg cm^2 (axis 10 cm from the butt)"),
        ("recoil weight", beam.recoil_weight_kgcm2, "kg cm^2 (about the centre of mass)"),
        *(
            [("twistweight", beam.twistweight_kgcm2, "kg cm^2 (about the long axis)")]
            if beam.roll_inertia is not None
            else []
        ),
        *(
            [("first torsion mode", beam.roll_modes.frequencies[0], "Hz (free frame)")]
            if beam.roll_modes is not None and beam.roll_modes.count > 1
            else []
        ),
        (
            "centre of percussion",
            cop["from_tip_cm"],
            f"cm from the tip (hand at {cop['value']:.1f} cm from the tip)",
        ),
        ("string-bed stiffness", racket.strings.stiffness, "N/m"),
        ("string bed", 100 * (racket.strings.extent[1] - racket.strings.extent[0]), "cm long"),
        (
            "flex-test tip stiffness",
            flex_test_stiffness(beam, throat),
            "N/m (handle and bottom of the head supported; not converted to RA)",
        ),
    ]
    added = beam.point_array[:, 1].sum()
    if added > 0:
        rows.append(("added point masses", 1e3 * added, "g (lead tape)"))
    return pd.DataFrame(rows, columns=["quantity", "value", "unit"])


def _modes(racket: Racket, count: int) -> pd.DataFrame:
    modes = racket.beam.modes
    held = held_system(modes, racket.hand)
    lam = held.blocks[:, 0, 0] + 1j * held.blocks[:, 0, 1]
    order = np.argsort(np.abs(lam))
    rows = []
    for k in range(1, min(count, modes.count - 2) + 1):
        row = {
            "mode": k,
            "free_Hz": modes.frequencies[k - 1],
            "nodes_cm_from_tip": ", ".join(f"{100 * n:.1f}" for n in modes.nodes(k)),
        }
        row["hand_held_Hz"], row["hand_held_damping_ratio"] = held_mode(held, k + 1)
        rows.append(row)
    free = np.all(held.blocks == [[0.0, 1.0], [0.0, 0.0]], axis=(1, 2))  # racket and hand
    rocking = [j for j in order[held.dc[order]] if not free[j]]
    for i, j in enumerate(rocking):
        root = lam[j]
        rows.append(
            {
                "mode": f"rocking {i + 1}",
                "hand_held_Hz": abs(root.imag) / (2 * np.pi),
                "hand_held_damping_ratio": -root.real / abs(root),
            }
        )
    return pd.DataFrame(rows)


def spec_report(
    racket: Racket, specs: dict | None = None, count: int = 4, ball: Ball | None = None
) -> SpecReport:
    """Tables describing ``racket``; with the spec sheet it was fitted to (``specs``, the
    keywords of :func:`racket.from_specs`), also the sheet against the fitted model (before
    any lead tape), the fitted parts with their plausible ranges, and a warning for each
    part at the edge of its range.

    The modes table lists the free-free bending modes and, for the racket held by its
    :class:`racket.Hand`, the coupled modes (frequency and damping ratio), including the
    slow modes of the racket rocking on the hand.

    Parameters
    ----------
    racket : Racket
        The racket model.
    specs : dict, optional
        The spec sheet it was fitted to, as keywords of :func:`racket.from_specs` (units in
        their names); None: no fit tables.
    count : int, optional
        Bending modes to list, in [1, 200] (at most the beam's).
    ball : Ball, optional
        The ball of the sweet spots; default the ITF type 2 ball (:data:`ball.DEFAULT_BALL`).
    """
    racket = racket_argument(racket)
    ball = None if ball is None else ball_argument(ball)
    specs = instance("specs", specs, dict | type(None), "a dict of from_specs keywords or None")
    count = whole("count", count, 1, MAX_MODES)
    x = np.linspace(*racket.strings.extent, 9)
    effective = pd.DataFrame(
        {
            "position_from_tip_m": x,
            "position_from_tip_cm": 100 * x,
            "effective_mass_kg": racket.beam.effective_mass(x),
        }
    )
    fit, parts, warnings = pd.DataFrame(), pd.DataFrame(), ()
    if specs is not None:
        sheet = spec_sheet(**specs)
        fitted, profile = fit_profile(sheet)
        fit = _fit_table(sheet, fitted, profile.layout.head_length)
        parts = _parts(profile)
        warnings = tuple(profile.warnings())
    spots = sweet_spots(racket, BALL_PRESETS[DEFAULT_BALL].ball() if ball is None else ball)
    return SpecReport(
        fit=fit,
        properties=_properties(racket, spots),
        modes=_modes(racket, count),
        effective_mass=effective,
        parts=parts,
        sweet_spots=spots,
        warnings=warnings,
    )
