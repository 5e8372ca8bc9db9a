"""A ball dropped on the floor, on strings or on a racket (``racket-impact drop``)."""

import math
from dataclasses import replace

import numpy as np
import pytest

from ball import BALL_PRESETS
from ball.catalog import TYPE_2_BANDS
from racket import CATALOG
from studies.cli import main
from studies.config import load_ball
from studies.drop import drop


def test_the_itf_rebound_test_of_the_type_2_ball():
    """From 254 cm onto concrete a type 2 ball must rise 135-147 cm (ITF Rules, App. I)."""
    bounce = drop(BALL_PRESETS["itf-type-2"].ball(), 2.54)
    low, high = (0.01 * h for h in TYPE_2_BANDS.rebound_cm)
    assert low <= bounce.bounce_height <= high
    assert bounce.speed == pytest.approx(math.sqrt(2 * 9.80665 * 2.54), rel=1e-12)
    assert bounce.bounce_height == pytest.approx(2.54 * bounce.rebound_ratio**2, rel=1e-12)
    assert bounce.force[0] == 0.0 and bounce.peak_force == pytest.approx(bounce.force.max())


def test_the_unhappy_ball_does_not_bounce_off_the_floor():
    """The paper's Fig. 2: the unhappy ball on a rigid surface has no rebound."""
    bounce = drop(load_ball("unhappy"), 1.0)
    assert bounce.rebound_speed == pytest.approx(0.0, abs=1e-9)
    assert bounce.bounce_height == pytest.approx(0.0, abs=1e-9)


def test_clamped_strings_give_back_more_than_the_floor_and_a_free_racket_less():
    ball, racket = BALL_PRESETS["itf-type-2"].ball(), CATALOG["pure-drive-2021"].racket()
    floor = drop(ball, 1.0)
    strings = drop(ball, 1.0, replace(racket, support="clamped-head"))
    free = drop(ball, 1.0, racket)
    assert strings.bounce_height > floor.bounce_height > free.bounce_height > 0
    assert np.all(np.diff(strings.t) > 0) and strings.contact_time > floor.contact_time


def test_drop_command_prints_writes_and_refuses_a_height_in_cm(tmp_path, capsys):
    out, plot = tmp_path / "d.csv", tmp_path / "d.png"
    assert main(["drop", "--onto", "strings", "--height-m", "1", "--out", str(out),
                 "--plot", str(plot)]) == 0  # fmt: skip
    printed = capsys.readouterr().out
    assert "bounces back" in printed and "apparent COR" in printed
    assert out.stat().st_size > 0 and plot.stat().st_size > 1000
    assert (tmp_path / "d.csv.meta.json").exists()
    assert main(["drop", "--height-m", "254"]) == 2
    err = capsys.readouterr().err.strip()
    assert err.count("\n") == 0 and "--height-m must be in [0.01, 50] m" in err
    assert "cm typed as m? 254 would be 2.54 m" in err
