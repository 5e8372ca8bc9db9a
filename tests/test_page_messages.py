"""The page survives any message (issue 34): malformed, early, empty, huge or of the wrong
type, each ends in an error card in the page (an output whose value is the card), never a
traceback on the server's stderr or a page left waiting; a fresh session afterwards gets its
numbers.  The page's server runs in a subprocess on 127.0.0.1; the tests speak Shiny's
websocket protocol to it directly (the client's first message ``{"method": "init", "data":
{...}}``, then ``{"method": "update", "data": {...}}``; shiny/session/_session.py).  What the
checks say is tested without a server too."""

import html
import json
import re
import socket
import subprocess
import sys
import time

import pytest

from studies.cli.racket_options import LEAD_GRAMS
from studies.page.dashboard import LEAD_MAX_G, MY_SHEET, PageInputs, page_racket, page_results
from studies.page.guard import ERROR_OUTPUT, MESSAGE_MAX_CHARS, refusal
from studies.page.inputs import LABELS, LEAD_CLOCKS, page_inputs

pytest.importorskip("shiny")
from websockets.sync.client import connect  # shiny's own dependency

SENT = {
    "racket": "pure-drive-2021", "racket_b": "pro-staff-97l-cv", "mass_g": 300,
    "balance_cm": 33, "swingweight": 315, "head": 100, "stiffness": "f1", "f1": 150, "ra": 66,
    "lead_g": 0, "lead_at": "3 and 9", "swing": 70, "ball_speed": 36.9084, "tension": 55,
    "string": "own", "played": False, "ball": "itf-type-2", "at_wrist": True, "pivot": 74,
}  # fmt: skip
"""The page's controls as a browser sends them at the start (the numeric inputs typed)."""

NUMERIC = ("mass_g", "balance_cm", "swingweight", "head", "f1", "ra")
"""The page's numeric inputs (the browser sends them as "id:shiny.number")."""

OUTPUTS = ("status", "cards", "notes", "serve_plot", "exit_plot", "power_plot", "face_a",
           "face_b", "face_a_error", "face_b_error", "spots")  # fmt: skip
WRONG = ({"a": 1}, [1, 2], "70", None, float("nan"), 1e308, True)
"""Values of the wrong type (or size) for a control: an object, a list, a string, null, NaN,
1e308, a bool."""

FIRST_NUMBERS_S = 180.0  # the first session may compile the solver (once per machine)
ANSWER_S = 60.0  # any later answer


def _message(controls: dict, method: str = "init", seen: bool = True) -> str:
    """A message carrying ``controls`` as the browser names them; ``seen``: with the client
    data that says every output is in sight (as a browser's first message does).
    """
    data = {f"{k}:shiny.number" if k in NUMERIC else k: v for k, v in controls.items()}
    if seen:
        data |= {f".clientdata_output_{o}_hidden": False for o in OUTPUTS}
        data |= {".clientdata_pixelratio": 1, ".clientdata_url_search": ""}
    return json.dumps({"method": method, "data": data})


def test_each_wrong_type_is_named_as_the_page_labels_it():
    assert page_inputs(SENT) == PageInputs(ball_speed_mph=36.9084)
    sheet = {**SENT, "racket": MY_SHEET, "at_wrist": False}
    for name in LABELS:
        for value in WRONG:
            if value is None or value == 1e308 or _fine(name, value):
                continue  # null: "sent no value" when used; a number: its range checked later
            with pytest.raises(ValueError, match=f"^{re.escape(LABELS[name])}"):
                page_inputs({**sheet, name: value})
    with pytest.raises(ValueError, match=r"no value for .*Strung mass \[g\]"):
        page_inputs({**sheet, "mass_g": None})
    assert page_inputs({**SENT, "mass_g": None}).mass_g == PageInputs.mass_g  # unused
    with pytest.raises(ValueError, match=r"no value for Racket A, Racket B, .*Ball, Pivot"):
        page_inputs({})
    with pytest.raises(ValueError) as huge:
        page_inputs({**SENT, "racket": "x" * 500_000})
    assert len(str(huge.value)) < 500 and "500002 characters" in str(huge.value)


def test_a_number_out_of_range_is_one_line_naming_the_control():
    for name, field in (("tension", "tension_lb"), ("lead_g", "lead_g"),
                        ("ball_speed", "ball_speed_mph")):  # fmt: skip
        with pytest.raises(ValueError, match=f"^{LABELS[name]} must be in".replace("[", r"\[")):
            page_results(PageInputs(**{field: 1e308}), points=5)
    assert LEAD_MAX_G == LEAD_GRAMS[1]  # the page takes what the command line takes
    # a head speed beyond a stroke's (60 m/s, 134 mph; the slider stops at 114): each racket
    # one line naming the control, not the Stroke's head_speed in m/s
    for swing_mph in (200.0, 1e308):
        errors = page_results(PageInputs(swing_mph=swing_mph), points=5).errors
        assert list(errors) == ["A", "B"]
        for side, line in errors.items():
            assert re.match(rf"Racket {side} \([^)]+\): {re.escape(LABELS['swing'])} must be in "
                            r"\[[^]]+, 134.2\] mph, got ", line), line  # fmt: skip
            assert "head_speed" not in line and "m/s" not in line and "\n" not in line


def test_every_lead_position_offered_is_accepted():
    for clock in LEAD_CLOCKS:
        untaped, taped = page_racket(PageInputs()), page_racket(PageInputs(lead_g=5, lead_at=clock))
        pieces = 2 if " and " in clock else 1  # "3 and 9": a piece on each side
        assert taped.beam.mass == pytest.approx(untaped.beam.mass + pieces * 0.005), clock


@pytest.mark.parametrize(
    ("text", "said"),
    [
        (None, "binary"),
        ("", "not JSON"),
        ("{nope", "not JSON"),
        ("[" * 100_000, "not JSON"),
        ("[1]", "without a method"),
        ("{}", "without a method"),
        ('{"method": 1}', "without a method"),
        ('{"method": "nope"}', "unknown method"),
        ('{"method": "update", "data": {}}', "update before the first"),
        ('{"method": "x", "tag": 1, "args": []}', "before the first"),
        ('{"method": "init"}', "data is not an object"),
        ('{"method": "init", "data": [1]}', "data is not an object"),
        ('{"method": "init", "data": {"a:b:c": 1}}', "more than one ':'"),
        ('{"method": "init", "data": {"a:shiny.date": {}}}', "type the page's controls"),
        ('{"method": "init", "data": {".clientdata_url_search": {}}}', "must be a string"),
        ('{"method": "init", "data": {".clientdata_pixelratio": 1e308}}', "(0, 8]"),
        ('{"method": "init", "data": {".clientdata_output_face_a_width": []}}', "px in"),
        ('{"method": "init", "data": {".clientdata_output_cards_hidden": 3}}', "true or false"),
        ("x" * (MESSAGE_MAX_CHARS + 1), "characters"),
    ],
)
def test_a_message_shiny_cannot_take_is_turned_away(text, said):
    assert said in refusal(text, started=False)
    assert refusal(_message(SENT), started=False) is None
    assert refusal(_message(SENT), started=True) == "a second first message"
    assert refusal(_message({"swing": 80}, "update"), started=True) is None


@pytest.fixture(scope="module")
def page(tmp_path_factory):
    """The page's server (``racket-impact app``) on a free port: its websocket's address
    and the file its stderr goes to."""
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    errors = tmp_path_factory.mktemp("page") / "stderr.txt"
    with errors.open("w") as err:
        server = subprocess.Popen(
            [sys.executable, "-m", "studies.cli", "app", "--port", str(port)],
            stdout=subprocess.PIPE, stderr=err, text=True,
        )  # fmt: skip
    line = server.stdout.readline()
    if f"127.0.0.1:{port}" not in line:
        server.kill()
        pytest.fail(f"the page did not come up: {line} {errors.read_text()[-2000:]}")
    url = f"ws://127.0.0.1:{port}/websocket/"
    assert _answer(url, [_message(SENT)], "cards", FIRST_NUMBERS_S, first=_served)
    yield url, errors
    server.terminate()
    server.wait(timeout=30)


def _answer(url, frames, output: str, within: float, then=(), want=bool, first=bool) -> str:
    """The text (HTML unescaped) of ``output`` the page shows after ``frames`` are sent on a
    fresh session, waited for ``within`` seconds at most ("" if none came); ``then``: more
    frames sent once it came on the same session, and the first cards after those that
    satisfy ``want`` instead; ``first``: what the first answer must satisfy.
    """
    deadline = time.monotonic() + within
    with connect(url, open_timeout=10, max_size=2**24) as ws:
        said = _next(ws, frames, output, deadline, first)
        return _next(ws, then, "cards", deadline, want) if said and then else said


def _next(ws, frames, output: str, deadline: float, want) -> str:
    """The first value of ``output`` that satisfies ``want`` after ``frames`` are sent on
    the open session ``ws`` ("" if none came by ``deadline``)."""
    for frame in frames:
        ws.send(frame)
    for _ in range(10_000):  # bounded in count and, by the deadline, in time
        left = deadline - time.monotonic()
        if left <= 0:
            return ""
        try:
            got = json.loads(ws.recv(timeout=left))
        except TimeoutError:
            return ""
        values = got.get("values") or {}
        said = html.unescape((values.get(output) or {}).get("html", ""))
        if output in values and want(said):
            return said
    return ""


def _served(card: str) -> bool:
    """Whether ``card`` is the headline numbers."""
    return "card_serve" in card


def _fine(name: str, value) -> bool:
    """Whether ``value`` is one the page takes for the control ``name`` (of the page's
    controls with the spec sheet on A, the pivot not at the wrist, f1 chosen): RA unused
    and left empty or as a number, the wrist box or the played box ticked.
    """
    ticked = name in ("at_wrist", "played") and value is True
    return (name == "ra" and value in (None, 1e308)) or ticked


def _no_traceback(errors) -> None:
    said = errors.read_text()
    assert "Traceback" not in said, said[-3000:]


BAD_FRAMES = {
    "not JSON": "{nope",
    "empty": "",
    "no method": "{}",
    "an update before the first message": _message({"swing": 80}, "update"),
    "unknown method": '{"method": "hello", "data": {}}',
    "data a list": '{"method": "init", "data": [1, 2]}',
    "huge (3 MB)": json.dumps({"method": "init", "data": {"racket": "x" * 3_000_000}}),
    "a plot a billion px wide": _message({**SENT, ".clientdata_output_face_a_width": 1e9}),
    "binary": b"\x00\xff" * 10,
}


@pytest.mark.timeout(300)
@pytest.mark.parametrize("kind", list(BAD_FRAMES))
def test_a_message_turned_away_leaves_the_session_alive(page, kind):
    url, errors = page
    card = _answer(url, [BAD_FRAMES[kind]], ERROR_OUTPUT, ANSWER_S)
    assert "it was ignored" in card and "alert-danger" in card, f"{kind}: {card[:300]}"
    numbers = _answer(url, [BAD_FRAMES[kind]], ERROR_OUTPUT, ANSWER_S, [_message(SENT)], _served)
    assert numbers, f"{kind}: the session did not go on to the numbers"
    _no_traceback(errors)


@pytest.mark.timeout(300)
@pytest.mark.parametrize(
    ("kind", "frames", "said"),
    [
        ("an empty first message", [_message({}, seen=False)], "the page sent no value for"),
        ("no controls", [_message({})], "the page sent no value for Racket A"),
        ("a huge racket name", [_message({**SENT, "racket": "x" * 400_000})], "Racket A must"),
        ("an unknown ball", [_message({**SENT, "ball": "pumpkin"})], "Ball must be one of"),
    ],
)
def test_a_first_message_without_good_controls_ends_in_an_error_card(page, kind, frames, said):
    url, errors = page
    card = _answer(url, frames, "cards", ANSWER_S)
    assert said in card and "alert-danger" in card, f"{kind}: {card[:300]}"
    assert len(card) < 2000  # one line, a huge value cut
    _no_traceback(errors)


@pytest.mark.timeout(600)
@pytest.mark.parametrize("name", list(LABELS))
def test_a_control_of_the_wrong_type_ends_in_an_error_card(page, name):
    url, errors = page
    sheet = {**SENT, "racket": MY_SHEET, "at_wrist": False}  # every control used
    for value in WRONG:
        card = _answer(url, [_message({**sheet, name: value})], "cards", ANSWER_S)
        assert card, f"{name} = {value!r}: no answer in {ANSWER_S} s"
        if not _fine(name, value):
            assert "alert-danger" in card and LABELS[name] in card, f"{name}={value!r}: {card}"
    # and later in a session, an update of the wrong type
    update = [_message({name: {"a": 1}}, "update", seen=False)]
    card = _answer(url, [_message(sheet)], "cards", ANSWER_S, update, lambda c: not _served(c))
    assert LABELS[name] in card, f"an update of {name}: {card[:300]}"
    _no_traceback(errors)
    assert _answer(url, [_message(SENT)], "cards", ANSWER_S, want=_served)  # still serving
