"""Serve what-ifs (paper Sec. VIII) for every ball: presets and the example TOML balls."""

from pathlib import Path

import numpy as np
import pytest

from ball import WALL, Ball, LinearHysteresis, PowerLawHysteresis, SineLaw, collide
from racket import paper_racket
from studies.cli import main
from studies.config import BALLS, load_ball
from studies.serve import serve_table, zero_cor_ball

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
EXAMPLE_BALLS = sorted(str(p) for p in EXAMPLES.glob("*.toml") if "ball" in p.read_text())
ALL_BALLS = list(BALLS) + [p for p in EXAMPLE_BALLS if "[ball]" in Path(p).read_text()]


@pytest.mark.parametrize("name", ALL_BALLS)
def test_serve_runs_for_every_ball_with_a_reduction_in_range(name):
    table = serve_table(paper_racket(), load_ball(name), racket_speed=40.0)
    for how in ("eq22", "simulated"):
        reduction = table.loc["zero-COR", f"reduction_{how}_percent"]
        assert 0.0 <= reduction <= 100.0
    # The collision sees only the relative motion: Eq. 22 with the simulated e and m2 is
    # the swung racket's answer (rotation about the wrist included), to round-off for a
    # monotone ball, to the 3e-11 to which the sine-law ball's Xo is found otherwise.
    assert table["serve_simulated_m_s"].to_numpy() == pytest.approx(
        table["serve_eq22_m_s"].to_numpy(), rel=1e-9
    )


@pytest.mark.parametrize("name", ["unhappy", "zero-cor-tennis", "happy"])
def test_serve_command_for_the_presets_the_help_lists(name, capsys):
    assert main(["serve", "--ball", name, "--racket-speed", "30"]) == 0
    out = capsys.readouterr().out
    assert "(simulated)" in out and "[m/s]" in out
    assert "zero-COR" not in out and "Traceback" not in out
    assert main(["serve", "--ball", name, "--racket-speed", "30", "--what-if"]) in (0, 2)
    assert "zero-COR" in capsys.readouterr().out  # (the stiffness sweep needs a linear ball)


def test_sine_law_ball_is_its_own_zero_cor_ball():
    ball = load_ball("unhappy")
    assert zero_cor_ball(ball, 400.0) is ball
    table = serve_table(paper_racket(), ball, racket_speed=40.0)
    assert table.loc["zero-COR", "reduction_simulated_percent"] == 0.0


@pytest.mark.parametrize(
    "law",
    [
        LinearHysteresis(4e4, 0.75),
        PowerLawHysteresis(2e6, 1.5, 3.0),
        PowerLawHysteresis(5e5, 1.2, 1.2),
    ],
)
@pytest.mark.parametrize("speed", [5.0, 40.0])
def test_twin_has_the_ball_s_stiffness_at_that_speed_and_no_rebound(law, speed):
    ball = Ball(0.057, law)
    on_wall = collide(ball, WALL, speed)
    twin = zero_cor_ball(ball, on_wall.peak_force)  # the twin of the ball in that bounce
    assert isinstance(twin.law, SineLaw) and twin.mass == ball.mass
    # Secant stiffness F_max / X_max of the ball's own bounce on a rigid surface.
    assert twin.law.k0 == pytest.approx(
        on_wall.peak_force / np.max(on_wall.history.compression_a), rel=1e-3
    )
    assert collide(twin, WALL, speed).e == pytest.approx(0.0, abs=1e-9)


def test_twin_serves_slower_for_every_law():
    racket = paper_racket()
    for ball in (
        load_ball("paper"),
        load_ball("happy"),
        Ball(0.057, PowerLawHysteresis(2e6, 1.5, 3.0)),
    ):
        table = serve_table(racket, ball, racket_speed=40.0)
        assert table.loc["zero-COR", "e"] < table.loc["normal", "e"]


@pytest.mark.parametrize("stiffness", [10.0, 1e9, float("nan")])
def test_serve_what_if_checks_the_string_stiffness(stiffness):
    from studies.serve import serve_what_if

    with pytest.raises(ValueError, match=r"string_stiffness must be"):
        serve_what_if(paper_racket(), BALLS["paper"](), string_stiffness=[3e4, stiffness])


def test_the_simulated_serves_alone_are_the_same_and_eq22_is_left_nan():
    """``eq22=False`` (``racket-impact paper``'s what-if figure) computes the simulated
    serves alone: the same bits, Eq. 22's values NaN; no cases give no columns."""
    from studies.serve import serve_what_if, serve_what_if_columns

    racket, ball = paper_racket(), BALLS["paper"]()
    cases = dict(string_stiffness=[2e4, 5e4], ball_stiffness=[3e4])
    both = serve_what_if(racket, ball, **cases)
    alone = serve_what_if_columns(racket, ball, **cases, eq22=False)
    assert list(alone) == list(both.columns)
    for name in alone:
        if "eq22" in name or name in ("e", "effective_mass_kg"):
            assert np.isnan(alone[name]).all(), name
        elif name == "varied":
            assert alone[name] == list(both[name])
        else:
            assert np.array_equal(alone[name], both[name].to_numpy()), name
    assert serve_what_if(racket, ball, string_stiffness=[], ball_stiffness=[]).empty
    with pytest.raises(TypeError, match="eq22"):
        serve_what_if_columns(racket, ball, string_stiffness=[], ball_stiffness=[], eq22="no")


def test_centre_of_percussion_is_simulated_and_is_the_formula_for_a_free_racket():
    """The sweet spots' centre of percussion is where the hand's rigid-body velocity after
    the impact is zero: the rigid-body formula for a free racket (to round-off), not for a
    held one (the hand pushes during the contact)."""
    from dataclasses import replace

    from racket import CATALOG, paper_ball
    from studies.face.landmarks import hand_pivot, rigid_centre_of_percussion
    from studies.face.sweetspots import sweet_spots

    free = CATALOG["pure-drive-2021"].racket()
    held = replace(free, support="hand-held")
    cop = {}
    for name, racket in (("free", free), ("held", held)):
        table = sweet_spots(racket, paper_ball()).set_index("spot")
        cop[name] = table.loc["centre of percussion", "from_tip_cm"] / 100
    formula = rigid_centre_of_percussion(free, hand_pivot(free))
    assert cop["free"] == pytest.approx(formula, abs=1e-10)
    assert abs(cop["held"] - formula) > 0.005
    # and the grip given moves it as the formula says, for the free racket
    table = sweet_spots(free, paper_ball(), hand_from_tip=free.beam.length - 0.07).set_index("spot")
    formula = rigid_centre_of_percussion(free, free.beam.length - 0.07)
    assert table.loc["centre of percussion", "from_tip_cm"] / 100 == pytest.approx(
        formula, abs=1e-10
    )


def test_the_hand_given_from_the_tip_on_the_command_line_moves_the_centre_of_percussion(
    tmp_path, capsys
):
    """``sweetspots --hand-cm-from-tip CM``: the centre of percussion for that hand (the
    formula, on the default free racket); the hand in m typed as cm refused with the hint."""
    import json

    from racket import default_racket
    from studies.face.landmarks import rigid_centre_of_percussion

    out = tmp_path / "spots.json"
    assert main(["sweetspots", "--hand-cm-from-tip", "61.58", "--out", str(out)]) == 0
    assert "centre of percussion (hand at 61.6 cm)" in capsys.readouterr().out
    spots = {row["spot"]: row for row in json.loads(out.read_text())}
    formula = rigid_centre_of_percussion(default_racket(), 0.6158)
    assert spots["centre of percussion"]["from_tip_cm"] / 100 == pytest.approx(formula, abs=1e-10)
    assert main(["sweetspots", "--hand-cm-from-tip", "0.6158"]) == 2
    assert "(m typed as cm? 0.6158 m would be 61.58 cm)" in capsys.readouterr().err


@pytest.mark.parametrize(
    "pivot, match",
    [
        ("centre of mass", r"pivot must be in \(.*\] m \(beyond the centre of mass"),
        (float("nan"), r"pivot must be a finite number"),
        (2.0, r"pivot must be in \[0, "),
    ],
)
def test_centre_of_percussion_formula_refuses_bad_pivots(pivot, match):
    from studies.face.landmarks import rigid_centre_of_percussion

    racket = paper_racket()
    if pivot == "centre of mass":
        pivot = racket.beam.center_of_mass
    with pytest.raises(ValueError, match=match):
        rigid_centre_of_percussion(racket, pivot)


@pytest.mark.parametrize("points", [40.5, 4.7, 10])
def test_sweet_spots_points_must_be_a_whole_number_in_range(points):
    from racket import paper_ball
    from studies.face.sweetspots import sweet_spots

    with pytest.raises(ValueError, match=r"points must be"):
        sweet_spots(paper_racket(), paper_ball(), points=points)
