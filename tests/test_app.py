"""The interactive page in a real browser: headless Chromium (Debian's package) driven by
Playwright loads the page served by ``racket-impact app``, changes a control, and sees the
numbers and the plot change, with no request leaving the machine (issue 14).  What the page
computes is tested without a browser too."""

import os
import shutil
import socket
import subprocess
import sys
import time
import urllib.request

import pytest

from racket.swing import EFFORT_EXPONENT
from studies.dashboard import MY_SHEET, PageInputs, page_results

CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser")
CHROMIUM_FLAGS = [
    "--no-sandbox",
    "--disable-gpu",
    "--disable-quic",
    "--no-first-run",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
]  # without the background-networking flags Chromium keeps calling out (closed network)


def test_page_results_follow_the_controls():
    base = page_results(PageInputs())
    taped = page_results(PageInputs(lead_g=6.0, lead_at="3 and 9"))
    assert taped.summary["twistweight_kgcm2"] > base.summary["twistweight_kgcm2"]
    assert taped.summary["e_A_3_oclock"] > base.summary["e_A_3_oclock"]
    assert base.summary["serve_tipward_mph"] > base.summary["serve_centre_mph"]
    # lead tape: the swing at equal effort is slower by the swingweight law (issue 25)
    assert "effort_head_taped_mph" not in base.summary
    heavier = page_results(PageInputs(lead_g=5.0, lead_at="12")).summary
    ratio = heavier["effort_head_taped_mph"] / heavier["effort_head_untaped_mph"]
    assert ratio == pytest.approx(
        (base.summary["swingweight_kgcm2"] / heavier["swingweight_kgcm2"]) ** EFFORT_EXPONENT,
        rel=1e-9,
    )
    assert heavier["effort_exit_taped_mph"] > 0 and heavier["effort_exit_untaped_mph"] > 0
    mine = page_results(PageInputs(racket=MY_SHEET, mass_g=310, swingweight_kgcm2=320))
    assert mine.summary["mass_g"] == pytest.approx(310.0)
    with pytest.raises(ValueError, match="racket must be one of"):
        page_results(PageInputs(racket="no such racket"))


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


@pytest.fixture
def served():
    port = _free_port()
    server = subprocess.Popen(
        [sys.executable, "-m", "studies.cli", "app", "--port", str(port)],
        stdout=subprocess.PIPE,
        stderr=subprocess.STDOUT,
    )
    url = f"http://127.0.0.1:{port}"
    deadline = time.monotonic() + 60
    while time.monotonic() < deadline:
        try:
            urllib.request.urlopen(url, timeout=2).read()
            break
        except OSError:
            time.sleep(0.3)
    else:
        server.kill()
        pytest.fail(f"the page did not come up: {server.stdout.read().decode()[-2000:]}")
    yield url
    server.terminate()
    server.wait(timeout=10)


def test_the_page_in_a_real_browser(served, tmp_path):
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
        page = browser.new_page(viewport={"width": 1400, "height": 1100})
        page.route("**/*", local_only)
        page.goto(served)
        numbers = page.locator("#numbers-text")
        numbers.wait_for(timeout=180_000)  # the first run may compile the solver
        page.wait_for_function("document.querySelector('#along img') !== null", timeout=60_000)
        before = numbers.inner_text()
        plot_before = page.locator("#along img").get_attribute("src")
        assert "e_A at the centre" in before and "twistweight" in before
        page.select_option("#racket", "pro-staff-97l-cv")
        page.wait_for_function(
            "t => document.querySelector('#numbers-text').innerText !== t", arg=before,
            timeout=60_000,
        )  # fmt: skip
        page.wait_for_function(
            "s => document.querySelector('#along img').getAttribute('src') !== s",
            arg=plot_before,
            timeout=60_000,
        )
        after = numbers.inner_text()
        assert after != before and "e_A at the centre" in after
        page.screenshot(path=str(tmp_path / "page.png"), full_page=True)
        browser.close()
    assert outside == [], f"the page fetched from outside the machine: {outside}"
    assert (tmp_path / "page.png").stat().st_size > 50_000
