"""Every public function and class documents each of its parameters in a numpydoc section
(as python-control's docstring test does), every number with its unit in brackets; the
checkers themselves are shown to fail on a docstring that lost a parameter or a unit
(issue 15)."""

import importlib
import inspect
import pkgutil
import re
import warnings

import pytest
from numpydoc.docscrape import ClassDoc, FunctionDoc

PACKAGES = ("ball", "bat", "beam", "racket", "studies", "common")
SKIP_MODULES = ("studies.page.app", "studies.cli")  # the page's callbacks, the argparse layer (all)


NUMERIC = re.compile(r"\b(float|complex|array|ndarray|array_like)\b")
"""Types that carry a physical quantity (ints are counts and indices)."""

UNIT = re.compile(r"\[([^\[\]]+)\]")
"""A unit in brackets: ``[kg]``, ``[m/s]``; ``[-]`` for a dimensionless number, ``[SI]`` for
an array whose rows hold different quantities, each in SI."""

RANGE = re.compile(r"^\s*[-+]?[\d.]+(e[-+]?\d+)?\s*,")
"""A bracket that opens with a number and a comma is a range (``[0, 1]``), not a unit."""


def _has_unit(text: str) -> bool:
    return any(not RANGE.match(inside) for inside in UNIT.findall(text))


def _doc(obj):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return ClassDoc(obj) if inspect.isclass(obj) else FunctionDoc(obj)


def _items(doc):
    return [
        item
        for section in ("Parameters", "Other Parameters", "Attributes")
        for item in doc[section]
    ]


def without_unit(obj) -> list[str]:
    """The documented numeric parameters of ``obj`` whose type or description gives no unit
    in brackets."""
    return [
        item.name
        for item in _items(_doc(obj))
        if NUMERIC.search(item.type) and not _has_unit(" ".join([item.type, *item.desc]))
    ]


def undocumented(obj) -> list[str]:
    """The parameters of ``obj``'s signature that its docstring's Parameters, Other
    Parameters or Attributes sections do not name."""
    try:
        signature = inspect.signature(obj)
    except (TypeError, ValueError):
        return []
    names = [
        name
        for name, p in signature.parameters.items()
        if name not in ("self", "cls")
        and not name.startswith("_")
        and p.kind not in (p.VAR_KEYWORD, p.VAR_POSITIONAL)
    ]
    documented = {part.strip() for item in _items(_doc(obj)) for part in item.name.split(",")}
    return [name for name in names if name not in documented]


def _public():
    for package in PACKAGES:
        root = importlib.import_module(package)
        for info in pkgutil.walk_packages(root.__path__, f"{package}."):
            if any(info.name == m or info.name.startswith(f"{m}.") for m in SKIP_MODULES):
                continue
            module = importlib.import_module(info.name)
            for name, obj in vars(module).items():
                public = not name.startswith("_") and getattr(obj, "__module__", "") == info.name
                if public and (inspect.isfunction(obj) or inspect.isclass(obj)):
                    yield f"{info.name}.{name}", obj


def test_the_checker_catches_a_parameter_missing_from_a_docstring():
    def documented(mass, speed=1.0):
        """A fixture.

        Parameters
        ----------
        mass : float
            Ball mass [kg].
        speed : float
            Ball speed [m/s].
        """

    def one_lost(mass, speed=1.0):
        """A fixture.

        Parameters
        ----------
        mass : float
            Ball mass [kg].
        """

    assert undocumented(documented) == []
    assert undocumented(one_lost) == ["speed"]


def test_the_checker_catches_a_number_without_its_unit():
    def with_units(mass, e, count):
        """A fixture.

        Parameters
        ----------
        mass : float
            Ball mass [kg].
        e : float
            Coefficient of restitution [-].
        count : int
            How many.
        """

    def unit_lost(mass, e, count):
        pass

    # The same docstring, the unit of e lost: only a range in brackets.
    unit_lost.__doc__ = with_units.__doc__.replace("restitution [-]", "restitution, in [0, 1]")
    assert without_unit(with_units) == []
    assert without_unit(unit_lost) == ["e"]  # a range in brackets is not a unit


@pytest.mark.parametrize(
    "name, obj", list(_public()), ids=lambda v: v if isinstance(v, str) else ""
)
def test_every_public_parameter_is_documented(name, obj):
    assert undocumented(obj) == [], f"{name}: parameters missing from the docstring"
    assert without_unit(obj) == [], f"{name}: numbers without a unit in brackets"
