"""A ball's bounce on a court (issue 36): Cross's oblique bounces without spin (calibration,
Table II; validation, Table I), the energy budget, the sliding and rolling limits, the ITF
Court Pace Rating and the input checks (``ball/court.py``)."""

import math

import pytest

from ball import BALL_PRESETS, DEFAULT_BALL
from ball.court import (
    COURT_SOURCES,
    COURTS,
    LAB_SURFACES,
    Court,
    bounce,
    category,
    court_pace_rating,
)
from ball.spin import BallSpin
from studies.validation.spin_rows import CROSS_TABLE_II

BALL = BALL_PRESETS[DEFAULT_BALL].ball()
R = BALL.radius

TABLE_II = CROSS_TABLE_II  # Cross 2002, Table II, with its source (validate's rows)
KNOWN_GAPS = {}
"""Table II rows the model misses (none, with the offset at 2 mm)."""


@pytest.mark.parametrize(
    "row",
    [
        pytest.param(name, marks=[pytest.mark.xfail(strict=True, reason=KNOWN_GAPS[name])])
        if name in KNOWN_GAPS
        else name
        for name in TABLE_II
    ],
)
def test_cross_table_ii(row):
    """Rebound angle within 3 degrees, spin within 15 %, vx2/vx1 within 0.07 (issue 36)."""
    surface, theta1, v1, theta2, omega2, ratio = TABLE_II[row]
    b = bounce(LAB_SURFACES[surface], v1, math.radians(theta1))
    assert math.degrees(b.angle_after) == pytest.approx(theta2, abs=3.0)
    assert b.spin_after == pytest.approx(omega2, rel=0.15)
    assert b.vx_ratio == pytest.approx(ratio, abs=0.07)


@pytest.fixture(scope="module")
def table_i():
    """Cross 2002 Table I (emery paper, 25 cm drop; validation, not in the fit): vx1 2.10
    +/- 0.04, vy1 0.77 +/- 0.014 m/s."""
    vx1, vy1 = 2.10, 0.77
    b = bounce(LAB_SURFACES["emery paper"], math.hypot(vx1, vy1), math.atan2(vy1, vx1))
    return b, b.vx_ratio * vx1, b.e_y * vy1


def test_cross_table_i_rebound_angle_and_vertical_speed(table_i):
    """theta2 26.2 +/- 1.5 degrees, vy2 0.61 +/- 0.03 m/s: model 27.1, 0.628."""
    b, _, vy2 = table_i
    assert math.degrees(b.angle_after) == pytest.approx(26.2, abs=1.5)
    assert vy2 == pytest.approx(0.61, abs=0.03)
    assert not b.slid_throughout  # it grips, and leaves spinning faster than rolling
    assert R * b.spin_after > b.vx_ratio * 2.10


@pytest.mark.xfail(strict=True, reason="model omega2 50.9 vs 52.4 +/- 0.5 rad/s (vx2 1.23 m/s "
                   "vs 1.23 +/- 0.03, inside since issue 44): within the Table II targets "
                   "(15 %), not within this bounce's own uncertainty")  # fmt: skip
def test_cross_table_i_within_its_uncertainties(table_i):
    b, vx2, _ = table_i
    assert vx2 == pytest.approx(1.23, abs=0.03)
    assert b.spin_after == pytest.approx(52.4, abs=0.5)


def test_cross_table_i_within_the_table_ii_targets(table_i):
    b, vx2, _ = table_i
    assert vx2 / 2.10 == pytest.approx(1.23 / 2.10, abs=0.07)
    assert b.spin_after == pytest.approx(52.4, rel=0.15)


@pytest.mark.parametrize("court", sorted(COURTS))
@pytest.mark.parametrize("spin", [0.0, 300.0, -300.0])
def test_a_bounce_keeps_its_energy_budget(court, spin):
    b = bounce(COURTS[court], 25.0, math.radians(18), spin=spin)
    assert abs(b.residual) < 1e-9 * b.energy_in
    assert b.normal_loss > 0.0 and b.slip_loss >= 0.0
    assert b.e_y == pytest.approx(COURTS[court].cor, abs=1e-9)


def test_a_ball_that_slides_throughout_follows_coulomb():
    """No offset, low friction and angle: |dvx| = mu (1 + e) vy, d omega = m R |dvx| / I."""
    court, speed, angle = Court("slick", 0.1, 0.75), 20.0, math.radians(10)
    spin = BallSpin(radius=R, offset_ratio=0.0)
    b = bounce(court, speed, angle, ball_spin=spin)
    vx, vy = speed * math.cos(angle), speed * math.sin(angle)
    dvx = 0.1 * (1 + b.e_y) * vy
    assert b.slid_throughout
    assert vx * (1 - b.vx_ratio) == pytest.approx(dvx, rel=1e-6)
    assert b.spin_after == pytest.approx(BALL.mass * R * dvx / spin.inertia(BALL.mass), rel=1e-6)
    assert b.apparent_friction == pytest.approx(0.1, rel=1e-6)


def test_a_stiff_grippy_contact_leaves_rolling():
    """k_t 1e8 N/m, friction 1.5, 45 degrees: the ball grips and leaves rolling but for the
    stiff spring's ring at release (0.3 % of vx2); a soft spring springs back far more (both
    undamped: the patch's dashpot, issue 44, would damp the ring it is about)."""
    court, speed, angle = Court("grippy", 1.5, 0.8), 10.0, math.radians(45)
    vx1 = speed * math.cos(angle)

    def slip(k_t):
        spin = BallSpin(radius=R, tangential_stiffness=k_t, damping_ratio=0.0)
        b = bounce(court, speed, angle, ball_spin=spin)
        assert not b.slid_throughout
        vx2 = b.vx_ratio * vx1
        return (vx2 - R * b.spin_after) / vx2

    assert abs(slip(1e8)) < 5e-3
    # how far a soft spring springs back depends on its phase at release (with the ball's
    # own pulse, issue 44: -0.07 at 1e6 N/m, +0.18 at 5e5, -0.69 at 3e5)
    assert max(abs(slip(k)) for k in (1e6, 5e5, 3e5)) > 0.1


def test_court_pace_ratings_land_in_their_sourced_categories():
    """The simulated bounce's category is the one the preset's own friction and COR give in
    the ITF formula; grass fast, clay slow."""
    rated = {name: court_pace_rating(court) for name, court in COURTS.items()}
    for name, court in COURTS.items():
        assert rated[name][1] == category(100 * (1 - court.friction) + 150 * (0.81 - court.cor))
    assert rated["grass"][1] == 5 and rated["clay"][1] == 1
    assert rated["grass"][0] == pytest.approx(56.0, abs=1e-6)  # slides throughout: mu exact
    assert set(COURT_SOURCES) == set(COURTS) | set(LAB_SURFACES)


@pytest.mark.parametrize(
    ("cpr", "expected"),
    [(0.0, 1), (29.9, 1), (30.0, 2), (34.9, 2), (35.0, 3), (40.0, 4), (44.9, 4), (45.0, 5)],
)
def test_category_bounds(cpr, expected):
    assert category(cpr) == expected


def test_an_angle_in_degrees_is_refused_with_a_hint():
    with pytest.raises(ValueError, match=r"angle must be in \(0, 1.571\) rad.*degrees typed"):
        bounce(COURTS["clay"], 30.0, 16)


@pytest.mark.parametrize(
    ("kwargs", "match"),
    [
        ({"speed": 0.0}, r"speed must be in \(0, 80\] m/s"),
        ({"speed": 120.0}, r"speed must be in \(0, 80\] m/s"),
        ({"angle": 0.0}, "angle must be in"),
        ({"spin": 3000.0}, "rpm typed as rad/s"),
    ],
)
def test_bad_inputs_are_refused(kwargs, match):
    args = {"court": COURTS["grass"], "speed": 30.0, "angle": 0.3, **kwargs}
    with pytest.raises(ValueError, match=match):
        bounce(**args)


@pytest.mark.parametrize(
    ("friction", "cor", "match"), [(2.5, 0.8, "friction must be in"), (0.5, 1.2, "cor must be in")]
)
def test_a_court_checks_its_numbers(friction, cor, match):
    with pytest.raises(ValueError, match=match):
        Court("bad", friction, cor)


def test_a_ball_that_hardly_comes_down_is_refused_in_one_line():
    with pytest.raises(ValueError, match=r"must come down at 0\.001 m/s at least"):
        bounce(COURTS["grass"], 0.001, math.radians(30.0))


@pytest.mark.parametrize("speed, angle", [(3.7, 45.0), (30.0, 16.0)])
def test_the_courts_normal_pulse_is_the_balls_own(speed, angle):
    """Issue 44: the normal pulse is the ball's own law's on a rigid wall (a linear stand-in's
    was 15-20 % shorter), its impulse the court's, so the bounce's COR is the court's."""
    from ball import WALL, collide

    court = COURTS["hard"]
    b = bounce(court, speed, math.radians(angle))
    own = collide(BALL, WALL, speed * math.sin(math.radians(angle)))
    assert b.contact_time == pytest.approx(own.contact_time, rel=1e-6)
    assert b.e_y == pytest.approx(court.cor, rel=1e-12)


def test_the_calibrated_numbers_are_the_calibrations():
    """Issue 44: kappa, the offset and the lab surfaces' frictions in the code are what
    studies.validation.grip_calibration finds at them (the scan itself, over kappa and the
    offset, is `python -m studies.validation.grip_calibration`), and meet every Table II
    row's targets."""
    from ball.spin import OFFSET_RATIO, STIFFNESS_RATIO
    from studies.validation.grip_calibration import calibrate

    found = calibrate(kappas=(STIFFNESS_RATIO,), offsets=(OFFSET_RATIO,))
    assert found["frictions"] == {name: s.friction for name, s in LAB_SURFACES.items()}
    assert found["misfit"] < 1.0
