"""Checks of an argument's kind, shared by every layer: an object of a class, a flag, a word
from a list, a file's path.  Each raises :class:`common.checks.ArgumentTypeError` (a
``TypeError`` and a ``ValueError``) whose message names the argument, says what it takes and
quotes the value it got, in one line.
"""

from __future__ import annotations

import os

import numpy as np

from common.checks import ArgumentTypeError, shown


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
        raise ArgumentTypeError(f"{name} must be {what}, got {shown(value)}{hint}")
    return value


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
