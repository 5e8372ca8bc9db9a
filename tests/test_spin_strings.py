"""Issue 36's targets for the spin off the strings, each a test on published numbers
(``data/measurements.md`` sec. 6; TWU, Lindsey): the spin off a clamped racket by string,
polyester against nylon, lubricated against dry, the spin of a laterally rigid bed whatever
the ball-string friction, and the mains' slide ("a few mm", "about 2 ms").

The sideways bed is :mod:`racket.strings.sideways`'s picture, its numbers chosen from the
stringing and stated assumptions, none tuned to these rows.  Met: the mains' slide and
snapback period, the order polyester > nylon, nylon's lubrication gain, and TWU's
"nearly the same for all magnitudes of string-ball friction" in its own limit (a
tangentially noncompliant contact).  Not met, kept as strict expected failures with the
model's number and the measured band as their reason: the spin's level (a laterally rigid
bed is already above it, and the snapback adds 30-60 %), polyester's margin over nylon,
polyester's lubrication gain, and the rigid bed's indifference to the ball's friction with
the ball's own tangential spring.
"""

import numpy as np
import pytest

from ball import BALL_PRESETS
from ball.spin import INERTIA_FACTOR, BallSpin
from common.units import LB, MPH
from racket.solver.oblique import oblique_impact
from racket.strings.sideways import BedSideways, sideways, snapback_period
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
    """The oblique impact at the bed's centre: the ball slides down the face (along) with
    backspin (about the across axis); its spin out is ``.spin[0, 1]`` (> 0: reversed)."""
    angle = np.radians(angle_deg)
    return oblique_impact(
        racket, BALL, racket.strings.center, speed * np.cos(angle),
        slip_velocity=(speed * np.sin(angle), 0.0), spin=(0.0, spin_rpm / RPM_PER_RAD_S, 0.0),
        side=side, ball_spin=ball_spin,
    )  # fmt: skip


def _rpm(hit):
    return float(hit.spin[0, 1] * RPM_PER_RAD_S)


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
    "model {:.0f} rpm vs TWU 1207-1803 (band 1200-1810): a laterally rigid bed already gives "
    "about 2000 (the ball's contact, ball/spin.py: kappa k_n(N), offset 0.06 R), and the "
    "snapback adds 30-60 %: the mains take the ball's whole friction (0.42-0.44 of its force) "
    "against a hold of 0.09-0.15 of it, slide 2.6-4.3 mm against 77-91 kN/m and give back "
    "0.3-0.7 J (HOLD_SPACINGS 0.5-2, CONTACT_WIDTH 3-5 cm, PRESS_RATIO 1-1.5 give 2610-3580 "
    "for polyester at 52 lb); closing it needs the ball's grip shared between the mains (the "
    "layer) and the crosses it slides along (the surface) in ball.grip, or a hold near the "
    "ball's pull, and the rigid bed's level"
)
_MODEL_RPM = {
    ("polyester", 52.0): 3096, ("polyester", 62.0): 3049, ("nylon", 52.0): 2939,
    ("nylon", 62.0): 2922, ("natural-gut", 52.0): 2704, ("natural-gut", 62.0): 2724,
}  # fmt: skip
"""The model's spin out [rpm] the expected failures' reasons quote."""


@pytest.mark.parametrize(
    ("material", "lb"),
    [
        pytest.param(m, lb, marks=pytest.mark.xfail(strict=True, reason=_LEVEL_GAP.format(
            _MODEL_RPM[m, lb])))
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
    """TWU: polyester about 20 % more spin than nylon.  The order is the sliding mains'
    (polyester's string-string friction is the lowest): a laterally rigid bed gives nylon
    9 % more, from the ball's friction and the normal history alone."""
    assert _mean_rpm(clamped, "polyester") > _mean_rpm(clamped, "nylon")


@pytest.mark.xfail(strict=True, reason="model +5 % (3073 vs 2931 rpm) vs TWU +20 % (band "
                   "10-30 %): the hold (0.086 against 0.108 of the ball's force) is a fifth to a "
                   "quarter of the ball's pull, so polyester's mains slide only 15 % further; a "
                   "hold near the pull (see the level's gap) would make the spin follow the "
                   "string-string friction")  # fmt: skip
def test_polyester_is_above_nylon_by_twus_20_percent(clamped):
    gain = _mean_rpm(clamped, "polyester") / _mean_rpm(clamped, "nylon") - 1.0
    assert 0.10 <= gain <= 0.30


@pytest.mark.parametrize(
    "material",
    [
        pytest.param("polyester", marks=pytest.mark.xfail(strict=True, reason=(
            "model +2.4 % (1441 -> 1476 rpm) vs TWU +14 to +58 %: lubrication takes the hold "
            "from 0.086 to 0.04 of the ball's force, little beside its pull of 0.444, and the "
            "spin barely depends on the hold (not even monotonically: 0.04 gives less than "
            "0.086 at 40 degrees); as for the level, a hold near the pull would close it"))),
        "nylon",
    ],
)  # fmt: skip
def test_lubricated_strings_spin_the_ball_more_by_twus_margin(lubricated, material):
    """TWU: +14 to +58 % spin lubricated over dry (16x19 at 60 lb, 28 degrees, 49 mph,
    -3150 rpm)."""
    dry, lube = lubricated[material]
    assert LUBE_BAND[0] <= lube / dry - 1.0 <= LUBE_BAND[1]


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


def test_the_mains_spring_back_within_twus_2_ms(clamped):
    """Lindsey: the mains "slide sideways and spring back in about 2 ms": on their own
    (without the ball's mass) they are no slower."""
    for material in MATERIALS:
        for lb in TENSIONS_LB:
            bed = clamped_racket(None, material, lb * LB).strings
            for lubricate in (False, True):
                assert snapback_period(sideways(bed, lubricated=lubricate)) <= 2e-3
