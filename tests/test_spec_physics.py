"""What spec-sheet changes do to the power along the strings (issue acceptance): a stiffer
frame and a lower tension, on the paper's linear spring (by name: the real strings are
tests/test_stringing.py's)."""

import numpy as np
import pytest

from racket import CATALOG, from_specs, impact, paper_ball

# 321 g, 33 cm, 325 kg cm^2, 645 cm^2; the frame's stiffness given as f1 below
SHEET = {k: v for k, v in CATALOG["pure-drive-2021"].specs.items() if k != "ra"}
BALL = paper_ball()


def _e(f1=150.0, tension=55.0, where=("tip", "node", "throat"), speed=20.0):
    racket = from_specs(**(SHEET | dict(f1_hz=f1, tension_lb=tension)), string="linear")
    points = {
        "tip": 0.02,
        "node": racket.beam.modes.nodes(1)[0],
        "centre": racket.strings.center,
        "throat": racket.strings.extent[1] - 0.02,
    }
    return impact(racket, BALL, np.array([points[w] for w in where]), speed).e


def test_stiffer_frame_raises_e_at_tip_and_throat_not_at_the_node():
    soft, stiff = _e(f1=120.0), _e(f1=180.0)
    assert stiff[0] > soft[0] + 0.05  # tip
    assert stiff[2] > soft[2] + 0.05  # throat
    assert abs(stiff[1] - soft[1]) <= 0.01  # node


@pytest.mark.parametrize("where", ["node", "centre"])
def test_higher_tension_lowers_e(where):
    e = [_e(tension=t, where=(where,))[0] for t in (45.0, 55.0, 65.0)]
    assert e[0] > e[1] > e[2]
