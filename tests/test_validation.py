"""The model against published measurements (:mod:`studies.validation`; issue 26).

One test per comparison, asserting the model's value lies in the measured band.  The
calibration comparisons (numbers the model was set from) are in
:class:`TestCalibration`, apart from the validations: their agreement checks that the
calibration holds, it does not validate.  Where the model disagrees beyond the band, the
test is a strict expected failure whose reason is the measured gap; nothing was tuned to
move it in (the docs page, ``docs/validation.md``, says what would close each gap).
"""

import re

import pytest

from studies.validation import COLUMNS, KINDS, comparisons, summary

ITEMS = {c.name: c for c in comparisons()}

KNOWN_GAPS = {
    # calibration: the grips' and the membrane model's compromises, kept visible (validate
    # prints why beside them, tests/test_one_band.py)
    "savage-A-tight": "model drop 18.0 % vs 20.0-22.7 % (142-147 Hz): one grip stiffness "
    "for all grips, fitted to both rackets by least squares",
    "savage-B-tight": "model drop 15.8 % vs 12.3 % (10.3-14.3 %): racket B's tight grip "
    "drops less than A's; one tight grip cannot meet both",
    **{
        f"ert-{string}-40": f"model {dt} kp/cm vs the ERT's 28-46 in play: the membrane "
        "model, in proportion to the tension and set to the seed's 3e4 N/m at 55 lb, reads "
        "below the range at 40 lb even with the bed's stiffening by 1 cm (issue 45); a DT "
        "measured against the tension would say which is off"
        for string, dt in (
            ("polyester", 25.5),
            ("nylon", 25.0),
            ("multifilament", 25.0),
            ("natural-gut", 23.9),
        )
    },
    # validation
    "cross-1m-drop-e": "model 0.876 vs 0.837 (0.81-0.87): the strings' loss (5.9 %) took it "
    "from 0.917 to 0.896, the bed's mass to 0.876; the rest would be the ball's own loss at a "
    "drop's low compression on strings (no published COR against speed to check it)",
    "hamori-drive-polyester-67-forehand": "model 4.43 ms vs 3.8 ms (3.3-4.3): the bed's mass "
    "(3.6 g) lengthens this contact by about 0.25 ms",
    "hamori-drive-polyester-67-volley": "model 4.64 ms vs 3.75 ms (3.25-4.25): the volley's "
    "20 m/s closing speed is an assumption; the bed's mass adds 0.2 ms",
    "hamori-drive-polyester-37-volley": "model 5.23 ms vs 4.1 ms (3.6-4.6): as the 67 lb volley",
    "hamori-85-polyester-54-forehand": "model 4.55 ms vs 3.6 ms (3.1-4.1): polyester's stretch "
    "makes it only about 0.2 ms shorter than gut in the model, 0.9 ms in Hamori's strokes",
    "hamori-97-gut-54-volley": "model 4.91 ms vs 4.1 ms (3.6-4.6): as the other volleys",
    "hamori-97-gut-54-serve": "model 4.29 ms vs 3.7 ms (3.2-4.2): the bed's mass adds about "
    "0.26 ms",
    "twu-pivot-throat": "model 0.37 vs about 0.5 (0.45-0.55)",
    "typical-throat": "model 0.36 vs 0.50 (0.45-0.55)",
    "twu-held-3-oclock-lead": "model 0.230 vs 0.25-0.35: TWU's racket names no strings and is "
    "strung by the one rule since issue 45 (fresh polyester), whose loss and mass take e_A "
    "off the side; with the paper's lossless spring it was 0.265 (inside)",
    # validation of the oblique impacts and spin (issue 36)
    "bounce-table-i-omega2": "model 50.9 vs 52.4 +/- 0.5 rad/s: within Table II's 15 %, not "
    "within this bounce's own uncertainty (vx2 is, since issue 44: 1.23 m/s)",
    **{
        f"spin-twu-{material}": f"model {model} vs 1200-1810 rpm: a laterally stiff bed gives "
        "1590-1690 (inside); the strings' slide and snapback add 25-40 % for these (gut's "
        "crossings hold best); over the sideways bed's assumed ranges (the grip's share on the "
        "mains 0.4-0.6, kinetic friction 0.6-1.0 of static, the snapback 1.5-2.5 ms) "
        "polyester at 52 lb spans 1950-2390 rpm"
        for material, model in (("polyester", 2181), ("nylon", 2096))
    },
    "spin-lubricated-polyester": "model +10.4 % vs TWU's +14 to +58 % (13.3-58.7 with the "
    "test's own input scatter): polyester's strings already slide far dry, and lubrication "
    "(an assumed 0.04 against 0.086) frees them a little further; nylon's gain is inside",
    "spin-twu-polyester-over-nylon": "model 1.04 vs 1.20 (1.10-1.30): polyester's mains "
    "slide further (its crossings hold at 0.086 against 0.108), but a laterally stiff bed "
    "starts nylon 4 % ahead",
    "stroke-kick-serve": "model 4762 rpm vs 3270-4500 (6 % over), mainly sidespin as "
    "measured: the preset's 45 degrees across the ball (Cross's 'mostly across', read as "
    "at least as much across as forward) and vertical face are assumptions",
    "stroke-flat-serve": "model 0.77 vs 0.8-1.2 of the first serves' line at its own 117 mph "
    "(1310 against 1698 rpm): the preset's level path and 7 degrees closed face are "
    "assumptions; a real first serve rises through the ball",
}
"""The comparisons the model is known to miss, and by how much (the measured gap)."""


@pytest.fixture(scope="module")
def table(validation_rows):
    return validation_rows.copy()


def _params(kind):
    return [
        pytest.param(
            name,
            id=name,
            marks=[pytest.mark.xfail(strict=True, reason=KNOWN_GAPS[name])]
            if name in KNOWN_GAPS
            else [],
        )
        for name, c in ITEMS.items()
        if c.kind == kind
    ]


def _check(table, name):
    row = table.loc[name]
    print(f"\n{name}: measured {row.measured:.4g} ({row.low:.4g}-{row.high:.4g}), "
          f"model {row.model:.4g}")  # fmt: skip
    assert row.low <= row.model <= row.high


class TestCalibration:
    """Numbers the model was set from: these check that the calibration holds."""

    @pytest.mark.parametrize("name", _params("calibration"))
    def test_calibration_in_measured_band(self, table, name):
        _check(table, name)


@pytest.mark.parametrize("name", _params("validation"))
def test_validation_in_measured_band(table, name):
    _check(table, name)


def test_table_columns_kinds_and_sources(table):
    assert tuple(table.columns) == COLUMNS
    assert set(table["kind"]) == set(KINDS)
    assert table["source"].str.len().min() > 10
    assert (table["low"] <= table["measured"]).all() and (table["measured"] <= table["high"]).all()
    assert table["agrees"].dtype == bool
    assert set(KNOWN_GAPS) <= set(ITEMS)
    # at least 15 comparisons with published measurements, from at least 10 sources
    assert table["source"].nunique() >= 10 and len(table) >= 15
    line = summary(table)
    agreed = int(table["agrees"].sum())
    assert f"{len(table)} comparisons" in line and agreed == len(table) - len(KNOWN_GAPS)


def test_a_comparison_fails_outside_its_band():
    c = ITEMS["rebound-itf-type-2"]
    assert c.agrees(c.measured) and not c.agrees(c.high + 1e-6) and not c.agrees(c.low - 1e-6)


def test_cli_validate_writes_table_and_plot(tmp_path, capsys, table, monkeypatch):
    import studies.validation as validation
    from studies.cli import main

    monkeypatch.setattr(validation, "validation_table", lambda: table)
    out, plot = tmp_path / "v.csv", tmp_path / "v.png"
    assert main(["validate", "--out", str(out), "--plot", str(plot)]) == 0
    printed = capsys.readouterr().out
    assert "comparisons with published measurements" in printed and "Hamori" in printed
    assert out.exists() and plot.exists() and plot.stat().st_size > 1000
    assert main(["validate", "--out", str(tmp_path / "v.txt")]) == 2
    err = capsys.readouterr().err.strip()
    assert err.count("\n") == 0 and "--out must be a table file" in err


def test_every_comparison_is_in_exactly_one_group(table):
    from studies.validation import groups

    named = [name for _, rows in groups(table) for name in rows.index]
    assert sorted(named) == sorted(table.index)  # each once, none left out


def test_the_savage_rows_name_their_racket_and_grip():
    savage = {name: c.quantity for name, c in ITEMS.items() if name.startswith("savage-")}
    assert len(savage) >= 5 and len(set(savage.values())) == len(savage)  # no row twice
    for name, quantity in savage.items():
        _, racket, grip = name.split("-")
        assert f"racket {racket}, {grip} grip" in quantity, quantity


def test_every_row_names_its_racket_and_the_printed_table_its_band(table, capsys, monkeypatch):
    """Issue 33: no two rows read alike (racket, strings and tension, support or grip in each
    racket's row), and the printed table shows the band each value must fall in."""
    import studies.validation as validation
    from studies.cli import main

    assert table["quantity"].is_unique
    for name, c in ITEMS.items():
        if name.startswith(("hamori", "twu", "typical", "grabiner")):
            assert re.search(r"(Pure Drive|AeroPro Drive|Pro Staff \d+)", c.quantity), c.quantity
            assert re.search(r"\d+ lb", c.quantity), c.quantity
            assert re.search(r"grip|hand-held|pinned", c.quantity), c.quantity
    monkeypatch.setattr(validation, "validation_table", lambda: table)
    assert main(["validate"]) == 0
    printed = capsys.readouterr().out
    assert "band" in printed.splitlines()[0]
    for low, high in zip(table["low"], table["high"], strict=True):
        assert f"{low:.4g}-{high:.4g}" in printed


def test_the_strokes_said_validated_are_those_whose_rows_agree(table):
    """Issue 44: the stroke table and the page say which strokes lie outside what validate
    supports (:func:`studies.strokes.stroke.spin_note`): a preset is said validated when
    every one of its rows agrees, and only then."""
    from racket import STROKES
    from studies.strokes.stroke import VALIDATED, spin_note

    agreeing = set()
    for name in STROKES:
        rows = [r for r in table.index if r == f"stroke-{name}" or r.startswith(f"stroke-{name}-")]
        if rows and table.loc[rows, "agrees"].all():
            agreeing.add(name)
    assert agreeing == set(VALIDATED)
    assert spin_note({name: STROKES[name] for name in VALIDATED}) == ""
    listed = spin_note(STROKES).split(":")[0]  # the strokes named outside
    assert "kick-serve" in listed and "topspin-forehand" not in listed
