"""Issue 44: every stroke preset's exit speed and launch angle checked for plausibility, not
only its spin.

Necessary conditions only, each a bound the ball must meet whatever the air does to it:

* it clears the net in a flight without air (drag and topspin only pull a ball down
  sooner): from the baseline, 11.89 m from the net (ITF Rules of Tennis, court dimensions),
  over its 0.914 m at the centre; struck at 2.7 m for a serve and 1.0 m for a groundstroke
  (**assumptions**: a tall player's serve, a ball near the top of its bounce);
* it leaves no faster than players hit: serves below the fastest measured, 149 mph
  (Shelton, US Open, as reported by theencinotenniscoach.com), forehands below 120 mph, which
  "wasn't unheard of, but it was extraordinary" (Fawcette, "Groundstroke velocities soar in
  pro tennis", tennisplayer.net: the 2017 Australian Open's fastest men's forehands
  108-112 mph);
* a serve leaves downwards or nearly level, a groundstroke upwards (a drive climbs over the
  net): launch below +5 deg for serves, above -5 deg for groundstrokes (**assumptions**).
"""

import math

import pytest

from common.units import MPH
from racket import STROKES, default_ball, default_racket, hit

NET_DISTANCE, NET_HEIGHT, GRAVITY = 11.89, 0.914, 9.81
"""The baseline's distance from the net [m], the net's height at the centre [m], g [m/s^2]."""

HEIGHTS = {"serve": 2.7, "groundstroke": 1.0}
"""Where the ball is struck [m above the court] (assumptions)."""

FASTEST_MPH = {"serve": 149.0, "groundstroke": 120.0}
"""The fastest balls players hit [mph] (sources in the module's docstring)."""

GROUNDSTROKES = ("topspin-forehand", "flat-forehand", "slice-backhand")


def _kind(name: str) -> str | None:
    if name.endswith("serve"):
        return "serve"
    return "groundstroke" if name in GROUNDSTROKES else None


@pytest.fixture(scope="module")
def flights():
    racket, ball = default_racket(), default_ball()
    return {name: hit(stroke, racket, ball).flight for name, stroke in STROKES.items()}


@pytest.mark.parametrize("name", [n for n in STROKES if _kind(n) is not None])
def test_every_preset_clears_the_net_and_leaves_no_faster_than_players_hit(flights, name):
    kind, f = _kind(name), flights[name]
    speed, launch = f.speed, f.launch_angle
    horizontal = speed * math.cos(launch)
    t = NET_DISTANCE / horizontal
    height = HEIGHTS[kind] + speed * math.sin(launch) * t - 0.5 * GRAVITY * t * t
    print(f"\n{name}: {speed / MPH:.0f} mph, launch {math.degrees(launch):.1f} deg, "
          f"{height:.2f} m over the net's line without air")  # fmt: skip
    assert height > NET_HEIGHT
    assert speed < FASTEST_MPH[kind] * MPH
    if kind == "serve":
        assert launch < math.radians(5.0)
    else:
        assert launch > math.radians(-5.0)
