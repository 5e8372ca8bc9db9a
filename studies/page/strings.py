"""The interactive page's string choice, one for both rackets (issue 35): each racket's own
strings, a preset of :data:`racket.STRINGS` at its own gauge or a hybrid, fresh or played;
checked, said in the page's words, and turned into the keywords with which
:func:`racket.specs.from_specs` strings the racket, as the API strings it.
"""

from __future__ import annotations

from common.typechecks import choice, flag
from racket import CATALOG
from racket.specs.strung import STRUNG
from racket.strings.stringing import STRING_CHOICES, stringing

OWN_STRINGS = "own"
"""The choice that keeps each racket's own strings: a catalogue racket's
(:attr:`racket.specs.catalog.Entry.strung`, fresh polyester 16L in its own pattern) and, for
a spec sheet, the one rule (:data:`racket.specs.strung.STRUNG`), so that a spec sheet
is compared with a catalogue racket on the same strings."""

PAGE_STRINGS = (OWN_STRINGS, *STRING_CHOICES)
"""The strings the page offers: each racket's own (:data:`OWN_STRINGS`), each preset of
:data:`racket.STRINGS` and the hybrid (:data:`racket.strings.stringing.STRING_CHOICES`), a chosen
one strung in the racket's own pattern."""

STRING_LABELS = {
    "string": "Strings, both",
    "played": "Played strings, both (the tension lost in play)",
}
"""The string controls as the page labels them (its select, its box and its messages)."""


def _words(choice: str) -> str:
    """How the page's select says the choice ``choice`` (one of :data:`PAGE_STRINGS`)."""
    if choice == OWN_STRINGS:
        return f"each racket's own (catalogue: {STRUNG['string']} {STRUNG['gauge']})"
    strung = stringing(choice)
    if not strung.hybrid:
        return strung.mains.describe()
    return f"{strung.mains.describe()} mains, {strung.crosses.describe()} crosses"


STRING_WORDS = {choice: _words(choice) for choice in PAGE_STRINGS}
"""The choices -> their words on the page ("polyester 1.25 mm", "natural gut 1.30 mm mains,
polyester 1.25 mm crosses", each racket's own)."""


def checked_strings(string, played) -> tuple[str, bool]:
    """The page's string choice and its state, checked: one line naming the control as the
    page labels it (:data:`STRING_LABELS`) for a choice it does not offer or a state that is
    not True or False.

    Parameters
    ----------
    string : str
        One of :data:`PAGE_STRINGS`.
    played : bool
        Played strings (True) or fresh.
    """
    return choice(STRING_LABELS["string"], string, PAGE_STRINGS), flag(
        STRING_LABELS["played"], played
    )


def strung(name: str, string: str, played: bool) -> dict:
    """The keywords of :func:`racket.specs.from_specs` (``string``, ``gauge``, ``pattern``,
    ``state``) that string the page's racket ``name`` with the choice ``string``: its own
    strings (:data:`OWN_STRINGS`), or the chosen preset at its own gauge in the racket's own
    pattern; ``played`` or fresh.

    Parameters
    ----------
    name : str
        A catalogue racket (:data:`racket.CATALOG`), or any other name for a spec sheet.
    string : str
        One of :data:`PAGE_STRINGS`.
    played : bool
        Played strings (True) or fresh.
    """
    own = CATALOG[name].strung if name in CATALOG else STRUNG
    chosen = own if string == OWN_STRINGS else {"string": string, "pattern": own["pattern"]}
    return {**chosen, "state": "played" if played else "fresh"}
