"""Rackets from spec sheets: the fit round-trips with every part in its plausible range,
impossible sheets are refused with the reason, units, the membrane string-bed model, the
flex test and the catalogue.  (The sample of real spec sheets and lead tape by clock
position: tests/test_spec_sheets.py.)"""

import dataclasses

import numpy as np
import pytest
from helpers import examples
from hypothesis import given, settings
from hypothesis import strategies as st

from common.units import IN2, LB, POINT
from racket import CATALOG, flex_test_stiffness, from_specs, string_bed_stiffness
from racket.specs import PARTS, fit_profile, spec_sheet
from racket.specs.mass_fit import fit_masses
from racket.specs.parts import layout

# Five spec sheets from light and head-heavy to heavy and head-light, flexible to stiff.
SHEETS = {
    "light head-heavy oversize, stiff": dict(
        mass_kg=0.265, balance_pts_hl=-4, swingweight_kgcm2=300, head_size_in2=110, f1_hz=185
    ),
    "light even, mid-plus": dict(
        mass_kg=0.285, balance_cm=34.0, swingweight_kgcm2=305, head_size_in2=102, f1_hz=160
    ),
    "Pure Drive-like": dict(
        mass_kg=0.321, balance_cm=33.0, swingweight_kgcm2=325, head_size_cm2=645, f1_hz=150
    ),
    "player's frame": dict(
        mass_kg=0.340, balance_pts_hl=7, swingweight_kgcm2=330, head_size_in2=98, f1_hz=135
    ),
    "heavy head-light midsize, flexible": dict(
        mass_kg=0.360, balance_pts_hl=10, swingweight_kgcm2=335, head_size_in2=90, f1_hz=115
    ),
}


def _targets(specs):
    sheet = spec_sheet(tension_lb=55, **specs)
    return sheet.mass, sheet.balance, sheet.swingweight, sheet.f1


@pytest.mark.parametrize("name", SHEETS)
def test_fit_round_trips(name):
    specs = SHEETS[name]
    racket = from_specs(tension_lb=55, **specs)
    mass, balance, swingweight, f1 = _targets(specs)
    beam = racket.beam
    assert beam.mass == pytest.approx(mass, rel=1e-3)
    assert beam.balance == pytest.approx(balance, rel=1e-3)
    assert beam.swingweight == pytest.approx(swingweight, rel=1e-3)
    assert beam.modes.frequencies[0] == pytest.approx(f1, rel=1e-2)
    # In fact the fit is exact, and f1 is exact to the eigen-solver's accuracy.
    assert beam.swingweight == pytest.approx(swingweight, rel=1e-12)
    assert beam.modes.frequencies[0] == pytest.approx(f1, rel=1e-7)
    assert min(beam.mass_per_length) > 0
    _, profile = fit_profile(spec_sheet(tension_lb=55, **specs))
    for part in PARTS:
        assert part.low <= profile.masses[part.name] <= part.high
    assert sum(profile.masses.values()) == pytest.approx(mass, rel=1e-12)


def test_units_are_explicit_and_equivalent():
    base = dict(mass_kg=0.3, swingweight_kgcm2=310, f1_hz=150)
    a = spec_sheet(balance_cm=34.29, head_size_in2=100, tension_lb=55, **base)
    b = spec_sheet(balance_pts_hl=0, head_size_cm2=100 * IN2 * 1e4, tension_n=55 * LB, **base)
    assert a.balance == pytest.approx(0.6858 / 2)
    assert b.balance == pytest.approx(a.balance)
    assert b.head_area == pytest.approx(a.head_area)
    assert b.string_stiffness == pytest.approx(a.string_stiffness)
    eight_hl = spec_sheet(balance_pts_hl=8, head_size_in2=100, tension_lb=55, **base)
    assert a.balance - eight_hl.balance == pytest.approx(8 * POINT)  # 8 pts = 1 inch
    given_k = spec_sheet(balance_cm=33, head_size_in2=100, string_stiffness_n_m=3.3e4, **base)
    assert given_k.string_stiffness == 3.3e4 and given_k.tension is None


@pytest.mark.parametrize(
    "change, match",
    [
        (dict(swingweight_kgcm2=400), r"swingweight_kgcm2 must be in \(\d+, \d+\) kg cm\^2"),
        (dict(swingweight_kgcm2=200), r"swingweight_kgcm2 must be in \(\d+, \d+\) kg cm\^2"),
        (dict(balance_cm=60.0), r"balance_cm must be in \[20, 50\] cm from the butt, got 60"),
        (dict(head_size_cm2=1300.0), r"head_size_cm2 must be in \[\d+, \d+\] cm\^2"),
        (dict(length_m=0.53, balance_cm=30.0), r"too large"),
        (dict(length_m=0.5, balance_cm=30.0), r"length_m must be in \[0.52, 0.75\] m"),
        (dict(mass_kg=0.01), r"mass_kg must be in \[0.15, 0.5\] kg, got 0.01"),
        (dict(mass_kg=float("nan")), r"mass_kg must be a finite number"),
        (dict(f1_hz=-3), r"f1_hz must be in \[60, 400\] Hz, got -3"),
    ],
)
def test_infeasible_or_bad_specs_raise_with_the_reason(change, match):
    specs = dict(SHEETS["Pure Drive-like"], tension_lb=55) | change
    with pytest.raises(ValueError, match=match):
        from_specs(**specs)


def test_a_balance_off_the_racket_is_refused():
    sheet = spec_sheet(**SHEETS["Pure Drive-like"], tension_lb=55)
    with pytest.raises(ValueError, match=r"balance must lie on the racket"):
        dataclasses.replace(sheet, length=0.46, balance=0.47)


def test_swingweight_range_in_the_message_is_the_feasible_range():
    specs = dict(SHEETS["Pure Drive-like"], tension_lb=55, swingweight_kgcm2=500)
    with pytest.raises(ValueError) as err:
        from_specs(**specs)
    lo, hi = (float(v) for v in err.value.args[0].split("(")[1].split(")")[0].split(","))
    from_specs(**(specs | dict(swingweight_kgcm2=lo + 1)))
    from_specs(**(specs | dict(swingweight_kgcm2=hi - 1)))
    for outside in (lo - 1, hi + 1):
        with pytest.raises(ValueError):
            from_specs(**(specs | dict(swingweight_kgcm2=outside)))


@pytest.mark.parametrize(
    "specs, match",
    [
        (dict(balance_cm=33, balance_pts_hl=4), "give exactly one balance"),
        (dict(), "give exactly one balance"),
        (dict(balance_cm=33, tension_lb=55, tension_n=245), "give exactly one string bed"),
        (dict(balance_cm=33, ra=66, f1_hz=150), "give exactly one frame stiffness"),
    ],
)
def test_missing_or_doubled_specs(specs, match):
    base = dict(mass_kg=0.32, swingweight_kgcm2=320, head_size_in2=100)
    specs = base | {"tension_lb": 55, "f1_hz": 150} | specs
    if "tension_n" in specs and "tension_lb" in specs and match != "give exactly one string bed":
        specs.pop("tension_n")
    with pytest.raises(ValueError, match=match):
        from_specs(**specs)


def test_membrane_model_calibration_and_trends():
    assert string_bed_stiffness(245.0, 100 * IN2) == pytest.approx(3e4, rel=1e-12)
    small, large = string_bed_stiffness(245.0, 90 * IN2), string_bed_stiffness(245.0, 115 * IN2)
    assert small > 3e4 > large  # the same tension is stiffer on a smaller head
    with pytest.raises(ValueError, match="head size"):
        string_bed_stiffness(245.0, 10 * IN2)


@settings(max_examples=examples(40), deadline=None)
@given(
    st.floats(20.0, 400.0),
    st.floats(1.001, 2.0),
    st.floats(80.0, 130.0),
)
def test_membrane_stiffness_rises_with_tension(tension, factor, head_in2):
    low = string_bed_stiffness(tension, head_in2 * IN2)
    assert string_bed_stiffness(tension * factor, head_in2 * IN2) > low > 0


@pytest.mark.parametrize("where_cm_from_tip", [0.0, 16.58, 34.58, 58.58, 68.58])
def test_lead_tape_follows_the_parallel_axis_rule(where_cm_from_tip):
    racket = from_specs(tension_lb=55, **SHEETS["Pure Drive-like"])
    beam, m = racket.beam, 0.004
    x = where_cm_from_tip / 100
    taped = racket.with_mass(m, x).beam
    d = beam.length - 0.10 - x  # distance from the swingweight axis (10 cm from the butt)
    assert taped.swingweight - beam.swingweight == pytest.approx(m * d**2, rel=1e-10, abs=1e-15)
    y = beam.center_of_mass - x  # from the old centre of mass, towards the tip
    shift = beam.center_of_mass - taped.center_of_mass  # towards the tip
    assert shift == pytest.approx(y * m / (beam.mass + m), rel=1e-10, abs=1e-15)
    # the balance (spec sheets give it from the butt) moves as far
    assert taped.balance - beam.balance == pytest.approx(shift, rel=1e-10, abs=1e-15)
    assert taped.mass == pytest.approx(beam.mass + m)
    # Recoil weight: the new I about the new centre of mass.
    recoil = beam.inertia_cm + beam.mass * shift**2 + m * (y - shift) ** 2
    assert taped.inertia_cm == pytest.approx(recoil, rel=1e-10)
    assert taped.recoil_weight_kgcm2 == pytest.approx(1e4 * recoil, rel=1e-10)


def test_lead_at_twelve_raises_power_near_the_tip():
    from racket import impact, paper_ball

    racket = from_specs(tension_lb=55, **SHEETS["Pure Drive-like"])
    x = np.array([0.02, 0.15, 0.30])
    plain = impact(racket, paper_ball(), x, 20.0)
    taped = impact(racket.with_mass(0.006, 0.0), paper_ball(), x, 20.0)
    assert taped.e[0] > plain.e[0] + 0.005  # heavier tip: more effective mass there
    assert taped.effective_mass[0] > plain.effective_mass[0]


def test_flex_test_matches_the_overhanging_beam_formula():
    from beam import Beam

    beam = Beam.uniform(0.68, 0.34, 120.0)
    throat = 0.32
    span = (0.68 - 0.07) - throat
    ei = beam.bending_stiffness[0]
    expected = 3 * ei / (throat**2 * (throat + span))  # P a^2 (a + L) / (3 EI), a overhang
    assert flex_test_stiffness(beam, throat) == pytest.approx(expected, rel=1e-7)


def test_flex_test_stiffness_scales_with_f1_squared():
    soft = from_specs(tension_lb=55, **(SHEETS["Pure Drive-like"] | dict(f1_hz=120)))
    stiff = from_specs(tension_lb=55, **(SHEETS["Pure Drive-like"] | dict(f1_hz=180)))
    ratio = flex_test_stiffness(stiff.beam, 0.33) / flex_test_stiffness(soft.beam, 0.33)
    assert ratio == pytest.approx(1.5**2, rel=1e-6)


@pytest.mark.parametrize("name", CATALOG)
def test_catalogue_rackets_fit_and_name_every_source(name):
    entry = CATALOG[name]
    assert set(entry.sources) == set(entry.specs)
    assert all(entry.sources.values())
    sheet = spec_sheet(**entry.specs)
    beam = entry.racket().beam
    assert beam.mass == pytest.approx(sheet.mass, rel=1e-9)
    assert beam.balance == pytest.approx(sheet.balance, rel=1e-9)
    assert beam.swingweight == pytest.approx(sheet.swingweight, rel=1e-9)


@settings(max_examples=examples(30), deadline=None)
@given(
    mass=st.floats(0.22, 0.40),
    balance=st.floats(0.28, 0.38),
    swingweight=st.floats(200.0, 420.0),
    head=st.floats(85.0, 120.0),
)
def test_any_sheet_round_trips_or_is_refused_with_a_reason(mass, balance, swingweight, head):
    specs = dict(
        mass_kg=mass,
        balance_cm=100 * balance,
        swingweight_kgcm2=swingweight,
        head_size_in2=head,
        f1_hz=150.0,
        tension_lb=55,
    )
    try:
        racket = from_specs(**specs)
    except ValueError as err:
        assert str(err).startswith(("swingweight_kgcm2 must be in", "balance must be in"))
        return
    beam = racket.beam
    assert min(beam.mass_per_length) > 0
    assert beam.mass == pytest.approx(mass, rel=1e-9)
    assert beam.balance == pytest.approx(balance, rel=1e-9)
    assert beam.swingweight_kgcm2 == pytest.approx(swingweight, rel=1e-9)


def test_a_mass_no_plausible_parts_add_up_to_is_refused():
    lay = layout(0.6858, 100 * IN2)
    total = sum(p.low for p in PARTS)
    with pytest.raises(ValueError, match=r"mass_kg must be in \(0.\d+, 0.\d+\) kg .*got 0.12"):
        fit_masses(lay, 0.12, 0.33, 0.03)
    assert total > 0.12


def test_a_sheet_checks_its_torsion_frequency_however_it_is_built():
    from dataclasses import replace

    from racket.specs.sheet import spec_sheet

    sheet = spec_sheet(**SHEETS["Pure Drive-like"], length_m=0.685, tension_lb=55, torsion_hz=320)
    assert sheet.torsion_hz == 320.0 and isinstance(sheet.torsion_hz, float)
    with pytest.raises(ValueError, match=r"torsion_hz must be in \[150, 1500\] Hz"):
        replace(sheet, torsion_hz=5.0)
