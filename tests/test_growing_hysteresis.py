"""The ball whose COR falls with speed (GrowingHysteresis): its rigid-surface bounce against
the closed form, its trend with speed, on strings, in the racket solver, and in TOML."""

import math
import warnings

import numpy as np
import pytest

from ball import WALL, Ball, GrowingHysteresis, LinearSpring, collide
from ball.falling_cor import COR_FLOOR
from racket import impact, paper_racket
from studies.config import ball_from_table

LAW = GrowingHysteresis(k=1e6, a=1.4, e0=0.82, slope=8.0)
BALL = Ball(0.057, LAW, 0.0335)


def _contact_time_on_wall(law, mass, speed):
    """Closed form: t = X_max / v (I(a) + I(b) / e), I(n) = int_0^1 du / sqrt(1 - u**(n+1))."""
    x_max = law.peak_compression(mass, speed)
    e = float(law.cor_at_compression(x_max))
    b = (law.a + 1.0) / e**2 - 1.0

    def integral(n):
        p = 1.0 / (n + 1.0)
        return math.sqrt(math.pi) * math.gamma(1.0 + p) / math.gamma(0.5 + p)

    return x_max / speed * (integral(law.a) + integral(b) / e)


@pytest.mark.parametrize("speed", [3.0, 7.06, 20.0, 40.0])
def test_bounce_on_a_wall_matches_the_closed_form(speed):
    c = collide(BALL, WALL, speed)
    x_max = LAW.peak_compression(BALL.mass, speed)
    assert c.e == pytest.approx(float(LAW.cor_at_compression(x_max)), abs=1e-9)
    assert c.contact_time == pytest.approx(_contact_time_on_wall(LAW, BALL.mass, speed), rel=1e-3)


def test_cor_and_contact_time_fall_with_speed_on_a_wall():
    speeds = [5.0, 10.0, 20.0, 30.0, 45.0]
    runs = [collide(BALL, WALL, v) for v in speeds]
    assert np.all(np.diff([r.e for r in runs]) < 0)
    assert np.all(np.diff([r.contact_time for r in runs]) < 0)


def test_strings_return_most_of_the_energy_and_flatten_the_trend():
    strings = Ball(1e6, LinearSpring(4e4))
    wall = [collide(BALL, WALL, v).e for v in (7.06, 30.0)]
    clamped = [collide(BALL, strings, v).e for v in (7.06, 30.0)]
    assert clamped[0] > wall[0] and clamped[1] > wall[1]
    assert clamped[0] - clamped[1] < wall[0] - wall[1]


def test_racket_solver_agrees_with_collide_on_a_clamped_head():
    clamped = paper_racket("clamped-head")
    strings = Ball(1e9, LinearSpring(clamped.strings.stiffness))
    for speed in (7.06, 30.0):
        r = impact(clamped, BALL, 0.16, speed)
        assert r.e == pytest.approx(collide(BALL, strings, speed).e, abs=2e-5)
        assert abs(r.energy_residual) < 1e-5 * r.energy_initial


def test_floor_and_parameter_checks():
    assert float(LAW.cor_at_compression(1.0)) == COR_FLOOR
    for kwargs, name in (
        (dict(k=-1.0, a=1.2, e0=0.8, slope=1.0), "k"),
        (dict(k=1e6, a=0.5, e0=0.8, slope=1.0), "a"),
        (dict(k=1e6, a=1.2, e0=1.2, slope=1.0), "e0"),
        (dict(k=1e6, a=1.2, e0=0.8, slope=-1.0), "slope"),
        (dict(k=1e6, a=1.2, e0=0.8, slope=1.0, calibrated_to=0.0), "calibrated_to"),
    ):
        with pytest.raises(ValueError, match=name):
            GrowingHysteresis(**kwargs)


def test_compression_beyond_the_calibrated_range_warns():
    calibrated = Ball(0.057, GrowingHysteresis(1e6, 1.4, 0.82, 8.0, calibrated_to=0.005), 0.0335)
    with pytest.warns(UserWarning, match="calibrated to"):
        impact(paper_racket(), calibrated, 0.16, 30.0)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        impact(paper_racket(), calibrated, 0.16, 3.0)


def test_toml_table_round_trip():
    table = dict(mass=0.057, law="growing-hysteresis", k=1e6, a=1.4, e0=0.82, slope=8.0)
    assert ball_from_table(table).law == GrowingHysteresis(1e6, 1.4, 0.82, 8.0)
    with_range = ball_from_table({**table, "calibrated_to": 0.03})
    assert with_range.law.calibrated_to == 0.03
    with pytest.raises(ValueError, match="takes"):
        ball_from_table({**table, "b": 3.0})
