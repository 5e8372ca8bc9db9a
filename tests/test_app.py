"""The interactive page in a real browser: headless Chromium (Debian's package) driven by
Playwright loads the page served by ``racket-impact app``, checks that no card's content
overflows it and that the serve speed is in sight, chooses racket B and sees the difference
B - A of the numbers shown, "Recalculating" in place of "Ready." until all is drawn, and a
new head speed drawing again only the plots it changes, with no request leaving the machine
(issues 14, 28 and 45).  What the page computes and draws is tested without a browser too
(one colour scale for both face maps, no axis label clipped), and the port is bound before
the page's address is announced."""

import importlib.util
import os
import pickle
import re
import shutil
import socket
import subprocess
import sys
import urllib.request
from dataclasses import replace
from pathlib import Path

import matplotlib
import numpy as np
import pytest

from common.checks import shown
from common.units import MPH
from racket import STROKES, default_ball
from racket.swing import EFFORT_EXPONENT
from studies.page.dashboard import (
    COMPARED,
    HEAD_SPEED_MAX_MPH,
    HEAD_SPEEDS_MPH,
    MY_SHEET,
    PageInputs,
    page_results,
)
from studies.page.plots import PLOTS, page_plots
from studies.page.strokes import GROUNDSTROKE_RATIO
from studies.strokes.stroke import stroke_table

matplotlib.use("Agg")


def _hook():
    """The docs' page-picture hook (docs/hooks/page_picture.py): its Chromium flags, one list
    for the build and this test."""
    path = Path(__file__).resolve().parent.parent / "docs" / "hooks" / "page_picture.py"
    spec = importlib.util.spec_from_file_location("docs_hook_page_picture", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser")
CHROMIUM_FLAGS = list(_hook().CHROMIUM_FLAGS)
CARDS = (
    "card_serve", "card_groundstroke", "card_power", "card_sweet", "card_feel", "card_racket"
)  # fmt: skip


def test_page_results_follow_the_controls():
    base = page_results(PageInputs())
    taped = page_results(PageInputs(lead_g=6.0, lead_at="3 and 9"))
    a, b = base.a.summary, base.b.summary
    assert taped.a.summary["twistweight_kgcm2"] > a["twistweight_kgcm2"]
    assert taped.a.summary["e_A_3_oclock"] > a["e_A_3_oclock"]
    assert taped.b.summary == b  # the tape is on A only
    assert a["serve_tipward_mph"] > a["serve_mph"]
    # lead tape: the swing at equal effort is slower by the swingweight law (issue 25)
    assert "effort_head_taped_mph" not in a
    heavier = page_results(PageInputs(lead_g=5.0, lead_at="12")).a.summary
    ratio = heavier["effort_head_taped_mph"] / heavier["effort_head_untaped_mph"]
    assert ratio == pytest.approx(
        (a["swingweight_kgcm2"] / heavier["swingweight_kgcm2"]) ** EFFORT_EXPONENT, rel=1e-9
    )
    assert heavier["effort_exit_taped_mph"] > 0 and heavier["effort_exit_untaped_mph"] > 0
    mine = page_results(PageInputs(racket=MY_SHEET, mass_g=310, swingweight_kgcm2=320))
    assert mine.a.summary["mass_g"] == pytest.approx(310.0)
    assert mine.a.summary["swingweight_kgcm2"] == pytest.approx(320.0)
    for which in ("racket", "racket_b"):
        with pytest.raises(ValueError, match=f"{which} must be one of"):
            page_results(PageInputs(**{which: "no such racket"}))
    with pytest.raises(
        ValueError, match=r"Incoming ball speed \[mph\] must be in \[.*\] mph, got 900"
    ):
        page_results(PageInputs(ball_speed_mph=900.0))


def test_two_rackets_and_their_difference():
    r = page_results(PageInputs(racket="pure-drive-2021", racket_b="pro-staff-97l-cv"))
    for key in COMPARED:
        assert r.difference[key] == pytest.approx(r.b.summary[key] - r.a.summary[key], abs=1e-12)
    assert r.a.summary["swingweight_kgcm2"] != pytest.approx(r.b.summary["swingweight_kgcm2"])
    same = page_results(PageInputs(racket_b="pure-drive-2021"))
    assert all(same.difference[k] == 0.0 for k in COMPARED)


def test_serve_speed_against_head_speed_covers_real_play():
    r = page_results(PageInputs(swing_mph=HEAD_SPEED_MAX_MPH))
    serves = r.a.serves
    assert serves["head_speed_mph"].max() == pytest.approx(HEAD_SPEED_MAX_MPH)
    assert list(serves["head_speed_mph"]) == pytest.approx(list(HEAD_SPEEDS_MPH))
    assert serves["serve_simulated_mph"].is_monotonic_increasing
    # the card's serve at the page's head speed is the curve's point there
    assert r.a.summary["serve_mph"] == pytest.approx(serves["serve_simulated_mph"].iloc[-1])
    # the flat and kick serves follow the head speed; the forehand stays the preset's
    head = HEAD_SPEED_MAX_MPH * MPH
    strokes = {
        name: replace(STROKES[name], head_speed=head) for name in ("flat-serve", "kick-serve")
    }
    api = stroke_table(strokes, r.a.racket, default_ball(), unit="mph").set_index("stroke")
    for key, name in (("flat_serve", "flat-serve"), ("kick_serve", "kick-serve")):
        assert r.a.summary[f"{key}_mph"] == pytest.approx(api.loc[name, "exit_speed_mph"], rel=1e-9)
        assert r.a.summary[f"{key}_spin_rpm"] == pytest.approx(api.loc[name, "spin_rpm"], rel=1e-9)
    slow = page_results(PageInputs()).a.summary
    assert r.a.summary["kick_serve_mph"] > slow["kick_serve_mph"]
    assert r.a.summary["kick_serve_spin_rpm"] > slow["kick_serve_spin_rpm"]
    # the forehand follows the head speed too, in the presets' ratio (issue 44)
    forehand = {"topspin-forehand": replace(STROKES["topspin-forehand"],
                                            head_speed=GROUNDSTROKE_RATIO * head)}  # fmt: skip
    api = stroke_table(forehand, r.a.racket, default_ball(), unit="mph").set_index("stroke")
    assert r.a.summary["forehand_mph"] == pytest.approx(
        api.loc["topspin-forehand", "exit_speed_mph"], rel=1e-9
    )
    assert r.a.summary["forehand_mph"] > slow["forehand_mph"]
    said = r.conditions
    assert f"flat-serve at {HEAD_SPEED_MAX_MPH:g} mph head speed" in said["serve_spin"]
    assert f"kick-serve at {HEAD_SPEED_MAX_MPH:g} mph head speed" in said["serve_spin"]
    ground = shown(round(GROUNDSTROKE_RATIO * HEAD_SPEED_MAX_MPH, 6))
    assert f"topspin-forehand at {ground} mph head speed" in said["groundstroke"]


def test_the_pivot_is_from_the_tip_or_the_wrist():
    wrist = page_results(PageInputs()).a.summary["serve_mph"]
    length_cm = 100 * page_results(PageInputs()).a.racket.beam.length
    same = page_results(PageInputs(pivot_cm_from_tip=length_cm + 5.0)).a.summary["serve_mph"]
    assert same == pytest.approx(wrist, rel=1e-9)  # the wrist is 5 cm beyond the butt
    closer = page_results(PageInputs(pivot_cm_from_tip=length_cm - 10.0)).a.summary
    assert closer["serve_tipward_mph"] != pytest.approx(same)
    on_strings = page_results(PageInputs(pivot_cm_from_tip=10.0)).errors  # each racket's line
    assert list(on_strings) == ["A", "B"]
    assert re.search(r"Swing pivot \[cm from the tip\] must be in \(.*\] cm", on_strings["A"])


def _overlap(a, b) -> bool:
    return a.x0 < b.x1 and b.x0 < a.x1 and a.y0 < b.y1 and b.y0 < a.y1


def test_the_page_plots_one_quantity_each_with_legends_outside():
    from studies.page.plots import plot_along_racket, plot_face_map_page, plot_serve_speeds

    r = page_results(PageInputs())
    along = {"A": r.a.along, "B": r.b.along}
    axes = [
        plot_serve_speeds({"A": r.a.serves, "B": r.b.serves}, 70.0),
        plot_along_racket(along, "exit_speed_swung_mph", "ball speed [mph]", mph=True),
        plot_along_racket(along, "e_A", "rebound ratio e_A [-]"),
    ]
    for ax in axes:
        ax.figure.canvas.draw()
        renderer = ax.figure.canvas.get_renderer()
        assert re.search(r"\[.+\]", ax.get_ylabel()) and re.search(r"\[.+\]", ax.get_xlabel())
        assert len(ax.get_lines()) >= 2 and {ln.get_label() for ln in ax.get_lines()} >= {"A", "B"}
        legend = ax.get_legend().get_window_extent(renderer)
        assert not _overlap(legend, ax.get_window_extent(renderer)), "legend on the data"
        assert all(other.get_ylabel() for other in ax.figure.axes)  # each with its quantity
    face = plot_face_map_page(r.a.face, "A", conditions=r.conditions["face_a"])
    face.figure.set_size_inches(5.4, 6.25)  # the page's card (600 px high), as Shiny sizes it
    face.figure.tight_layout()  # as the page lays it out
    face.figure.canvas.draw()
    renderer = face.figure.canvas.get_renderer()
    box = face.get_legend().get_window_extent(renderer)
    assert box.y0 >= 0 and box.y1 <= face.figure.bbox.y1  # in the figure
    assert not _overlap(box, face.xaxis.label.get_window_extent(renderer))
    assert not _overlap(box, face.get_window_extent(renderer))
    (bar,) = [other for other in face.figure.axes if other is not face]  # the colour bar
    assert not _overlap(face.xaxis.label.get_window_extent(renderer), bar.get_window_extent())
    assert not _overlap(box, bar.get_window_extent())
    heading = face.figure._suptitle.get_window_extent(renderer)
    assert heading.y1 <= face.figure.bbox.y1 and heading.y0 >= box.y1 - 8  # above the legend


def _filled(ax):
    """The filled contours of a face map's Axes."""
    from matplotlib.contour import ContourSet

    (filled,) = [c for c in ax.collections if isinstance(c, ContourSet) and c.filled]
    return filled


def test_the_face_maps_of_a_and_b_share_one_colour_scale():
    r = page_results(PageInputs())
    drawn = page_plots(r, PageInputs().swing_mph)
    a, b = (_filled(PLOTS[key](**drawn[key])) for key in ("face_a", "face_b"))
    assert list(a.levels) == list(b.levels)  # equal colours, equal e_A
    assert (a.norm.vmin, a.norm.vmax) == (b.norm.vmin, b.norm.vmax)
    assert a.colorbar.ax.get_ylim() == b.colorbar.ax.get_ylim()  # the two bars alike
    both = np.r_[r.a.face.e_A.ravel(), r.b.face.e_A.ravel()]
    assert a.levels[0] <= both.min() and both.max() <= a.levels[-1]  # the scale spans both
    # each map on its own scale (as the page drew them before) would not compare
    own = [_filled(PLOTS[key](**{**drawn[key], "levels": None})) for key in ("face_a", "face_b")]
    assert list(own[0].levels) != list(own[1].levels)
    # with B not built, A's map on its own scale
    alone = page_results(PageInputs(racket_b=MY_SHEET, swingweight_kgcm2=370.0))
    drawn = page_plots(alone, PageInputs().swing_mph)
    assert "face_b" not in drawn
    assert list(_filled(PLOTS["face_a"](**drawn["face_a"])).levels) == list(own[0].levels)


def _clipped(fig) -> list[str]:
    """The axis labels of ``fig`` (its Axes' and their secondary axes') not wholly inside it."""
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    out = []
    for ax in fig.axes:
        for axes in (ax, *ax.child_axes):
            for label in (axes.xaxis.label, axes.yaxis.label):
                box = label.get_window_extent(renderer)
                inside = box.x0 >= 0 and box.y0 >= 0 and box.x1 <= fig.bbox.x1
                if label.get_text() and not (inside and box.y1 <= fig.bbox.y1):
                    out.append(label.get_text())
    return out


@pytest.mark.parametrize("width_px", [480, 740])  # a 1400 px window's card; a 1920 px one's
def test_no_axis_label_of_the_page_s_plots_is_clipped(width_px):
    drawn = page_plots(page_results(PageInputs()), PageInputs().swing_mph)
    for key in ("serve_plot", "exit_plot", "power_plot"):
        fig = PLOTS[key](**drawn[key]).figure
        fig.set_size_inches(width_px / fig.dpi, 380 / fig.dpi)  # its card, as Shiny sizes it
        fig.set_layout_engine("tight")  # as Shiny lays it out
        assert _clipped(fig) == [], key
    # the exit plot's label of before, "... off the strings [mph] (swing 70 mph)", was clipped
    fig = PLOTS["exit_plot"](**drawn["exit_plot"]).figure
    fig.axes[0].set_ylabel("ball speed off the strings [mph] (swing 70 mph)")
    fig.set_size_inches(width_px / fig.dpi, 380 / fig.dpi)
    fig.set_layout_engine("tight")
    assert _clipped(fig) == ["ball speed off the strings [mph] (swing 70 mph)"]


def test_a_new_head_speed_leaves_the_plots_at_rest_as_they_were():
    # the page draws a plot again only when what it draws changes (pickled: studies/page/app.py)
    before = page_plots(page_results(PageInputs()), 70.0)
    after = page_plots(page_results(PageInputs(swing_mph=80.0)), 80.0)
    same = {key for key in before if pickle.dumps(before[key]) == pickle.dumps(after[key])}
    assert same == {"face_a", "face_b", "power_plot"}  # the racket at rest
    other_b = page_plots(page_results(PageInputs(racket_b="pure-drive-2025")), 70.0)
    assert pickle.dumps(other_b["face_b"]) != pickle.dumps(before["face_b"])


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


class _Stop(Exception):
    pass


def test_the_port_is_bound_before_the_address_is_announced():
    from studies.cli import build_parser
    from studies.page.app import DEFAULT_PORT, run

    port, heard = _free_port(), []

    def announce(url):
        with socket.create_connection(("127.0.0.1", port), timeout=5):  # already listening
            heard.append(url)
        raise _Stop

    with pytest.raises(_Stop):
        run("127.0.0.1", port, announce)
    assert heard == [f"http://127.0.0.1:{port}"]
    socket.create_server(("127.0.0.1", port)).close()  # released
    with socket.create_server(("127.0.0.1", 0)) as taken:
        busy = taken.getsockname()[1]
        with pytest.raises(ValueError, match=f"port {busy} on 127.0.0.1 cannot be served"):
            run("127.0.0.1", busy, heard.append)
    assert len(heard) == 1  # nothing announced for the port in use
    assert build_parser().parse_args(["app"]).port == DEFAULT_PORT != 8000  # mkdocs: 8000


def test_a_port_in_use_is_one_line_and_status_2():
    with socket.create_server(("127.0.0.1", 0)) as taken:
        port = taken.getsockname()[1]
        done = subprocess.run(
            [sys.executable, "-m", "studies.cli", "app", "--port", str(port)],
            capture_output=True, text=True, timeout=120,
        )  # fmt: skip
    assert done.returncode == 2
    assert done.stdout == ""  # no address announced
    assert done.stderr.count("\n") == 1 and "Traceback" not in done.stderr
    assert f"port {port} on 127.0.0.1 cannot be served: Address already in use" in done.stderr


@pytest.fixture
def served():
    port = _free_port()
    server = subprocess.Popen(
        [sys.executable, "-m", "studies.cli", "app", "--port", str(port)],
        stdout=subprocess.PIPE,
        stderr=subprocess.STDOUT,
        text=True,
    )
    line = server.stdout.readline()  # announced once the port is bound
    url = f"http://127.0.0.1:{port}"
    if url not in line:
        server.kill()
        pytest.fail(f"the page did not come up: {line}{server.stdout.read()[-2000:]}")
    urllib.request.urlopen(url, timeout=60).read()  # answers at once: no retries
    yield url
    server.terminate()
    server.wait(timeout=10)


_OVERFLOWS = """cards => cards.flatMap(id => {
    const card = document.getElementById(id);
    return [card, ...card.querySelectorAll('*')]
        .filter(el => el.clientWidth > 0 && el.scrollWidth > el.clientWidth)
        .map(el => `${id}: <${el.tagName.toLowerCase()} id=${el.id}> ${el.scrollWidth} > `
                   + `${el.clientWidth}`);
})"""

_IN_SIGHT = """id => {
    const el = document.getElementById(id), r = el.getBoundingClientRect();
    const card = el.closest('.card').getBoundingClientRect();
    const inside = r.left >= card.left && r.right <= card.right && r.top >= card.top
        && r.bottom <= card.bottom;
    const seen = r.width > 0 && r.top >= 0 && r.left >= 0 && r.bottom <= innerHeight
        && r.right <= innerWidth;
    const hit = document.elementFromPoint((r.left + r.right) / 2, (r.top + r.bottom) / 2);
    return inside && seen && hit !== null && el.contains(hit);
}"""


_STATUS_SEEN = """() => {
    window.statusSeen = [];
    const shown = id => {
        const el = document.getElementById(id);
        return el !== null && getComputedStyle(el).display !== 'none';
    };
    const note = () => window.statusSeen.push([
        document.documentElement.classList.contains('shiny-busy'), shown('ready'), shown('busy')]);
    new MutationObserver(note).observe(document.documentElement,
        {attributes: true, attributeFilter: ['class']});
    new MutationObserver(note).observe(document.getElementById('cards'),
        {childList: true, subtree: true, characterData: true});
}"""  # [Shiny busy, "Ready." shown, "Recalculating" shown] at each change of either or a card

_DRAWN_AGAIN = """ids => {
    window.drawnAgain = {};
    for (const id of ids) {
        window.drawnAgain[id] = 0;
        new MutationObserver(() => window.drawnAgain[id]++).observe(document.getElementById(id),
            {childList: true, subtree: true, attributes: true});
    }
}"""  # per plot, how often Shiny touched it (recalculating, a new image)

_IDLE = "!document.documentElement.classList.contains('shiny-busy')"


def _numbers(page, card: str) -> list[tuple[float, float, float]]:
    """(A, B, B - A) as shown, per column of ``card``."""
    count = page.locator(f"#{card} [id^='{card}_diff_']").count()
    shown = [
        tuple(float(page.inner_text(f"#{card}_{row}_{k}").replace("−", "-"))
              for row in ("a", "b", "diff"))
        for k in range(count)
    ]  # fmt: skip
    assert shown, f"no numbers in {card}"
    return shown


def _decimals(page, card: str, k: int) -> int:
    text = page.inner_text(f"#{card}_a_{k}")
    return len(text.split(".")[1]) if "." in text else 0


def test_the_page_in_a_real_browser(served):
    if CHROMIUM is None:
        if os.environ.get("CI"):
            pytest.fail("CI must install Debian's chromium for the browser test (.ci/run)")
        pytest.skip("no chromium on this machine (apt-get install chromium)")
    from playwright.sync_api import sync_playwright

    outside = []

    def local_only(route):
        if route.request.url.startswith(served):
            route.continue_()
        else:
            outside.append(route.request.url)
            route.abort()

    with sync_playwright() as p:
        browser = p.chromium.launch(executable_path=CHROMIUM, args=CHROMIUM_FLAGS)
        page = browser.new_page(viewport={"width": 1400, "height": 1000})
        page.route("**/*", local_only)
        page.goto(served)
        page.locator("#card_serve_a_0").wait_for(timeout=180_000)  # may compile the solver
        for plot in PLOTS:
            page.wait_for_function(f"document.querySelector('#{plot} img') !== null",
                                   timeout=60_000)  # fmt: skip
        assert page.evaluate(_OVERFLOWS, list(CARDS)) == []
        assert page.evaluate(_IN_SIGHT, "card_serve_a_0"), "the serve speed is not in sight"
        assert page.evaluate(_IN_SIGHT, "card_serve_b_0")
        assert "mph" in page.inner_text("#card_serve") and "rpm" in page.inner_text("#card_serve")
        assert page.evaluate(_IN_SIGHT, "card_groundstroke_a_1"), "the forehand's spin"
        assert "kg cm²" in page.inner_text("#card_racket")
        serve_a, serve_b, _ = _numbers(page, "card_serve")[0]
        page.wait_for_function(_IDLE)
        assert page.is_visible("#ready") and page.is_hidden("#busy")
        page.evaluate(_STATUS_SEEN)
        page.select_option("#racket_b", "pure-drive-2025")
        page.wait_for_function(
            "t => document.getElementById('card_serve_b_0')?.innerText !== t",
            arg=page.inner_text("#card_serve_b_0"), timeout=60_000,
        )  # fmt: skip
        page.wait_for_function(_IDLE, timeout=60_000)
        seen = page.evaluate("window.statusSeen")
        assert [True, False, True] in seen  # at work: "Recalculating", no "Ready."
        assert all(not ready and busy for working, ready, busy in seen if working), seen
        assert seen[-1] == [False, True, False]  # all drawn: "Ready." again
        assert "pure-drive-2025" in page.inner_text("#card_racket")
        for card in CARDS:
            for k, (a, b, diff) in enumerate(_numbers(page, card)):
                assert diff == pytest.approx(round(b - a, _decimals(page, card, k)), abs=1e-9)
        after_a, after_b, _ = _numbers(page, "card_serve")[0]
        assert after_a == serve_a and after_b != serve_b  # only B changed
        assert page.evaluate(_OVERFLOWS, list(CARDS)) == []
        # a new head speed: the plots of the racket at rest are not drawn again
        page.evaluate(_DRAWN_AGAIN, list(PLOTS))
        page.evaluate("$('#swing').data('ionRangeSlider').update({from: 80})")
        page.wait_for_function("window.drawnAgain.exit_plot > 0", timeout=60_000)
        page.wait_for_function(_IDLE, timeout=60_000)
        again = page.evaluate("window.drawnAgain")
        # the swung plots follow each value the slider passes; the plots at rest are not drawn
        # again for them (at most once, when the cards' new text resizes the page: seen on a
        # loaded machine)
        swung = min(again["serve_plot"], again["exit_plot"])
        assert swung > 0 and all(n <= 1 < swung or n == 0 for p, n in again.items()
                                 if p not in ("serve_plot", "exit_plot")), again  # fmt: skip
        # the card's text may follow the plots (seen on a loaded machine): wait for it
        page.wait_for_function(
            "() => document.getElementById('card_serve')?.innerText.includes('80 mph head speed')",
            timeout=60_000,
        )
        assert "80 mph head speed" in page.inner_text("#card_serve")
        browser.close()
    assert outside == [], f"the page fetched from outside the machine: {outside}"
