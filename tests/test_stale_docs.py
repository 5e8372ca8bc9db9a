"""Docs that cannot go stale (issue 33): a number of a guide's prose that describes an output is
put there by the site's build from that output, and a hand-typed copy fails.

The rule and its markers are those of docs/hooks/run.py (``quote``, ``copied_numbers``,
``check``); tests/test_docs.py applies them to every page as it runs the page's blocks (the
site's build too), and to the README.  These tests show the rule on small pages: no site, no
``docs`` extra needed.
"""

import importlib.util
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
_SPEC = importlib.util.spec_from_file_location("docs_hook_run", ROOT / "docs/hooks/run.py")
RUN = importlib.util.module_from_spec(_SPEC)
_SPEC.loader.exec_module(RUN)

OUTPUT = [
    "largest e = 0.8872 at 52.0 cm from the butt\n  (pure-drive-2021)\n",
    "sweet area (e_A within 5 %\n  of its largest) 34.2 cm^2; twist -67.3 rad/s;\n",
    "5,000,000 impacts\n",
]


def test_a_marker_quotes_the_number_an_output_prints_after_its_text():
    text = (
        "e peaks at {{ output: largest e = }}; the sweet area, "
        "{{ output: sweet area (e_A within 5 % of its largest) }} cm², twists at "
        "{{ output: twist }} rad/s; the ball comes at {{ code: ball.catalog.TWU_SPEED }} m/s."
    )
    from ball.catalog import TWU_SPEED

    assert RUN.quote(text, OUTPUT) == (
        f"e peaks at 0.8872; the sweet area, 34.2 cm², twists at -67.3 rad/s; the ball comes at "
        f"{TWU_SPEED:g} m/s."
    )
    assert RUN.copied_numbers(text, OUTPUT) == []  # what the build fills is no copy


@pytest.mark.parametrize(
    ("marker", "error"),
    [
        ("{{ output: largest e_A = }}", "no output of the page prints a number after"),
        ("{{ output: from the butt }}", "no output of the page prints a number after"),
        ("{{ code: ball.catalog.NO_SUCH_NAME }}", "no such constant"),
        ("{{ code: ball.catalog }}", "is a module"),
        ("{{ value: largest e }}", "unknown marker"),
        ("{{ given: about 34 }}", "a given number is a number"),
    ],
)
def test_a_marker_that_finds_nothing_fails(marker, error):
    with pytest.raises(RUN.RunError, match=error):
        RUN.quote(f"e is {marker} there", OUTPUT)


@pytest.mark.parametrize(
    "sentence",
    [
        "e peaks at 0.8872 near the node",  # a copy of the output
        "a sweet area of 34.2 cm²",
        "it twists at 67.3 rad/s",  # the output's -67.3, its sign aside
        "twists at 67.3 rad/s or 67.30",
        "at **52.0** cm",
    ],
)
def test_prose_that_copies_an_output_fails(sentence):
    copies = RUN.copied_numbers(sentence, OUTPUT)
    assert len(copies) == 1, copies
    with pytest.raises(RUN.RunError, match="the prose copies numbers of the page's output"):
        RUN.check(sentence, "guide/x.md", RUN.Run([], {}, OUTPUT, ""))


@pytest.mark.parametrize(
    "sentence",
    [
        "e is about 0.9 at the node",  # not an output's number
        "at 52 cm",  # fewer than three significant digits: too common to tell
        "at 5,000,000 or 5000000 impacts",  # one significant digit
        "sweet area near 34 cm²",
        "the racket of 2021",  # a year
        "`largest e = 0.8872` and [the map](map-0.8872.md)",  # code and a link's address
        "<!-- 0.8872 -->",
        "the table's median, {{ given: 34.2 }} cm², a source's",  # equal to an output by chance
        "```console\n$ racket-impact sweep\nlargest e = 0.8872\n```",  # a code block
        "typed at 34.2 cm²",  # an input the page's blocks typed (below)
    ],
)
def test_prose_that_copies_no_output_passes(sentence):
    assert RUN.copied_numbers(sentence, OUTPUT, inputs="--area 34.2") == []
    RUN.check(sentence, "guide/x.md", RUN.Run([], {}, OUTPUT, "--area 34.2"))


def test_only_the_checked_pages_are_held_to_the_rule():
    made = RUN.Run([], {}, OUTPUT, "")
    RUN.check("e is 0.8872", "toml.md", made)  # not a guide page
    for page in ("guide/sweeps.md", "index.md", "python.md", "cli.md"):
        with pytest.raises(RUN.RunError):
            RUN.check("e is 0.8872", page, made)


def test_a_page_whose_prose_copies_its_output_fails_to_run():
    """The whole path, as the site's build and tests/test_docs.py run a page."""
    block = "```python run\nprint('largest e =', 8872 / 10000)\n```\n"
    with pytest.raises(RUN.RunError, match=r"0\.8872: \.\.\. e peaks at 0\.8872"):
        RUN.run_page(block + "e peaks at 0.8872.\n", "guide/bad.md")
    made = RUN.run_page(block + "e peaks at {{ output: largest e = }}.\n", "guide/good.md")
    assert made.outputs == ["largest e = 0.8872\n"]  # a number the code typed is an input
    assert RUN.quote("e peaks at {{ output: largest e = }}.", made.outputs) == "e peaks at 0.8872."


def test_the_guides_have_no_hand_typed_output_in_a_console_block():
    """A ``console`` block the build does not run holds commands only: an output typed by hand
    there would be as stale as one in the prose."""
    pages = [*sorted((ROOT / "docs/guide").glob("*.md"))]
    pages += [ROOT / "docs" / name for name in ("index.md", "python.md", "cli.md")]
    typed = []
    for page in pages:
        for block in RUN.FENCE.finditer(page.read_text()):
            head, *lines = block[0].strip().splitlines()[:-1]
            if head.strip("`~ ").startswith("console") and " run" not in head:
                command = ""  # a command's continued lines (after a \\) are the command's
                for line in lines:
                    command = line if line.startswith("$ ") or command.endswith("\\") else ""
                    typed += [] if command else [f"{page.name}: {line}"]
    assert not typed, "hand-typed output in a console block:\n" + "\n".join(typed)
