"""Unit slips in the commands added since the old ones learnt to catch them (issue 46, "Why"
item 5), and a ``[racket.hand]`` table on a free racket (item 4): each is asked about in a
one-line warning naming the likely slip, where the value could still be meant, or refused in
one line (status 2, no traceback) where it cannot, naming the input as typed, its value, its
unit and its range."""

import pytest
from clihelpers import refusal, run_ok, warning

from studies.config import load_racket

ASKED = {
    "bbcor --pitch 136 (mph typed as m/s)": (
        ["bat", "bbcor", "--pitch", "136"],
        "--pitch 136 m/s is not the BBCOR test's speed (60.8-67.05 m/s: from the 136 mph "
        "often cited to the cannon's 150 mph), so the verdict is not the standard's: mph "
        "typed as m/s? 136 mph would be 60.8 m/s (--pitch-mph 136)",
    ),
    "bbcor at a speed no source gives the test": (
        ["bat", "bbcor", "--pitch-mph", "100"],
        "--pitch-mph 100 mph is not the BBCOR test's speed (136-150 mph",
    ),
    "bat --cm-speed 54 (mph typed as m/s)": (
        ["bat", "--cm-speed", "54", "--points", "3"],
        "--cm-speed 54 m/s is faster than batters swing a bat's centre of mass (about 36 m/s, "
        "estimated): mph typed as m/s? 54 mph would be 24.14 m/s (--cm-speed-mph 54)",
    ),
    "court --speed 67 (mph typed as m/s)": (
        ["court", "grass", "--speed", "67"],
        "--speed 67 m/s is faster than a ball comes down on a court (about 54.9 m/s: the "
        "serve record less what the air takes, estimated): mph typed as m/s? 67 mph would "
        "be 29.95 m/s (--speed-mph 67)",
    ),
    "--string-bed-dt 300 (N/cm typed as kp/cm)": (
        ["sweep", "--points", "3", "--string-bed-dt", "300"],
        "--string-bed-dt 300 kp/cm is stiffer than players' beds read (most 28-46 kp/cm): "
        "N/cm typed as kp/cm? 300 N/cm would be 30.59 kp/cm",
    ),
    "--offset 0.05 (m typed as cm)": (
        ["sweep", "--points", "3", "--offset", "0.05"],
        "--offset 0.05 cm from the long axis is within 1 cm of it: m typed as cm? 0.05 m "
        "would be 5 cm from the long axis",
    ),
}
"""What is typed, and the warning's words."""


@pytest.mark.parametrize("argv, asked", ASKED.values(), ids=list(ASKED))
def test_a_slip_of_unit_is_asked_about(argv, asked):
    assert asked in warning(argv)


@pytest.mark.parametrize(
    "argv",
    [["bat", "bbcor", "--pitch-mph", "136"], ["bat", "bbcor", "--pitch", "60.8"],
     ["court", "grass", "--speed", "30"], ["sweep", "--points", "3", "--string-bed-dt", "40"],
     ["sweep", "--points", "3", "--offset", "5"]],
    ids=" ".join,
)  # fmt: skip
def test_what_is_meant_is_not_asked_about(argv):
    _, err = run_ok(argv)
    assert "warning" not in err, err


def _toml(tmp_path, text: str) -> str:
    path = tmp_path / "racket.toml"
    path.write_text(text)
    return str(path)


def test_a_dt_in_n_per_cm_from_toml_is_asked_about(tmp_path):
    toml = _toml(tmp_path, "[racket.strings]\ndt_kp_cm = 300\n")
    said = warning(["sweep", "--points", "3", "--racket", toml])
    assert (
        "[racket.strings] dt_kp_cm 300 kp/cm is stiffer than players' beds read (most 28-46 "
        "kp/cm): N/cm typed as kp/cm? 300 N/cm would be 30.59 kp/cm"
    ) in said
    with pytest.warns(UserWarning, match=r"dt_kp_cm 300 kp/cm .* N/cm typed as kp/cm\?"):
        load_racket(toml)


def test_lead_in_kg_typed_as_grams_is_refused_with_the_hint():
    said = refusal(["sweep", "--points", "3", "--lead", "0.005@12"])
    assert said.endswith(
        "--lead must be in [0.1, 200] g per side, got 0.005 (kg typed as g? 0.005 kg would be "
        "5 g per side)"
    )


def test_lead_tape_in_kg_in_toml_is_asked_about(tmp_path):
    toml = _toml(tmp_path, '[racket]\nlead_tape = [{mass_g = 0.005, at = "12"}]\n')
    said = warning(["sweep", "--points", "3", "--racket", toml])
    assert (
        "lead_tape mass_g 0.005 g is less than lead tape weighs (at least 0.1 g): kg typed as "
        "g? 0.005 kg would be 5 g"
    ) in said


def test_twelve_kg_of_lead_is_refused(tmp_path):
    toml = _toml(tmp_path, "[racket]\npoint_masses = [[0.05, 12]]\n")
    expected = (
        "[racket] point_masses mass must be in [0, 0.2] kg, got 12 (grams typed as kg? 12 "
        "would be 0.012 kg)"
    )
    assert refusal(["sweep", "--points", "3", "--racket", toml]).endswith(expected)
    with pytest.raises(ValueError, match=r"point_masses mass must be in \[0, 0\.2\] kg, got 12"):
        load_racket(toml)


HAND = '[racket]\npreset = "pure-drive-2021"\n[racket.hand]\ngrip = "tight"\n'
"""A racket whose file gives a hand and leaves its support the preset's (free)."""


def test_a_hand_on_a_free_racket_is_refused(tmp_path):
    toml = _toml(tmp_path, HAND)
    said = refusal(["sweep", "--points", "3", "--racket", toml])
    assert said.endswith(
        f"[racket.hand] in {toml} does not apply to a free racket (its preset's support, "
        "free): only a hand-held racket has a hand; give --support hand-held, or leave the "
        "table out"
    )
    said = refusal(["sweep", "--points", "3", "--racket", toml, "--support", "free"])
    assert "[racket.hand] in" in said and "a free racket (--support free)" in said
    said = refusal(["serve", "--racket", toml])
    assert said.endswith("serve swings a free racket: leave the table out")
    toml = _toml(tmp_path, HAND.replace("[racket]\n", '[racket]\nsupport = "free"\n'))
    assert 'a free racket (its support = "free")' in refusal(["sweep", "--racket", toml])


def test_a_hand_on_a_held_racket_is_taken(tmp_path):
    toml = _toml(tmp_path, HAND)
    held = ["sweep", "--points", "3", "--support", "hand-held"]

    def table(argv) -> str:
        out, _ = run_ok(argv)
        return out[out.index("[cm]") :]

    ours = table([*held, "--racket", toml])
    assert ours == table([*held, "--grip", "tight"])  # the file's hand holds it
    assert ours != table(held)  # not the default one
