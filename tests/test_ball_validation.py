"""Bad input raises ValueError naming the argument and the value."""

import math

import pytest

from ball import WALL, Ball, collide, series_cor
from ball.laws import LinearHysteresis, LinearSpring, PowerLawHysteresis, SineLaw
from ball.series import series_force, series_solver


@pytest.mark.parametrize(
    "make, name",
    [
        (lambda: LinearSpring(0.0), "k"),
        (lambda: LinearSpring(-5.0), "k"),
        (lambda: LinearSpring(math.nan), "k"),
        (lambda: LinearSpring(math.inf), "k"),
        (lambda: LinearHysteresis(4e4, 1.2), "e"),
        (lambda: LinearHysteresis(4e4, -0.1), "e"),
        (lambda: LinearHysteresis(4e4, math.nan), "e"),
        (lambda: PowerLawHysteresis(1e6, 1.5, 1.0), "b"),
        (lambda: PowerLawHysteresis(1e6, 0.0, 1.0), "a"),
        (lambda: PowerLawHysteresis.with_cor(1e6, 1.5, 0.0), "e"),
        (lambda: SineLaw(-2e4), "k0"),
        (lambda: Ball(0.0, LinearSpring(1.0)), "mass"),
        (lambda: Ball(-1.0, LinearSpring(1.0)), "mass"),
        (lambda: Ball(math.inf, LinearSpring(1.0)), "mass"),
        (lambda: Ball(0.05, "rubber"), "law"),
        (lambda: series_cor(1.5, 1.0, 1.0), "e1"),
    ],
)
def test_constructors_reject_bad_values(make, name):
    with pytest.raises(ValueError, match=rf"^{name} "):
        make()


BALL = Ball(0.057, LinearHysteresis(4e4, 0.75))


@pytest.mark.parametrize(
    "args, needle",
    [
        ((BALL, BALL, 1.0, 2.0), "approach"),
        ((BALL, BALL, 1.0, 1.0), "approach"),
        ((BALL, WALL, -3.0), "approach"),
        ((BALL, BALL, math.nan), "v_a"),
        ((BALL, BALL, 3.0, math.inf), "v_b"),
        ((BALL, WALL, 3.0, 1.0), "v_b"),
        ((WALL, BALL, 3.0), "a must"),
        ((BALL, "floor", 3.0), "b must"),
        ((Ball(0.01, SineLaw(2e4)), Ball(0.01, SineLaw(2e4)), 3.0), "SineLaw"),
        ((Ball(0.01, SineLaw(2e4)), Ball(0.01, PowerLawHysteresis(1e3, 0.5, 0.6)), 3.0), "softens"),
    ],
)
def test_collide_rejects_bad_input(args, needle):
    with pytest.raises(ValueError, match=needle):
        collide(*args)


def test_message_names_value_and_range():
    with pytest.raises(ValueError) as err:
        LinearHysteresis(4e4, 1.2)
    assert "1.2" in str(err.value) and "[0, 1]" in str(err.value)


@pytest.mark.parametrize("f_max", [-1.0, [5.0, -1.0], -1e30])
def test_a_negative_largest_force_is_refused_not_warned(f_max):
    """A force is never negative: one line naming f_max and the value, no power of a
    negative number (a RuntimeWarning before)."""
    laws = [PowerLawHysteresis(1e6, 1.5, 2.5), LinearSpring(4e4)]
    with pytest.raises(ValueError, match=r"^f_max must be >= 0 N, got -1"):
        series_force(laws, 0.001, f_max)
    with pytest.raises(ValueError, match=r"^f_max must be >= 0 N"):
        series_solver(laws, -1.0)
