"""The picture of the interactive page on the command line page (issue 45): the site's build
takes it from the page as it runs (``docs/hooks/page_picture.py``: the page served on a port
of its own, headless Chromium), and says under it how long two changes took in that build; a
build without Chromium fails, saying so.  The hook is run here as the build runs it, with no
site built."""

import importlib.util
import io
import os
import shutil
import struct
from pathlib import Path

import matplotlib.image
import pytest

ROOT = Path(__file__).resolve().parent.parent
DOCS = ROOT / "docs"


def _hook():
    spec = importlib.util.spec_from_file_location(
        "docs_hook_page_picture", DOCS / "hooks" / "page_picture.py"
    )
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


HOOK = _hook()


def _png_size(png: bytes) -> tuple[int, int]:
    """Width and height [px] of a PNG (its IHDR chunk)."""
    assert png[:8] == b"\x89PNG\r\n\x1a\n" and png[12:16] == b"IHDR", "not a PNG"
    return struct.unpack(">II", png[16:24])


@pytest.fixture(scope="module")
def picture():
    if shutil.which("chromium") is None and shutil.which("chromium-browser") is None:
        if os.environ.get("CI"):
            pytest.fail("CI must install Debian's chromium for the page's picture (.ci/run)")
        pytest.skip("no chromium on this machine (apt-get install chromium)")
    pytest.importorskip("playwright", reason="the picture needs Playwright (the test extra)")
    return HOOK.photograph()


@pytest.mark.timeout(600)
def test_the_build_photographs_the_running_page(picture):
    width, height = _png_size(picture.png)
    assert width == HOOK.WIDTH
    assert 2000 < height < 6000  # the whole page: cards, plots and the table of spots
    assert len(picture.png) > 200_000
    rgb = matplotlib.image.imread(io.BytesIO(picture.png))[..., :3]
    coloured = float(((rgb.max(axis=2) - rgb.min(axis=2)) > 0.3).mean())
    # the plots drawn (the face maps' colours, the lines): 2.6 % of the page's pixels in
    # November 2026, 0.13 % on the page still waiting for its numbers (spinners, sliders)
    assert coloured > 0.01, coloured
    assert list(picture.seconds) == [words for words, *_ in HOOK.CHANGES]
    for there, back in picture.seconds.values():
        assert 0 < there < HOOK.CHANGE_S and 0 < back < HOOK.CHANGE_S
    assert picture.cores == os.cpu_count() and picture.load >= 0


@pytest.fixture
def built(picture, monkeypatch):
    """The hook as a build runs it, the picture taken once for these tests."""
    pytest.importorskip("mkdocs", reason="the docs extra")
    monkeypatch.setattr(HOOK, "photograph", lambda: picture)
    monkeypatch.setattr(HOOK, "_CACHE", {})
    return HOOK.on_files([], _config())


def test_the_sentence_under_the_picture_gives_this_build_s_times(picture, built):
    said = HOOK.caption(picture)
    for words, (there, back) in picture.seconds.items():
        assert f"{words}, {there:.1f} s, and back, {back:.1f} s" in said
    assert f"{picture.cores} cores with a load average of {picture.load:.1f}" in said
    cli = (DOCS / "cli.md").read_text()
    assert "![the interactive page](app.png)" in cli and HOOK.CAPTION in cli
    filled = HOOK.on_page_markdown(cli, None, None, None)
    assert HOOK.CAPTION not in filled and said in filled


def _config():
    from mkdocs.config.defaults import MkDocsConfig

    config = MkDocsConfig()
    config.load_dict({"site_name": "racket-impact", "docs_dir": str(DOCS), "site_dir": "site"})
    config.validate()
    config.plugins._current_plugin = None  # as during a build (File.generated reads it)
    return config


def test_the_picture_is_the_build_s_not_a_file_of_the_docs(picture, built):
    assert not (DOCS / HOOK.IMAGE).exists()  # only the build's picture: none goes stale
    assert "docs/hooks/page_picture.py" in (ROOT / "mkdocs.yml").read_text()
    (added,) = built
    assert added.src_uri == HOOK.IMAGE and added.content_bytes == picture.png


def test_a_build_without_chromium_fails_saying_so(monkeypatch):
    mkdocs = pytest.importorskip("mkdocs.exceptions", reason="the docs extra")
    monkeypatch.setattr(HOOK.shutil, "which", lambda name: None)
    monkeypatch.setattr(HOOK, "_CACHE", {})
    with pytest.raises(mkdocs.PluginError, match="no chromium on PATH: apt-get install chromium"):
        HOOK.on_files([], None)
