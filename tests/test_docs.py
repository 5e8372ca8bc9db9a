"""The README's Python code runs as written, and every example file loads and runs: the
documentation cannot drift from the code (issue 15)."""

import re
from pathlib import Path

import pytest

from studies.cli import main

ROOT = Path(__file__).resolve().parent.parent
README = (ROOT / "README.md").read_text()
BLOCKS = re.findall(r"```python\n(.*?)```", README, re.S)
EXAMPLES = sorted((ROOT / "examples").glob("*.toml"))


def test_the_readme_has_code_to_run():
    assert len(BLOCKS) >= 4


@pytest.mark.parametrize("index", range(len(BLOCKS)))
def test_readme_python_block_runs(index, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    exec(compile(BLOCKS[index], f"README.md python block {index + 1}", "exec"), {})


@pytest.mark.parametrize("example", EXAMPLES, ids=[p.name for p in EXAMPLES])
def test_every_example_file_runs(example, tmp_path, capsys):
    text = example.read_text()
    if "[racket" in text:
        argv = [
            "sweep",
            "--racket",
            str(example),
            "--points",
            "5",
            "--out",
            str(tmp_path / "s.csv"),
        ]
    else:
        argv = ["ball", str(example), "--speeds", "5", "10", "--out", str(tmp_path / "b.csv")]
    assert main(argv) == 0, capsys.readouterr().err
    assert (tmp_path / argv[-1].split("/")[-1]).stat().st_size > 0


@pytest.mark.parametrize(
    "module",
    [
        "ball.closed_forms",
        "ball.collision",
        "beam.beam",
        "racket.solver",
        "racket.specs.fit",
        "racket.swing",
        "studies.maps",
    ],
)
def test_docstring_examples_run(module):
    """The Examples sections of the docstrings are doctests."""
    import doctest
    import importlib

    flags = doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE
    result = doctest.testmod(importlib.import_module(module), optionflags=flags)
    assert result.attempted > 0 and result.failed == 0
