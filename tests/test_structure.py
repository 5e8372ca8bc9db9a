"""The code's shape (issues 29 and 43): no module over 500 lines, no import circle between
modules, the physics packages (``ball``, ``beam``, ``racket``, ``bat``, ``common``) never
importing plotting, tables or the studies on top of them, and the rooms of the developer
guide's map (docs/developer.md, "The map of the code") each importing only the rooms below
it: no arrow upwards, none from ``racket`` to ``bat``, and the model never reaching into the
solver's rooms.

The import graph is read from the sources with :mod:`ast`: every import, at module level or
inside a function (a lazy import that closes a circle still closes it), each resolved to the
module that defines the imported name (``from racket import Racket`` is an edge to
``racket.racket``, not to the package's ``__init__`` that re-exports it).
"""

import ast
import importlib
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
PACKAGES = ("ball", "bat", "beam", "common", "racket", "studies")
PHYSICS = ("ball", "bat", "beam", "common", "racket")
"""The layers below ``studies``: SI floats and arrays, no plots and no tables."""

FORBIDDEN = ("matplotlib", "pandas", "studies")
MOST_LINES = 500


def _modules() -> dict[str, Path]:
    """Every module of the packages: dotted name -> file (a package is its ``__init__``)."""
    found = {}
    for package in PACKAGES:
        for path in sorted((ROOT / package).rglob("*.py")):
            parts = path.relative_to(ROOT).with_suffix("").parts
            found[".".join(parts[:-1] if parts[-1] == "__init__" else parts)] = path
    return found


MODULES = _modules()
_TREES: dict[str, ast.Module] = {}


def _tree(module: str) -> ast.Module:
    if module not in _TREES:
        _TREES[module] = ast.parse(MODULES[module].read_text(), str(MODULES[module]))
    return _TREES[module]


def _package(module: str) -> str:
    """The package a relative import in ``module`` starts from."""
    return module if MODULES[module].name == "__init__.py" else module.rpartition(".")[0]


def _absolute(module: str, node: ast.ImportFrom) -> str:
    """The module an ``import from`` names, relative imports resolved."""
    if not node.level:
        return node.module or ""
    base = _package(module)
    for _ in range(node.level - 1):
        base = base.rpartition(".")[0]
    return f"{base}.{node.module}" if node.module else base


def _top(tree: ast.Module) -> list[ast.stmt]:
    """A module's top-level statements, with those under ``if TYPE_CHECKING:`` (where a
    package whose names load on first use, :mod:`common.lazy`, re-exports them)."""
    guarded = [
        node.body
        for node in tree.body
        if isinstance(node, ast.If) and ast.unparse(node.test) == "TYPE_CHECKING"
    ]
    return [*tree.body, *(statement for body in guarded for statement in body)]


def _defining(module: str, name: str, seen=()) -> str:
    """The module that defines ``name`` as ``module`` offers it: followed through the
    package's re-exports (``from racket.racket import Racket`` in ``racket/__init__.py``).
    """
    if f"{module}.{name}" in MODULES:
        return f"{module}.{name}"
    for node in _top(_tree(module)):
        if isinstance(node, ast.ImportFrom) and (module, name) not in seen:
            source = _absolute(module, node)
            for alias in node.names:
                if (alias.asname or alias.name) == name and source in MODULES:
                    return _defining(source, alias.name, (*seen, (module, name)))
    return module


def _imports(module: str):
    """Each import anywhere in ``module``: (the module as written, the module it reaches in
    the packages or None)."""
    for node in ast.walk(_tree(module)):
        if isinstance(node, ast.Import):
            for alias in node.names:
                yield alias.name, _known(alias.name)
        elif isinstance(node, ast.ImportFrom):
            source = _absolute(module, node)
            for alias in node.names:
                if source in MODULES:
                    yield source, _defining(source, alias.name)
                else:
                    yield source, _known(source)


def _known(name: str) -> str | None:
    """``name`` or its closest enclosing module among the packages', None outside them."""
    while name and name not in MODULES:
        name = name.rpartition(".")[0]
    return name or None


def _graph() -> dict[str, set[str]]:
    return {
        module: {target for _, target in _imports(module) if target not in (None, module)}
        for module in MODULES
    }


def _circles(graph: dict[str, set[str]]) -> list[list[str]]:
    """The strongly connected components of more than one module (Tarjan's algorithm)."""
    index, low, stack, on_stack, found = {}, {}, [], set(), []

    def visit(node):
        index[node] = low[node] = len(index)
        stack.append(node)
        on_stack.add(node)
        for nxt in sorted(graph.get(node, ())):
            if nxt not in index:
                visit(nxt)
                low[node] = min(low[node], low[nxt])
            elif nxt in on_stack:
                low[node] = min(low[node], index[nxt])
        if low[node] == index[node]:
            component = []
            while True:
                top = stack.pop()
                on_stack.discard(top)
                component.append(top)
                if top == node:
                    break
            if len(component) > 1:
                found.append(sorted(component))

    for node in sorted(graph):
        if node not in index:
            visit(node)
    return found


def _lines(path: Path) -> int:
    return len(path.read_text().splitlines())


def test_the_packages_are_found():
    assert {"racket.racket", "racket.system", "studies.cli", "beam", "common.units"} <= set(MODULES)


def test_no_module_over_500_lines():
    long = {
        str(path.relative_to(ROOT)): _lines(path)
        for path in MODULES.values()
        if _lines(path) > MOST_LINES
    }
    assert long == {}


def test_no_import_circle():
    assert _circles(_graph()) == []


def test_the_circle_finder_finds_a_circle_and_resolves_re_exports():
    assert _circles({"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}}) == [["a", "b", "c"]]
    assert _circles({"a": {"b"}, "b": set()}) == []
    assert _defining("racket", "Racket") == "racket.racket"  # through racket/__init__.py
    assert "racket.hand" in _graph()["racket.system"]  # the hand from its own module
    assert "racket.system" in _graph()["racket.racket"]


@pytest.mark.parametrize("package", PHYSICS)
def test_the_physics_never_imports_plots_tables_or_studies(package):
    reached = {
        f"{module}: {name}"
        for module in MODULES
        if module.split(".")[0] == package
        for name, _ in _imports(module)
        if name.split(".")[0] in FORBIDDEN
    }
    assert reached == set()


SOLVER = "racket.solver"
SOLVER_USERS = ("racket", "racket.feel")
"""The model modules that use the solver (its public face only): the package's own face
(``impact`` re-exported) and the feel, which computes with impacts."""


def _in_solver(module: str) -> bool:
    return module == SOLVER or module.startswith(SOLVER + ".")


def test_the_solver_has_its_own_room_and_the_model_never_imports_it():
    """The racket's description (racket/, outside racket/solver/) never imports the
    time-stepping machinery; the feel and the package's face use its public face only."""
    model = [m for m in MODULES if m.split(".")[0] == "racket" and not _in_solver(m)]
    assert {"racket.racket", "racket.system", "racket.hand", "racket.swing"} <= set(model)
    reached = {
        f"{module}: {name}"
        for module in model
        for name, _ in _imports(module)
        if _in_solver(name) and (module not in SOLVER_USERS or name != SOLVER)
    }
    assert reached == set()


def test_outside_racket_only_the_solvers_public_face_is_used():
    """The studies (and the docs' hooks) reach the solver through ``racket.solver`` itself,
    never its rooms; the tests and benchmarks may look inside."""
    face = set(importlib.import_module(SOLVER).__all__)
    inside = {
        f"{module}: {name}"
        for module in MODULES
        if module.split(".")[0] not in ("racket",)
        for name, _ in _imports(module)
        if _in_solver(name) and name != SOLVER
    }
    assert inside == set()
    used = set()
    for module in (m for m in MODULES if not _in_solver(m)):
        for node in ast.walk(_tree(module)):
            if isinstance(node, ast.ImportFrom) and node.module == SOLVER:
                used |= {alias.name for alias in node.names}
    assert used <= face


ROOMS = {
    "common": set(),
    "beam": {"common"},
    "ball": {"common", "beam"},
    "racket.strings": {"common", "ball"},
    "racket": {"common", "beam", "ball", "racket.strings", "racket.specs", "racket.solver"},
    "racket.specs": {"common", "beam", "racket", "racket.strings"},
    "racket.solver": {"common", "ball", "racket", "racket.strings"},
    "bat": {"common", "beam", "ball", "racket"},
}
"""The physics' rooms (docs/developer.md, "The map of the code") and the rooms each may
import.  ``racket`` and ``racket.specs`` import each other's modules (a preset is a fitted
spec sheet; a fit builds a racket), never in a circle of modules (the test above)."""

STUDIES_TOP = {"studies.cli": ("studies.entry",), "studies.page": ("studies.cli.app",)}
"""The top of the studies: the command line, reached only by the console entry point, and
the page, reached only by the command line's ``app``."""


def _room(module: str) -> str:
    """The room of the map that holds ``module``: its longest enclosing room."""
    rooms = [*ROOMS, *STUDIES_TOP, "studies"]
    return max((r for r in rooms if module == r or module.startswith(r + ".")), key=len, default="")


def test_every_module_has_a_room():
    assert {m for m in MODULES if not _room(m)} == set()


def test_each_physics_room_imports_only_the_rooms_below_it():
    graph = _graph()
    upwards = {
        f"{module} -> {target}"
        for module, targets in graph.items()
        if _room(module) in ROOMS
        for target in targets
        if _room(target) != _room(module) and _room(target) not in ROOMS[_room(module)]
    }
    assert upwards == set()


def test_a_racket_never_imports_a_bat():
    """Bats build on the racket's hand, block system and solver; nothing of the racket (or
    below it) knows a bat: the solver strikes either through :class:`racket.implement.Implement`."""
    graph = _graph()
    reached = {
        f"{module} -> {target}"
        for module in MODULES
        if module.split(".")[0] in ("common", "beam", "ball", "racket")
        for target in graph[module]
        if target.split(".")[0] == "bat"
    }
    assert reached == set()
    assert {"racket.racket", "bat.bat"} <= {
        m for m in MODULES if "racket.implement" in graph[m]
    }  # both implements derive from the solver's face


def test_the_command_line_and_the_page_are_the_top():
    graph = _graph()
    reached = {
        f"{module} -> {target}"
        for module, targets in graph.items()
        for target in targets
        for top, users in STUDIES_TOP.items()
        if _room(target) == top and _room(module) != top and module not in users
    }
    assert reached == set()


def test_the_rooms_finder_and_the_layers_can_fail():
    assert _room("racket.strings.bed") == "racket.strings"
    assert _room("racket.solver.driver") == "racket.solver"
    assert _room("studies.page.app") == "studies.page"
    assert _room("studies.face.maps") == "studies"
    assert "bat" not in ROOMS["racket"] and "racket" in ROOMS["bat"]


def test_the_studies_root_holds_only_what_serves_many_jobs():
    """Issue 43: the page, the bats, the strings, the strokes and the face each have a room;
    at most 20 modules stay at ``studies/``' root, none of them named for one job."""
    root = sorted(p.stem for p in (ROOT / "studies").glob("*.py"))
    assert len(root) <= 20, root
    assert [n for n in root if n.startswith(("page_", "bat_", "plots_"))] == []
