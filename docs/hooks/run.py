"""MkDocs hook: the commands and Python blocks of the pages, run when the site is built.

A page marks a block to run by adding ``run`` to its fence's language::

    ```console run
    $ racket-impact sweep --points 9 --plot e_along_racket.png
    ```

    ```python run
    print("hello")
    ```

Each ``$ racket-impact ...`` line runs in this process (``studies.cli.main``, the function
behind the console command, so the solver is loaded once for the whole site), each Python
block in a fresh namespace, both in a scratch directory per page where ``examples/`` is the
project's (so a page can name ``examples/my_racket_specs.toml`` as a reader in the project
would) and the files an earlier block of the page wrote are still there.  The block becomes the
command or code, its real output, and every figure it drew (an image file a command wrote, or
the open matplotlib figures of a Python block), as generated files of the site.  A command
that exits with another status than expected (``exit=2`` after ``run``; 0 by default) or a
block that raises fails the build, with what it printed.

**Numbers in the prose come from the outputs.** The prose quotes what a block printed with a
marker the build fills: ``{{ output: TEXT }}`` becomes the number printed right after the first
``TEXT`` in the page's outputs (spaces and line breaks count as one space), so "e peaks at
{{ output: largest e = }}" reads "e peaks at 0.8872"; ``{{ code: module.NAME }}`` (or
``module.NAME:FORMAT``, ``:.3g``) becomes the value of a constant of the code: a default, or a
published number that the code holds beside its source; ``{{ given: 148 }}`` (or a range,
``{{ given: 135-147 }}``), the number as written, says that the number is no output of this
project: a source's (named beside it), a dataset's, a measurement's.  A marker that finds
nothing fails the build.

On the pages :data:`CHECKED` the rule is default-deny (:func:`loose_numbers`): every number of
the prose (not in code, a marker, a link's address, a DOI or an HTML comment) with at least
three significant digits (:func:`counted`: a year, 1900-2099, aside; a section, equation,
figure or table number is no prose, :func:`prose`) is a marker, or a number the page's blocks
typed (a command's flag, a Python argument, a value of an example file they read: an input),
or it fails the build: a hand-typed result goes stale as soon as the code changes, whether or
not a block prints it.  Shorter numbers (0.27, 10, 120) are too common in ranges, exponents and
round assumptions to tell a result from them; a page writes its results with markers all the
same.  The README, which GitHub shows with no build to fill a marker, is held to the older rule
(:func:`copied_numbers`): its prose copies no number its console blocks print.

The blocks run in ``on_files`` (the figures must be files of the site before the pages are
read, so that the strict build checks their links); ``on_page_markdown`` puts the results and
the quoted numbers in.
The output is wrapped in ``<div class="run-output">``, which ``tests/test_site.py`` looks for.
The build writes ``run-manifest.json`` into the site: for each page it ran, the fingerprint of
the page and of the code it ran (:func:`fingerprint`), so that ``tests/test_docs.py`` knows
which pages the site's build has already run as they are now, and runs the others itself
(:func:`run_page`, which needs no MkDocs); :func:`built_site` says which site the tests read.
"""

from __future__ import annotations

import contextlib
import hashlib
import io
import json
import os
import re
import shlex
import tempfile
import traceback
from pathlib import Path
from typing import NamedTuple

ROOT = Path(__file__).resolve().parents[2]
BLOCK = re.compile(
    r"^```(?P<lang>console|python) run(?P<options>[^\n]*)\n(?P<body>.*?)^```[ \t]*$", re.M | re.S
)
IMAGES = (".png", ".svg")
COLUMNS = "100"  # the width of --help, as a terminal of 100 columns shows it
_RESULTS: dict[str, Run] = {}  # page -> what its blocks made
_CACHE: dict[tuple[str, str], Run] = {}  # for mkdocs serve
_MANIFEST: dict[str, str] = {}  # page -> fingerprint, of the pages this build ran
MANIFEST = "run-manifest.json"
CODE = ("ball", "bat", "beam", "common", "racket", "studies", "examples")  # what the blocks run
CHECKED = ("guide/", "index.md", "python.md", "cli.md")  # pages whose prose types no result
SITE_VARIABLE = "RACKET_IMPACT_SITE"  # the built site the tests read (built_site)
MARKER = re.compile(r"\{\{\s*(?P<kind>[a-z]+):\s*(?P<what>.*?)\s*\}\}")
NUMBER = re.compile(r"(?<![\w.])\d+(?:,\d{3})*(?:\.\d+)?(?:[eE][-+]?\d+)?(?![\w]|\.\d)")
GIVEN = re.compile(f"-?{NUMBER.pattern}(?:-{NUMBER.pattern})?")  # {{ given: 135-147 }}
COMMENT = re.compile(r"(?:^|(?<=\s))#.*$", re.M)  # a Python or TOML comment
FENCE = re.compile(r"^[ \t]*(?P<fence>`{3,}|~{3,}).*?^[ \t]*(?P=fence)`*~*[ \t]*$", re.M | re.S)
NOT_PROSE = re.compile(
    r"<!--.*?-->"  # an HTML comment
    r"|(?P<ticks>`+).+?(?P=ticks)"  # inline code
    r"|\]\([^)]*\)"  # a link's address
    r"|<[^>\n]*>"  # an HTML tag
    r"|\b[a-z]+://\S+"  # an address in the text
    r"|\bdoi:\S+"  # a DOI
    r"|\b(?:Eqs?|Secs?|Figs?|Sections?|Tables?|Appendix)\.?\s*\d+(?:[-,]\s*\d+)*",  # a reference
    re.S,
)


class RunError(Exception):
    """A block failed: a command exited with another status than expected, or Python raised;
    or the prose copies an output or quotes one that is not there.
    """


class Run(NamedTuple):
    """What a page's blocks made."""

    results: list[str]
    """The Markdown each block becomes."""
    figures: dict[str, bytes]
    """The figures, by the name (relative to the page's directory) the Markdown links them by."""
    outputs: list[str]
    """What each command and each Python block printed."""
    inputs: str
    """What the blocks typed: their commands and code, and the example files they name."""


def built_site() -> Path | None:
    """The built site the tests read: the directory ``RACKET_IMPACT_SITE`` names (CI sets it for
    its run of the tests that need the site, after building it there); else none under CI (the
    README's own ``pytest``, run before any build); else site/ (a build by hand).
    """
    if os.environ.get(SITE_VARIABLE):
        return Path(os.environ[SITE_VARIABLE])
    return None if os.environ.get("CI") else ROOT / "site"


def fingerprint(text: str) -> str:
    """A digest of a page's text and of every file the blocks may run (the packages' Python
    and ``examples/``): equal digests, equal results.
    """
    digest = hashlib.sha256(text.encode())
    for folder in CODE:
        for path in sorted((ROOT / folder).rglob("*")):
            if path.is_file() and "__pycache__" not in path.parts:
                digest.update(path.relative_to(ROOT).as_posix().encode())
                digest.update(path.read_bytes())
    return digest.hexdigest()


def parse_options(text: str) -> dict[str, str]:
    """The ``key=value`` options after ``run`` in a fence (``exit=2``)."""
    options = dict(item.split("=", 1) for item in text.split() if "=" in item)
    unknown = set(options) - {"exit"}
    if unknown:
        raise RunError(f"unknown option {sorted(unknown)[0]!r} of a run block")
    return options


def commands(body: str) -> list[list[str]]:
    """The commands of a ``console run`` block: its ``$ `` lines, each split as a shell would."""
    lines = [line[2:] for line in body.splitlines() if line.startswith("$ ")]
    if not lines:
        raise RunError(f"a console run block has no '$ ' line:\n{body}")
    argvs = [shlex.split(line) for line in lines]
    for argv in argvs:
        if argv[0] != "racket-impact":
            raise RunError(f"a console run block runs racket-impact only, got {argv[0]!r}")
    return argvs


@contextlib.contextmanager
def _inside(directory: Path):
    """Run in ``directory``, with stdout and stderr captured and a terminal of COLUMNS."""
    out, err = io.StringIO(), io.StringIO()
    before, columns = Path.cwd(), os.environ.get("COLUMNS")
    os.environ["COLUMNS"] = COLUMNS
    os.chdir(directory)
    try:
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
            yield out, err
    finally:
        os.chdir(before)
        if columns is None:
            del os.environ["COLUMNS"]
        else:
            os.environ["COLUMNS"] = columns


def _images(directory: Path) -> dict[Path, int]:
    """The image files under ``directory`` (not in examples/) with their modification times."""
    found = {}
    for path in directory.rglob("*"):
        if path.suffix in IMAGES and path.parts[len(directory.parts)] != "examples":
            found[path] = path.stat().st_mtime_ns
    return found


def _new_images(directory: Path, before: dict[Path, int]) -> list[Path]:
    after = _images(directory)
    return sorted(p for p, mtime in after.items() if before.get(p) != mtime)


def run_command(argv: list[str], directory: Path) -> tuple[int, str]:
    """Run ``racket-impact ARGS`` in this process in ``directory``: its exit status and what
    it printed (stdout, then stderr).
    """
    from studies.cli import main

    with _inside(directory) as (out, err):
        try:
            status = main(argv[1:])
        except SystemExit as exit_:  # --help
            status = exit_.code if isinstance(exit_.code, int) else 0
    return status, out.getvalue() + err.getvalue()


def run_python(code: str, directory: Path, name: str) -> tuple[str, list[bytes]]:
    """Run a Python block in a fresh namespace in ``directory``: what it printed and the PNG
    of each figure it left open.
    """
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    plt.close("all")
    with _inside(directory) as (out, err):
        try:
            exec(compile(code, name, "exec"), {"__name__": "__main__"})
        except Exception:
            raise RunError(f"{name} raised:\n{traceback.format_exc()}") from None
    pngs = []
    for number in plt.get_fignums():
        buffer = io.BytesIO()
        plt.figure(number).savefig(buffer, format="png", dpi=96, bbox_inches="tight")
        pngs.append(buffer.getvalue())
    plt.close("all")
    return out.getvalue() + err.getvalue(), pngs


def _fence(lang: str, text: str, title: str | None = None) -> str:
    """A fenced block holding ``text``, with a fence longer than any backticks inside."""
    ticks = "`" * max(3, 1 + max((len(m) for m in re.findall(r"`+", text)), default=0))
    head = f'{ticks}{lang} title="{title}"' if title else f"{ticks}{lang}"
    return f"{head}\n{text.rstrip()}\n{ticks}\n"


def _wrap(parts: list[str]) -> str:
    """The Markdown of a block's output, in a div that ends with a marker (the site's tests
    read only what lies between the two).
    """
    return (
        '<div class="run-output" markdown>\n\n'
        + "\n".join(parts)
        + '\n\n<span class="run-end"></span>\n\n</div>\n'
    )


def load_kernel() -> None:
    """Compile or load the solver before any block runs, so that no output shows the
    one-off notice of its compilation.
    """
    with contextlib.suppress(ImportError), contextlib.redirect_stderr(io.StringIO()):
        from racket.solver import load_kernel as load

        load()


def _value(what: str) -> str:
    """The value of a constant of the code, ``module.NAME`` or ``module.NAME:FORMAT``
    (``ball.catalog.ITF_DROP_SPEED:.3g``), as the prose shows it.
    """
    import importlib

    name, _, spec = what.partition(":")
    parts = name.split(".")
    for split in range(len(parts) - 1, 0, -1):
        try:
            value = importlib.import_module(".".join(parts[:split]))
        except ImportError:
            continue
        for attribute in parts[split:]:
            if not hasattr(value, attribute):
                break
            value = getattr(value, attribute)
        else:
            if isinstance(value, int | float) and not isinstance(value, bool):
                return format(value, spec or "g")
            if isinstance(value, str):
                return format(value, spec)
            raise RunError(f"{{{{ code: {what} }}}} is a {type(value).__name__}")
    raise RunError(f"{{{{ code: {what} }}}}: no such constant in the code")


def _quoted(match: re.Match, printed: str) -> str:
    """The text a marker becomes (``printed``: the page's outputs, spaces collapsed)."""
    kind, what = match["kind"], match["what"]
    if kind == "code":
        return _value(what)
    if kind == "given":  # a number that is no output of this project (a source's)
        if not GIVEN.fullmatch(what):
            raise RunError(f"{match[0]!r}: a given number is a number, or a range N-M")
        return what
    if kind != "output":
        raise RunError(f"unknown marker {match[0]!r}: output, code or given")
    after = " ".join(what.split())
    found = re.search(re.escape(after) + r"\s*(-?" + NUMBER.pattern + ")", printed)
    if not found:
        raise RunError(f"{match[0]!r}: no output of the page prints a number after {after!r}")
    return found[1]


def quote(text: str, outputs: list[str]) -> str:
    """``text`` with its markers (``{{ output: TEXT }}``, ``{{ code: NAME }}``) filled."""
    printed = " ".join(" ".join(outputs).split())
    return MARKER.sub(lambda match: _quoted(match, printed), text)


def prose(text: str) -> str:
    """The prose of a page: its text but the fenced blocks, the markers, inline code, links'
    addresses, HTML tags and comments, addresses, DOIs and the numbers of references to a
    section, an equation, a figure or a table (Sec. 4, Eqs. 20-22).
    """
    return NOT_PROSE.sub(" ", MARKER.sub(" ", FENCE.sub(" ", text)))


def counted(number: str) -> bool:
    """Whether a number of the prose may be a copy of an output: it has at least three
    significant digits (16.5, 0.745, 139, 5,000,000; not 0.27, 10 or 120, too common to tell a
    copy from a coincidence) and is not a year (1900-2099).
    """
    mantissa = re.split(r"[eE]", number.replace(",", ""))[0]
    if re.fullmatch(r"(?:19|20)\d\d", mantissa):
        return False
    digits = mantissa.replace(".", "").lstrip("0")
    if "." not in mantissa:
        digits = digits.rstrip("0")  # an integer's trailing zeros are not significant
    return len(digits) >= 3


def _around(words: str, match: re.Match) -> str:
    """A number of the prose with the prose around it, for an error message."""
    around = words[max(0, match.start() - 50) : match.end() + 20]
    return f"{match[0]}: ... {' '.join(around.split())} ..."


def _numbers(text: str) -> set[str]:
    """The numbers of ``text``, without their thousands' commas."""
    return {n.replace(",", "") for n in NUMBER.findall(text)}


def copied_numbers(text: str, outputs: list[str], inputs: str = "") -> list[str]:
    """The numbers of ``text``'s prose that are copies of ``outputs`` (see :func:`counted`),
    each with the prose around it; the numbers of ``inputs`` (what the blocks typed) are not.
    The README's rule: GitHub shows it with no build to fill a marker.
    """
    printed = _numbers("\n".join(outputs)) - _numbers(inputs)
    words = prose(text)
    return [
        _around(words, m)
        for m in NUMBER.finditer(words)
        if counted(m[0]) and m[0].replace(",", "") in printed
    ]


def loose_numbers(text: str, inputs: str = "", outputs: tuple[str, ...] = ()) -> list[str]:
    """The numbers of ``text``'s prose (see :func:`counted`) that no marker put there and the
    page did not type (``inputs``), each with the prose around it, and "(printed)" after one
    that is also a number of ``outputs``: a hand-typed copy.  The checked pages' rule.
    """
    typed, printed = _numbers(inputs), _numbers("\n".join(outputs))
    words = prose(text)
    return [
        _around(words, m) + (" (printed)" if m[0].replace(",", "") in printed else "")
        for m in NUMBER.finditer(words)
        if counted(m[0]) and m[0].replace(",", "") not in typed
    ]


def check(text: str, page: str, run: Run) -> None:
    """Fail (:class:`RunError`) on a marker that finds nothing and, on the pages
    :data:`CHECKED`, on a number of the prose that no marker put there and no block typed.
    """
    quote(text, run.outputs)
    if page.startswith(CHECKED):
        loose = loose_numbers(text, run.inputs, tuple(run.outputs))
        if loose:
            raise RunError(
                f"{page}: the prose types numbers by hand (quote an output with "
                "{{ output: TEXT }}, a constant of the code with {{ code: NAME }}, mark a "
                "source's number {{ given: N }} with the source beside it, or leave the number "
                "out):\n  " + "\n  ".join(loose)
            )


def _typed(body: str) -> str:
    """What a block typed: its text and that of the example files it names, without their
    comments (a number in a comment is prose, not an input).
    """
    files = [ROOT / name for name in re.findall(r"examples/[\w.-]+", body)]
    return COMMENT.sub("", "\n".join([body, *(f.read_text() for f in files if f.is_file())]))


def run_page(text: str, page: str) -> Run:
    """Run every block of a page, then :func:`check` its prose."""
    load_kernel()
    stem = Path(page).with_suffix("").as_posix().replace("/", "-")
    figures: dict[str, bytes] = {}
    results, outputs, inputs = [], [], []
    with tempfile.TemporaryDirectory(prefix="racket-impact-docs-") as scratch:
        directory = Path(scratch)
        (directory / "examples").symlink_to(ROOT / "examples")
        for number, match in enumerate(BLOCK.finditer(text), start=1):
            options = parse_options(match["options"])
            body = match["body"]
            inputs.append(_typed(body))
            where = f"{page}, run block {number}"
            links = []
            if match["lang"] == "console":
                expected = int(options.get("exit", 0))
                session = []
                for argv in commands(body):
                    before = _images(directory)
                    status, output = run_command(argv, directory)
                    shown = " ".join(shlex.quote(a) for a in argv)
                    if status != expected:
                        raise RunError(
                            f"{where}: `{shown}` exited with {status}, not {expected}:\n{output}"
                        )
                    session.append(f"$ {shown}\n{output}".rstrip())
                    outputs.append(output)
                    for path in _new_images(directory, before):
                        links.append((path.name, path.read_bytes()))
                parts = [_fence("console", "\n".join(session))]
            else:
                output, pngs = run_python(body, directory, where)
                outputs.append(output)
                parts = [_fence("python", body)]
                if output.strip():
                    parts.append(_fence("text", output, title="output"))
                links = [(f"figure-{i}.png", png) for i, png in enumerate(pngs, start=1)]
            for k, (name, content) in enumerate(links, start=1):
                uri = f"run/{stem}-{number}-{k}-{name}"
                figures[uri] = content
                parts.append(f"![{name}]({uri})\n")
            results.append(_wrap(parts))
    run = Run(results, figures, outputs, "\n".join(inputs))
    check(text, page, run)
    return run


def on_files(files, config):
    """Run the blocks of every page; add their figures to the site's files."""
    from mkdocs.exceptions import PluginError
    from mkdocs.structure.files import File

    pages = [f for f in files.documentation_pages() if BLOCK.search(f.content_string)]
    _MANIFEST.clear()
    for file in pages:
        text = file.content_string
        key = (file.src_uri, text)
        if key not in _CACHE:
            try:
                _CACHE[key] = run_page(text, file.src_uri)
            except RunError as err:
                raise PluginError(str(err)) from None
        _MANIFEST[file.src_uri] = fingerprint(text)
        _RESULTS[file.src_uri] = _CACHE[key]
        folder = Path(file.src_uri).parent
        for uri, content in _CACHE[key].figures.items():
            files.append(File.generated(config, (folder / uri).as_posix(), content=content))
    return files


def on_page_markdown(markdown, page, config, files):
    """Put the numbers the prose quotes, then each block's results, in their places."""
    run = _RESULTS.get(page.file.src_uri)
    if run is None:
        return markdown
    results = iter(run.results)
    return BLOCK.sub(lambda match: next(results), quote(markdown, run.outputs))


def on_post_build(config):
    """Say which pages this build ran, and from what."""
    path = Path(config.site_dir) / MANIFEST
    path.write_text(json.dumps(_MANIFEST, indent=1, sort_keys=True) + "\n")
