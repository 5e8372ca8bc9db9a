"""The lists of the README and the home page are complete (issue 45): every subcommand of
``racket-impact --help`` is named where the README lists the commands, and every page of the
site's user guide (``nav`` of mkdocs.yml) is linked from the README's and the home page's
guide lists.  A command or a guide page added without a word in those lists fails here."""

import argparse
import re
from pathlib import Path

import pytest

from studies.cli import build_parser

ROOT = Path(__file__).resolve().parent.parent
README = (ROOT / "README.md").read_text()
INDEX = (ROOT / "docs/index.md").read_text()


def _subcommands() -> list[str]:
    """The subcommands the parser offers, as ``racket-impact --help`` lists them."""
    parser = build_parser()
    (action,) = [a for a in parser._actions if isinstance(a, argparse._SubParsersAction)]
    return list(action.choices)


def _guide_pages() -> list[str]:
    """The user guide's pages, in the order of mkdocs.yml's ``nav`` (``guide/NAME.md``)."""
    nav = (ROOT / "mkdocs.yml").read_text().split("\nnav:", 1)[1].split("\nplugins:", 1)[0]
    return re.findall(r":\s*(guide/[\w-]+\.md)\s*$", nav, re.M)


def _paragraph(text: str, start: str) -> str:
    """The paragraph or list item of ``text`` that begins with ``start``."""
    found = re.search(re.escape(start) + r".*?(?=\n\s*\n|\n\* )", text, re.S)
    assert found, f"no paragraph starts with {start!r}"
    return found[0]


def test_the_lists_are_read():
    """The helpers find what they list: the known commands and pages are among them."""
    assert {"paper", "sweep", "strings", "bat", "app"} <= set(_subcommands())
    assert {"guide/paper.md", "guide/spin.md", "guide/scale-out.md"} <= set(_guide_pages())


@pytest.mark.parametrize("command", _subcommands())
def test_the_readme_names_every_subcommand(command):
    listed = _paragraph(README, "Every subcommand has `--help`")
    assert f"`{command}`" in listed, f"README.md's list of commands omits `{command}`"


@pytest.mark.parametrize("page", _guide_pages())
@pytest.mark.parametrize(
    ("name", "text", "link"),
    [("README.md", README, "](docs/{page})"), ("docs/index.md", INDEX, "]({page})")],
)
def test_the_guide_lists_link_every_guide_page(page, name, text, link):
    listed = _paragraph(text, "* User guide" if name == "README.md" else "* **User guide**")
    assert link.format(page=page) in listed, f"{name}'s guide list omits {page}"
