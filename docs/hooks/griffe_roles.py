"""Griffe extension: the docstrings' Sphinx roles become links of the API reference.

The docstrings cross-reference as Sphinx does, ``:class:`LinearSpring```,
``:func:`~racket.specs.ra.f1_from_ra```, ``:mod:`studies.outputs```; mkdocstrings reads
Markdown and would print the roles as they are.  No maintained Griffe extension converts them
(griffe-sphinx reads Sphinx's attribute comments, not roles; mkdocstrings-python-xref adds a
relative syntax of its own), so this one does, when Griffe has loaded a package and before
any docstring is parsed: each role becomes an *optional* cross-reference of mkdocs-autorefs,
``<autoref identifier="ball.laws.LinearSpring" optional><code>LinearSpring</code></autoref>``,
which autorefs turns into a link to the object's entry in the reference, or into plain code
when the object is not rendered there (a private helper, another library), never into an
error.  A name written short is looked up as Python would from where the docstring is: the
object's own members, then its parents' (the module's imports included), and an imported
name becomes the path of what it imports.  ``~`` shows the last part only, as in Sphinx, and
``title <target>`` a title of its own.
"""

from __future__ import annotations

import html
import re
from collections.abc import Callable, Iterator

import griffe

ROLE = re.compile(r":(?:py:)?(?:class|func|meth|attr|mod|data|exc|obj|const):`(?P<body>[^`]+)`")
PACKAGES = {"ball", "bat", "beam", "common", "racket", "studies"}


def convert(text: str, resolve: Callable[[str], str]) -> str:
    """``text`` with every Sphinx role made an optional autorefs cross-reference.

    Parameters
    ----------
    text : str
        A docstring.
    resolve : callable
        The full identifier of a target as written in the role (``~`` and leading dots
        removed).
    """

    def replace(match: re.Match) -> str:
        body = match["body"].strip()
        explicit = re.fullmatch(r"(?P<title>.+?)\s*<(?P<target>[^<>]+)>", body)
        target = re.sub(r"\s+", "", explicit["target"] if explicit else body)  # over two lines
        short = target.startswith("~")
        target = target.lstrip("~!.")
        title = " ".join(explicit["title"].split()) if explicit else target
        title = target.rsplit(".", 1)[-1] if short and not explicit else title
        identifier = html.escape(resolve(target), quote=True)
        code = f"<code>{html.escape(title)}</code>"
        return f'<autoref identifier="{identifier}" optional>{code}</autoref>'

    return ROLE.sub(replace, text)


def resolver(obj: griffe.Object) -> Callable[[str], str]:
    """How a target named in ``obj``'s docstring resolves: a name of this project's packages
    as it is; else its first part looked up in ``obj`` and its parents, an imported name
    replaced by the path it imports; a name found nowhere as it is.
    """

    def resolve(target: str) -> str:
        head, dot, rest = target.partition(".")
        if head in PACKAGES:
            return target
        scope = obj
        while scope is not None:
            member = _members(scope).get(head)
            if member is not None:
                path = member.target_path if member.is_alias else member.path
                return path + dot + rest
            scope = scope.parent
        return target

    return resolve


def _members(scope: griffe.Object) -> dict:
    """The members of ``scope``, a class's inherited ones included where Griffe can find
    its bases.
    """
    try:
        return scope.all_members
    except (griffe.AliasResolutionError, griffe.CyclicAliasError):
        return scope.members


def _objects(obj: griffe.Object) -> Iterator[griffe.Object]:
    """``obj`` and every object defined in it (imported names are not: their docstrings are
    converted where they are defined).
    """
    yield obj
    for member in obj.members.values():
        if not member.is_alias:
            yield from _objects(member)


class SphinxRoles(griffe.Extension):
    """Convert the Sphinx roles of a package's docstrings once it is loaded."""

    def on_package(self, *, pkg: griffe.Module, **kwargs) -> None:
        """Convert every docstring of ``pkg``."""
        for obj in _objects(pkg):
            if obj.docstring is not None and ROLE.search(obj.docstring.value):
                obj.docstring.value = convert(obj.docstring.value, resolver(obj))
