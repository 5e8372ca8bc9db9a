"""The rigid-surface bounce table and the ITF numbers it is drawn against."""

import math

import pytest

from ball.catalog import ITF_DROP_SPEED, TYPE_2_BANDS
from racket import paper_ball
from studies.bounce import rigid_bounce_table

ITF_TYPE2_COR = TYPE_2_BANDS.cor


def test_itf_drop_speed_and_cor_band():
    # 254 cm drop: sqrt(2 g h); rebound 135-147 cm: e = sqrt(h / 254).
    assert ITF_DROP_SPEED == pytest.approx(7.058, abs=1e-3)
    assert ITF_TYPE2_COR == pytest.approx((0.7290, 0.7607), abs=1e-4)


def test_paper_ball_bounces_at_its_own_cor_in_its_own_contact_time():
    table = rigid_bounce_table(paper_ball(), [ITF_DROP_SPEED, 20.0])
    assert table["e"].to_numpy() == pytest.approx([0.75, 0.75], abs=1e-9)
    # Loading a quarter period of k, unloading a quarter period of k / e**2:
    t = math.pi * math.sqrt(0.057 / 4e4) / 2 * (1 + 0.75)
    assert table["contact_time_s"].to_numpy() == pytest.approx([t, t], rel=1e-4)
    assert ITF_TYPE2_COR[0] < table["e"].iloc[0] < ITF_TYPE2_COR[1]
