"""Docs that cannot go stale (issue 33): a number of a guide's prose that describes an output is
put there by the site's build from that output, and a hand-typed result fails, whether or not a
block of the page prints it.

The rule and its markers are those of docs/hooks/run.py (``quote``, ``loose_numbers``,
``check``; ``copied_numbers`` for the README); tests/test_docs.py applies them to every page as
it runs the page's blocks (the site's build too), and to the README.  These tests show the rule
on small pages: no site, no ``docs`` extra needed.
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
        "it twists at -67.3 rad/s",
        "at **52.0** cm",
    ],
)
def test_prose_that_copies_an_output_fails(sentence):
    loose = RUN.loose_numbers(sentence, "", tuple(OUTPUT))
    assert len(loose) == 1 and loose[0].endswith("(printed)"), loose
    assert len(RUN.copied_numbers(sentence, OUTPUT)) == 1  # the README's rule finds it too
    with pytest.raises(RUN.RunError, match="the prose types numbers by hand"):
        RUN.check(sentence, "guide/x.md", RUN.Run([], {}, OUTPUT, ""))


@pytest.mark.parametrize(
    "sentence",
    [
        "the twistweight is 14.8 kg cm² on the Pure Drive",  # a model result no block prints
        "e at the node falls 0.913 -> 0.892",
        "at 55 lb: 3.09e4 N/m on 90 in²",
        "| 144.1 | 0.604 | 0.900 |",  # a hand-made table of results
        "swingweight 325 -> 338.7",
        "617 fit and 5 were refused",
        "    f1 = -3.99 Hz + 2.329 Hz x RA",  # an indented block is prose to the rule
        "Table 3 gives 0.913",  # a reference's number is exempt, the result is not
    ],
)
def test_a_hand_typed_result_that_no_output_prints_fails(sentence):
    """Default-deny: a number of three or more significant digits is a marker, an input or
    a given number; an output need not print it for the rule to fail it."""
    assert RUN.copied_numbers(sentence, OUTPUT) == []  # the old rule let it through
    loose = RUN.loose_numbers(sentence, "", tuple(OUTPUT))
    assert loose and not any(n.endswith("(printed)") for n in loose), loose
    with pytest.raises(RUN.RunError, match="the prose types numbers by hand"):
        RUN.check(sentence, "guide/x.md", RUN.Run([], {}, OUTPUT, ""))


@pytest.mark.parametrize(
    "sentence",
    [
        "e is about 0.9 at the node",  # fewer than three significant digits
        "at 52 cm",
        "at 5,000,000 or 5000000 impacts",  # one significant digit
        "sweet area near 34 cm²",
        "the racket of 2021, measured 2026-11-24",  # a year, a date
        "`largest e = 0.8872` and [the map](map-0.8872.md)",  # code and a link's address
        "<!-- 0.8872 -->",
        "the table's median, {{ given: 34.2 }} cm², a source's",  # equal to an output by chance
        "TWU measured a {{ given: 291 }} g racket",  # a source's number, said so
        "*Am. J. Phys.* **68**, {{ given: 1025-1031 }} (2000), doi:10.1119/1.1285945",
        "Eq. 121, Eqs. 120-122, Sec. 101 and Table 104",  # references, not results
        "e peaks at {{ output: largest e = }}, the ball at {{ code: ball.catalog.TWU_SPEED }}",
        "```console\n$ racket-impact sweep\nlargest e = 0.8872\n```",  # a code block
        "typed at 34.2 cm²",  # an input the page's blocks typed (below)
    ],
)
def test_prose_that_types_no_result_passes(sentence):
    assert RUN.loose_numbers(sentence, "--area 34.2", tuple(OUTPUT)) == []
    RUN.check(sentence, "guide/x.md", RUN.Run([], {}, OUTPUT, "--area 34.2"))


def test_a_given_range_is_written_as_typed_and_a_given_word_fails():
    assert RUN.quote("pages {{ given: 1025-1031 }}", OUTPUT) == "pages 1025-1031"
    with pytest.raises(RUN.RunError, match="a given number is a number, or a range"):
        RUN.quote("{{ given: 1025 to 1031 }}", OUTPUT)


def test_a_number_in_a_comment_of_a_block_is_no_input():
    """A comment is prose written in a block: its number exempts nothing."""
    block = "```python run\nprint('largest e =', 0.8872)  # about 0.913 at 20 m/s\n```\n"
    with pytest.raises(RUN.RunError, match=r"0\.913: \.\.\. e at 20 m/s is 0\.913\. \.\.\.$"):
        RUN.run_page(block + "e at 20 m/s is 0.913.\n", "guide/comment.md")
    assert "0.913" not in RUN._typed("x = 1  # about 0.913\ny = '#' + '2'")


def test_only_the_checked_pages_are_held_to_the_rule():
    made = RUN.Run([], {}, OUTPUT, "")
    RUN.check("e is 0.8872", "toml.md", made)  # not a guide page
    for page in ("guide/sweeps.md", "index.md", "python.md", "cli.md"):
        with pytest.raises(RUN.RunError):
            RUN.check("e is 0.8872", page, made)


def test_a_page_whose_prose_types_a_result_fails_to_run():
    """The whole path, as the site's build and tests/test_docs.py run a page: a copy of the
    output fails, and so does a result the page's blocks do not print at all."""
    block = "```python run\nprint('largest e =', 8872 / 10000)\n```\n"
    with pytest.raises(RUN.RunError, match=r"0\.8872: \.\.\. e peaks .* \(printed\)"):
        RUN.run_page(block + "e peaks at 0.8872.\n", "guide/bad.md")
    with pytest.raises(RUN.RunError, match=r"0\.913: \.\.\. e at the node is 0\.913\. \.\.\.$"):
        RUN.run_page(block + "e at the node is 0.913.\n", "guide/unprinted.md")
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
