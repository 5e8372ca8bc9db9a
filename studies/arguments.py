"""The studies' checks of the objects their functions take: a racket, a ball, a swing (an
executor: :func:`studies.scale.executor_argument`).  Each is refused in one line that names
the argument and says how to make what it takes (:func:`common.checks.instance`): a
preset's name where a racket is asked for is the command line's habit, ``load_racket``
turns it into one.
"""

from __future__ import annotations

import numbers

from ball import Ball
from common.checks import shown
from common.typechecks import instance
from racket import Racket, Swing


def _named(value, load: str) -> str:
    """The hint for a word given where an object is asked for: the loader that makes one."""
    if not isinstance(value, str):
        return ""
    return f" (a name or a file? studies.config.{load}({value!r}) makes one)"


def racket_argument(racket, name: str = "racket") -> Racket:
    """``racket``, a :class:`racket.Racket`; TypeError (a ValueError too) otherwise.

    Parameters
    ----------
    racket : object
        The value given.
    name : str, optional
        The argument's name, as the message quotes it.
    """
    return instance(name, racket, Racket, "a racket.Racket", _named(racket, "load_racket"))


def ball_argument(ball, name: str = "ball") -> Ball:
    """``ball``, a :class:`ball.Ball`; TypeError (a ValueError too) otherwise.

    Parameters
    ----------
    ball : object
        The value given.
    name : str, optional
        The argument's name, as the message quotes it.
    """
    return instance(name, ball, Ball, "a ball.Ball", _named(ball, "load_ball"))


def swing_argument(swing) -> Swing | None:
    """``swing``, a :class:`racket.Swing` or None; TypeError (a ValueError too) otherwise,
    with the swing a number would be (a head speed [m/s]).

    Parameters
    ----------
    swing : object
        The value given.
    """
    number = isinstance(swing, numbers.Real) and not isinstance(swing, bool)
    hint = f" (a head speed? racket.Swing({shown(swing)}) swings about the wrist)" if number else ""
    return instance("swing", swing, Swing | type(None), "a Swing or None", hint)
