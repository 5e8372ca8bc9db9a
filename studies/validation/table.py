"""The comparisons run into one table, grouped by what they test, and summed up in one line."""

from __future__ import annotations

import pandas as pd

from studies.validation.comparison import KINDS, Comparison
from studies.validation.measurements import comparisons


def validation_table(items: list[Comparison] | None = None) -> pd.DataFrame:
    """Run the comparisons: one row each, with the model's value and whether it agrees.

    Parameters
    ----------
    items : list of Comparison, optional
        The comparisons to run; default :func:`comparisons`.

    Returns
    -------
    DataFrame
        Columns :data:`COLUMNS` (``measured``, ``low``, ``high``: the band widened by the
        inputs' scatter, :meth:`Comparison.limits`; and ``model``, in the unit of
        ``quantity``; ``agrees`` a bool; ``band_from``, where the band comes from; ``gap``,
        why a calibration row misses it), indexed by each comparison's name.
    """
    items = comparisons() if items is None else items
    rows = []
    for c in items:
        value = float(c.model())
        low, high = c.limits()
        rows.append(
            dict(
                quantity=c.quantity, conditions=c.conditions, measured=c.measured, low=low,
                high=high, model=value, agrees=c.agrees(value), kind=c.kind, source=c.source,
                band_from=c.band, gap=c.gap,
            )
        )  # fmt: skip
    return pd.DataFrame(rows, index=pd.Index([c.name for c in items], name="name"))


GROUPS = {
    "the ball on a rigid surface": ("rebound", "concrete"),
    "the ball on clamped strings": ("seed", "cross", "clamped", "strings"),
    "the string bed (steel ball, ERT)": ("steel", "ert"),
    "the hand": ("savage", "grabiner"),
    "the frame's stiffness (RA)": ("ra",),
    "dwell times in real strokes (Hamori)": ("hamori",),
    "power over the face (e_A)": ("twu", "typical"),
    "oblique bounces without spin (Cross)": ("bounce",),
    "spin off the strings (TWU)": ("spin",),
    "strokes in play": ("stroke",),
    "courts (ITF pace)": ("court",),
}
"""The comparisons by what they test: group -> the first words of their names."""


def groups(table: pd.DataFrame):
    """The rows of a :func:`validation_table` by :data:`GROUPS`: (group, rows) pairs.

    Parameters
    ----------
    table : DataFrame
        The table of :func:`validation_table`.
    """
    first = table.index.str.split("-").str[0]
    for group, words in GROUPS.items():
        yield group, table[first.isin(words)]


def summary(table: pd.DataFrame) -> str:
    """One line: how many comparisons agree, by kind.

    Parameters
    ----------
    table : DataFrame
        The table of :func:`validation_table`.
    """
    parts = []
    for kind in KINDS:
        rows = table[table["kind"] == kind]
        parts.append(f"{kind}: {int(rows['agrees'].sum())} of {len(rows)} agree")
    return f"{len(table)} comparisons with published measurements; " + "; ".join(parts)
