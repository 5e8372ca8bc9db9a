"""The page's string choice (issue 35): a select of the string presets and one hybrid (the
racket's own by default) and a "played" box, for both rackets.  Each choice strings the
page's racket as the API strings it (:func:`racket.strings.stringing.stringing`,
:meth:`racket.strings.stringing.Stringing.bed`), the page's numbers for a non-default string are the
API's, played strings are softer than fresh by their material's tension loss, a choice the
page does not offer is one line, and every output names the string it was computed for.
No browser: the page's own functions, called as its server calls them.
"""

import re
from dataclasses import replace
from types import SimpleNamespace

import pytest

from common.units import LB, MPH
from racket import CATALOG, DEFAULT_RACKET, MATERIALS, STRINGS, default_ball, from_specs, impact
from racket.specs.strung import STRUNG
from racket.strings.material import material_key
from racket.strings.stringing import HYBRID, stringing
from studies.conditions import racket_details
from studies.face.maps import face_map
from studies.page.app import app_ui
from studies.page.cards import headline_cards
from studies.page.conditions import page_conditions
from studies.page.dashboard import CONTROL_LABELS, MY_SHEET, PageInputs, page_racket, page_results
from studies.page.inputs import LABELS, page_inputs
from studies.page.strings import OWN_STRINGS, PAGE_STRINGS, strung
from studies.serve import serve_table
from studies.sweeps import BALL_SPEED, sweep

SAME = 1e-8
"""How closely the page's numbers for a non-default string and the API's agree [-] (the
brief's 1e-8; an impact's result may differ in its 11th digit with what ran before)."""

CHOSEN = PageInputs(string=HYBRID, played=True, tension_lb=60.0)
"""A page far from its defaults: the hybrid, played, at 60 lb."""

SENT = {
    "racket": DEFAULT_RACKET, "racket_b": "pro-staff-97l-cv", "lead_g": 0,
    "lead_at": "3 and 9", "swing": 70, "ball_speed": 36.9084, "tension": 55,
    "string": OWN_STRINGS, "played": False, "ball": "itf-type-2", "at_wrist": True,
}  # fmt: skip
"""The page's controls as a browser sends them (the spec sheet's unused)."""

SHEET = dict(mass_kg=0.3, balance_cm=33.0, swingweight_kgcm2=315.0, head_size_in2=100.0,
             f1_hz=150.0)  # fmt: skip
""":class:`PageInputs`' spec sheet as :func:`racket.specs.from_specs` takes it."""


def _api_racket(string: str, played: bool, tension_lb: float, name: str = DEFAULT_RACKET):
    """The catalogue racket ``name`` strung as the API strings it: its bed replaced by
    ``Stringing.bed`` of the chosen string in its own pattern (its own stringing at the new
    tension and state for :data:`OWN_STRINGS`).
    """
    racket = CATALOG[name].racket()
    bed, state = racket.strings, "played" if played else "fresh"
    own = bed.stringing
    if string == OWN_STRINGS:
        chosen = replace(own, tension=tension_lb * LB, state=state)
    else:
        chosen = stringing(string, pattern=own.pattern, tension_n=tension_lb * LB, state=state)
    return replace(racket, strings=chosen.bed(bed.extent, bed.width, bed.profile))


@pytest.fixture(scope="module")
def chosen():
    return page_results(CHOSEN)


def test_the_page_offers_every_preset_and_a_hybrid_from_the_racket_s_own():
    assert set(STRINGS) < set(PAGE_STRINGS) and HYBRID in PAGE_STRINGS
    assert (PageInputs().string, PageInputs().played) == (OWN_STRINGS, False)
    html = str(app_ui)
    select = re.search(r'<select[^>]*id="string">.*?</select>', html, re.S)[0]
    assert tuple(re.findall(r'<option value="([^"]+)"', select)) == PAGE_STRINGS
    assert re.search(r'<option value="([^"]+)" selected', select)[1] == OWN_STRINGS
    box = re.search(r'<input[^>]*id="played"[^>]*>', html)[0]
    assert 'type="checkbox"' in box and "checked" not in box
    assert page_inputs(SENT) == PageInputs(ball_speed_mph=36.9084)


@pytest.mark.parametrize("played", [False, True])
@pytest.mark.parametrize("string", PAGE_STRINGS)
def test_each_choice_strings_the_racket_as_the_api_does(string, played):
    bed = page_racket(PageInputs(string=string, played=played, tension_lb=60.0)).strings
    api = _api_racket(string, played, 60.0).strings
    assert bed.stringing == api.stringing
    for number in ("stiffness", "stretch", "loss"):
        assert getattr(bed, number) == pytest.approx(getattr(api, number), rel=1e-12), number
    assert (bed.extent, bed.width, bed.profile) == (api.extent, api.width, api.profile)
    first = STRUNG["string"] if string == OWN_STRINGS else string.split("/")[0]
    assert bed.stringing.mains.material == MATERIALS[material_key(first)]
    assert bed.stringing.pattern == CATALOG[DEFAULT_RACKET].racket().strings.stringing.pattern


def test_a_string_other_than_the_racket_s_own_changes_its_bed():
    own = page_racket(PageInputs()).strings
    for string in PAGE_STRINGS[1:]:
        bed = page_racket(PageInputs(string=string)).strings
        same = (bed.stringing.mains, bed.stringing.crosses) == (
            own.stringing.mains, own.stringing.crosses)  # fmt: skip
        assert ((bed.loss, bed.stretch) == (own.loss, own.stretch)) == same, string


def test_a_chosen_string_is_strung_in_the_racket_s_own_pattern(monkeypatch):
    entry = CATALOG[DEFAULT_RACKET]
    monkeypatch.setitem(CATALOG, "wide", replace(entry, strung=STRUNG | {"pattern": (18, 20)}))
    for string in PAGE_STRINGS:
        racket = from_specs(**entry.specs, **strung("wide", string, False))
        assert racket.strings.stringing.pattern == (18, 20), string


@pytest.mark.parametrize("string", [OWN_STRINGS, "nylon", HYBRID])
def test_a_spec_sheet_is_strung_as_the_api_strings_it(string):
    racket = page_racket(PageInputs(racket=MY_SHEET, string=string, played=True))
    words = STRUNG if string == OWN_STRINGS else dict(string=string, pattern=STRUNG["pattern"])
    api = from_specs(**SHEET, tension_lb=55.0, **words, state="played")
    assert racket.strings == api.strings
    assert racket.beam.mass == api.beam.mass


def test_a_non_default_string_on_the_page_gives_the_api_s_numbers(chosen):
    racket, ball = _api_racket(HYBRID, True, 60.0), default_ball()
    assert chosen.a.racket.strings == racket.strings
    head = CHOSEN.swing_mph * MPH
    served = serve_table(racket, ball, None, head, zero_cor=False)["serve_simulated_mph"]
    assert chosen.a.summary["serve_mph"] == pytest.approx(float(served.iloc[0]), rel=SAME)
    row = chosen.a.along.iloc[20]
    still = sweep(racket, ball, [float(row["position_from_tip_m"])], BALL_SPEED, progress=False)
    assert row["e_A"] == pytest.approx(float(still["e_A"].iloc[0]), rel=SAME)
    face = face_map(racket, ball, BALL_SPEED)
    assert chosen.a.face.e_A[7, 4] == pytest.approx(face.e_A[7, 4], rel=SAME)
    assert chosen.a.summary["e_A_centre"] == pytest.approx(face.e_A_centre, rel=SAME)
    own = page_results(PageInputs(tension_lb=60.0), points=5)  # the choice changes them
    assert chosen.a.summary["e_A_centre"] != pytest.approx(own.a.summary["e_A_centre"], rel=1e-3)


@pytest.mark.parametrize("string", PAGE_STRINGS)
def test_played_strings_are_softer_than_fresh_by_their_tension_loss(string):
    fresh = page_racket(PageInputs(string=string))
    played = page_racket(PageInputs(string=string, played=True))
    worn = played.strings.stringing
    kept = 1 - (worn.mains.material.tension_loss + worn.crosses.material.tension_loss) / 2
    # the membrane's stiffness is proportional to the tension: k = C T / ln(R / a)
    ratio = played.strings.stiffness / fresh.strings.stiffness
    assert ratio == pytest.approx(kept, rel=1e-12) and ratio < 1
    ball, centre = default_ball(), fresh.strings.center
    dwell = [impact(r, ball, centre, BALL_SPEED).contact_time for r in (fresh, played)]
    assert dwell[1] > dwell[0]  # a softer bed holds the ball longer


@pytest.mark.parametrize(
    ("sent", "said"),
    [
        ({"string": "silk"}, f"{LABELS['string']} must be one of ["),
        ({"string": "natural gut"}, f"{LABELS['string']} must be one of ["),
        ({"played": "yes"}, f"{LABELS['played']} must be true or false, got 'yes'"),
        ({"played": None}, f"the page sent no value for {LABELS['played']}"),
    ],
)
def test_a_string_the_page_does_not_offer_is_one_line(sent, said):
    with pytest.raises(ValueError) as refused:
        page_inputs({**SENT, **sent})
    assert str(refused.value).startswith(said) and "\n" not in str(refused.value)


@pytest.mark.parametrize(
    ("given", "said"),
    [
        (dict(string="silk"), f"{CONTROL_LABELS['string']} must be one of "),
        (dict(played="yes"), f"{CONTROL_LABELS['played']} must be True or False"),
    ],
)
def test_the_page_s_computation_refuses_them_too(given, said):
    for call in (page_results, page_racket):
        with pytest.raises(ValueError) as refused:
            call(PageInputs(**given))
        assert str(refused.value).startswith(said) and "\n" not in str(refused.value)


def test_every_output_names_the_string_it_was_computed_for(chosen):
    said = {side: racket_details(_api_racket(HYBRID, True, 60.0, name))["strings"]
            for side, name in (("A", CHOSEN.racket), ("B", CHOSEN.racket_b))}  # fmt: skip
    described = _api_racket(HYBRID, True, 60.0).strings.stringing.describe()
    assert described == "natural gut 1.30 mm/polyester 1.25 mm 16x19 at 60 lb, played"
    assert said["A"].startswith(described)  # as the command line says it
    for output, line in chosen.conditions.items():
        for side in {"face_a": "A", "face_b": "B"}.get(output, "AB"):
            assert said[side] in line, (output, side)
    html = str(headline_cards(chosen, CHOSEN.swing_mph))
    for card in re.findall(r'id="card_\w+_conditions">([^<]*)<', html):
        assert said["A"] in card and said["B"] in card


def test_rackets_strung_apart_are_named_apart():
    a = page_racket(PageInputs())
    bed = a.strings
    wider = replace(bed.stringing, pattern=(18, 20)).bed(bed.extent, bed.width, bed.profile)
    b = replace(a, strings=wider)
    held = {"feel_support": "hand-held", "feel_grip": None}
    sides = [SimpleNamespace(racket=r, summary=held) for r in (a, b)]
    lines = page_conditions(PageInputs(), *sides)
    said = [racket_details(r)["strings"] for r in (a, b)]
    assert "16x19" in said[0] and "18x20" in said[1]
    assert f"(free, A {said[0]}; B {said[1]})" in lines["serve"]
    assert f"(free, {said[0]})" in lines["face_a"] and f"(free, {said[1]})" in lines["face_b"]
    alike = page_conditions(PageInputs(), sides[0], sides[0])  # one string said once
    assert f"(free, {said[0]})" in alike["serve"]
