"""Swings at equal effort (issue 25): a racket of larger swingweight is swung more slowly,
V = C / I0^0.27 (Cross and Bower, J. Sports Sci. 24, 2006)."""

import re

import pytest

from racket import CATALOG, Swing
from racket.swing import EFFORT_EXPONENT, equal_effort
from studies.cli import main
from studies.config import load_ball
from studies.face.maps import compare_summary
from studies.sweeps import compare


def test_ten_grams_at_12_oclock_swing_slower_by_the_swingweight_law(tmp_path):
    base = CATALOG["pure-drive-2021"].racket()
    heavier = base.with_lead_tape(0.010, "12")
    i0, i1 = base.beam.swingweight, heavier.beam.swingweight
    assert i1 > i0
    rackets = {"base": base, "lead": heavier}
    ball = load_ball("itf-type-2")
    table = compare(rackets, ball, 18.0, 11, swing=Swing(30.0), equal_effort=True)
    heads = table.groupby("racket", sort=False)["head_speed_m_s"].first()
    assert heads["base"] == 30.0
    assert heads["lead"] / heads["base"] == pytest.approx((i0 / i1) ** EFFORT_EXPONENT, rel=1e-12)
    summary = compare_summary(rackets, table, ball, 18.0).set_index("racket")
    assert summary.loc["lead", "head_speed_mph"] < summary.loc["base", "head_speed_mph"]
    assert summary["largest_exit_mph"].notna().all()
    same = compare(rackets, ball, 18.0, 11, swing=Swing(30.0))  # at equal head speed
    assert set(same.groupby("racket")["head_speed_m_s"].first()) == {30.0}


def test_equal_effort_needs_a_swing_and_positive_swingweights(capsys):
    assert main(["compare", "--equal-effort", "--points", "5"]) == 2
    assert "needs a swing" in capsys.readouterr().err
    with pytest.raises(ValueError, match="swingweight must be > 0"):
        equal_effort(Swing(30.0), 0.03, 0.0)


def test_compare_equal_effort_prints_both_head_and_exit_speeds(tmp_path, capsys):
    lead = tmp_path / "lead.toml"
    lead.write_text(
        '[racket]\npreset = "pure-drive-2021"\nlead_tape = [{mass_g = 10, at = "12"}]\n'
    )
    argv = ["compare", "--racket", "pure-drive-2021", "--racket", f"lead={lead}", "--points",
            "11", "--swing-speed-mph", "70", "--speed-mph", "40", "--equal-effort"]  # fmt: skip
    assert main(argv) == 0
    out = capsys.readouterr().out
    lines = out.splitlines()
    top = next(i for i, line in enumerate(lines) if line.startswith("quantity"))  # under the
    assert "(equal effort)" in " ".join(" ".join(lines[:top]).split())  # the conditions say it
    cells = [re.split(r"\s{2,}", line.strip()) for line in lines[top + 1 :]]
    rows = {row[0]: row[1:] for row in cells}
    assert "lead" in lines[top]  # the rackets side by side
    head, fastest = rows["head speed [mph]"], rows["fastest exit [mph]"]
    assert head[0] == "70" and float(head[1]) < 70  # the heavier racket swung slower
    assert all(float(v) > 70 for v in fastest)
