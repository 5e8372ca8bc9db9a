"""Lead tape at any clock position that exists on a racket works everywhere (issue 34): on
the long axis (12 and 6 o'clock) a point mass keeps the racket symmetric about it, a mirrored
pair does too, and one side alone is refused with what to type instead; the page offers only
what the tool accepts."""

import numpy as np
import pytest

from racket import default_ball, default_racket, impact
from studies.cli import main

AXIS_AND_PAIRS = ["12", "6", "3 and 9", "2 and 10", "1 and 11", "4 and 8", "5 and 7"]


def run(capsys, *args):
    status = main(list(args))
    out, err = capsys.readouterr()
    return status, out, err


@pytest.mark.parametrize("at", ["12", "6"])
def test_lead_on_the_long_axis_sits_on_it_exactly(at):
    x, y = default_racket().hoop.clock(at)
    assert y.tolist() == [0.0]  # not sin(pi)'s 2e-17 m
    assert 0.0 <= x[0] <= default_racket().beam.length


@pytest.mark.parametrize("at", AXIS_AND_PAIRS)
def test_every_accepted_clock_position_keeps_the_racket_symmetric(at):
    taped = default_racket().with_lead_tape(0.005, at)
    assert taped.beam.is_mirror_symmetric
    x, y = taped.check_points(0.17, 0.02)  # an impact off the axis is then allowed
    assert x.tolist() == [0.17] and y.tolist() == [0.02]


def test_a_point_mass_on_the_axis_but_for_round_off_is_on_the_axis():
    bare = default_racket().beam
    assert bare.with_point_masses((0.3, 0.005, 2e-17)).is_mirror_symmetric
    assert bare.with_point_masses((0.3, 0.005, 0.0), (0.2, 0.003, 0.1),
                                  (0.2, 0.003, -0.1)).is_mirror_symmetric  # fmt: skip
    assert not bare.with_point_masses((0.3, 0.005, 0.01)).is_mirror_symmetric


def test_one_side_alone_is_refused_with_what_to_do():
    racket = default_racket()
    with pytest.raises(ValueError, match=r"one side only; give both sides, '3 and 9'"):
        racket.with_lead_tape(0.002, "3")
    lopsided = racket.__class__(
        racket.beam.with_point_masses((0.17, 0.003, 0.1)), racket.strings, racket.support
    )
    with pytest.raises(ValueError, match=r"symmetric about its long axis"):
        lopsided.check_points(0.17, 0.02)


@pytest.mark.parametrize("at", ["6", "12", "3 and 9"])
def test_the_api_hits_off_the_axis_with_lead_anywhere(at):
    racket, ball = default_racket(), default_ball()
    taped = racket.with_lead_tape(0.005, at)
    hit = impact(taped, ball, 0.17, 16.5, offset=0.03)
    bare = impact(racket, ball, 0.17, 16.5, offset=0.03)
    assert np.isfinite(hit.e) and 0.0 < float(hit.e) < 1.0
    assert float(hit.e) != float(bare.e)  # the lead counts


def test_the_page_offers_only_accepted_positions():
    from studies.page.inputs import LEAD_CLOCKS  # the page's choices (studies/page/app.py)

    for at in LEAD_CLOCKS:
        assert default_racket().with_lead_tape(0.005, at).beam.is_mirror_symmetric


COMMANDS = [
    ["map", "--grid", "4", "4"],
    ["compare", "--points", "3"],
    ["sweep", "--points", "3", "--offset", "2"],
    ["feel", "--offset", "2", "--duration-ms", "10"],
    ["sweetspots"],
    ["specs", "--count", "1"],
]


@pytest.mark.parametrize("lead", ["5@6", "5@12", "2@3/9"])
@pytest.mark.parametrize("words", COMMANDS, ids=lambda words: words[0])
def test_every_command_takes_lead_at_any_accepted_clock_position(words, lead, capsys):
    status, out, err = run(capsys, *words, "--lead", lead)
    assert status == 0, err
    assert f"lead {lead}" in out  # said in the conditions line


@pytest.mark.parametrize(
    ("lead", "hint"),
    [
        ("2@3", "give both sides, 2@3/9"),
        ("2g@9", "give both sides, 2@9/3"),
        ("2@3/8", "a mirrored pair H/K with H + K = 12, e.g. 2@12, 2@6, 2@3/9"),
        ("2@13", "must be at 12 (the tip), 6 (the throat)"),
    ],
)
def test_the_command_line_says_what_to_type_in_its_own_spelling(lead, hint, capsys):
    status, _, err = run(capsys, "modes", "--lead", lead)
    assert status == 2 and hint in err
    assert len(err.strip().splitlines()) == 1
