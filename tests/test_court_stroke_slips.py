"""``racket-impact court`` and ``racket-impact stroke`` (issue 36): a value that looks like
another unit, or faster than any recorded stroke, is asked about (a warning) and the run goes
on."""

import pytest
from clihelpers import warning

ASKED = {
    ("court", "grass"): [
        (["--topspin", "200"], "rad/s typed as rpm? 200 rad/s would be 1910 rpm"),
        (["--angle", "0.28"], "radians typed as deg? 0.28 rad would be 16.04 deg"),
        (["--speed", "75"], "--speed 75 m/s is faster than any recorded stroke"),
    ],
    ("stroke", "volley"): [
        (["--topspin", "200"], "rad/s typed as rpm? 200 rad/s would be 1910 rpm"),
        (["--face", "0.2"], "radians typed as deg? 0.2 rad would be 11.46 deg"),
        (["--head-speed-mph", "120"], "--head-speed-mph 120 mph is faster than any recorded"),
    ],
}
"""The command and its preset, then each value typed and what it is asked."""


@pytest.mark.parametrize(
    "argv, asked",
    [([*command, *argv], asked) for command, cases in ASKED.items() for argv, asked in cases],
    ids=lambda value: " ".join(value) if isinstance(value, list) else "",
)
def test_a_value_that_looks_like_another_unit_is_asked_about(argv, asked):
    assert asked in warning(argv)
