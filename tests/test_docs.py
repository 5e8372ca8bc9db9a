"""The documentation cannot drift from the code (issues 15 and 29): the README's commands print
what the README shows, every worked example of the docs runs (its commands and Python blocks,
in order, as the site's build runs them), every example file loads and runs, and the
docstrings' Examples run as doctests."""

import importlib.util
import json
import re
import shlex
from pathlib import Path

import pytest

from studies.cli import main

ROOT = Path(__file__).resolve().parent.parent
README = ROOT / "README.md"
EXAMPLES = sorted((ROOT / "examples").glob("*.toml"))


def _hook(name):
    """A module of the site's build (docs/hooks/), imported from its file."""
    spec = importlib.util.spec_from_file_location(
        f"docs_hook_{name}", ROOT / "docs/hooks" / f"{name}.py"
    )
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


RUN = _hook("run")
PAGES = sorted(
    path.relative_to(ROOT / "docs").as_posix()
    for path in (ROOT / "docs").rglob("*.md")
    if RUN.BLOCK.search(path.read_text())
)


def test_the_docs_have_worked_examples():
    blocks = [m["lang"] for p in PAGES for m in RUN.BLOCK.finditer((ROOT / "docs" / p).read_text())]
    assert blocks.count("python") >= 10 and blocks.count("console") >= 20
    guides = {p.relative_to(ROOT / "docs").as_posix() for p in (ROOT / "docs/guide").glob("*.md")}
    assert guides <= set(PAGES), f"guide pages without a worked example: {guides - set(PAGES)}"


@pytest.mark.parametrize("page", PAGES)
def test_documentation_page_runs(page, validation_once, bounce_once):
    """Every command and Python block of the page runs, in order, in one scratch directory,
    as the site's build runs them (docs/hooks/run.py): a command exits with the status its
    block expects, a block does not raise; the markers of its prose find what they quote, and
    its prose copies no number of its outputs (:func:`check` of docs/hooks/run.py).  A page
    that the built site ran from this very text and code is not run twice.  The validation
    table of every comparison (``racket-impact validate``'s) and a ball's rigid-wall bounce
    table (``racket-impact ball``'s) are simulated once a process (tests/conftest.py)."""
    text = (ROOT / "docs" / page).read_text()
    site = RUN.built_site()
    manifest = site / RUN.MANIFEST if site else None
    if manifest and manifest.exists():
        if json.loads(manifest.read_text()).get(page) == RUN.fingerprint(text):
            pytest.skip(f"the site in {site} was built from this page and this code: it ran it")
    run = RUN.run_page(text, page)  # RunError: a block failed, or the prose copies an output
    assert len(run.results) == len(list(RUN.BLOCK.finditer(text)))


def _readme_sessions():
    """The README's console blocks: (command, the output it shows)."""
    sessions = []
    for block in re.findall(r"```console\n(.*?)```", README.read_text(), re.S):
        for chunk in re.split(r"^\$ ", block, flags=re.M)[1:]:
            command, _, output = chunk.partition("\n")
            sessions.append((command, output))
    return sessions


def test_the_readme_starts_with_the_two_commands_and_fits_three_screens():
    lines = README.read_text().splitlines()
    commands = [line.strip() for line in lines if line.startswith("    ")][:2]
    assert commands == [
        "pip install -e . && racket-impact paper",
        'pip install -e ".[test]" && pytest',
    ]
    assert len(lines) <= 160
    assert len(_readme_sessions()) >= 3 and "](docs/validation.md)" in README.read_text()


def test_the_readme_prose_copies_no_output():
    """The README's prose quotes no number its console blocks print (the docs pages' rule,
    ``copied_numbers`` of docs/hooks/run.py): GitHub shows the README as written, with no
    build to fill a marker, so a copy would go stale when the output changes."""
    sessions = _readme_sessions()
    typed = "\n".join(command for command, _ in sessions)
    copies = RUN.copied_numbers(README.read_text(), [shown for _, shown in sessions], typed)
    assert not copies, "README.md's prose copies its outputs:\n" + "\n".join(copies)


@pytest.mark.parametrize("index", range(len(_readme_sessions())))
def test_readme_command_prints_what_the_readme_shows(index, tmp_path):
    """The README's tour shows real output: run now, each command prints what is shown (when
    an output format changes, the README shows the new one)."""
    command, shown = _readme_sessions()[index]
    RUN.load_kernel()  # so that the output holds no one-off compilation notice
    status, output = RUN.run_command(shlex.split(command), tmp_path)
    assert status == 0, output
    lines = [line.rstrip() for line in output.rstrip().splitlines()]
    assert lines == [line.rstrip() for line in shown.rstrip().splitlines()], (
        f"README.md: `{command}` now prints\n{output}"
    )


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
    for package in ("ball", "bat", "beam", "racket", "studies", "common"):
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


def _named_paths():
    """The source files and the ``studies``/``common`` modules the README and the docs name."""
    texts = [README.read_text()] + [p.read_text() for p in (ROOT / "docs").rglob("*.md")]
    files, modules = set(), set()
    for text in texts:
        files |= set(
            re.findall(
                r"`((?:ball|beam|racket|studies|common|tests|benchmarks|data)/[\w/]+\.\w+)`", text
            )
        )
        modules |= set(re.findall(r"`((?:studies|common)(?:\.[a-z_][a-z0-9_]*)+)", text))
    return sorted(files), sorted(modules)


@pytest.mark.parametrize("path", _named_paths()[0])
def test_a_file_the_docs_name_exists(path):
    assert (ROOT / path).exists(), f"the docs name {path}, which does not exist"


@pytest.mark.parametrize("name", _named_paths()[1])
def test_a_module_or_object_the_docs_name_exists(name):
    """``studies.sweeps.MAX_IMPACTS`` and the like: a module, or an object of one."""
    import importlib

    parts = name.split(".")
    for split in range(len(parts), 0, -1):
        try:
            obj = importlib.import_module(".".join(parts[:split]))
        except ModuleNotFoundError:
            continue
        for attribute in parts[split:]:
            assert hasattr(obj, attribute), f"the docs name {name}, which does not exist"
            obj = getattr(obj, attribute)
        return
    pytest.fail(f"the docs name {name}, which does not exist")
