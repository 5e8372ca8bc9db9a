"""The interactive page tells the command line's truth (issue 33, "One truth"): it starts at
the one default (racket, ball, ball speed), its serve, a point along the racket and a point
of its face map are the Python API's numbers for the same racket, ball, speed and point (the
functions the guides show and the commands call), its head speeds stop where players stop,
every card and plot says what it was computed for, positions are from the tip, and an
impossible spec sheet for B is one line in B's place, A left whole.  No browser: the page's
own functions, called as its server calls them.
"""

import re
from dataclasses import replace

import matplotlib
import numpy as np
import pandas as pd
import pytest

from ball import BALL_PRESETS, DEFAULT_BALL
from ball.catalog import TWU_SPEED
from common.checks import FASTEST_STROKE, shown
from common.units import MPH
from racket import CATALOG, DEFAULT_RACKET, STROKES, Swing, default_ball, default_racket
from racket.strings.sideways import sideways
from studies.cli import main
from studies.conditions import racket_details
from studies.config import BALLS
from studies.face.maps import face_map
from studies.page.app import app_ui
from studies.page.cards import headline_cards, spots_table
from studies.page.dashboard import (
    HEAD_SPEED_MAX_MPH,
    HEAD_SPEEDS_MPH,
    MY_SHEET,
    PageInputs,
    feel_summary,
    page_results,
    said_on_page,
)
from studies.page.strokes import GROUNDSTROKE_RATIO
from studies.serve import serve, serve_table
from studies.strokes.stroke import bed_words, stroke_table
from studies.sweeps import BALL_SPEED, sweep

matplotlib.use("Agg")

ROUND_OFF = 1e-9
"""How closely the page's numbers and the API's agree [-]: to round-off (an impact's result
may differ in its 11th digit with what the process ran before: 1.6e-11 measured on the serve
after a batch of impacts)."""
SPIN_ROUND_OFF = 1e-8
"""How closely the page's strokes with spin and the API's agree [-]: the grip on the strings
amplifies the impact's round-off (6e-9 measured on the forehand's spin after a batch of
impacts; ``racket-impact stroke`` against the Python API: 1e-8, tests/test_one_truth.py)."""
CARDS = (
    "card_serve", "card_groundstroke", "card_power", "card_sweet", "card_feel", "card_racket"
)  # fmt: skip
SPIN_CARDS = {
    "card_serve": [
        ("flat_serve_mph", "flat-serve", "exit_speed_mph", 1),
        ("flat_serve_spin_rpm", "flat-serve", "spin_rpm", 0),
        ("kick_serve_mph", "kick-serve", "exit_speed_mph", 1),
        ("kick_serve_spin_rpm", "kick-serve", "spin_rpm", 0),
    ],
    "card_groundstroke": [
        ("forehand_mph", "topspin-forehand", "exit_speed_mph", 1),
        ("forehand_spin_rpm", "topspin-forehand", "spin_rpm", 0),
        ("forehand_launch_deg", "topspin-forehand", "launch_deg", 1),
    ],
}
"""The cards with spin, column by column: the racket's summary key, the stroke and its column
in ``racket-impact stroke``'s table, and the digits the card shows."""


@pytest.fixture(scope="module")
def page():
    return page_results(PageInputs())


def _slider(html: str, name: str) -> dict:
    tag = re.search(rf'<input class="js-range-slider" id="{name}"[^>]*>', html)[0]
    return {k: float(v) for k, v in re.findall(r'data-(min|max|from|step)="([^"]+)"', tag)}


def _selected(html: str, name: str) -> str:
    select = re.search(rf'<select[^>]*id="{name}">.*?</select>', html, re.S)[0]
    return re.search(r'<option value="([^"]+)" selected', select)[1]


def test_the_page_starts_at_the_one_default():
    start = PageInputs()
    assert (start.racket, start.ball) == (DEFAULT_RACKET, DEFAULT_BALL)
    assert start.ball_speed_mph * MPH == pytest.approx(BALL_SPEED, rel=1e-15)
    assert BALL_SPEED == TWU_SPEED == 16.5
    assert start.tension_lb == CATALOG[DEFAULT_RACKET].specs["tension_lb"]
    assert start.pivot_cm_from_tip is None  # the wrist, as `racket-impact serve`
    html = str(app_ui)
    assert _selected(html, "racket") == DEFAULT_RACKET
    assert _selected(html, "ball") == DEFAULT_BALL
    assert _slider(html, "ball_speed")["from"] == pytest.approx(BALL_SPEED / MPH, rel=ROUND_OFF)
    assert _slider(html, "swing")["from"] == start.swing_mph
    assert _slider(html, "tension")["from"] == start.tension_lb


def test_one_serve_is_the_api_s(page):
    # racket-impact serve --racket pure-drive-2021 --racket-speed-mph 70, in Python
    racket, ball = default_racket(), default_ball()
    head = PageInputs().swing_mph * MPH
    table = serve_table(racket, ball, None, head, zero_cor=False)
    same = pytest.approx(float(table["serve_simulated_mph"].iloc[0]), rel=ROUND_OFF)
    assert page.a.summary["serve_mph"] == same
    tipward = serve_table(racket, ball, racket.strings.center - 0.05, head, zero_cor=False)
    same = pytest.approx(float(tipward["serve_simulated_mph"].iloc[0]), rel=ROUND_OFF)
    assert page.a.summary["serve_tipward_mph"] == same


def _stroke_cli(capsys, tmp_path, *args) -> pd.DataFrame:
    """``racket-impact stroke ARGS --out FILE``'s table, by stroke."""

    out = tmp_path / f"stroke{len(list(tmp_path.iterdir()))}.json"
    assert main(["stroke", *args, "--out", str(out)]) == 0
    capsys.readouterr()
    return pd.read_json(out).set_index("stroke")


def test_the_strokes_with_spin_are_racket_impact_stroke_s(page, tmp_path, capsys):
    # racket-impact stroke flat-serve kick-serve --head-speed-mph 70 (the page's head speed),
    # and racket-impact stroke topspin-forehand at the page's head speed times the presets'
    # ratio (it follows the slider, issue 44)
    serves = _stroke_cli(capsys, tmp_path, "flat-serve", "kick-serve", "--head-speed-mph", "70")
    ground_mph = GROUNDSTROKE_RATIO * PageInputs().swing_mph
    forehand = _stroke_cli(capsys, tmp_path, "topspin-forehand", "--head-speed-mph",
                           repr(ground_mph))  # fmt: skip
    cli = pd.concat([serves, forehand])
    summary = page.a.summary
    for name, key in (("flat-serve", "flat_serve"), ("kick-serve", "kick_serve"),
                      ("topspin-forehand", "forehand")):  # fmt: skip
        row = cli.loc[name]
        assert summary[f"{key}_mph"] == pytest.approx(row["exit_speed_mph"], rel=1e-8)
        assert summary[f"{key}_spin_rpm"] == pytest.approx(row["spin_rpm"], rel=1e-8)
        assert summary[f"{key}_launch_deg"] == pytest.approx(row["launch_deg"], rel=1e-8)
    assert cli.loc["topspin-forehand", "head_speed_m_s"] == pytest.approx(ground_mph * MPH)
    # the same in Python for each racket, the serves at the page's head speed
    head = PageInputs().swing_mph * MPH
    strokes = {
        "flat-serve": replace(STROKES["flat-serve"], head_speed=head),
        "kick-serve": replace(STROKES["kick-serve"], head_speed=head),
        "topspin-forehand": replace(STROKES["topspin-forehand"],
                                    head_speed=GROUNDSTROKE_RATIO * head),
    }  # fmt: skip
    html = str(headline_cards(page, PageInputs().swing_mph))
    for side, racket in (("a", default_racket()), ("b", CATALOG["pro-staff-97l-cv"].racket())):
        api = stroke_table(strokes, racket, default_ball(), unit="mph").set_index("stroke")
        one = getattr(page, side).summary
        for card, columns in SPIN_CARDS.items():
            for k, (key, name, column, digits) in enumerate(columns):
                # the spin amplifies the impact's round-off
                assert one[key] == pytest.approx(api.loc[name, column], rel=SPIN_ROUND_OFF)
                shown = re.search(rf'id="{card}_{side}_{k}"[^>]*>([^<]*)<', html)[1]
                assert shown == f"{one[key]:.{digits}f}", (card, k)
    assert summary["flat_serve_mph"] > summary["kick_serve_mph"]  # as measured (issue 36)
    assert summary["flat_serve_spin_rpm"] < summary["kick_serve_spin_rpm"]


def _card(html: str, card: str, row: str) -> list[str]:
    """The numbers of ``row`` ("a", "b") of ``card`` as the page shows them."""
    return re.findall(rf'id="{card}_{row}_\d+"[^>]*>([^<]*)<', html)


def test_the_serve_card_s_speed_and_spin_come_from_one_stroke(tmp_path, capsys):
    # each serve's speed beside its own spin, both racket-impact stroke's for the same racket,
    # ball and head speed (issue 45: the head-on serve's speed stood beside the flat's spin)
    chosen = PageInputs(racket_b="pure-drive-2025", swing_mph=85.0)
    r = page_results(chosen)
    html = str(headline_cards(r, chosen.swing_mph))
    card = html.split('id="card_serve"')[1].split("</thead>")[0]
    assert re.findall(r'<th class="unit text-end">\s*(.*?)<br/>', card) == [
        "flat-serve", "its spin", "kick-serve", "its spin"
    ]  # fmt: skip
    assert "flat-serve and the kick-serve at 85 mph head speed" in html
    for row, name in (("a", chosen.racket), ("b", chosen.racket_b)):
        cli = _stroke_cli(capsys, tmp_path, "flat-serve", "kick-serve", "--racket", name,
                          "--head-speed-mph", "85")  # fmt: skip
        flat, kick = cli.loc["flat-serve"], cli.loc["kick-serve"]
        assert _card(html, "card_serve", row) == [
            f"{flat['exit_speed_mph']:.1f}", f"{flat['spin_rpm']:.0f}",
            f"{kick['exit_speed_mph']:.1f}", f"{kick['spin_rpm']:.0f}",
        ]  # fmt: skip
        head_on = getattr(r, row).summary["serve_mph"]  # the serve plot's, not the card's
        assert f"{head_on:.1f}" not in _card(html, "card_serve", row)


def test_one_sweep_point_is_the_api_s(page):
    racket, ball = default_racket(), default_ball()
    row = page.a.along.iloc[20]
    x = float(row["position_from_tip_m"])
    assert row["position_from_tip_cm"] == pytest.approx(100 * x)  # from the tip
    still = sweep(racket, ball, [x], BALL_SPEED, progress=False)
    assert row["e_A"] == pytest.approx(float(still["e_A"].iloc[0]), rel=ROUND_OFF)
    assert row["e"] == pytest.approx(float(still["e"].iloc[0]), rel=ROUND_OFF)
    swung = sweep(racket, ball, [x], BALL_SPEED, swing=Swing(PageInputs().swing_mph * MPH),
                  progress=False)  # fmt: skip
    assert row["exit_speed_swung_mph"] * MPH == pytest.approx(
        float(swung["ball_rebound_m_s"].iloc[0]), rel=ROUND_OFF
    )


def test_one_face_map_point_is_the_api_s(page):
    face = face_map(default_racket(), default_ball(), BALL_SPEED)
    assert np.allclose(page.a.face.e_A, face.e_A, rtol=1e-12, atol=0)
    assert page.a.face.e_A[7, 4] == pytest.approx(face.e_A[7, 4], rel=ROUND_OFF)
    assert page.a.summary["e_A_centre"] == pytest.approx(face.e_A_centre, rel=ROUND_OFF)
    assert page.a.summary["sweet_area_cm2"] == pytest.approx(face.sweet_area_cm2, rel=ROUND_OFF)


def test_the_feel_card_is_the_feel_command_s(page):
    # feel_summary is what `racket-impact feel` reports (tests of the feel compare the two);
    # a peak of the handle's history: the impact's round-off grows to 2e-9 in it
    feel = feel_summary(default_racket(), default_ball(), BALL_SPEED)
    assert (feel["feel_support"], feel["feel_grip"]) == ("hand-held", "medium grip")
    for key, value in feel.items():
        assert page.a.summary[key] == (
            pytest.approx(value, rel=1e-6) if isinstance(value, float) else value
        )
    html = str(headline_cards(page, PageInputs().swing_mph))
    said = re.search(r'id="card_feel_conditions">([^<]*)<', html)[1]
    strung = racket_details(default_racket())["strings"]  # "polyester ... at 55 lb, ..."
    assert "(hand-held, medium grip, " in said and strung in said and " at 55 lb" in strung
    shock = re.search(r'id="card_feel_a_0"[^>]*>([^<]*)<', html)[1]
    assert float(shock) == round(feel["feel_shock_g"], 1)


def test_no_head_speed_on_the_page_serves_faster_than_anyone_has():
    html = str(app_ui)
    assert _slider(html, "swing")["max"] == HEAD_SPEED_MAX_MPH
    assert HEAD_SPEEDS_MPH[-1] == HEAD_SPEED_MAX_MPH  # the curve ends at the slider's end
    swing = Swing(HEAD_SPEED_MAX_MPH * MPH)
    tennis_balls = [*BALL_PRESETS, "paper"]
    served = [
        serve(entry.racket(), BALLS[ball](), entry.racket().strings.center, swing)
        for entry in CATALOG.values()
        for ball in tennis_balls
    ]
    fastest = max(s["serve_simulated_m_s"] for s in served)
    assert fastest <= FASTEST_STROKE
    assert fastest > 0.95 * FASTEST_STROKE  # and it reaches the fastest serves


def test_every_card_names_its_conditions(page):
    html = str(headline_cards(page, PageInputs().swing_mph))
    strung = [racket_details(r)["strings"] for r in (page.a.racket, page.b.racket)]
    assert strung[0] == racket_details(default_racket())["strings"]
    for card in CARDS:
        said = re.search(rf'id="{card}_conditions">([^<]*)<', html)[1]
        assert "racket A pure-drive-2021 and B pro-staff-97l-cv" in said
        assert all(s in said and " at 55 lb" in s for s in strung)  # each racket's strings
        if card != "card_racket":
            assert f"ball {DEFAULT_BALL}" in said
    said = page.conditions
    # the strokes with spin: each stroke's numbers, the ball, the bed as racket-impact stroke
    # says it (the same for both rackets here), and no pivot
    bed = bed_words(sideways(default_racket().strings))
    assert bed == bed_words(sideways(page.b.racket.strings))
    assert "mains and crosses sliding on dry crossings" in bed and "ball-string friction" in bed
    serves, ground = said["serve_spin"], said["groundstroke"]
    assert serves.startswith(said["racket"])  # no head-on serve's line: not this card's
    assert "the ball at rest" not in serves and "about the wrist" not in serves
    for part in ("flat-serve at 70 mph head speed (the page's), path 0°, face 7° closed",
                 "kick-serve at 70 mph head speed (the page's), path 5° up, 45° across to the "
                 "right, face 0°", f"ball {DEFAULT_BALL} tossed at 3.36 mph falling at 60°",
                 "at the string centre, the racket moving with it (no pivot)", bed):  # fmt: skip
        assert part in serves, part
    ground_mph = shown(round(GROUNDSTROKE_RATIO * PageInputs().swing_mph, 6))
    for part in (f"ball {DEFAULT_BALL} at 44.7 mph falling at 10°,",  # no spin (Landlinger's)
                 f"topspin-forehand at {ground_mph} mph head speed (the page's times 0.92, the "
                 "presets' ratio)", "path 18.6° up, face 0°", "(no pivot)", bed,
                 "spin not validated for flat-serve, kick-serve"):  # fmt: skip
        assert part in (serves if part.startswith("spin not") else ground), part
    for card, key in (("card_serve", "serve_spin"), ("card_groundstroke", "groundstroke")):
        assert said[key] in re.search(rf'id="{card}_conditions">([^<]*)<', html)[1]
    card = re.search(r'id="card_groundstroke".*?</div>', html, re.S)[0]
    assert f"{GROUNDSTROKE_RATIO * PageInputs().swing_mph:.0f} mph head speed" in card
    assert "at 36.91 mph" in said["power"] and "at 36.91 mph" in said["sweet"]
    assert "swung at 70 mph head speed" in said["serve"] and "about the wrist" in said["serve"]
    assert "(free" in said["serve"]
    for key in ("exit", "e_A", "spots", "face_a", "face_b"):
        assert f"ball {DEFAULT_BALL} at 36.91 mph" in said[key]


def test_the_page_plots_name_their_conditions_inside_the_figure(page):
    from studies.page.plots import plot_along_racket, plot_face_map_page, plot_serve_speeds

    said = page.conditions
    along = {"A": page.a.along, "B": page.b.along}
    axes = [
        plot_serve_speeds({"A": page.a.serves}, 70.0, conditions=said["serve"]),
        plot_along_racket(along, "e_A", "rebound ratio e_A [-]", conditions=said["e_A"]),
        plot_face_map_page(page.a.face, "A", conditions=said["face_a"]),
    ]
    for ax in axes:
        fig = ax.figure
        fig.set_size_inches(5.4, 3.9 if len(fig.axes) < 3 else 6.2)  # a card, as Shiny sizes it
        fig.set_layout_engine("tight")  # as Shiny lays it out
        fig.canvas.draw()
        renderer = fig.canvas.get_renderer()
        heading = fig._suptitle
        assert heading.get_text().replace("\n", " ") in said.values()
        box = heading.get_window_extent(renderer)
        assert 0 <= box.x0 and box.x1 <= fig.bbox.x1 and 0 <= box.y0 and box.y1 <= fig.bbox.y1
        assert box.y0 >= ax.get_window_extent(renderer).y1  # above the data


def test_where_to_hit_is_from_the_tip_and_its_headers_sit_over_their_columns(page):
    html = str(spots_table(page))
    heads = re.findall(r'<th class="(\w+)">([^<]*)</th>', html)
    assert [text for _, text in heads] == ["spot", "A: pure-drive-2021", "B: pro-staff-97l-cv"]
    for row in re.findall(r"<tr>(.*?)</tr>", html, re.S)[1:]:
        cells = re.findall(r'<td class="(\w+)">', row)
        assert cells == [kind for kind, _ in heads]  # each aligned as its header
    spots = page.a.spots.set_index("spot")["from_tip_cm"]
    shown = re.search(r"<td class=\"words\">largest e_A</td>\s*<td class=\"number\">([\d.]+)<",
                      html)[1]  # fmt: skip
    assert float(shown) == round(spots["largest e_A"], 1)
    assert 0 < spots["largest e_A"] < 100 * page.a.racket.strings.extent[1]


@pytest.mark.parametrize(
    ("typed", "label"),
    [
        ({"swingweight_kgcm2": 370.0}, "Swingweight [kg cm²] must be in ("),
        ({"mass_g": 600.0}, "Strung mass [g] must be in [150, 500] g, got 600"),
        ({"balance_cm": 60.0}, "Balance [cm from the butt] must be in [20, 50]"),
        ({"ra": 95.0, "f1_hz": None}, "RA must be in [40, 90], got 95"),
    ],
)
def test_an_impossible_spec_sheet_for_b_is_one_line_in_b_s_place(page, typed, label):
    r = page_results(PageInputs(racket_b=MY_SHEET, **typed))
    assert r.b is None and list(r.errors) == ["B"]
    line = r.errors["B"]
    assert line.startswith(f"Racket B ({MY_SHEET}): {label}") and "\n" not in line
    assert not re.search(r"\w_\w|racket\.specs", line)  # no Python identifier
    assert r.a.summary == page.a.summary  # A whole
    html = str(headline_cards(r, 70.0))
    assert 'id="error_b"' in html and "card_serve_a_0" in html and "card_serve_b_0" not in html
    assert "B − A" not in html
    assert "A: pure-drive-2021" in str(spots_table(r)) and "B:" not in str(spots_table(r))
    assert "B pro-staff" not in r.conditions["serve"] and "face_b" not in r.conditions


def test_the_fit_s_refusals_in_the_page_s_words():
    said = said_on_page(
        "swingweight_kgcm2 must be in (257, 333) kg cm^2 for a 300 g racket balanced at 33 cm "
        "with a 100 in^2 head with every part in its plausible range "
        "(racket.specs.parts.PARTS), got 370"
    )
    assert said == (
        "Swingweight [kg cm²] must be in (257, 333) kg cm² for a 300 g racket balanced at 33 "
        "cm with a 100 in² head with every part in its plausible range, got 370"
    )
    assert said_on_page("head size 150 in^2 is too large").startswith("Head size [in²] 150 in²")
