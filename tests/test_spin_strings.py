"""Issues 36 and 44's targets for the spin off the strings, each a test on published
numbers (``data/measurements.md`` sec. 6; TWU, Lindsey): the spin off a clamped racket by
string, polyester against nylon, lubricated against dry, the spin of a laterally rigid bed
whatever the ball-string friction, and the mains' slide ("a few mm", "about 2 ms"); and how
the spin moves over the sideways bed's assumptions (the grip's share on the mains, kinetic
friction, the snapback's time).

The sideways bed is :mod:`racket.strings.sideways`'s picture: the ball grips mains and
crosses through two patches, the strings held at the crossings by the weave's preload and
the ball's force, their spring set on the measured snapback; no number tuned to these rows.
TWU's ball slides across the mains (it films them moving sideways).  Met: the mains' slide
and snapback, gut's level at 52 lb, the order polyester > nylon, nylon's lubrication gain
within TWU's band widened by its inputs' scatter, and TWU's "nearly the same for all
magnitudes of string-ball friction" in its own limit (a tangentially noncompliant contact).
Not met, kept as strict expected failures with the model's number and the measured band as
their reason: the level of polyester, nylon and gut at 62 lb, polyester's margin over
nylon, polyester's lubrication gain, and the rigid bed's indifference to the ball's friction
with the ball's own tangential spring.
"""

import dataclasses

import numpy as np
import pytest

from ball import BALL_PRESETS
from ball.spin import INERTIA_FACTOR, BallSpin
from common.units import LB, MPH
from racket.solver.oblique import oblique_impact
from racket.strings.sideways import SNAPBACK_TIME, BedSideways, sideways, snapback_time
from studies.validation import comparisons
from studies.validation.conditions import clamped_racket

BALL = BALL_PRESETS["itf-type-2"].ball()
RPM_PER_RAD_S = 60.0 / (2.0 * np.pi)
"""rpm per rad/s."""

MATERIALS = ("polyester", "nylon", "natural-gut")
TENSIONS_LB = (52.0, 62.0)
STRING_TEST = (25.0, 40.0, -3820.0)
"""TWU "String movement and spin": ball speed [m/s] (56 mph), angle from the normal [deg],
incident spin [rpm] (backspin)."""
SPIN_BAND = (1200.0, 1810.0)
"""Its spin out over 7 strings, 1207-1803 rpm, rounded outwards [rpm]."""
LUBE_TEST = (49.0 * MPH, 28.0, -3150.0, 60.0)
"""TWU "String lubrication and movement in spin": speed [m/s], angle [deg], spin [rpm],
tension [lb] (16x19)."""
LUBE_BAND = (0.14, 0.58)
"""Its gain of spin, lubricated over dry [-]."""
FRICTIONS = (0.3, 0.45, 0.6)
"""Ball-string coefficients of friction [-] spanning TWU's strings (p10-p90 0.32-0.56)."""


def _hit(racket, side, speed, angle_deg, spin_rpm, ball_spin=None):
    """The oblique impact at the bed's centre: the ball slides across the mains with
    backspin (about the along axis), as in TWU's tests; its spin out is ``-.spin[0, 0]``
    (> 0: reversed)."""
    angle = np.radians(angle_deg)
    return oblique_impact(
        racket, BALL, racket.strings.center, speed * np.cos(angle),
        slip_velocity=(0.0, speed * np.sin(angle)), spin=(-spin_rpm / RPM_PER_RAD_S, 0.0, 0.0),
        side=side, ball_spin=ball_spin,
    )  # fmt: skip


def _rpm(hit):
    return float(-hit.spin[0, 0] * RPM_PER_RAD_S)


@pytest.fixture(scope="module")
def clamped():
    """TWU's clamped test: (material, lb, "dry" | "lubricated" | "stiff") -> the impact."""
    out = {}
    for material in MATERIALS:
        for lb in TENSIONS_LB:
            racket = clamped_racket(None, material, lb * LB)
            bed = racket.strings
            sides = {
                "dry": sideways(bed),
                "lubricated": sideways(bed, lubricated=True),
                "stiff": sideways(bed, slide=False),
            }
            for kind, side in sides.items():
                out[material, lb, kind] = _hit(racket, side, *STRING_TEST)
    return out


@pytest.fixture(scope="module")
def lubricated():
    """TWU's lubrication test: material -> (dry, lubricated) spin out [rpm]."""
    speed, angle, spin, lb = LUBE_TEST
    out = {}
    for material in ("polyester", "nylon"):
        racket = clamped_racket(None, material, lb * LB)
        dry = _hit(racket, sideways(racket.strings), speed, angle, spin)
        lube = _hit(racket, sideways(racket.strings, lubricated=True), speed, angle, spin)
        out[material] = (_rpm(dry), _rpm(lube))
    return out


@pytest.fixture(scope="module")
def rigid_bed_spins():
    """Spin out [rpm] of a laterally rigid polyester bed at 52 lb over :data:`FRICTIONS`,
    for three balls: noncompliant with no offset, noncompliant with Cross's offset, and the
    model's own (tangential spring and offset)."""
    racket = clamped_racket(None, "polyester", 52.0 * LB)
    balls = {
        "noncompliant, no offset": BallSpin(BALL.radius, INERTIA_FACTOR, 1e8, 0.0),
        "noncompliant": BallSpin(BALL.radius, tangential_stiffness=1e8),
        "model": BallSpin(BALL.radius),
    }
    return {
        name: np.array([_rpm(_hit(racket, BedSideways(mu), *STRING_TEST, ball_spin=spin))
                        for mu in FRICTIONS])
        for name, spin in balls.items()
    }  # fmt: skip


_LEVEL_GAP = (
    "model {:.0f} rpm vs TWU 1207-1803 (band 1200-1810): a laterally rigid bed gives "
    "1590-1690, inside; the strings' slide and snapback add 5-40 % (gut least, its crossings "
    "hold best); over the assumptions' ranges (SHARE 0.4-0.6, KINETIC_RATIO 0.6-1.0, "
    "SNAPBACK_TIME 1.5-2.5 ms) polyester at 52 lb spans 1950-2390; a measured share of the "
    "grip, kinetic string-string friction and the mains' displacement against time would "
    "test the slide's share"
)
_MODEL_RPM = {
    ("polyester", 52.0): 2169, ("polyester", 62.0): 2249, ("nylon", 52.0): 2058,
    ("nylon", 62.0): 2118, ("natural-gut", 62.0): 1820,
}  # fmt: skip
"""The model's spin out [rpm] the expected failures' reasons quote."""


@pytest.mark.parametrize(
    ("material", "lb"),
    [
        pytest.param(m, lb, marks=[pytest.mark.xfail(strict=True, reason=_LEVEL_GAP.format(
            _MODEL_RPM[m, lb]))] if (m, lb) in _MODEL_RPM else [])
        for m in MATERIALS for lb in TENSIONS_LB
    ],
)  # fmt: skip
def test_the_spin_off_a_clamped_racket_is_twus(clamped, material, lb):
    """TWU: 25 m/s, 40 degrees from the normal, -3820 rpm: 1207-1803 rpm out, 7 strings."""
    spin = _rpm(clamped[material, lb, "dry"])
    assert SPIN_BAND[0] <= spin <= SPIN_BAND[1]


def _mean_rpm(clamped, material, kind="dry"):
    return np.mean([_rpm(clamped[material, lb, kind]) for lb in TENSIONS_LB])


def test_polyester_spins_the_ball_more_than_nylon(clamped):
    """TWU: polyester about 20 % more spin than nylon.  The order is the sliding strings'
    (polyester's string-string friction is the lowest): a laterally rigid bed gives nylon
    about 4 % more, from the ball's friction and the normal history alone."""
    assert _mean_rpm(clamped, "polyester") > _mean_rpm(clamped, "nylon")


@pytest.mark.xfail(strict=True, reason="model +6 % (2209 vs 2088 rpm) vs TWU +20 % (band "
                   "10-30 %): the crossings' hold, 0.086 against 0.108 of the preload and the "
                   "ball's force, lets polyester's mains slide 28 % further than nylon's, but a "
                   "laterally rigid bed starts nylon 4 % ahead; a measured share of the grip on "
                   "the mains and the strings' kinetic friction would test it")  # fmt: skip
def test_polyester_is_above_nylon_by_twus_20_percent(clamped):
    gain = _mean_rpm(clamped, "polyester") / _mean_rpm(clamped, "nylon") - 1.0
    assert 0.10 <= gain <= 0.30


@pytest.mark.parametrize(
    "material",
    [
        pytest.param("polyester", marks=pytest.mark.xfail(strict=True, reason=(
            "model +12.9 % vs TWU +14 to +58 % (13.3-58.7 with the test's input scatter): "
            "polyester's strings already slide far dry; lubrication (an assumed 0.04 "
            "against 0.086) frees them a little further"))),
        "nylon",
    ],
)  # fmt: skip
def test_lubricated_strings_spin_the_ball_more_by_twus_margin(lubricated, material):
    """TWU: +14 to +58 % spin lubricated over dry (16x19 at 60 lb, 28 degrees, 49 mph,
    -3150 rpm, fresh strings), the band widened by the model's spread over the test's stated
    input scatter (+/- 1 mph, 1 degree, 286 rpm; ``validate``'s row)."""
    dry, lube = lubricated[material]
    gain = lube / dry - 1.0
    assert gain > 0.0
    (row,) = [c for c in comparisons() if c.name == f"spin-lubricated-{material}"]
    low, high = row.limits()
    assert LUBE_BAND == (row.low / 100.0, row.high / 100.0)
    assert low / 100.0 <= gain <= high / 100.0
    assert row.model() == pytest.approx(100.0 * gain, rel=1e-12)


def test_a_noncompliant_contact_spins_the_same_whatever_the_friction(rigid_bed_spins):
    """TWU: "for a tangentially noncompliant surface, the spin will be nearly the same for
    all magnitudes of string-ball friction".  With no tangential spring and no offset, a
    ball that bites rolls off at the value its angular momentum about the contact point
    gives, (m v R + I w) / (m R^2 + I), whatever the friction; Cross's offset of the normal
    force (acting while it slides, longer at low friction) spreads it by a few per cent."""
    speed, angle, spin = STRING_TEST
    v, w = speed * np.sin(np.radians(angle)), spin / RPM_PER_RAD_S
    m, radius = BALL.mass, BALL.radius
    inertia = BallSpin(radius).inertia(m)
    rolling = (m * v * radius + inertia * w) / (m * radius**2 + inertia) * RPM_PER_RAD_S
    assert rigid_bed_spins["noncompliant, no offset"] == pytest.approx(rolling, rel=5e-3)
    spins = rigid_bed_spins["noncompliant"]
    assert np.all(np.abs(spins / spins.mean() - 1.0) < 0.10)


@pytest.mark.xfail(strict=True, reason="model 2337 -> 1916 -> 1331 rpm over friction 0.3-0.45-"
                   "0.6 vs TWU's 'nearly the same' (within 10 %): the ball's tangential spring "
                   "(calibrated on Cross) rings with a period near the contact's against "
                   "a 5.4 ms contact, so the sooner it bites the more of the spin the friction's "
                   "reversal takes back; TWU's surface is the bed and their ball was as "
                   "compliant as any, so the gap is the ball's tangential contact (1e6 N/m "
                   "gives 1947-1741 rpm, within 6 %)")  # fmt: skip
def test_a_laterally_rigid_bed_spins_the_same_whatever_the_friction(rigid_bed_spins):
    spins = rigid_bed_spins["model"]
    assert np.all(np.abs(spins / spins.mean() - 1.0) < 0.10)


def test_the_mains_slide_a_few_mm(clamped):
    """Lindsey: the mains slide sideways "a few mm" and spring back.  Bound: 10 mm, below
    the 13 mm gap between the outermost moving main and its neighbour (the mains' spacing,
    14.6 mm in this 16x19 head, less a string), which the picture lets it pass through."""
    for key, hit in clamped.items():
        peak = hit.grip.layer_peak[0]
        if key[2] == "stiff":
            assert peak == 0.0
        else:
            assert 0.0 < peak < 0.010, key


def test_the_mains_spring_back_in_twus_2_ms(clamped):
    """Lindsey: the mains "slide sideways and spring back in about 2 ms".  Their spring is
    set on it (calibration): loaded by their share of the ball's tangential mass they go out
    and back in 2 ms, on every string, tension and lubrication; the stiffer the spring (the
    shorter the time), the less they slide."""
    for material in MATERIALS:
        for lb in TENSIONS_LB:
            bed = clamped_racket(None, material, lb * LB).strings
            for lubricate in (False, True):
                side = sideways(bed, lubricated=lubricate)
                assert snapback_time(side) == pytest.approx(SNAPBACK_TIME, rel=1e-12)
    assert snapback_time(sideways(bed, slide=False)) == np.inf


def _twu_polyester(**kwargs):
    """Polyester at 52 lb in TWU's test, the bed sideways with ``kwargs``: the impact."""
    racket = clamped_racket(None, "polyester", 52.0 * LB)
    return _hit(racket, sideways(racket.strings, **kwargs), *STRING_TEST)


def test_the_spin_over_the_sideways_assumptions(monkeypatch):
    """How polyester's spin at 52 lb in TWU's test moves over each assumption's range
    (:mod:`racket.strings.sideways`): more grip on the mains, a longer snapback (a softer
    spring) and kinetic friction further below static all let the mains slide further and
    give more spin, each by 5-15 % at the range's ends."""
    import sys

    module = sys.modules["racket.strings.sideways"]
    base = _rpm(_twu_polyester())
    moves = {
        "share": [_rpm(_twu_polyester(share=s)) for s in (0.4, 0.6)],
        "kinetic_ratio": [_rpm(_twu_polyester(kinetic_ratio=r)) for r in (1.0, 0.6)],
    }
    peaks = []
    for time in (1.5e-3, 2.5e-3):
        monkeypatch.setattr(module, "SNAPBACK_TIME", time)
        hit = _twu_polyester()
        moves.setdefault("SNAPBACK_TIME", []).append(_rpm(hit))
        peaks.append(hit.grip.layer_peak[0])
    assert peaks[0] < peaks[1]  # a stiffer spring: a shorter slide
    print(f"\npolyester at 52 lb: {base:.0f} rpm; " + ", ".join(
        f"{name} {low:.0f}-{high:.0f}" for name, (low, high) in moves.items()))  # fmt: skip
    for name, (low, high) in moves.items():
        assert low < base < high, name
        assert 0.05 < (high - low) / (2.0 * base) < 0.15, name


def test_a_preload_that_holds_the_strings_is_a_stiff_bed():
    """Crossings pressed far beyond the ball's pull never slide: the spin is the stiff
    bed's, and the strings do not move (the two patches on strings that stick act as one)."""
    racket = clamped_racket(None, "polyester", 52.0 * LB)
    held = dataclasses.replace(sideways(racket.strings), preload=1e5)
    hit = _hit(racket, held, *STRING_TEST)
    stiff = _hit(racket, sideways(racket.strings, slide=False), *STRING_TEST)
    assert hit.grip.layer_peak[0] < 1e-15  # [m]: round-off of the sticking impulse
    assert _rpm(hit) == pytest.approx(_rpm(stiff), rel=1e-9)
