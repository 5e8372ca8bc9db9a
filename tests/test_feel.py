"""What the hand feels (issue 33): the shock and the vibration of the handle at the middle of
the hand, the racket held in the hand.  The shock is least at the centre of percussion (none
at all on a free racket), the racket and the hand drifting away together after the impact is
in neither number, and the page's feel card and ``racket-impact feel`` report the same
numbers for the same racket, ball and speed.
"""

import re

import numpy as np
import pytest

from racket import default_ball, default_racket
from racket.feel import hand_feel
from studies.cli import main
from studies.face.landmarks import hand_pivot, rigid_centre_of_percussion
from studies.feel import FEEL_SUPPORT
from studies.page.dashboard import feel_summary
from studies.sweeps import BALL_SPEED

BALL = default_ball()
HELD = default_racket(FEEL_SUPPORT)
FREE = default_racket()


def _centre_of_percussion(racket) -> float:
    """The centre of percussion for the middle of the hand [m from the tip]."""
    return rigid_centre_of_percussion(racket, hand_pivot(racket))


def _printed(capsys, *argv) -> tuple[str, dict]:
    """What ``racket-impact feel ARGV`` prints, and its shock, vibration [g] and strongest
    vibration [Hz] read off it."""
    assert main(["feel", *argv]) == 0
    out = capsys.readouterr().out

    def number(name: str, unit: str) -> float:
        return float(re.search(rf"^{name} +([\d.]+) {unit} ", out, re.M)[1])

    return out, {
        "feel_shock_g": number("shock", "g"),
        "feel_vibration_g": number("vibration", "g"),
        "feel_hz": number("strongest vibration", "Hz"),
    }


def test_feel_reports_a_smaller_shock_at_the_centre_of_percussion_than_at_the_tip(capsys):
    cop, (tip, throat) = _centre_of_percussion(HELD), HELD.strings.extent
    shock = {
        name: _printed(capsys, "--position", str(100 * x))[1]["feel_shock_g"]
        for name, x in (("centre of percussion", cop), ("tip", tip), ("throat", throat))
    }
    print(f"\nshock at the hand, held (medium grip), 16.5 m/s: {shock} [g]")
    assert shock["centre of percussion"] < 0.15 * min(shock["tip"], shock["throat"])


def test_a_free_racket_hit_at_its_centre_of_percussion_has_no_shock():
    """The shock of a free racket is its rigid-body acceleration at the hand: the contact
    force times the rigid-body modes' shapes at the impact point and the hand, zero at the
    centre of percussion; the vibration is all the rest."""
    cop, tip = _centre_of_percussion(FREE), FREE.strings.extent[0]
    at_cop, at_tip = (hand_feel(FREE, BALL, x, BALL_SPEED) for x in (cop, tip))
    assert at_cop.shock < 1e-9 * at_tip.shock
    assert at_cop.vibration > 0.1 * at_tip.vibration  # the frame still rings
    _, phi, _ = FREE.point_dynamics(tip)
    _, phi_hand, _ = FREE.point_dynamics(hand_pivot(FREE))
    rigid = list(FREE.system.rigid)
    expected = at_tip.force * (phi[0, rigid] @ phi_hand[0, rigid])
    assert np.abs(at_tip.shock_acceleration - expected).max() < 1e-9 * at_tip.shock
    whole = at_tip.shock_acceleration + at_tip.vibration_acceleration
    assert np.abs(whole - at_tip.acceleration).max() < 1e-9 * at_tip.peak_acceleration


def test_the_drift_of_the_racket_and_the_hand_is_in_neither_number():
    """1 cm from the centre of percussion the handle moves at metres per second 40 ms after
    the impact (the racket and the hand's mass moving on together, nothing holding the hand
    to a body), yet the shock is small and the shock and the vibration do not change when the
    racket is followed four times as long."""
    x = _centre_of_percussion(HELD) + 0.01
    short, long = (hand_feel(HELD, BALL, x, BALL_SPEED, duration=d) for d in (0.05, 0.2))
    tip = hand_feel(HELD, BALL, HELD.strings.extent[0], BALL_SPEED)
    assert np.abs(short.velocity).max() > 3.0  # [m/s]
    assert short.shock < 0.15 * tip.shock
    assert long.shock == pytest.approx(short.shock, rel=1e-12)
    assert long.vibration == pytest.approx(short.vibration, rel=1e-12)


def test_the_vibration_is_least_near_the_node_of_the_first_mode():
    node = HELD.beam.modes.nodes(1)[0]
    tip, throat = HELD.strings.extent
    vibration = {x: hand_feel(HELD, BALL, x, BALL_SPEED).vibration for x in (node, tip, throat)}
    # (a third less than at either end: the string bed's own vibration, some 450 Hz, reaches
    # the frame's higher modes, which have no node there; half without the bed's mass)
    assert vibration[node] < 0.75 * min(vibration[tip], vibration[throat])


def test_the_page_and_the_command_report_the_same_feel(capsys):
    """The page's feel card (:func:`studies.page.dashboard.feel_summary`, given the page's free
    racket) and ``racket-impact feel`` with its defaults: the same racket held the same way,
    the same ball at the same speed, the same numbers; the command's header says them."""
    page = feel_summary(FREE, BALL, BALL_SPEED)
    out, printed = _printed(capsys)
    assert (page["feel_support"], page["feel_grip"]) == ("hand-held", "medium grip")
    assert "racket pure-drive-2021 (hand-held, medium grip" in out.splitlines()[0]
    assert "ball itf-type-2 at 16.5 m/s" in " ".join(out.splitlines()[:2])
    assert printed["feel_shock_g"] == float(f"{page['feel_shock_g']:.1f}")
    assert printed["feel_vibration_g"] == float(f"{page['feel_vibration_g']:.1f}")
    assert printed["feel_hz"] == float(f"{page['feel_hz']:.1f}")
    assert f"({page['feel_mode']})" in out
    # held already or not, the page's racket is held the same way
    assert feel_summary(HELD, BALL, BALL_SPEED) == page
