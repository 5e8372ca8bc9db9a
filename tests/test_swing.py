"""A swing about a pivot: every impact point at its own speed, exit speeds, the serve as one
swing, and the racket-head speed for a target serve (issue 14)."""

import numpy as np
import pytest

from ball import Ball, PowerLawHysteresis, serve_speed
from common.units import MPH
from racket import CATALOG, Swing, impact, paper_ball
from studies.serve import head_speed_for, serve_table
from studies.sweeps import sweep


@pytest.fixture(scope="module")
def racket():
    return CATALOG["pure-drive-2021"].racket()


@pytest.mark.parametrize(
    "ball",
    [paper_ball(), Ball(0.057, PowerLawHysteresis.with_cor(3e5, 1.5, 0.75), 0.033)],
    ids=["linear", "power-law"],
)
@pytest.mark.parametrize("speed", [0.0, 10.0])
def test_each_point_of_a_swing_is_its_own_impact(racket, ball, speed):
    """A swing's sweep (all points together) gives at each point what that point alone, at
    its own speed about the same pivot, gives; a power-law ball's contact time depends on
    the closing speed, so its points run with their own time steps."""
    swing = Swing(22.0, racket.beam.length + 0.05)  # the wrist, given
    x = np.linspace(*racket.strings.extent, 7)
    table = sweep(racket, ball, x, speed, swing=swing, progress=False)
    v = swing.point_speeds(racket, x)
    assert table["swing_speed_m_s"].to_numpy() == pytest.approx(v, rel=1e-15)
    assert v[0] > v[-1]  # the tip moves fastest
    for i in (0, 3, 6):
        alone = impact(racket, ball, x[i], speed, swing_speed=v[i], pivot=swing.pivot(racket))
        assert table["ball_rebound_m_s"].iloc[i] == pytest.approx(alone.ball_rebound, abs=1e-9)
        assert table["exit_speed_mph"].iloc[i] == pytest.approx(alone.ball_rebound / MPH)


def test_a_swing_agrees_with_eq22_and_its_e_A_is_the_racket_at_rest(racket):
    """Ball at rest (a serve): the exit speed is Eq. 22 with e and m2 of the racket at rest
    hit at the point's speed; a ball coming in: e_A in the swing's frame is the racket at
    rest's at the closing speed (the swing superposes on the collision)."""
    swing = Swing(28.0)
    x = np.array([0.08, racket.strings.center, 0.25])
    v = swing.point_speeds(racket, x)
    served = impact(racket, paper_ball(), x, 0.0, **swing.impact_kwargs(racket, x))
    for i in range(x.size):
        rest = impact(racket, paper_ball(), x[i], v[i])
        eq22 = serve_speed(rest.e, paper_ball().mass, rest.effective_mass, v[i])
        assert served.ball_rebound[i] == pytest.approx(eq22, rel=1e-9)
    rally = impact(racket, paper_ball(), x, 8.0, **swing.impact_kwargs(racket, x))
    rest = [impact(racket, paper_ball(), x[i], 8.0 + v[i]).e_A for i in range(x.size)]
    assert rally.e_A == pytest.approx(rest, abs=1e-9)


def test_serve_is_one_swing_and_the_tip_ward_point_is_faster(racket):
    points = [racket.strings.center, racket.strings.center - 0.05]
    table = serve_table(racket, paper_ball(), points, 100 * MPH, zero_cor=False)
    centre, tipward = table.to_dict("records")
    assert centre["point_speed_mph"] == pytest.approx(100.0, rel=1e-12)
    ratio = (0.05 + racket.beam.length + 0.05 - racket.strings.center) / (
        racket.beam.length + 0.05 - racket.strings.center
    )
    assert tipward["point_speed_mph"] == pytest.approx(100.0 * ratio, rel=1e-12)
    assert tipward["serve_simulated_mph"] > centre["serve_simulated_mph"]
    assert table["serve_simulated_m_s"].to_numpy() == pytest.approx(
        table["serve_eq22_m_s"].to_numpy(), rel=1e-9
    )


@pytest.mark.parametrize("target_mph", [90.0, 125.0])
def test_the_head_speed_for_a_target_serve_meets_it(racket, target_mph):
    head = head_speed_for(racket, paper_ball(), target_mph * MPH, racket.strings.center - 0.03)
    table = serve_table(racket, paper_ball(), racket.strings.center - 0.03, head, zero_cor=False)
    assert abs(table["serve_simulated_mph"].iloc[0] - target_mph) < 0.01


@pytest.mark.parametrize(
    "kwargs, match",
    [
        (dict(head_speed=0.0), r"head_speed must be in \[0.001, 300\] m/s"),
        (dict(head_speed=30.0, pivot_from_tip=2.7), r"pivot_from_tip must be in \[0, 2.5\] m"),
        (dict(head_speed=30.0, pivot_from_tip=-0.1), r"pivot_from_tip must be in \[0, 2.5\] m"),
        (dict(head_speed=float("nan")), r"head_speed must be a finite number"),
    ],
)
def test_bad_swings_are_refused(kwargs, match):
    with pytest.raises(ValueError, match=match):
        Swing(**kwargs)


def test_a_held_racket_is_not_swung(racket):
    from dataclasses import replace

    held = replace(racket, support="hand-held")
    with pytest.raises(ValueError, match="swing_speed must be 0 for a hand-held racket"):
        sweep(held, paper_ball(), [0.1, 0.2], 10.0, swing=Swing(30.0), progress=False)


def test_the_head_speed_for_a_target_near_the_tip_stays_in_range(racket):
    """Near the tip the point moves faster than the head: the search keeps it in range."""
    head = head_speed_for(racket, paper_ball(), 50 * MPH, racket.strings.extent[0])
    table = serve_table(racket, paper_ball(), racket.strings.extent[0], head, zero_cor=False)
    assert abs(table["serve_simulated_mph"].iloc[0] - 50.0) < 0.01
    with pytest.raises(ValueError, match=r"target ball speed must be in \("):
        head_speed_for(racket, paper_ball(), 299.0, racket.strings.extent[0])


def test_a_swung_sweeps_vibration_fraction_is_the_racket_at_rest(racket):
    """The vibration's share is of the ball's energy in the swing's frame: the same as the
    racket at rest hit at the closing speed."""
    from studies.tables import impact_table

    swing, x = Swing(25.0), np.array([0.05, 0.2])
    swung = impact_table(impact(racket, paper_ball(), x, 5.0, **swing.impact_kwargs(racket, x)))
    v = swing.point_speeds(racket, x)
    for i in range(x.size):
        rest = impact_table(impact(racket, paper_ball(), x[i], 5.0 + v[i]))
        assert swung["vibration_energy_fraction"].iloc[i] == pytest.approx(
            rest["vibration_energy_fraction"].iloc[0], rel=1e-9
        )


@pytest.mark.parametrize(
    "argv, match",
    [
        (["serve", "--racket-speed-mph", "100", "--target-ball-speed-mph", "120"], "not both"),
        (["sweep", "--pivot-cm-from-tip", "80"], "--pivot-cm-from-tip needs --swing-speed"),
    ],
)
def test_contradicting_or_incomplete_options_are_refused(argv, match, capsys):
    from studies.cli import main

    assert main(argv) == 2
    assert match in capsys.readouterr().err


def test_the_feel_is_followed_past_the_contact(racket):
    from dataclasses import replace

    from racket.feel import hand_feel

    soft = replace(racket, strings=replace(racket.strings, stiffness=1e4, stretch=0.0, loss=0.0))
    with pytest.raises(ValueError, match=r"duration must be longer than the contact, 7"):
        hand_feel(soft, paper_ball(), racket.strings.center, 20.0, duration=0.005)


@pytest.mark.parametrize(
    "target, match",
    [
        (float("nan"), r"target must be a finite number"),
        (0.0, r"target must be in \[0.001, 300\] m/s"),
        (400.0, r"target must be in \[0.001, 300\] m/s"),
    ],
)
def test_the_head_speed_target_is_checked_before_any_impact(racket, target, match, monkeypatch):
    import studies.serve

    def no_impact(*args, **kwargs):
        raise AssertionError("an impact ran before the target was checked")

    monkeypatch.setattr(studies.serve, "impact", no_impact)
    with pytest.raises(ValueError, match=match):
        head_speed_for(racket, paper_ball(), target)


def test_the_head_speed_search_runs_only_swung_impacts(racket, monkeypatch):
    """Each evaluation is one swung impact (the ball at rest), none of the racket at rest."""
    import studies.serve

    speeds = []

    def counted(*args, **kwargs):
        speeds.append(args[3])
        return impact(*args, **kwargs)

    monkeypatch.setattr(studies.serve, "impact", counted)
    head_speed_for(racket, paper_ball(), 100 * MPH)
    assert speeds and all(s == 0.0 for s in speeds)
