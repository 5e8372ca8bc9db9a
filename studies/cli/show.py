"""Printed tables: human labels with units (dimensionless said as [-]), headers wrapped over
up to three lines, at most :data:`WIDTH` columns wide (the columns that do not fit named on
a last line).  The files keep the tables' own column names (SI units in the names).
"""

from __future__ import annotations

import re
import textwrap

import numpy as np

WIDTH = 100
"""Widest line a printed table makes [characters] (a terminal's or an e-mail's)."""

LABELS = {
    "position_from_tip_cm": "from the tip [cm]",
    "position_from_tip_m": "from the tip [m]",
    "e": "e [-]",
    "e_A": "e_A [-]",
    "effective_mass_kg": "effective mass [kg]",
    "ball_rebound_m_s": "ball rebound [m/s]",
    "vibration_energy_fraction": "vibration / ball's energy [-]",
    "swing_speed_m_s": "impact point's speed [m/s]",
    "swing_speed_mph": "impact point's speed [mph]",
    "swing_speed_kmh": "impact point's speed [km/h]",
    "recontacts": "re-contacts [-]",
    "relative_difference": "relative difference [-]",
    "spec_sheet": "spec sheet",
    "fitted_model": "fitted model",
    "self_consistent": "self-consistent",
    "e_van_zandt": "e (Van Zandt) [-]",
    "reduction_simulated_percent": "reduction (simulated) [%]",
    "reduction_eq22_percent": "reduction (Eq. 22) [%]",
    "serve_eq22_m_s": "serve (Eq. 22) [m/s]",
    "serve_eq22_mph": "serve (Eq. 22) [mph]",
    "serve_eq22_kmh": "serve (Eq. 22) [km/h]",
    "serve_simulated_m_s": "serve (simulated) [m/s]",
    "serve_simulated_mph": "serve (simulated) [mph]",
    "serve_simulated_kmh": "serve (simulated) [km/h]",
    "dt_kp_cm": "DT [kp/cm]",
    "stiffness_kN_m": "stiffness [kN/m]",
    "stretch_1_m2": "stretch [1/m^2]",
}
"""Labels of the columns whose names do not read well by :func:`label`'s rule."""

DIMENSIONLESS = frozenset({"e", "e_A", "e0", "e_van_zandt", "mode", "recontacts"})
"""The numeric columns without a unit (besides names ending in ``_ratio``, ``_fraction`` or
``_count``): labelled "[-]"; any other numeric column's name must say its unit."""

_UNITS = (
    ("_kgcm2", "kg cm^2"), ("_cm2", "cm^2"), ("_in2", "in^2"), ("_m_s2", "m/s^2"),
    ("_m_s", "m/s"), ("_rad_s", "rad/s"), ("_mph", "mph"), ("_kmh", "km/h"), ("_N_m", "N/m"),
    ("_n_m", "N/m"),
    ("_mm", "mm"), ("_cm", "cm"), ("_ms", "ms"), ("_m", "m"), ("_kg", "kg"), ("_g", "g"),
    ("_N", "N"), ("_Hz", "Hz"), ("_hz", "Hz"), ("_J", "J"), ("_s", "s"), ("_lb", "lb"),
    ("_percent", "%"), ("_fraction", "-"), ("_pts_hl", "pts head-light"),
)  # fmt: skip


def label(column: str, numeric: bool = True) -> str:
    """A column's printed label: "contact_time_s" -> "contact time [s]",
    "nodes_cm_from_butt" -> "nodes from butt [cm]"; a numeric column listed in
    :data:`DIMENSIONLESS` (or named a ratio, fraction or count) says "[-]"; any other name
    without a unit gets none (a slip the tests catch); a label that already ends in "]" is kept.

    Parameters
    ----------
    column : str
        The column's name (SI units in the name, as the files have it).
    numeric : bool
        Whether its values are numbers (a column of words has no unit).
    """
    if column in LABELS:
        return LABELS[column]
    if column.endswith("]"):
        return column
    name = str(column)
    moved = re.match(r"(.*?)(_cm|_m)(_from_.*)$", name)  # nodes_cm_from_butt
    if moved:
        name = moved.group(1) + moved.group(3) + moved.group(2)
    for suffix, unit in _UNITS:
        if name.endswith(suffix) and len(name) > len(suffix):
            return f"{name[: -len(suffix)].replace('_', ' ')} [{unit}]"
    plain = column in DIMENSIONLESS or name.endswith(("_ratio", "_count"))
    return name.replace("_", " ") + (" [-]" if numeric and plain else "")


_UNIT_WORDS = {"kg", "g", "cm", "mm", "m", "cm^2", "in^2", "Hz", "N", "N/m", "m/s", "mph", "s",
               "ms", "lb", "J", "%", "rad/s", "kN/m"}  # fmt: skip


def _with_unit(name: str, unit: str) -> str:
    """A row's name with its unit: ("balance", "cm from the butt") -> "balance [cm] from the
    butt", ("swingweight", "kg cm^2 (axis 10 cm from the butt)") -> "swingweight [kg cm^2]
    (axis 10 cm from the butt)"; "[-]" for no unit.
    """
    words = str(unit or "").split(" ")
    k = 0
    while k < len(words) and words[k] in _UNIT_WORDS:
        k += 1
    core, note = " ".join(words[:k]), " ".join(words[k:])
    if not core:
        return f"{name} [-]" + (f" {note}" if note else "")
    return f"{name} [{core}]" + (f" {note}" if note else "")


def spots_view(spots):
    """The sweet spots (:func:`studies.face.sweetspots.sweet_spots`) as printed: each spot in a
    player's words, where it is, and what it means.

    Parameters
    ----------
    spots : DataFrame
        The sweet-spot table.
    """
    view = spots[["said", "from_tip_cm", "meaning"]]
    return view.rename(columns={"said": "spot"})


def compare_view(summary, unit: str, swung: bool):
    """The summary of ``compare`` (:func:`studies.face.maps.compare_summary`) as printed: one
    column per racket, one row per quantity, its unit in a ``unit`` column (speeds in mph
    in ``unit``; positions from the tip, as everywhere).

    Parameters
    ----------
    summary : DataFrame
        One row per racket.
    unit : str
        The unit the user typed speeds in: "m/s", "mph" or "km/h".
    swung : bool
        The rackets were swung (exit speeds), or at rest (the ball's rebound).
    """
    import pandas as pd

    from common.units import MPH, SPEED_UNITS

    speed = MPH / SPEED_UNITS[unit]  # the summary's speeds are in mph
    exit_ = "largest_exit" if swung else "largest_rebound_at_rest"
    rows = [
        ("largest e", "largest_e", "", 1.0),
        ("  where, from the tip", "largest_e_from_tip_cm", "cm", 1.0),
        ("e at the string centre", "e_at_string_centre", "", 1.0),
        ("e at the tip end of the strings", "e_at_tip_end", "", 1.0),
        *([("head speed", "head_speed_mph", unit, speed)] if swung else []),
        ("fastest exit" if swung else "best rebound, racket at rest", f"{exit_}_mph",
         unit, speed),
        ("  where, from the tip", f"{exit_}_from_tip_cm", "cm", 1.0),
        ("node of the first mode, from the tip", "node_from_tip_cm", "cm", 1.0),
        ("centre of percussion, from the tip", "centre_of_percussion_from_tip_cm", "cm", 1.0),
        ("e_A at the string centre", "e_A_centre", "", 1.0),
        ("e_A at 3 o'clock, ball at the frame", "e_A_3_oclock", "", 1.0),
        ("sweet area", "sweet_area_cm2", "cm^2", 1.0),
    ]  # fmt: skip
    data = {"quantity": [name for name, *_ in rows], "unit": [unit for _, _, unit, _ in rows]}
    for _, racket in summary.iterrows():
        data[str(racket["racket"])] = [float(racket[key]) * k for _, key, _, k in rows]
    return pd.DataFrame(data)


def _wrap(text: str, size: int) -> list[str]:
    """``text`` wrapped to ``size`` columns, names such as "pure-drive-2021" kept whole."""
    return textwrap.wrap(text, size, break_on_hyphens=False)


def _cells(values, floatfmt: str) -> tuple[list[str], bool]:
    """A column's values as text, and whether they are numbers (right-aligned)."""
    values = list(values)
    numbers = all(
        isinstance(v, int | float | np.integer | np.floating) and not isinstance(v, bool | np.bool_)
        for v in values
    )
    if not numbers:
        missing = ("nan", "None", "")
        return ["-" if v is None or str(v) in missing else str(v) for v in values], False
    text = []
    for v in values:
        if isinstance(v, int | np.integer):
            text.append(str(int(v)))
        elif np.isnan(v):
            text.append("-")
        else:
            text.append(floatfmt.format(v))
    return text, True


TEXT_WIDTH = 60
"""Widest cell of words [characters]; a longer one is wrapped over several lines, and so
are the widest cells of words of a table that would not fit in :data:`WIDTH` (down to a
third of this)."""


def _columns(table) -> dict:
    """The columns of ``table`` as lists: a DataFrame's (its named index first, if any), or
    a dict of 1-D arrays' (the sweep's, without pandas).
    """
    if isinstance(table, dict):
        return {name: np.asarray(values).tolist() for name, values in table.items()}
    frame = table.reset_index() if table.index.name is not None else table
    return {name: frame[name].tolist() for name in frame.columns}


def table_lines(table, floatfmt: str = "{:.4g}", width: int = WIDTH) -> list[str]:
    """The lines of a printed ``table``: its named index first (if any), each column under
    its label (:func:`label`, wrapped over up to three lines; a ``unit`` column, one unit
    per row, folded into the first column), two spaces apart, cells of words wrapped at
    :data:`TEXT_WIDTH`; the columns past ``width`` left out and named on a last line.

    Parameters
    ----------
    table : DataFrame or dict
        The table (its own column names; SI units in them), or its columns (name -> 1-D
        array).
    floatfmt : str
        Format of a float, e.g. "{:.4g}".
    width : int
        Widest line [characters].
    """
    data = _columns(table)
    first = next(iter(data), None)
    rows = len(data[first]) if data else 0
    per_row = "unit" in data and first != "unit"
    if per_row:
        units = data.pop("unit")
        data[first] = [_with_unit(n, u) for n, u in zip(data[first], units, strict=True)]
    per_row = per_row or any(  # a column of names with their units: "rebound e [-]"
        all(isinstance(v, str) and v.endswith("]") for v in values) for values in data.values()
    )
    raw = []  # (name, title, cells, numeric, the narrowest the column can be)
    for name, values in data.items():
        cells, numeric = _cells(values, floatfmt)
        title = LABELS.get(name, name) if per_row and numeric else label(str(name), numeric)
        narrowest = max(map(len, title.split())) if numeric else TEXT_WIDTH // 3
        raw.append((str(name), title, cells, numeric, narrowest))
    sizes = [
        max([len(c) for c in cells] + [len(word) for word in title.split()])
        if numeric else min(max(len(c) for c in [*cells, ""]), TEXT_WIDTH)
        for _, title, cells, numeric, _ in raw
    ]  # fmt: skip
    while True:  # the widest cells of words wrapped until the table fits
        columns = []
        for (name, title, cells, numeric, _), size in zip(raw, sizes, strict=True):
            cells = [[c] if numeric else _wrap(c, size) or [""] for c in cells]
            size = max([len(line) for c in cells for line in c] + [len(w) for w in title.split()])
            while len(textwrap.wrap(title, size)) > 3:
                size += 1
            columns.append((name, textwrap.wrap(title, size), cells, numeric, size))
        if sum(c[4] for c in columns) + 2 * (len(columns) - 1) <= width:
            break
        k = max(range(len(raw)), key=lambda i: -1 if raw[i][3] else sizes[i])
        if raw[k][3] or sizes[k] <= raw[k][4]:
            break
        sizes[k] -= 1
    shown, used, left = [], -2, []
    for column in columns:
        if used + 2 + column[4] <= width and not left:
            shown.append(column)
            used += 2 + column[4]
        else:
            left.append(column[0])

    def lines_of(texts):
        depth = max(len(t) for t, _, _ in texts)
        out = []
        for k in range(depth):
            words = [
                (t[k] if k < len(t) else "").rjust(size) if numeric
                else (t[k] if k < len(t) else "").ljust(size)
                for t, numeric, size in texts
            ]  # fmt: skip
            out.append("  ".join(words).rstrip())
        return out

    depth = max(len(c[1]) for c in shown)
    lines = lines_of([([""] * (depth - len(head)) + head, num, size)
                      for _, head, _, num, size in shown])  # fmt: skip
    for i in range(rows):
        lines += lines_of([(cells[i], num, size) for _, _, cells, num, size in shown])
    if left:
        lines.append(
            textwrap.fill(
                f"(not shown, {len(left)} more column{'s' * (len(left) > 1)}: {', '.join(left)})",
                width,
            )
        )
    return lines


def print_table(table, floatfmt: str = "{:.4g}") -> None:
    """Print ``table`` as :func:`table_lines` lays it out.

    Parameters
    ----------
    table : DataFrame or dict
        The table, or its columns (name -> 1-D array).
    floatfmt : str
        Format of a float, e.g. "{:.4g}".
    """
    print("\n".join(table_lines(table, floatfmt)))
