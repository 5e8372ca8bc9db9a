"""MkDocs hook: the API reference of a package, from the package as it is when the site is built.

A page holding ``<!-- api-reference: racket -->`` gets, in its place, a mkdocstrings
``:::`` entry for the package and for each of its public modules, found by reading the
source (Griffe, nothing imported), so a module that is added, moved or renamed is documented
where it now is without editing the page.  Each object is rendered once: a package shows
what its ``__all__`` exports, and a module the public objects it defines that no package
above it exports already (a module whose objects all are shows its docstring only).
"""

from __future__ import annotations

import re
from collections.abc import Iterator
from pathlib import Path

import griffe

ROOT = Path(__file__).resolve().parents[2]
MARKER = re.compile(r"^<!-- api-reference: (?P<package>[\w.]+) -->$", re.M)


def _target(obj: griffe.Object | griffe.Alias) -> str:
    """Where ``obj`` is defined: an alias followed to its end (``racket.impact`` through
    ``racket.solver.impact`` to ``racket.solver.driver.impact``), or as far as it resolves.
    """
    if not obj.is_alias:
        return obj.path
    try:
        return obj.final_target.path
    except (griffe.AliasResolutionError, griffe.CyclicAliasError):
        return obj.target_path


def _exported(module: griffe.Module) -> set[str]:
    """The paths of the objects a module's ``__all__`` names (empty without one)."""
    names = [str(name) for name in module.exports or ()]
    return {_target(module.members[n]) for n in names if n in module.members}


def _modules(module: griffe.Module) -> Iterator[griffe.Module]:
    """``module`` and its public submodules, depth first, in name order."""
    yield module
    for name, member in sorted(module.modules.items()):
        if not name.startswith("_") and not member.is_alias:  # not a module it imports
            yield from _modules(member)


def _entry(path: str, members: list[str]) -> str:
    if not members:
        return f"::: {path}\n    options:\n      members: false\n"
    listed = "".join(f"        - {name}\n" for name in members)
    return f"::: {path}\n    options:\n      members:\n{listed}"


def _members(module: griffe.Module, above: set[str]) -> list[str]:
    """The objects ``module`` documents: what its ``__all__`` names, or else the public
    objects it defines, less what a package above it exports.
    """
    if module.exports is not None:
        names = [str(name) for name in module.exports if str(name) in module.members]
    else:
        names = [m.name for m in module.members.values() if not m.is_alias and not m.is_module]
    return [n for n in names if not n.startswith("_") and _target(module.members[n]) not in above]


def reference(package: str) -> str:
    """The mkdocstrings entries of a package's reference."""
    root = griffe.load(package, search_paths=[str(ROOT)], resolve_aliases=False)
    entries = []
    for module in _modules(root):
        above = set()
        parent = module.parent
        while parent is not None:
            above |= _exported(parent)
            parent = parent.parent
        entries.append(_entry(module.path, _members(module, above)))
    return "\n".join(entries)


def on_page_markdown(markdown, page, config, files):
    """Replace each marker by its package's reference."""
    return MARKER.sub(lambda match: reference(match["package"]), markdown)
