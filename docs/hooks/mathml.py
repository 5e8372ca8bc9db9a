r"""MkDocs hook: the pages' equations rendered to MathML when the site is built.

``pymdownx.arithmatex`` (generic mode) finds the maths of a page, ``$...$`` inline and
``$$...$$`` as a block, and leaves it as ``<span class="arithmatex">\(...\)</span>`` and
``<div class="arithmatex">\[...\]</div>`` for a script to typeset in the browser.  Here it is
typeset at build time instead, by latex2mathml (pure Python) into MathML, which browsers draw
themselves (MathML Core: Chromium and Edge since 109, January 2023; Firefox and Safari long
before: MDN, "MathML", Baseline 2023).  The site then needs no script, font or stylesheet for
its maths, from a CDN or otherwise, and shows it offline.  An equation numbered with
``\tag{20}`` shows its number at the right, as in the paper.
"""

from __future__ import annotations

import html
import re

from latex2mathml.converter import convert

MATH = re.compile(
    r'<(?P<tag>span|div) class="arithmatex">\s*\\(?P<open>[(\[])(?P<tex>.*?)\\[)\]]\s*</(?P=tag)>',
    re.S,
)
TAG = re.compile(r"\\tag\{([^{}]*)\}")  # an equation's number, \tag{20}, shown at its right


def to_mathml(page_html: str) -> str:
    """``page_html`` with every arithmatex element replaced by its MathML."""

    def replace(match: re.Match) -> str:
        tex = html.unescape(match["tex"]).strip()
        if match["open"] == "(":
            return convert(tex, display="inline")
        tag = TAG.search(tex)
        number = f'<span class="equation-number">({tag[1]})</span>' if tag else ""
        mathml = convert(TAG.sub("", tex).strip(), display="block")
        return f'<div class="equation">{mathml}{number}</div>'

    return MATH.sub(replace, page_html)


def on_page_content(html_text, page, config, files):
    """Typeset the page's maths."""
    return to_mathml(html_text)
