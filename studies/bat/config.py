"""A bat of one's own from a TOML file's ``[bat]`` table (the CLI's ``--bat FILE.toml``), or a
preset by name (:func:`load_bat`).

Schema (SI; positions from the knob, as bats are measured; unknown keys are errors)::

    [bat]
    preset = "r161"             # a preset (bat.BATS: "r161", "alloy"), with support,
                                # pivot_from_knob and clamp_offset only; or describe one:
    name = "my bat"             # what the outputs call it (default: the file's name)
    profile = [[0.0, 0.0505], [0.02, 0.0505], [0.03, 0.0354], ...]
                                # rows [m from the knob, outer diameter m(, inner diameter
                                # m)]: measured points, joined by straight lines, and the bat
                                # cut into slices of `slice` (each the diameter at its middle)
    slice = 0.01                # m (default 1 cm, Nathan's)
    length = 0.84               # m (default the profile's last point)
    # or, slice by slice:
    positions = [0.0, 0.01, ..., 0.84]   # segment boundaries, m from the knob, from 0
    diameters = [0.0505, ...]   # outer diameter of each segment, m
    bore = [0.0, ...]           # inner diameter of each segment, m (hollow; optional)
    wall = 0.003                # or a wall thickness, m, the same everywhere (optional)
    density = 649.0             # kg/m^3
    youngs_modulus = 1.814e10   # Pa
    shear_modulus = 1.05e9      # Pa
    shear_coefficient = 1.0     # kappa (optional; Nathan's 1)
    damping = 0.0               # modal damping ratio (optional; Nathan's none)
    n_modes = 18                # bending modes kept (optional; Nathan's 18)
    support = "free"            # or "pivoted" or "hand-held"
    pivot_from_knob = 0.1524    # m: a pivoted bat's pivot (default the rig's 6 in)
    clamp_offset = 0.0254       # m: its clamps either side (default 1 in; 0: one point)

Every number is checked in its range (:data:`BAT_RANGES`) before anything is built, with a
hint at a likely slip of unit (a diameter typed in mm, cm or inches; a modulus in GPa; a
density in g/cm^3), and the bat built is refused if it weighs outside :data:`BAT_MASS_RANGE`
(a slip the single keys did not show).
"""

from __future__ import annotations

import os
from dataclasses import replace
from pathlib import Path

import numpy as np

from bat import BATS, Bat
from bat.bat import BAT_SUPPORTS
from bat.pivot import CLAMP_OFFSET, PIVOT_FROM_KNOB
from bat.presets import NATHAN_MODES
from beam import ThickBeam
from beam.thick import SHEAR_COEFFICIENT
from common.checks import (
    CM_AS_M,
    INCH_AS_M,
    MM_AS_M,
    finite_array,
    in_range,
    shown,
    whole,
)
from common.typechecks import file_path, instance
from studies.bat.sweep import bat_argument
from studies.config import read_toml

GPA_AS_PA = (1e9, "GPa typed as Pa?", "GPa")
"""A modulus in GPa where Pa are asked for."""

MPA_AS_PA = (1e6, "MPa typed as Pa?", "MPa")
"""A modulus in MPa where Pa are asked for."""

G_CM3_AS_KG_M3 = (1e3, "g/cm^3 typed as kg/m^3?", "g/cm^3")
"""A density in g/cm^3 where kg/m^3 are asked for."""

LENGTH_SLIPS = (CM_AS_M, INCH_AS_M)
DIAMETER_SLIPS = (MM_AS_M, CM_AS_M, INCH_AS_M)

BAT_RANGES = {
    "length": (0.4, 1.2, "m", LENGTH_SLIPS),
    "slice": (0.002, 0.1, "m", (MM_AS_M, CM_AS_M)),
    "wall": (0.0005, 0.02, "m", (MM_AS_M,)),
    "density": (100.0, 10000.0, "kg/m^3", (G_CM3_AS_KG_M3,)),
    "youngs_modulus": (1e8, 1e12, "Pa", (GPA_AS_PA, MPA_AS_PA)),
    "shear_modulus": (1e8, 1e12, "Pa", (GPA_AS_PA, MPA_AS_PA)),
    "shear_coefficient": (0.01, 1.0, "", ()),
    "damping": (0.0, 0.5, "", ()),
    "pivot_from_knob": (0.02, 0.5, "m", LENGTH_SLIPS),
    "clamp_offset": (0.0, 0.05, "m", (MM_AS_M, CM_AS_M, INCH_AS_M)),
}
"""The range of each number of a ``[bat]`` table, (low, high, unit, likely slips of unit).
**ASSUMPTIONS**, generous around what bats are: 46-86 cm long (youth to professional, D. A.
Russell, Acoustics Today 2020, Table 1, ``data/bats.md`` section 4.4) within 0.4-1.2 m;
wood's density (the R161's 649 kg/m^3) to steel's; moduli from soft wood's (Van Zandt's
ash, 1.2e10 Pa, and his shear modulus 8.8e8) to carbon fibre's; a wall of 0.5-20 mm;
damping ratios to 0.5 (Van Zandt's Q = 10 for wood, about 0.05-0.1); the rig's pivot and
clamps as :class:`bat.Bat` takes them.  A value in mm, cm, inches, GPa, MPa or g/cm^3
falls outside and is refused with the hint."""

DIAMETER_RANGE = (0.01, 0.1)
"""A bat's diameter anywhere [m] (**an ASSUMPTION**: the R161's handle is 26 mm across,
its knob 50.5 mm, its barrel 64.3 mm, ``data/bats.md`` section 1.2; barrels of 2.25-2.625
in, section 4.4)."""

BAT_MASS_RANGE = (0.3, 1.5)
"""What a bat built from a table may weigh [kg] (**an ASSUMPTION**: the R161 0.885 kg, a
33-in alloy bat of the -3 rule 0.850 kg, ``data/bats.md`` sections 1.1 and 4.1; youth bats
lighter, none near 1.5 kg)."""

MAX_SEGMENTS = 400
"""Most segments (slices) of a bat [-] (**an assumption**: Nathan's 84 slices of 1 cm;
three finite elements each)."""

_KEYS = {"preset", "name", "profile", "slice", "length", "positions", "diameters", "bore",
         "wall", "density", "youngs_modulus", "shear_modulus", "shear_coefficient", "damping",
         "n_modes", "support", "pivot_from_knob", "clamp_offset"}  # fmt: skip
_HELD = {"support", "pivot_from_knob", "clamp_offset"}
_MATERIAL = {"density", "youngs_modulus", "shear_modulus"}


def bat_from_table(table: dict, name: str = "own bat") -> Bat:
    """A bat from a ``[bat]`` table (see the module docstring).

    Parameters
    ----------
    table : dict
        The ``[bat]`` table, SI, positions from the knob.
    name : str
        What the bat is called without a ``name`` key.
    """
    if not isinstance(table, dict):
        raise ValueError(f"[bat] must be a table of keys, got {shown(table)}")
    unknown = sorted(set(table) - _KEYS)
    if unknown:
        raise ValueError(f"unknown key {unknown[0]!r} in [bat]; valid keys: "
                         f"{', '.join(sorted(_KEYS))}")  # fmt: skip
    for key, (low, high, unit, slips) in BAT_RANGES.items():
        if key in table:
            in_range(f"[bat] {key}", table[key], low, high, unit, slips=slips)
    held = _held(table)
    if "preset" in table:
        extra = sorted(set(table) - _HELD - {"preset"})
        if extra:
            raise ValueError(f"[bat] with a preset takes only {', '.join(sorted(_HELD))}, "
                             f"got {extra[0]!r}")  # fmt: skip
        preset = table["preset"]
        if not isinstance(preset, str) or preset not in BATS:
            raise ValueError(f"unknown bat preset {shown(preset)}; presets: {', '.join(BATS)}")
        return replace(bat_argument(preset), **held)
    missing = sorted(_MATERIAL - set(table))
    if missing:
        raise ValueError(f"[bat] needs {', '.join(missing)} (or a preset)")
    knob_stations, outer, inner = _profile(table)
    n_modes = whole("[bat] n_modes", table.get("n_modes", NATHAN_MODES), 1, 60)
    label = table.get("name", name)
    instance("[bat] name", label, str, "a name")
    length = knob_stations[-1]
    try:
        beam = ThickBeam.round(
            (length - knob_stations)[::-1], outer[::-1], table["density"],
            table["youngs_modulus"], table["shear_modulus"],
            bore=None if inner is None else inner[::-1],
            shear_coefficient=table.get("shear_coefficient", SHEAR_COEFFICIENT),
            damping=table.get("damping", 0.0),
            n_modes=n_modes, elements=max(60, 3 * outer.size - 1),  # 3 per slice (fem.mesh)
        )  # fmt: skip
    except ValueError as err:  # the beam's own terms (EI, mass per length) in the table's
        if "must vary by at most" not in str(err):
            raise
        raise ValueError(
            f"[bat] sections differ too much along the bat (a wall or diameter near 0?): {err}"
        ) from None
    mass = beam.mass
    if not BAT_MASS_RANGE[0] <= mass <= BAT_MASS_RANGE[1]:
        raise ValueError(
            f"[bat] describes a bat of {mass:.4g} kg; bats weigh {BAT_MASS_RANGE[0]:g}-"
            f"{BAT_MASS_RANGE[1]:g} kg: check density, the diameters and their units"
        )
    return Bat(beam, name=label, **held)


def _held(table: dict) -> dict:
    """``support``, ``pivot_from_knob`` and ``clamp_offset`` of the table, for
    :class:`bat.Bat`.
    """
    held = {}
    if "support" in table:
        support = table["support"]
        if support not in BAT_SUPPORTS:
            raise ValueError(f"[bat] support must be one of {', '.join(BAT_SUPPORTS)}, got "
                             f"{shown(support)}")  # fmt: skip
        held["support"] = support
    for key, default in (("pivot_from_knob", PIVOT_FROM_KNOB), ("clamp_offset", CLAMP_OFFSET)):
        held[key] = float(table.get(key, default))
    return held


def _array(table: dict, key: str, slips=DIAMETER_SLIPS, low=DIAMETER_RANGE[0],
           high=DIAMETER_RANGE[1]) -> np.ndarray:  # fmt: skip
    """``table[key]``, a flat array of numbers each in [low, high] m (with the slips' hint)."""
    values = table[key]
    if not isinstance(values, list) or not values:
        raise ValueError(f"[bat] {key} must be an array of numbers [m], got {shown(values)}")
    array = finite_array(f"[bat] {key}", values, "m")
    if array.ndim != 1:
        raise ValueError(f"[bat] {key} must be a flat array of numbers [m]")
    for value in values:
        in_range(f"[bat] {key}", value, low, high, "m", slips=slips)
    return array


def _profile(table: dict):
    """(segment boundaries [m from the knob], outer diameters [m], inner diameters [m] or
    None) of the table: a profile interpolated onto slices, or the segments as given.
    """
    form = {"profile"} & set(table), {"positions", "diameters"} & set(table)
    if bool(form[0]) == bool(form[1]):
        raise ValueError("[bat] needs a profile, or positions and diameters (one of them)")
    if form[0]:
        extra = sorted({"positions", "diameters", "bore"} & set(table))
        rows = table["profile"]
        if (
            not isinstance(rows, list)
            or len(rows) < 2
            or any(not isinstance(row, list) or len(row) not in (2, 3) for row in rows)
        ):
            raise ValueError("[bat] profile must be rows [m from the knob, diameter m(, inner "
                             "diameter m)], two or more")  # fmt: skip
        if len({len(row) for row in rows}) > 1:
            raise ValueError("[bat] profile rows must all give an inner diameter, or none")
        columns = list(zip(*rows, strict=True))
        z = _array({"profile": list(columns[0])}, "profile", LENGTH_SLIPS, 0.0, 1.2)
        outer = _array({"profile": list(columns[1])}, "profile")
        inner = (_array({"profile": list(columns[2])}, "profile", DIAMETER_SLIPS, 0.0, 0.1)
                 if len(columns) == 3 else None)  # fmt: skip
        if np.any(np.diff(z) <= 0):
            raise ValueError("[bat] profile's positions must increase from the knob [m]")
        length = float(table.get("length", z[-1]))
        if z[0] > 0.0 or z[-1] < length:
            raise ValueError(
                f"[bat] profile must span the bat, from the knob (0) to its length "
                f"({length:g} m), got {z[0]:g} to {z[-1]:g} m"
            )
        slice_ = float(table.get("slice", 0.01))
        count = max(round(length / slice_), 1)
        if count > MAX_SEGMENTS:
            raise ValueError(f"[bat] cuts the bat into {count} slices, more than {MAX_SEGMENTS}: "
                             "give a longer slice")  # fmt: skip
        stations = np.linspace(0.0, length, count + 1)
        middle = 0.5 * (stations[1:] + stations[:-1])
        outer_s = np.interp(middle, z, outer)
        inner_s = None if inner is None else np.interp(middle, z, inner)
        if extra:
            raise ValueError(f"[bat] profile replaces {extra[0]}; give one of them")
    else:
        missing = sorted({"positions", "diameters"} - set(table))
        if missing or "slice" in table or "length" in table:
            said = missing[0] if missing else ("slice" if "slice" in table else "length")
            raise ValueError(f"[bat] positions and diameters go together, without slice or "
                             f"length (the last position is the length): {said}")  # fmt: skip
        stations = _array(table, "positions", LENGTH_SLIPS, 0.0, 1.2)
        outer_s = _array(table, "diameters")
        inner_s = _array(table, "bore", DIAMETER_SLIPS, 0.0, 0.1) if "bore" in table else None
        if stations[0] != 0.0 or np.any(np.diff(stations) <= 0):
            raise ValueError("[bat] positions must start at 0 (the knob) and increase [m]")
        if stations.size != outer_s.size + 1 or (inner_s is not None and inner_s.size !=
                                                 outer_s.size):  # fmt: skip
            raise ValueError("[bat] needs one diameter (and bore) per segment: one fewer "
                             "than positions")  # fmt: skip
        if outer_s.size > MAX_SEGMENTS:
            raise ValueError(f"[bat] has more than {MAX_SEGMENTS} segments")
    in_range("[bat] length", stations[-1], *BAT_RANGES["length"][:3], slips=LENGTH_SLIPS)
    if "wall" in table:
        if inner_s is not None:
            raise ValueError("[bat] takes a wall or inner diameters (bore), not both")
        inner_s = outer_s - 2.0 * float(table["wall"])
        if np.any(inner_s <= 0.0):
            raise ValueError(f"[bat] wall {shown(table['wall'])} m is thicker than half the "
                             f"bat's narrowest diameter, {outer_s.min():.4g} m")  # fmt: skip
    if inner_s is not None and np.any(inner_s >= outer_s):
        raise ValueError("[bat] inner diameters must be below the outer ones [m]")
    return stations, outer_s, inner_s


HOLLOW_PRESETS = ("alloy",)
"""The presets with a bore (:func:`bat.presets.alloy`): a beam has no wall, so a hollow
bat's trampoline effect is not in its answers (:func:`is_hollow`)."""


def is_hollow(spec: str | os.PathLike) -> bool:
    """Whether the bat ``spec`` (a preset's name or a ``.toml`` file, as :func:`load_bat`
    takes it) is hollow: a preset of :data:`HOLLOW_PRESETS`, or a ``[bat]`` table with an
    inner diameter above 0 (``bore``, ``wall``, a profile's third column) or such a preset.

    Parameters
    ----------
    spec : str or os.PathLike
        A key of :data:`bat.BATS`, or a ``.toml`` file that :func:`load_bat` has read.
    """
    if isinstance(spec, str) and spec in BATS:
        return spec in HOLLOW_PRESETS
    table = read_toml(spec)["bat"]
    if "preset" in table:
        return table["preset"] in HOLLOW_PRESETS
    inner = [row[2] for row in table.get("profile", []) if len(row) == 3]
    return "wall" in table or any(float(d) > 0.0 for d in [*table.get("bore", []), *inner])


def load_bat(spec: str | os.PathLike, support: str | None = None) -> Bat:
    """A bat from a preset name or a TOML file with a ``[bat]`` table, held by ``support``
    if given.

    Parameters
    ----------
    spec : str or os.PathLike
        A key of :data:`bat.BATS`, or a ``.toml`` file.
    support : str, optional
        "free", "pivoted" or "hand-held"; None: the preset's (free) or the file's.
    """
    if isinstance(spec, str) and spec in BATS:
        return bat_argument(spec, support)
    if isinstance(spec, os.PathLike) or (isinstance(spec, str) and spec.endswith(".toml")):
        path = file_path("spec", spec)
        data = read_toml(path)
        if "bat" not in data:
            raise ValueError(f"{path} has no [bat] table")
        try:
            bat = bat_from_table(data["bat"], Path(path).stem)
        except TypeError as err:  # a value of the wrong type deep in a constructor
            raise ValueError(f"{path}: a value in [bat] has the wrong type ({err})") from None
        return bat_argument(bat, support)
    raise ValueError(f"unknown bat {spec!r}; presets: {', '.join(BATS)} (or a .toml file)")
