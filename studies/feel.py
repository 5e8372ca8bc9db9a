"""What the hand feels, as the command line (``racket-impact feel``) and the page both report
it: the racket held in the hand (:data:`FEEL_SUPPORT`, the racket's own grip, the medium one
unless its file says otherwise), its shock and its vibration at the grip in g, and the mode
the vibration rings at, in words (:func:`feel_numbers`).  The definitions and their source:
:mod:`racket.feel`.
"""

from __future__ import annotations

import numpy as np

from common.units import GRAVITY
from racket.system import held_mode
from studies.conditions import racket_details

FEEL_SUPPORT = "hand-held"
"""The support of the feel, on the command line and the page: the hand holds the racket (its
shock and vibration are what reaches the hand; a free racket has no hand)."""

_ORDINALS = ("first", "second", "third", "fourth", "fifth")


def feel_numbers(feel, racket) -> dict:
    """The feel's headline numbers, the same on the command line and the page.

    Parameters
    ----------
    feel : HandFeel
        What the hand feels (:func:`racket.feel.hand_feel`, SI).
    racket : Racket
        The racket ``feel`` was computed for (its support and hand).

    Returns
    -------
    dict
        ``feel_shock_g`` and ``feel_vibration_g`` (:attr:`racket.feel.HandFeel.shock` and
        :attr:`~racket.feel.HandFeel.vibration` [g]), ``feel_hz`` (the strongest vibration,
        :meth:`racket.feel.HandFeel.strongest` [Hz]), ``feel_mode`` (that vibration in
        words: the racket's mode it is), ``feel_support`` and ``feel_grip`` (how the racket
        was held, :func:`studies.conditions.racket_details`; the grip None on a free racket).
    """
    hz, is_mode = feel.strongest()
    words = f"between the racket's modes (to ±{feel.frequencies[1]:.0f} Hz, the spectrum's bins)"
    details = racket_details(racket)
    return {
        "feel_shock_g": feel.shock / GRAVITY,
        "feel_vibration_g": feel.vibration / GRAVITY,
        "feel_hz": hz,
        "feel_mode": _mode_words(racket, hz) if is_mode else words,
        "feel_support": details["support"],
        "feel_grip": details["grip"],
    }


def _mode_words(racket, hz: float) -> str:
    """Which of ``racket``'s modes the natural frequency ``hz`` [Hz] is, in words: a bending
    mode of the frame as supported (free: its free-free frequency, which damping lowers by a
    few 1e-5; held: the held racket's mode it became, :func:`racket.system.held_mode`), or
    another natural frequency (torsion, the racket springing on the hand's grip).
    """
    modes = racket.beam.modes
    if racket.support == "hand-held":
        bending = np.array([held_mode(racket.system, k)[0] for k in range(2, modes.count)])
    else:
        bending = np.asarray(modes.frequencies)
    k = int(np.argmin(np.abs(bending - hz)))
    if abs(bending[k] - hz) > 1e-3 * hz:
        return f"a natural frequency of the {racket.support} racket (not a bending mode)"
    order = _ORDINALS[k] if k < len(_ORDINALS) else f"{k + 1}th"
    return f"the {order} bending mode of the {racket.support} racket"
