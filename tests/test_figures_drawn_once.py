"""Each figure of ``racket-impact paper`` is drawn at most twice (issue 47), laid out from
text extents measured with the renderer rather than by drawing it again and again; a PNG is
drawn once, its layout run at the saved resolution before (:func:`studies.cli.files.plot_bytes`);
and saved as it should look.
"""

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt
import pytest
from matplotlib.figure import Figure

from racket import paper_racket
from studies import plots
from studies.cli.paper import paper_figure, paper_figures
from studies.plots.layout import AXES_WIDTH

DRAWS = 1
"""Draws a PNG figure takes, made and saved: the saving's (matplotlib's own saving would draw
it twice, once without rendering to lay it out)."""

NAMES = list(paper_figures())


@pytest.fixture
def drawn(monkeypatch):
    """Each figure drawn since the test began: how often, and at its last draw the widths
    [in] of its Axes of the automatic aspect and whether everything in it lies inside it.
    """
    seen = {}
    original = Figure.draw

    def draw(fig, renderer):
        original(fig, renderer)
        page = fig.bbox
        inside = all(
            page.x0 - 1 <= box.x0 and box.x1 <= page.x1 + 1
            and page.y0 - 1 <= box.y0 and box.y1 <= page.y1 + 1
            for box in (ax.get_tightbbox(renderer) for ax in fig.axes)
        )  # fmt: skip
        widths = [ax.get_position().width * fig.get_figwidth()
                  for ax in fig.axes if ax.get_aspect() == "auto"]  # fmt: skip
        count = seen[fig]["draws"] + 1 if fig in seen else 1
        seen[fig] = {"draws": count, "widths": widths, "inside": inside}

    monkeypatch.setattr(Figure, "draw", draw)
    yield seen
    plt.close("all")


@pytest.mark.parametrize("name", NAMES)
def test_each_paper_figure_is_drawn_at_most_twice_and_still_fits(name, drawn):
    data, _caught = paper_figure(name)  # as the command draws each figure
    assert data.startswith(b"\x89PNG")
    assert len(drawn) == 1, (name, len(drawn))  # one figure, the one saved
    (saved,) = drawn.values()
    assert saved["draws"] == DRAWS, (name, saved["draws"])
    assert saved["inside"], name  # labels, ticks, legends, heading: nothing clipped
    # widened in one step, from one layout at the figure's own dpi: the Axes keep about
    # AXES_WIDTH beside their legends (a little more saved at 120 dpi, where text is narrower)
    assert AXES_WIDTH - 0.05 <= min(saved["widths"]) <= AXES_WIDTH + 0.2, (name, saved)


def test_a_plot_lays_out_its_figure_without_drawing_it(drawn):
    ax = plots.plot_modes(paper_racket(), conditions="a heading long enough " * 8)
    assert drawn == {}  # measured, widened and wrapped: nothing drawn yet
    fig = ax.figure
    assert "\n" in fig.get_suptitle()  # wrapped to the widened figure
    assert fig.get_figwidth() > 6.4
    fig.canvas.draw()
    assert drawn[fig]["inside"]
    assert drawn[fig]["widths"][0] == pytest.approx(AXES_WIDTH, abs=0.05)


def test_a_png_is_laid_out_alike_whatever_layout_the_user_asks_for_by_default(drawn):
    # with rcParams asking every new figure for a layout engine, fixing the layout before the
    # save must not install one (it would lay the figure out again, otherwise)
    name = "modes.png"
    plain, _ = paper_figure(name)
    with matplotlib.rc_context({"figure.autolayout": True}):
        asked, _ = paper_figure(name)
    assert asked == plain
    assert all(seen["draws"] == DRAWS for seen in drawn.values())
