"""Baseballs and softballs (ball.baseball): A. M. Nathan's ball law (Am. J. Phys. 68, 979
(2000), eqs. 7-8) on a rigid wall against its closed forms and his Fig. 2, in the racket
solver's kernel against ``collide``, its presets' numbers against their sources, and the
presets by name and in TOML."""

import math
import warnings
from dataclasses import replace

import numpy as np
import pytest
from helpers import assert_round_trips_through_toml

from ball import (
    BASEBALL_PRESETS,
    DEFAULT_BASEBALL,
    WALL,
    Ball,
    LinearSpring,
    PowerLawHysteresis,
    baseball,
    collide,
)
from ball.baseball import (
    BASEBALL_MASS_RULE,
    BASEBALL_RADIUS_RULE,
    COMPRESSION_SQUEEZE,
    E0_FIG2,
    FIG2_SPEED,
    LOWEST_E0,
    MLB_COR_RANGE,
    NATHAN_ALPHA,
    NATHAN_K1,
    SOFTBALL_COMPRESSIONS_LB,
    SOFTBALL_CORS,
    SOFTBALL_MASS_RULE,
    SOFTBALL_RADIUS_RULE,
    softball_stiffness,
)
from common.units import INCH, LB, OUNCE
from racket import impact, paper_racket
from studies.config import BALLS, load_ball

SPEEDS = (1.0, 10.0, 26.0, 40.0, 58.0, 70.0)
"""Impact speeds [m/s]: Nathan's low-speed case (1), the MLB rule's test (26), his
high-speed ball (40), his Fig. 2 (58) and his bat's impact speed at 71 cm (about 70)."""

BASEBALLS = ("baseball", "baseball-low-speed", "baseball-fig2", "mlb-low", "mlb-high")
SOFTBALLS = tuple(f"softball-{round(100 * c)}-{lb:g}" for lb in (375, 525) for c in SOFTBALL_CORS)


class _Bounces(dict):
    """A preset's bounce on a rigid wall, ``[name, speed]``, simulated the first time it is
    asked for (``collide``) and kept."""

    def __missing__(self, key):
        name, v = key
        self[key] = collide(BASEBALL_PRESETS[name].ball(), WALL, v)
        return self[key]


@pytest.fixture(scope="module")
def bounces():
    """Every preset's bounce on a rigid wall at each of :data:`SPEEDS`, each simulated when a
    test first reads it (35 s of CPU for them all: a test reads only its own presets', and
    under pytest-xdist each worker simulates only what its tests read)."""
    return _Bounces()


def test_the_presets_are_the_ones_named():
    assert set(BASEBALL_PRESETS) == set(BASEBALLS) | set(SOFTBALLS)
    assert DEFAULT_BASEBALL == "baseball" and BASEBALL_PRESETS["baseball"].e0 == 0.50
    e0 = {name: BASEBALL_PRESETS[name].e0 for name in BASEBALLS}
    assert e0 == {"baseball": 0.50, "baseball-low-speed": 0.66, "baseball-fig2": 0.53,
                  "mlb-low": 0.514, "mlb-high": 0.578}  # fmt: skip
    for preset in BASEBALL_PRESETS.values():
        assert preset.sources and any("N2000" in s for s in preset.sources)


@pytest.mark.parametrize("name", list(BASEBALL_PRESETS))
def test_on_a_rigid_wall_e_is_e0_at_every_speed(name, bounces):
    e0 = BASEBALL_PRESETS[name].e0
    for v in SPEEDS:
        r = bounces[name, v]
        assert r.e == pytest.approx(e0, abs=1e-4)
        assert 0.0 <= r.e <= 1.0
        # The energy budget closes: what is lost is what the ball's hysteresis took, and
        # that is 1 - e0**2 of the energy brought (a wall takes none).
        assert r.energy_lost == pytest.approx(r.energy_dissipated_a, rel=1e-9)
        assert r.energy_dissipated_b == 0.0
        assert r.energy_lost_fraction == pytest.approx(1.0 - e0**2, abs=2e-4)


def test_the_law_is_nathans(bounces):
    """beta = (1 + alpha) / e0**2 - 1 (N2000 eq. 8), and k1, alpha of his Fig. 2."""
    for preset in BASEBALL_PRESETS.values():
        law = preset.build()
        assert isinstance(law, PowerLawHysteresis) and law.a == NATHAN_ALPHA == 1.84
        assert law.b == pytest.approx((1.0 + law.a) / preset.e0**2 - 1.0, rel=1e-12)
    for name in BASEBALLS:
        assert BASEBALL_PRESETS[name].build().k == NATHAN_K1 == 6.53e7


def test_fig2_end_point_is_the_closed_form():
    """Nathan's Fig. 2: a 58 m/s ball on a rigid surface ends at about 18 mm and 40 kN (its
    axes; bats.md derives 17.72 mm and 39.1 kN with 0.145 kg).  The largest compression is
    where the loading has stored m v**2 / 2: u_max = ((alpha + 1) m v**2 / (2 k1))**(1 /
    (alpha + 1))."""
    ball = BASEBALL_PRESETS["baseball-fig2"].ball()
    law = ball.law
    assert law.rigid_cor == pytest.approx(E0_FIG2, abs=1e-12)
    u_max = ((law.a + 1.0) * ball.mass * FIG2_SPEED**2 / (2.0 * law.k)) ** (1.0 / (law.a + 1.0))
    r = collide(ball, WALL, FIG2_SPEED, samples=4000)
    assert np.max(r.history.compression_a) == pytest.approx(u_max, rel=1e-6)
    assert r.peak_force == pytest.approx(law.k * u_max**law.a, rel=1e-6)
    assert u_max == pytest.approx(17.72e-3, abs=0.01e-3)
    assert r.peak_force == pytest.approx(39.1e3, abs=0.05e3)


@pytest.mark.parametrize("name", ["baseball", "softball-44-375"])
def test_contact_time_on_a_wall_is_the_closed_form(name):
    """t = u_max / v (I(alpha) + I(beta) / e0), I(n) = int_0^1 du / sqrt(1 - u**(n + 1)):
    the loading and the expansion, each a power law from the same u_max."""
    ball = BASEBALL_PRESETS[name].ball()
    law = ball.law

    def integral(n):
        p = 1.0 / (n + 1.0)
        return math.sqrt(math.pi) * math.gamma(1.0 + p) / math.gamma(0.5 + p)

    for v in (10.0, 40.0):
        u_max = law.peak_compression(ball.mass, v)
        expected = u_max / v * (integral(law.a) + integral(law.b) / law.rigid_cor)
        assert collide(ball, WALL, v).contact_time == pytest.approx(expected, rel=1e-3)


def test_no_preset_is_squashed_past_its_radius_at_70_m_s(bounces):
    for name, preset in BASEBALL_PRESETS.items():
        fastest = bounces[name, 70.0]
        assert np.max(fastest.history.compression_a) < 0.7 * preset.radius  # no warning
        assert fastest.contact_time < bounces[name, 10.0].contact_time  # stiffens: alpha > 1
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        collide(BASEBALL_PRESETS["softball-44-375"].ball(), WALL, 70.0)  # the softest


@pytest.mark.parametrize("stiffness", [4e4, 1e7])
@pytest.mark.parametrize("name", ["baseball", "baseball-low-speed", "softball-44-525"])
def test_the_racket_kernel_agrees_with_collide_on_a_clamped_head(name, stiffness):
    """As the tennis balls' laws (tests/test_racket_impact.py): on a clamped head the ball
    meets immovable strings, ball.collide's problem with a partner of huge mass.  The paper's
    strings (4e4 N/m) are far softer than a baseball; 1e7 N/m strings are stiffer, and leave
    the ball most of the compression."""
    clamped = paper_racket("clamped-head")
    racket = replace(clamped, strings=replace(clamped.strings, stiffness=stiffness))
    ball = BASEBALL_PRESETS[name].ball()
    for v in (10.0, 40.0):
        r = impact(racket, ball, 0.1, v, steps_per_contact=2400)
        two_body = collide(ball, Ball(1e15, LinearSpring(stiffness)), v)
        assert r.e == pytest.approx(two_body.e, abs=1e-5)
        assert r.contact_time == pytest.approx(two_body.contact_time, rel=2e-3)
        assert r.peak_force == pytest.approx(two_body.peak_force, rel=1e-4)
        assert abs(r.energy_residual) < 1e-5 * r.energy_initial


def test_the_baseball_numbers_are_inside_the_rules():
    assert BASEBALL_MASS_RULE == pytest.approx((0.1417, 0.1488), abs=1e-4)
    assert BASEBALL_RADIUS_RULE == pytest.approx((0.03638, 0.03739), abs=1e-5)
    for name in BASEBALLS:
        ball = BASEBALL_PRESETS[name].ball()
        assert BASEBALL_MASS_RULE[0] <= ball.mass <= BASEBALL_MASS_RULE[1]
        assert BASEBALL_RADIUS_RULE[0] <= ball.radius <= BASEBALL_RADIUS_RULE[1]
    low, high = MLB_COR_RANGE
    assert (low, high) == (0.514, 0.578)
    assert low < BASEBALL_PRESETS["baseball-fig2"].e0 < high  # Nathan's Fig. 2 ball is legal


def test_the_softballs_meet_their_grades_and_the_rules():
    """Mass and size: the middle of the ASA's 6 1/4-7 oz and 11 7/8-12 1/8 in; COR and
    compression grades; the loading curve through the compression at 1/8 in per plate."""
    assert SOFTBALL_MASS_RULE == pytest.approx((6.25 * OUNCE, 7.0 * OUNCE), rel=1e-12)
    circumference = tuple(2.0 * math.pi * r / INCH for r in SOFTBALL_RADIUS_RULE)
    assert circumference == pytest.approx((11.875, 12.125), rel=1e-12)
    assert COMPRESSION_SQUEEZE == pytest.approx(0.25 * INCH)
    for cor in SOFTBALL_CORS:
        for lb in SOFTBALL_COMPRESSIONS_LB:
            preset = BASEBALL_PRESETS[f"softball-{round(100 * cor)}-{lb:g}"]
            ball = preset.ball()
            assert SOFTBALL_MASS_RULE[0] < ball.mass < SOFTBALL_MASS_RULE[1]
            assert 2.0 * math.pi * ball.radius == pytest.approx(12.0 * INCH, rel=1e-12)
            assert collide(ball, WALL, 60 * 0.44704).e == pytest.approx(cor, abs=1e-9)
            at_eighth = float(ball.law.compression(lb * LB, lb * LB))
            assert at_eighth == pytest.approx(0.125 * INCH, rel=1e-12)
    # A harder grade is stiffer, in the ratio of the forces.
    soft, hard = (softball_stiffness(lb) for lb in SOFTBALL_COMPRESSIONS_LB)
    assert hard / soft == pytest.approx(525.0 / 375.0, rel=1e-12)


def test_baseball_makes_nathans_ball_at_any_e0():
    ball = baseball()
    assert ball == BASEBALL_PRESETS[DEFAULT_BASEBALL].ball()
    custom = baseball(0.55, 0.142)
    assert custom.mass == 0.142 and custom.law.k == NATHAN_K1 and custom.law.a == NATHAN_ALPHA
    assert collide(custom, WALL, 30.0).e == pytest.approx(0.55, abs=1e-9)
    assert collide(baseball(1.0), WALL, 30.0).e == pytest.approx(1.0, abs=1e-9)
    assert baseball(LOWEST_E0).law.b <= 1000.0


@pytest.mark.parametrize(
    ("kwargs", "match"),
    [
        (dict(e0=0.0), r"e0 must be in \(0, 1\], got 0"),
        (dict(e0=-0.5), r"e0 must be in \(0, 1\]"),
        (dict(e0=1.2), r"e0 must be in \(0, 1\], got 1.2"),
        (dict(e0=0.01), r"e0 must be in \[0.054, 1\].*beta"),
        (dict(e0=math.nan), "e0 must be a finite number"),
        (dict(mass=145.0), r"mass must be in \[0.1, 0.25\] kg.*grams typed as kg\? 145"),
        (dict(mass=5.1), r"mass must be in \[0.1, 0.25\] kg.*ounces typed as kg\? 5.1 oz"),
        (dict(mass=-0.145), r"mass must be in \[0.1, 0.25\] kg, got -0.145"),
        (dict(mass="heavy"), "mass must be a finite number"),
    ],
)
def test_bad_inputs_are_refused_with_the_range_and_the_likely_slip(kwargs, match):
    with pytest.raises(ValueError, match=match):
        baseball(**kwargs)


def test_softball_stiffness_refuses_a_non_positive_force():
    with pytest.raises(ValueError, match="compression_lb must be > 0 lbf"):
        softball_stiffness(0.0)


@pytest.mark.parametrize("name", list(BASEBALL_PRESETS))
def test_every_preset_loads_by_name_and_round_trips_through_toml(name, tmp_path):
    ball = BASEBALL_PRESETS[name].ball()
    assert BALLS[name]() == ball and load_ball(name) == ball
    law = ball.law
    keys = f'law = "power-law"\nk = {law.k!r}\na = {law.a!r}\ne = {BASEBALL_PRESETS[name].e0!r}\n'
    assert_round_trips_through_toml(name, ball, keys, tmp_path)


def test_the_ball_command_bounces_a_baseball_without_the_tennis_balls_static_test(capsys):
    from studies.cli import main

    assert main(["ball", "mlb-high", "--speeds", "26", "58"]) == 0
    out = capsys.readouterr().out
    assert "ball mlb-high head on into a rigid wall at 26, 58 m/s" in out
    assert out.count("0.578") == 2 and "ITF" not in out and "Traceback" not in out
