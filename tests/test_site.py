"""The documentation site (issue 29): what the build made, read from the built site, and the
build's own tools (docs/hooks/).

The site tests need ``mkdocs build`` to have run, and the tools' tests the ``docs`` extra
(griffe, latex2mathml): without them they are skipped, with the reason.  Which site they read
is :func:`built_site` of docs/hooks/run.py: the one ``RACKET_IMPACT_SITE`` names (CI sets it
for its second run of these tests, after building the site: there a missing site fails), else
site/ when run by hand.  The README's own ``pytest`` (``[test]`` only) skips them.
"""

import importlib.util
import os
import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
DOCS = ROOT / "docs"
ROLE = re.compile(r":(?:py:)?(?:class|func|meth|attr|mod|data|exc|obj|const):`")


def _hook(name):
    """A module of the site's build (docs/hooks/), imported from its file (skipped, with the
    reason, when a tool it needs is not installed: the ``docs`` extra)."""
    needs = {"api": "griffe", "griffe_roles": "griffe", "mathml": "latex2mathml"}
    if name in needs:
        pytest.importorskip(needs[name], reason=f"docs/hooks/{name}.py needs the docs extra")
    spec = importlib.util.spec_from_file_location(
        f"docs_hook_{name}", DOCS / "hooks" / f"{name}.py"
    )
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


@pytest.fixture(scope="module")
def site():
    built = _hook("run").built_site()
    if built is None or not (built / "index.html").exists():
        if os.environ.get("RACKET_IMPACT_SITE"):
            pytest.fail(f"RACKET_IMPACT_SITE={built} holds no built site (.ci/run builds it)")
        pytest.skip("no built site: run `MPLBACKEND=Agg mkdocs build` first (the docs extra)")
    return built


def _html(path: Path) -> str:
    return path.read_text(encoding="utf-8")


def _page(site: Path, source: str) -> Path:
    """The HTML file of a docs page (``guide/serve.md`` -> site/guide/serve/index.html)."""
    stem = source.removesuffix(".md")
    return site / ("index.html" if stem == "index" else f"{stem}/index.html")


# --- the built site -----------------------------------------------------------------------


def test_the_api_reference_has_no_sphinx_roles_and_links_them(site):
    pages = sorted((site / "api").glob("*/index.html"))
    assert {p.parent.name for p in pages} >= {"ball", "bat", "beam", "racket", "studies", "common"}
    for page in pages:
        html = _html(page)
        left = ROLE.findall(html)
        assert not left, f"{page.relative_to(site)} prints Sphinx roles: {left[:3]}"
    # a role of ball.collide's docstring, :class:`LinearSpring`, is a link to the class
    ball = _html(site / "api/ball/index.html")
    assert re.search(
        r'<a class="autorefs autorefs-internal"[^>]*href="[^"]*#ball\.(\w+\.)?LinearSpring"', ball
    )
    links = sum(_html(p).count("autorefs-internal") for p in pages)
    assert links > 300


def _requests(html: str) -> list[str]:
    """What a page loads by itself: scripts, stylesheets and other <link>s, images, frames,
    media, and CSS @import and url()."""
    found = re.findall(
        r"<(?:script|img|iframe|source|audio|video|embed)\b[^>]*\bsrc=[\"']([^\"']+)", html
    )
    for tag in re.findall(r"<link\b[^>]*>", html):
        href = re.search(r"\bhref=[\"']([^\"']+)", tag)
        if href and not re.search(r"\brel=[\"']?(?:canonical|alternate|prev|next)\b", tag):
            found.append(href[1])
    found += re.findall(r"@import\s+(?:url\()?[\"']?([^\"')\s;]+)", html)
    found += re.findall(r"url\(\s*[\"']?([^\"')]+)", html)
    return found


def test_the_site_makes_no_request_off_the_machine(site):
    """No script, stylesheet, font, image or @import from another host: the site, its maths
    included, works offline."""
    off = []
    for path in sorted(site.rglob("*")):
        if path.suffix in {".html", ".css"}:
            for url in _requests(_html(path)):
                if re.match(r"(?:[a-z][a-z0-9+.-]*:)?//", url, re.I) or url.lower().startswith(
                    ("http:", "https:")
                ):
                    off.append(f"{path.relative_to(site)}: {url}")
    assert not off, "requests off the machine:\n" + "\n".join(off[:20])


def test_the_maths_is_typeset_when_the_site_is_built(site):
    html = _html(site / "physics/index.html")
    assert html.count("<math") >= 50 and 'class="equation-number">(21)' in html
    assert 'class="arithmatex"' not in html and "\\(" not in html


def _run_outputs(html: str) -> list[str]:
    """What each block the build ran made (docs/hooks/run.py wraps it between a div and an
    end marker): the page between the two, no further."""
    parts = html.split('<div class="run-output">')[1:]
    assert all('class="run-end"' in part for part in parts), "an output without its end"
    return [part.split('class="run-end"')[0] for part in parts]


@pytest.mark.parametrize(
    "source",
    [
        *sorted(p.relative_to(DOCS).as_posix() for p in DOCS.glob("guide/*.md")),
        *["cli.md", "toml.md", "python.md", "validation.md"],
    ],
)
def test_every_guide_page_shows_output_or_a_figure_the_build_made(site, source):
    """Each worked example's output and figures come from the build (docs/hooks/run.py):
    a console block shows more than its command, a figure is a file of the site."""
    page = _page(site, source)
    outputs = _run_outputs(_html(page))
    assert outputs, f"{source} has no output made by the build"
    made = "".join(outputs)  # only what the build made
    printed = made.count('<span class="go">') + made.count('<span class="filename">output</span>')
    figures = re.findall(r'<img [^>]*src="((?:\.\./)*run/[^"]+)"', made)
    for src in figures:
        assert (page.parent / src).resolve().stat().st_size > 1000, src
    assert printed + len(figures) >= 1, f"{source}: no output nor figure made by the build"


def test_the_cli_page_shows_every_commands_help(site):
    html = _html(site / "cli/index.html")
    commands = re.search(r"\{([a-z,]+)\}", html)[1].split(",")
    assert len(commands) >= 15
    for command in commands:
        assert (
            f'racket-impact<span class="w"> </span>{command}<span class="w"> </span>--help' in html
        )
        assert f"usage: racket-impact {command}" in html, f"no --help of {command} on the CLI page"


# --- the sources of the pages --------------------------------------------------------------


def test_the_input_files_page_names_every_key_law_and_preset():
    from racket import GRIPS
    from studies import config
    from studies.strings import inputs as string_inputs

    text = (DOCS / "toml.md").read_text()
    keys = set().union(
        config._RACKET_KEYS, string_inputs.STRING_KEYS, config._SPEC_KEYS, config._LEAD_KEYS,
        config._HAND_KEYS, config._BALL_KEYS,
    )  # fmt: skip
    names = keys | set(config.LAWS) | set(config.RACKETS) | set(config.BALLS) | set(GRIPS)

    def named(n):
        return any(f in text for f in (f"`{n}`", f'`"{n}"`', f"[racket.{n}]"))

    missing = sorted(n for n in names if not named(n))
    assert not missing, f"docs/toml.md does not name {missing}"


def test_the_cli_page_asks_every_command_for_its_help(capsys):
    from studies.cli import main

    with pytest.raises(SystemExit):
        main(["--help"])
    commands = re.search(r"\{([a-z,]+)\}", capsys.readouterr().out)[1].split(",")
    text = (DOCS / "cli.md").read_text()
    missing = [c for c in commands if f"$ racket-impact {c} --help" not in text]
    assert not missing, f"docs/cli.md has no `--help` block of {missing}"


# --- the build's tools ---------------------------------------------------------------------


def test_sphinx_roles_become_optional_cross_references():
    roles = _hook("griffe_roles")
    resolve = {"LinearSpring": "ball.laws.LinearSpring", "racket.impact": "racket.impact"}.get
    text = roles.convert(
        "See :class:`LinearSpring`, :func:`~racket.impact` and"
        " :mod:`the outputs <studies.outputs>`.",
        lambda target: resolve(target) or target,
    )
    assert not roles.ROLE.search(text)
    assert (
        '<autoref identifier="ball.laws.LinearSpring" optional><code>LinearSpring</code></autoref>'
        in text
    )
    assert '<autoref identifier="racket.impact" optional><code>impact</code></autoref>' in text
    assert (
        '<autoref identifier="studies.outputs" optional><code>the outputs</code></autoref>' in text
    )


def test_a_short_name_resolves_where_the_docstring_is():
    """An imported name becomes the path of what it imports; a member of the class, its
    path; a name found nowhere stays as written."""
    roles = _hook("griffe_roles")
    import griffe

    package = griffe.load("ball", search_paths=[str(ROOT)])
    collision = package["collision"]  # which imports SineLaw from ball.laws
    assert roles.resolver(collision)("SineLaw") == "ball.laws.SineLaw"
    assert roles.resolver(collision)("SineLaw.force") == "ball.laws.SineLaw.force"
    law = package["laws"]["PowerLawHysteresis"]
    method = next(m for m in law.members.values() if m.is_function)
    assert roles.resolver(method)(method.name) == f"ball.laws.PowerLawHysteresis.{method.name}"
    assert roles.resolver(method)("numpy.ndarray") == "numpy.ndarray"
    assert roles.resolver(method)("racket.impact") == "racket.impact"


def test_equations_become_mathml_with_their_numbers():
    mathml = _hook("mathml")
    html = mathml.to_mathml(
        '<p>then <span class="arithmatex">\\(e_A &lt; e\\)</span></p>'
        '<div class="arithmatex">\\[ e = \\frac{V_1 + V_2}{v_1} \\tag{21} \\]</div>'
    )
    assert "arithmatex" not in html and html.count("<math") == 2
    assert "<mo>&#x0003C;</mo>" in html or "<mo>&lt;</mo>" in html
    assert '<span class="equation-number">(21)</span>' in html and "tag" not in html


def test_the_api_reference_lists_every_public_module_once():
    api = _hook("api")
    entries = api.reference("racket")
    modules = re.findall(r"^::: ([\w.]+)$", entries, re.M)
    assert modules[0] == "racket" and len(modules) == len(set(modules))
    on_disk = set()
    for path in (ROOT / "racket").rglob("*.py"):
        parts = path.relative_to(ROOT).with_suffix("").parts
        parts = parts[:-1] if parts[-1] == "__init__" else parts
        if not any(part.startswith("_") for part in parts):
            on_disk.add(".".join(parts))
    assert set(modules) == on_disk
    # racket.impact is documented once, where the package exports it
    assert entries.count("- impact\n") == 1


def test_a_run_block_that_fails_fails_the_build(tmp_path):
    run = _hook("run")
    with pytest.raises(run.RunError, match="exited with 2, not 0"):
        run.run_page("```console run\n$ racket-impact sweep --speed-mph -10\n```\n", "bad.md")
    with pytest.raises(run.RunError, match="ZeroDivisionError"):
        run.run_page("```python run\n1 / 0\n```\n", "bad.md")
    with pytest.raises(run.RunError, match="racket-impact only"):
        run.run_page("```console run\n$ rm -rf /\n```\n", "bad.md")
    made = run.run_page(
        "```console run exit=2\n$ racket-impact sweep --speed-mph -10\n```\n"
        "```python run\nimport matplotlib.pyplot as plt\nprint('drawn')\nplt.plot([0, 1])\n```\n",
        "good.md",
    )
    assert "--speed-mph must be in" in made.results[0] and "drawn" in made.results[1]
    assert "--speed-mph must be in" in made.outputs[0] and made.outputs[1] == "drawn\n"
    assert (
        list(made.figures) == ["run/good-2-1-figure-1.png"]
        and made.figures["run/good-2-1-figure-1.png"][:4] == b"\x89PNG"
    )
