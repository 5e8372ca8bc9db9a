"""A package whose public names load on first use (PEP 562), so that importing it loads
nothing heavy: ``import racket`` takes no numpy, scipy or numba, and ``racket.Racket`` (or
``from racket import Racket``) imports :mod:`racket.racket` then, once.

The package keeps its imports under ``if TYPE_CHECKING:`` for the readers of its source
(type checkers, Griffe for the API reference, ``tests/test_structure.py``), and hands the
same names, by module, to :func:`lazy_names` (``tests/test_lazy_start.py`` checks that the
two lists and ``__all__`` agree).
"""

from __future__ import annotations

import importlib
import sys


def lazy_names(package: str, modules: dict[str, tuple[str, ...]]) -> tuple:
    """The module-level ``__getattr__`` and ``__dir__`` of a package whose public names
    load on first use: each name is imported from its module when first asked for, then
    kept on the package; a submodule not yet imported (``racket.specs``) is imported when
    named, as an eager package's imports would have left it there.

    Parameters
    ----------
    package : str
        The package's name (its ``__name__``).
    modules : dict
        Each module that defines public names of the package -> those names.

    Returns
    -------
    tuple
        ``(__getattr__, __dir__)``, to assign at the package's top level.
    """
    where = {name: module for module, names in modules.items() for name in names}

    def __getattr__(name: str):
        if name in where:
            value = getattr(importlib.import_module(where[name]), name)
            setattr(sys.modules[package], name, value)  # (found at once from now on)
            return value
        if not name.startswith("_"):
            try:
                return importlib.import_module(f"{package}.{name}")
            except ModuleNotFoundError as err:
                if err.name != f"{package}.{name}":
                    raise
        raise AttributeError(f"module {package!r} has no attribute {name!r}")

    def __dir__() -> list[str]:
        return sorted({*vars(sys.modules[package]), *where})

    return __getattr__, __dir__
