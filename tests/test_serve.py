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
    assert "serve_simulated_m_s" in out and "zero-COR" not in out and "Traceback" not in out
    assert main(["serve", "--ball", name, "--racket-speed", "30", "--what-if"]) in (0, 2)
    assert "zero-COR" in capsys.readouterr().out  # (the stiffness sweep needs a linear ball)


def test_sine_law_ball_is_its_own_zero_cor_ball():
    ball = load_ball("unhappy")
    assert zero_cor_ball(ball, 40.0) is ball
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
    twin = zero_cor_ball(ball, speed)
    assert isinstance(twin.law, SineLaw) and twin.mass == ball.mass
    on_wall = collide(ball, WALL, speed)
    # Secant stiffness F_max / X_max of the ball's own bounce on a rigid surface.
    assert twin.law.k0 == pytest.approx(
        on_wall.peak_force / np.max(on_wall.history.compression_a), rel=1e-3
    )
    assert collide(twin, WALL, speed).e == pytest.approx(0.0, abs=1e-9)


def test_twin_serves_slower_for_every_law():
    racket = paper_racket()
    for ball in (
        load_ball("tennis"),
        load_ball("happy"),
        Ball(0.057, PowerLawHysteresis(2e6, 1.5, 3.0)),
    ):
        table = serve_table(racket, ball, racket_speed=40.0)
        assert table.loc["zero-COR", "e"] < table.loc["normal", "e"]
