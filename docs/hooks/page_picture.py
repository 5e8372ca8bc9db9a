"""MkDocs hook: the picture of the interactive page (``app.png``, on the command line page),
taken by the build from the page as it is, and how long a change took on it.

The hook serves the page (:func:`studies.page.app.run`) in a process of its own on a port the
system picks, opens it in headless Chromium (Debian's ``chromium``, driven by Playwright, as
``tests/test_app.py`` drives it; every request off the machine refused), waits until the cards
and the five plots are drawn and the page is idle, times two changes as a coach makes them
(racket B to another racket, and back; the head speed up 10 mph, and back: from the change to
the last output the server sends, :data:`CHANGES`), and photographs the whole page at its
defaults.  The server is ended afterwards, whatever happened; every wait has a limit.

The picture becomes ``app.png`` of the site (a generated file: there is none in docs/), and the
comment :data:`CAPTION` on a page becomes the sentence saying how it was taken and the times
measured (:func:`caption`), so that the docs' numbers on the page's speed are this build's.
Chromium (``apt-get install chromium``) and the ``app`` and ``test`` extras (Shiny,
Playwright) are needed: without them the build fails, saying what is missing.  CI has them
(``.ci/run``).  Under ``mkdocs serve`` the picture is taken again only when the code changed.
"""

from __future__ import annotations

import contextlib
import hashlib
import os
import re
import selectors
import shutil
import subprocess
import sys
from pathlib import Path
from typing import NamedTuple

ROOT = Path(__file__).resolve().parents[2]
IMAGE = "app.png"
"""The picture's path in the site (the command line page links it)."""
CAPTION = "<!-- page-picture: how it was taken -->"
"""The comment a page holds where the sentence on the picture goes (:func:`caption`)."""
WIDTH = 1400
"""The browser window's width [px] (its height: the page's, so that the whole page is
photographed)."""
CHANGES = (
    ("racket B changed to another racket", "select", "racket_b", "pure-drive-2025",
     "pro-staff-97l-cv"),
    ("the head speed raised by 10 mph", "slider", "swing", 80, 70),
)  # fmt: skip
"""The changes timed: words, the control's kind and id, the value set, then the page's
default set back (timed too, as a second change: a racket or a swing seen before)."""
CODE = ("ball", "bat", "beam", "common", "racket", "studies")
"""What the page runs: the picture is taken again when a file of these changes."""
SERVE_S = 60.0
"""Longest wait for the server to announce its address [s]."""
FIRST_S = 300.0
"""Longest wait for the page's first numbers and plots [s]: it may compile the solver."""
CHANGE_S = 120.0
"""Longest wait for a change to be drawn [s]."""
CHROMIUM_FLAGS = (
    "--no-sandbox",
    "--disable-gpu",
    "--disable-quic",
    "--no-first-run",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
)  # as tests/test_app.py: without the background-networking flags Chromium calls out
PLOTS = ("serve_plot", "exit_plot", "power_plot", "face_a", "face_b")
_CACHE: dict[str, Picture] = {}  # code's digest -> its picture (mkdocs serve)
_TAKEN: list[Picture] = []  # this build's


class PictureError(Exception):
    """The picture cannot be taken: what is missing, or what the page did not do in time."""


class Picture(NamedTuple):
    """The page photographed, and how long its changes took."""

    png: bytes
    """The whole page at its defaults, as a PNG."""
    seconds: dict[str, tuple[float, float]]
    """Per change (:data:`CHANGES`' words), the change and the change back: from the change
    made on the page to the last output the server sent for it [s]."""
    cores: int
    """The machine's cores."""
    load: float
    """Its load average over the minute before the picture (the other work it did)."""


def chromium() -> str:
    """The path of Chromium (``chromium`` or ``chromium-browser`` on PATH), or
    :class:`PictureError` saying how to install it.
    """
    found = shutil.which("chromium") or shutil.which("chromium-browser")
    if found is None:
        raise PictureError(
            f"the picture of the interactive page ({IMAGE}) is taken from the running page by "
            "headless Chromium, and there is no chromium on PATH: apt-get install chromium "
            "(CI's .ci/run installs it)"
        )
    return found


def _code_digest() -> str:
    """A digest of every file the page runs (:data:`CODE`)."""
    digest = hashlib.sha256()
    for folder in CODE:
        for path in sorted((ROOT / folder).rglob("*.py")):
            digest.update(path.relative_to(ROOT).as_posix().encode())
            digest.update(path.read_bytes())
    return digest.hexdigest()


def _line(process: subprocess.Popen, within: float) -> str:
    """The first line ``process`` prints, waited for ``within`` seconds at most ("" if none)."""
    with selectors.DefaultSelector() as selector:
        selector.register(process.stdout, selectors.EVENT_READ)
        if not selector.select(timeout=within):
            return ""
    return process.stdout.readline()


@contextlib.contextmanager
def served():
    """The page served by a process of its own on a port of 127.0.0.1 the system picks (so
    always a free one): its address; the process ended afterwards, killed if it lingers.
    """
    code = "from studies.page.app import run; run('127.0.0.1', 0)"
    env = {**os.environ, "MPLBACKEND": "Agg"}
    process = subprocess.Popen(
        [sys.executable, "-c", code], cwd=ROOT, env=env, stdout=subprocess.PIPE,
        stderr=subprocess.STDOUT, text=True,
    )  # fmt: skip
    try:
        line = _line(process, SERVE_S)
        url = re.search(r"http://127\.0\.0\.1:\d+", line)
        if url is None:
            process.kill()
            said = line + process.communicate(timeout=10)[0][-2000:]
            raise PictureError(f"the interactive page did not come up in {SERVE_S:g} s: {said}")
        yield url[0]
    finally:
        process.terminate()
        try:
            process.wait(timeout=10)
        except subprocess.TimeoutExpired:
            process.kill()
            process.wait()


_SETTLED = """plots => document.getElementById('card_serve_a_0') !== null
    && plots.every(id => document.querySelector(`#${id} img`) !== null)
    && !document.documentElement.classList.contains('shiny-busy')
    && document.getElementById('ready') !== null
    && getComputedStyle(document.getElementById('ready')).display !== 'none'"""
_HEIGHT = """() => {
    const main = document.querySelector('.bslib-sidebar-layout > .main');
    return Math.ceil(main.getBoundingClientRect().top + main.scrollHeight);
}"""  # the page's height [px] when nothing scrolls (its main column scrolls in a window)
_TIMED = """([kind, id, value, within]) => new Promise(done => {
    const start = performance.now();
    let idle = false;
    const sent = e => {
        if (idle && e.message && e.message.values) {
            $(document).off('shiny:message', sent);
            done((performance.now() - start) / 1000);
        }
    };
    $(document).one('shiny:idle', () => { idle = true; }).on('shiny:message', sent);
    setTimeout(() => done(null), 1000 * within);
    if (kind === 'slider') $(`#${id}`).data('ionRangeSlider').update({from: value});
    else $(`#${id}`).val(value).trigger('change');
})"""  # the change made as the control makes it; the seconds until the outputs it changes
# arrive (Shiny's server says it is idle, then sends them all in one message)


def _settle(page, within: float) -> None:
    """Wait until ``page`` shows its numbers and plots and the server is idle."""
    page.wait_for_function(_SETTLED, arg=list(PLOTS), timeout=1e3 * within)
    page.wait_for_timeout(500)  # the last images decoded


def _timed(page, kind: str, control: str, value) -> float:
    """Seconds from setting ``control`` to ``value`` until the server has sent every output
    it changes; the page settled afterwards.
    """
    seconds = page.evaluate(_TIMED, [kind, control, value, CHANGE_S])
    if seconds is None:
        raise PictureError(f"setting {control} to {value!r} was not drawn in {CHANGE_S:g} s")
    _settle(page, CHANGE_S)
    return seconds


def photograph() -> Picture:
    """Serve the page, time :data:`CHANGES` on it and photograph it at its defaults.

    Returns
    -------
    Picture
        The PNG and the times; :class:`PictureError` if Chromium or Playwright is missing or
        the page does not answer in time.
    """
    executable = chromium()
    try:
        from playwright.sync_api import Error, sync_playwright
    except ImportError:
        raise PictureError(
            f"the picture of the interactive page ({IMAGE}) needs Playwright and Shiny: "
            "pip install -e '.[docs,app,test]'"
        ) from None
    seconds = {}
    with served() as url, sync_playwright() as p:
        browser = p.chromium.launch(executable_path=executable, args=list(CHROMIUM_FLAGS))
        try:
            height = 1000
            for within in (FIRST_S, CHANGE_S):  # then again in a window as tall as the page
                page = browser.new_page(viewport={"width": WIDTH, "height": height})
                page.route("**/*", lambda r: r.continue_() if r.request.url.startswith(url)
                           else r.abort())  # fmt: skip
                page.goto(url, timeout=1e3 * SERVE_S)
                _settle(page, within)
                height = page.evaluate(_HEIGHT)
            load = os.getloadavg()[0]
            for words, kind, control, value, default in CHANGES:
                there = _timed(page, kind, control, value)
                seconds[words] = there, _timed(page, kind, control, default)
            png = page.screenshot()
        except Error as err:
            raise PictureError(f"the interactive page, photographed: {err}") from None
        finally:
            browser.close()
    return Picture(png, seconds, os.cpu_count() or 1, load)


def caption(picture: Picture) -> str:
    """The sentence under the picture: how it was taken and how long each change took.

    Parameters
    ----------
    picture : Picture
    """
    took = "; ".join(
        f"{words}, {there:.1f} s, and back, {back:.1f} s"
        for words, (there, back) in picture.seconds.items()
    )
    return (
        "*The page at its defaults, as this site's build photographed it (headless Chromium, "
        f"{WIDTH} px wide). From a change made on the page to the last output the server sent "
        f"for it, that build measured: {took} (a racket or a swing seen before is not "
        "computed again, a plot whose contents did not change is not drawn again, and a "
        "slider's value is sent once the hand has rested on it for 250 ms, as Shiny's "
        f"sliders do), on a machine of {picture.cores} cores with a load average of "
        f"{picture.load:.1f}.*"
    )


def on_files(files, config):
    """Photograph the page (once per state of the code) and add the picture to the site."""
    from mkdocs.exceptions import PluginError
    from mkdocs.structure.files import File

    key = _code_digest()
    if key not in _CACHE:
        try:
            _CACHE[key] = photograph()
        except PictureError as err:
            raise PluginError(f"docs/hooks/page_picture.py: {err}") from None
    _TAKEN[:] = [_CACHE[key]]
    files.append(File.generated(config, IMAGE, content=_CACHE[key].png))
    return files


def on_page_markdown(markdown, page, config, files):
    """Put the sentence on the picture in place of :data:`CAPTION`."""
    return markdown.replace(CAPTION, caption(_TAKEN[0])) if CAPTION in markdown else markdown
