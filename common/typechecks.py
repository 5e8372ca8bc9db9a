"""Checks of an argument's kind, shared by every layer: an object of a class, a flag, a word
from a list, a file's path.  Each raises :class:`common.checks.ArgumentTypeError` (a
``TypeError`` and a ``ValueError``) whose message names the argument, says what it takes and
quotes the value it got, in one line.

And the questions the API asks about a value it takes but doubts (:func:`ask`: a likely slip
of unit, a speed beyond any on record), which a caller that has asked in its own words (the
command line, in the user's options and units) keeps unsaid (:func:`asked_by_caller`).
"""

from __future__ import annotations

import contextlib
import contextvars
import os

import numpy as np

from common.checks import ArgumentTypeError, shown

_ASKED = contextvars.ContextVar("asked_by_caller", default=False)
"""True inside :func:`asked_by_caller`: the API's questions (:func:`ask`) are not asked."""


def instance(name: str, value, types, what: str, hint: str = ""):
    """Return ``value``; raise :class:`ArgumentTypeError` ("ball must be a ball.Ball, got
    'x'") unless it is an instance of ``types``.

    Parameters
    ----------
    name : str
        The argument's name, as the message quotes it.
    value : object
        The value to check.
    types : type or tuple of type
        What it may be (``type(None)`` among them if None is allowed).
    what : str
        What it may be, as the message says it ("a racket.Racket or None").
    hint : str, optional
        Appended to the message, e.g. how to make one.
    """
    if not isinstance(value, types):
        raise ArgumentTypeError(f"{name} must be {what}, got {quoted(value)}{hint}")
    return value


QUOTED_MAX = 80
"""The longest a value is quoted in a message [characters]; a longer one (a Racket's repr
runs to pages) is named by its type: "got a Racket"."""


def quoted(value) -> str:
    """``value`` as a one-line message quotes it: :func:`common.checks.shown`, or its type's
    name if that is longer than :data:`QUOTED_MAX` characters or spans lines.

    Parameters
    ----------
    value : object
        The value to quote.
    """
    said = shown(value)
    if len(said) <= QUOTED_MAX and "\n" not in said:
        return said
    kind = type(value).__name__
    return f"{'an' if kind[:1].lower() in 'aeiou' else 'a'} {kind}"


def flag(name: str, value) -> bool:
    """Return ``value`` as a bool; raise :class:`ArgumentTypeError` unless it is True or
    False (a word or a number would pass for either).

    Parameters
    ----------
    name, value
        As in :func:`instance`.
    """
    return bool(instance(name, value, bool | np.bool_, "True or False"))


def choice(name: str, value, choices) -> str:
    """Return ``value``; raise ``ValueError`` unless it is one of the words ``choices`` (an
    :class:`ArgumentTypeError` if it is not a word at all).

    Parameters
    ----------
    name, value
        As in :func:`instance`.
    choices : sequence of str
        The words it may be.
    """
    said = f"{name} must be one of {', '.join(map(repr, choices))}, got {shown(value)}"
    if not isinstance(value, str):
        raise ArgumentTypeError(said)
    if value not in choices:
        raise ValueError(said)
    return value


def file_path(name: str, value) -> str:
    """Return ``value``, a file's path (a str or an ``os.PathLike`` such as a
    ``pathlib.Path``), as a str; raise :class:`ArgumentTypeError` for anything else (an int
    would open a file descriptor).

    Parameters
    ----------
    name, value
        As in :func:`instance`.
    """
    path = os.fspath(instance(name, value, str | os.PathLike, "a path (str or os.PathLike)"))
    return instance(name, path, str, "a path (str or os.PathLike)")


def ask(check, *args, **kwargs) -> None:
    """Ask about a value the API takes but doubts: call ``check``, a check that warns
    (:func:`common.checks.suspect`, :func:`common.checks.too_fast`, ...), with ``args`` and
    ``kwargs``, unless inside :func:`asked_by_caller`.

    Parameters
    ----------
    check : callable
        The check; it warns (``UserWarning``) or returns.
    *args, **kwargs
        Its arguments.
    """
    if not _ASKED.get():
        check(*args, **kwargs)


@contextlib.contextmanager
def asked_by_caller():
    """Inside the block, the API asks nothing (:func:`ask`): its caller has asked about the
    values it passes, in its own words (the command line names its options and their units:
    ``--swing-speed-mph 90``, never ``head_speed 40.23 m/s``), or made them itself (a value
    derived from an argument already asked about, a search through speeds no one typed).
    Refusals are not affected.  It holds in the thread (or task) that entered it.
    """
    token = _ASKED.set(True)
    try:
        yield
    finally:
        _ASKED.reset(token)
