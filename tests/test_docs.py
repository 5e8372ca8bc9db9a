"""The README's Python code runs as written, and every example file loads and runs: the
documentation cannot drift from the code (issue 15)."""

import re
from pathlib import Path

import pytest

from studies.cli import main

ROOT = Path(__file__).resolve().parent.parent
DOCUMENTS = [ROOT / "README.md", *sorted((ROOT / "docs").rglob("*.md"))]
BLOCKS = [
    (path.relative_to(ROOT), block)
    for path in DOCUMENTS
    if "generated" not in path.parts
    for block in re.findall(r"```python\n(.*?)```", path.read_text(), re.S)
]
EXAMPLES = sorted((ROOT / "examples").glob("*.toml"))
GALLERY = sorted((ROOT / "examples" / "gallery").glob("plot_*.py"))


def test_the_readme_and_the_docs_have_code_to_run():
    assert len(BLOCKS) >= 10


@pytest.mark.parametrize(
    "index", range(len(BLOCKS)), ids=[f"{p}-{i}" for i, (p, _) in enumerate(BLOCKS)]
)
def test_documentation_python_block_runs(index, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    path, block = BLOCKS[index]
    exec(compile(block, f"{path} python block", "exec"), {})


@pytest.mark.parametrize("script", GALLERY, ids=[p.name for p in GALLERY])
def test_gallery_script_draws_its_figure(script, tmp_path, monkeypatch):
    import runpy

    import matplotlib.pyplot as plt

    monkeypatch.chdir(tmp_path)
    plt.close("all")
    runpy.run_path(str(script), run_name="__main__")
    assert plt.get_fignums(), f"{script.name} drew no figure"
    plt.close("all")


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


def _modules_with_examples():
    """Every module of the packages whose source holds a doctest (``>>>``), found rather
    than listed, so that a new module's Examples cannot go untested."""
    for package in ("ball", "beam", "racket", "studies", "common"):
        for path in sorted((ROOT / package).rglob("*.py")):
            if ">>>" in path.read_text():
                yield ".".join(path.relative_to(ROOT).with_suffix("").parts)


@pytest.mark.parametrize("module", list(_modules_with_examples()))
def test_docstring_examples_run(module):
    """The Examples sections of the docstrings are doctests."""
    import doctest
    import importlib

    flags = doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE
    result = doctest.testmod(importlib.import_module(module), optionflags=flags)
    assert result.attempted > 0 and result.failed == 0
