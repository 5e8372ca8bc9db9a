"""Rackets and balls from presets or TOML files (the CLI's ``--racket`` and ``--ball``).

Schema (every key optional unless marked; SI units unless the key names its unit; unknown
keys are errors)::

    [racket]
    preset = "paper"            # start from a preset (see RACKETS; default pure-drive-2021,
                                # or the paper's for a frame of its own), then override
    length = 0.68               # m      } a uniform frame ...
    mass = 0.34                 # kg     }
    f1 = 120.0                  # Hz     }
    stations = [0.0, 0.3, 0.68] # m from the tip  } ... or a piecewise-constant profile
    mass_per_length = [...]     # kg/m per segment }
    bending_stiffness = [...]   # N m^2 per segment }
    roll_inertia_per_length = [...]  # kg m per segment (optional: offsets, twistweight)
    torsional_stiffness = [...] # N m^2 per segment (optional: torsion modes)
    point_masses = [[0.05, 0.004]]   # [position m from the tip, mass kg(, offset m)]
    lead_tape = [{mass_g = 3.0, from_tip_cm = 0.5},     # lead tape, in tennis units: on the
                 {mass_g = 2.0, at = "3 and 9"}]        # axis, or at a clock position
                                                        # of the head (mass_g per side)
    damping = 0.005             # modal damping ratio (one value or one per mode)
    n_modes = 8
    support = "free"            # or "clamped-head" or "hand-held"

    [racket.specs]              # ... or a spec sheet (racket.from_specs keywords):
    length_m = 0.6858
    mass_kg = 0.321
    balance_cm = 33.0           # or balance_pts_hl (1 pt = 1/8 in head-light)
    swingweight_kgcm2 = 325
    f1_hz = 150                 # or ra = 66 (f1 from the TWU regression, racket.specs.ra),
                                # or flex_deflection_mm with flex_load_n
    head_size_cm2 = 645         # or head_size_in2
    tension_lb = 55             # or tension_n, or string_stiffness_n_m
    beam_width_mm = [23, 26, 22]  # optional: tip, sides, throat (or one width)
    twistweight_kgcm2 = 14      # optional; recoil_weight_kgcm2 also (or for swingweight)
    torsion_hz = 320            # optional: measured first torsion frequency

    [racket.strings]            # each key optional: the others stay the racket's
    string = "polyester"        # racket.STRINGS, or a hybrid "natural-gut/polyester"
    gauge = 1.25                # mm, or a name: "16L"; pattern = "16x19"; state = "played"
    tension_lb = 55             # or tension_kg = 25; or the bed's stiffness itself:
    stiffness = 4e4             # N/m, or dt_kp_cm = 30 (the ERT's dynamic tension)
    extent = [0.0, 0.32]        # m from the tip
    profile = "membrane"        # or "uniform": stiffness over the face

    [racket.hand]               # the hand of a hand-held racket (racket.Hand): a preset,
    grip = "medium"             # "light", "medium" (the default) or "tight" (racket.GRIPS),
                                # or your own (no mass: the grip held still):
                                # stiffness = 1e4 (N/m), damping = 10.0 (N s/m),
                                # grip_length = 0.10 (m from the butt), mass = 0.2 (kg)

    [ball]
    preset = "itf-type-2"       # a real ball (ball.catalog), "paper" (the paper's), a
                                # baseball or softball ("baseball", ball.baseball), ...
                                # or: mass (kg) and law, with the law's parameters:
    mass = 0.057
    law = "linear-hysteresis"   # "linear-spring" (k), "linear-hysteresis" (k, e),
    k = 4e4                     # "power-law" (k, a, b, or k, a, e), "sine" (k0),
                                # "growing-hysteresis" (k, a, e0, slope [, calibrated_to]),
                                # "stiffening-hysteresis" (k, x_lim, e0, slope)
    e = 0.75
    radius = 0.0335             # m (default: the tennis ball's, racket.TENNIS_BALL_RADIUS)

The keys in :data:`TOML_RANGES` are checked in their ranges, with a hint at a likely slip
of unit (``mass = 340`` for a racket: grams typed as kg?); a ``tension_lb`` that is one in
kg is asked about, as ``--tension-lb`` is (:func:`common.checks.loose_tension`).
"""

from __future__ import annotations

import os
from dataclasses import replace

from ball import (
    BALL_PRESETS,
    BASEBALL_PRESETS,
    Ball,
    GrowingHysteresis,
    LinearHysteresis,
    LinearSpring,
    PowerLawHysteresis,
    SineLaw,
    StiffeningHysteresis,
)
from ball.bodies import BALL_MASS_RANGE, BALL_RADIUS_RANGE, MASS_SLIPS, RADIUS_SLIPS
from beam import Beam
from common import checks as slip  # the slips of unit: slip.CM_AS_M, ...
from common.checks import in_range, loose_tension, positive, shown, suspect
from racket import (
    CATALOG,
    DEFAULT_RACKET,
    GRIPS,
    TENNIS_BALL_MASS,
    TENNIS_BALL_RADIUS,
    Hand,
    Racket,
    from_specs,
    paper_ball,
    paper_racket,
)
from racket.racket import ADDED_MASS_MAX, added_mass, check_strings_fit
from racket.solver import F1_MIN
from racket.specs.restring import with_tension
from racket.specs.sheet import SPEC_RANGES, SPEC_SLIPS
from racket.strings.tension import TENSION_RANGE_LB
from studies.strings import inputs  # the string bed as typed
from studies.sweeps import F1_MAX, STRING_STIFFNESS_RANGE
from studies.toml_files import preset_or_file, read_toml

RACKETS = {"paper": paper_racket, **{name: entry.racket for name, entry in CATALOG.items()}}
"""Racket presets by name: the paper's uniform racket and the catalogue (racket.specs.catalog)."""

SMALL_BALL_RADIUS = 0.0125
"""Radius [m] of the 10.3 g happy and unhappy balls: an assumption (a rubber sphere of
that mass and a density of about 1.25 g/cm^3 is 2.5 cm across)."""

BALLS = {
    **{name: preset.ball for name, preset in BALL_PRESETS.items()},
    "paper": paper_ball,
    "zero-cor-tennis": lambda: Ball(TENNIS_BALL_MASS, SineLaw(k0=4e4), TENNIS_BALL_RADIUS),
    "happy": lambda: Ball(0.0103, LinearSpring(k=2e4), SMALL_BALL_RADIUS),
    "unhappy": lambda: Ball(0.0103, SineLaw(k0=2e4), SMALL_BALL_RADIUS),
    **{name: preset.ball for name, preset in BASEBALL_PRESETS.items()},
}
"""Ball presets by name: the real balls of :mod:`ball.catalog` (ITF types 1-3, high
altitude, pressureless, punctured), the paper's tennis ball, its zero-COR twin (Sec. VIII),
the happy and unhappy balls of Secs. IV-VI, and the baseballs and softballs of A. M. Nathan's
law (:mod:`ball.baseball`: ``baseball``, ``baseball-low-speed``, ``baseball-fig2``,
``mlb-low``, ``mlb-high`` and ``softball-44-375`` to ``softball-50-525``)."""

TOML_RANGES = {
    ("racket", "length"): (0.2, 1.5, "m", (slip.CM_AS_M, slip.INCH_AS_M)),
    ("racket", "mass"): (0.05, 2.0, "kg", (slip.GRAMS_AS_KG, slip.OZ_AS_KG)),
    ("racket", "f1"): (F1_MIN, F1_MAX, "Hz", ()),
    **{("racket.specs", key): (*SPEC_RANGES[key], slips) for key, slips in SPEC_SLIPS.items()},
    ("racket.strings", "stiffness"): (*STRING_STIFFNESS_RANGE, "N/m", (slip.KN_AS_N,)),
    ("racket.strings", "tension_lb"): (*TENSION_RANGE_LB, "lb", (slip.N_AS_LB,)),
    ("racket.strings", "tension_kg"): (*inputs.TENSION_KG_RANGE, "kg", (inputs.LB_AS_KG,)),
    ("racket.strings", "dt_kp_cm"): (*inputs.DT_RANGE, "kp/cm", (inputs.N_M_AS_KP_CM,)),
    ("ball", "mass"): (*BALL_MASS_RANGE, "kg", MASS_SLIPS),
    ("ball", "radius"): (*BALL_RADIUS_RANGE, "m", RADIUS_SLIPS),
    ("ball", "x_lim"): (*BALL_RADIUS_RANGE, "m", RADIUS_SLIPS),
    ("ball", "k"): (1e3, 1e7, "N/m", (slip.KN_AS_N,)),
    ("ball", "k0"): (1e3, 1e7, "N/m", (slip.KN_AS_N,)),
}
"""The range of each plain number of a TOML file that has one, (low, high, unit, likely
slips of unit) by (table, key), checked before anything is built (``k`` only for the linear
laws, whose k is in N/m).  All are assumptions, generous around what they describe: a
racket of any sport is 0.2-1.5 m long (table-tennis bats are about 0.26 m, tennis rackets
at most 0.737 m, ITF Rules of Tennis, Appendix II) and weighs 0.05-2 kg (badminton rackets
about 0.09 kg, strung tennis rackets 0.23-0.37 kg, :data:`racket.specs.sheet.SPEC_RANGES`);
f1 and the string bed are a sweep's ranges (:data:`racket.solver.F1_MIN`,
:data:`studies.sweeps.F1_MAX`, :data:`studies.sweeps.STRING_STIFFNESS_RANGE`); a ball
weighs 1 g-1 kg (a table-tennis ball 2.7 g, a basketball about 0.6 kg; the project's balls
10.3 and 57 g), is 5-150 mm in radius (table tennis 20 mm, basketball about 120 mm), and a
linear ball's stiffness is 1e3-1e7 N/m (a tennis ball's 4e4, paper Sec. III; the happy and
unhappy balls' 2e4, Secs. IV-VI); the spec-sheet keys with a likely slip
(:data:`racket.specs.sheet.SPEC_SLIPS`) in the spec sheets' ranges; a ball's radius and
its law's ``x_lim`` in :data:`ball.bodies.BALL_RADIUS_RANGE` (the hand's are
:class:`racket.Hand`'s own).  A value typed in g, oz, mm, cm, inches or kN/m falls outside
and is refused with the hint (``mass = 57`` for a ball would be 0.057 kg)."""

LEAD_GRAMS = (0.1, 1e3 * ADDED_MASS_MAX)
"""Lead tape per side [g] ``--lead`` takes: 0.1 g (**an assumption**: less is no tape) to
:data:`racket.racket.ADDED_MASS_MAX`; ``lead_tape`` asks about less (kg typed as g?)."""

LAWS = {
    "linear-spring": (LinearSpring, {"k"}),
    "linear-hysteresis": (LinearHysteresis, {"k", "e"}),
    "power-law": (PowerLawHysteresis, {"k", "a", "b"}),
    "growing-hysteresis": (GrowingHysteresis, {"k", "a", "e0", "slope"}),
    "stiffening-hysteresis": (StiffeningHysteresis, {"k", "x_lim", "e0", "slope"}),
    "sine": (SineLaw, {"k0"}),
}

_RACKET_KEYS = {"preset", "length", "mass", "f1", "stations", "mass_per_length",
                "bending_stiffness", "point_masses", "damping", "n_modes", "support", "strings",
                "specs", "lead_tape", "hand", "roll_inertia_per_length",
                "torsional_stiffness"}  # fmt: skip
_SPEC_KEYS = {
    "length_m",
    "mass_kg",
    "balance_cm",
    "balance_pts_hl",
    "swingweight_kgcm2",
    "f1_hz",
    "ra",
    "head_size_in2",
    "head_size_cm2",
    "tension_lb",
    "tension_n",
    "string_stiffness_n_m",
    "recoil_weight_kgcm2",
    "twistweight_kgcm2",
    "flex_deflection_mm",
    "flex_load_n",
    "beam_width_mm",
    "torsion_hz",
}
_LEAD_KEYS = {"mass_g", "from_tip_cm", "at"}
_HAND_KEYS = {"grip", "stiffness", "damping", "grip_length", "mass"}
_BALL_KEYS = {"preset", "mass", "radius", "law", "calibrated_to"} | {
    p for _, params in LAWS.values() for p in params
}


def _check_keys(table, allowed: set, where: str) -> None:
    if not isinstance(table, dict):
        raise ValueError(
            f"[{where}] must be a table of keys ({', '.join(sorted(allowed))}), got {shown(table)}"
        )
    unknown = sorted(set(table) - allowed)
    if unknown:
        raise ValueError(
            f"unknown key {unknown[0]!r} in [{where}]; valid keys: {', '.join(sorted(allowed))}"
        )


def _check_ranges(table: dict, where: str, keys=None) -> None:
    """Check each key of ``table`` (the ``[where]`` table) that :data:`TOML_RANGES` names
    (only ``keys`` if given): ValueError naming the key, with its range and a likely slip.
    """
    for (table_name, key), (low, high, unit, slips) in TOML_RANGES.items():
        if table_name == where and key in table and (keys is None or key in keys):
            positive(f"[{where}] {key}", table[key], unit)  # a sign slip said as such
            in_range(f"[{where}] {key}", table[key], low, high, unit, slips=slips)


def _preset(name: str, presets: dict, kind: str):
    if not isinstance(name, str) or name not in presets:
        raise ValueError(f"unknown {kind} preset {name!r}; presets: {', '.join(presets)}")
    return presets[name]()


def _list(table: dict, key: str, where: str) -> list:
    """``table[key]`` as a list (empty if absent); ValueError if it is not a TOML array."""
    value = table.get(key, [])
    if not isinstance(value, list):
        raise ValueError(f"{key} in [{where}] must be an array, got {shown(value)}")
    return value


def racket_from_table(table: dict) -> Racket:
    """A racket from a ``[racket]`` table (see the module docstring).

    Parameters
    ----------
    table : dict
        The ``[racket]`` table, in SI unless a key names its unit.
    """
    _check_keys(table, _RACKET_KEYS, "racket")
    _check_ranges(table, "racket")
    uniform = {"length", "mass", "f1"} & set(table)
    profile = {"stations", "mass_per_length", "bending_stiffness"} & set(table)
    twist = {"roll_inertia_per_length", "torsional_stiffness"} & set(table)
    if twist and not profile:
        raise ValueError(
            f"{sorted(twist)[0]} in [racket] goes with a profile (stations, mass_per_length, "
            "bending_stiffness)"
        )
    if "specs" in table:
        if uniform or profile or "preset" in table:
            raise ValueError(
                "[racket.specs] replaces preset, length/mass/f1 and the profile keys; "
                "give one of them"
            )
        _check_keys(table["specs"], _SPEC_KEYS, "racket.specs")
        _check_ranges(table["specs"], "racket.specs")
        if "tension_lb" in table["specs"]:  # asked about as --tension-lb is (kg typed as lb?)
            loose_tension("[racket.specs] tension_lb", table["specs"]["tension_lb"])
        base = from_specs(**table["specs"])
    else:
        # no preset: the one default racket, unless the table describes its own frame
        # (length/mass/f1 or a profile), whose string bed and support are then the paper's
        # racket's, the model those keys describe
        described = "paper" if uniform or profile else DEFAULT_RACKET
        base = _preset(table.get("preset", described), RACKETS, "racket")
    beam = base.beam
    if uniform and profile:
        raise ValueError(
            "give either length/mass/f1 or stations/mass_per_length/"
            "bending_stiffness in [racket], not both"
        )
    damping = table.get("damping", beam.damping)
    n_modes = table.get("n_modes", beam.n_modes)
    if uniform:
        stiffness = beam.bending_stiffness[0] if beam.is_uniform else None
        f1 = table.get("f1", beam.modes.frequencies[0] if stiffness else None)
        beam = Beam.uniform(
            table.get("length", beam.length),
            table.get("mass", beam.mass),
            f1,
            damping=damping,
            n_modes=n_modes,
        )
    elif profile:
        missing = {"stations", "mass_per_length", "bending_stiffness"} - profile
        if missing:
            raise ValueError(f"a profile needs {', '.join(sorted(missing))} in [racket]")
        beam = Beam(
            table["stations"],
            table["mass_per_length"],
            table["bending_stiffness"],
            damping=damping,
            n_modes=n_modes,
            roll_inertia_per_length=table.get("roll_inertia_per_length"),
            torsional_stiffness=table.get("torsional_stiffness"),
        )
    else:
        beam = replace(beam, damping=damping, n_modes=n_modes)
    points = _list(table, "point_masses", "racket")
    for point in points:  # lead tape in SI: its mass in kg (12 is grams typed as kg)
        if isinstance(point, list) and len(point) in (2, 3):
            added_mass("[racket] point_masses mass", point[1])
    beam = beam.with_point_masses(*points)
    strings_table = table.get("strings", {})
    _check_keys(strings_table, inputs.STRING_KEYS, "racket.strings")
    _check_ranges(strings_table, "racket.strings")
    strings, tension = inputs.strings_from_table(base.strings, strings_table)
    hand_table = table.get("hand", {})
    _check_keys(hand_table, _HAND_KEYS, "racket.hand")
    if "grip" in hand_table and len(hand_table) > 1:
        raise ValueError("[racket.hand] takes a grip preset or its own values, not both")
    grip = hand_table.get("grip")
    if grip is not None and (not isinstance(grip, str) or grip not in GRIPS):
        raise ValueError(f"unknown grip {grip!r}; grips: {', '.join(GRIPS)}")
    hand = GRIPS[grip] if grip else Hand(**hand_table) if hand_table else base.hand
    if "extent" in strings_table:  # a bed too long for the frame, named as typed
        check_strings_fit(beam, strings, hand, "[racket.strings] extent")
    racket = Racket(beam, strings, table.get("support", base.support), hand)
    if tension is not None:
        racket = with_tension(racket, tension)
    for tape in _list(table, "lead_tape", "racket"):
        racket = _with_lead_tape(racket, tape)
    return racket


def _with_lead_tape(racket: Racket, tape) -> Racket:
    """``racket`` with one ``lead_tape`` entry: ``mass_g`` and either ``from_tip_cm`` (on the
    long axis) or ``at`` (a clock position of the head, ``mass_g`` per side).
    """
    _check_keys(tape, _LEAD_KEYS, "racket.lead_tape")
    if "mass_g" not in tape or len(set(tape) & {"from_tip_cm", "at"}) != 1:
        raise ValueError(
            "each lead_tape entry needs mass_g and one of from_tip_cm or at (a clock "
            "position such as '12' or '3 and 9')"
        )
    mass_g = in_range("lead_tape mass_g", tape["mass_g"], 0.0, LEAD_GRAMS[1], "g")
    if mass_g == 0.0:
        raise ValueError("lead_tape mass_g must be > 0 g, got 0")
    suspect("lead_tape mass_g", mass_g, LEAD_GRAMS, "g", (slip.KG_AS_G,),
            f"less than lead tape weighs (at least {LEAD_GRAMS[0]:g} g)")  # fmt: skip
    if "at" in tape:
        return racket.with_lead_tape(mass_g / 1000.0, tape["at"])
    length = racket.beam.length
    from_tip = in_range("lead_tape from_tip_cm", tape["from_tip_cm"], 0.0, 100 * length, "cm")
    return racket.with_mass(mass_g / 1000.0, from_tip / 100.0)


def ball_from_table(table: dict) -> Ball:
    """A ball from a ``[ball]`` table (see the module docstring).

    Parameters
    ----------
    table : dict
        The ``[ball]`` table: a preset, or the mass [kg], the law and its parameters (SI),
        and the radius [m] (default the tennis ball's, :data:`racket.TENNIS_BALL_RADIUS`).
    """
    _check_keys(table, _BALL_KEYS, "ball")
    if "preset" in table:
        extra = sorted(set(table) - {"preset"})
        if extra:
            raise ValueError(f"[ball] with a preset takes no other keys, got {extra[0]!r}")
        return _preset(table["preset"], BALLS, "ball")
    if "law" not in table or "mass" not in table:
        raise ValueError("[ball] needs a preset, or mass and law")
    if not isinstance(table["law"], str) or table["law"] not in LAWS:
        raise ValueError(f"unknown law {shown(table['law'])}; laws: {', '.join(LAWS)}")
    cls, params = LAWS[table["law"]]
    linear = cls in (LinearSpring, LinearHysteresis, StiffeningHysteresis)  # k in N/m
    _check_ranges(table, "ball", {"mass", "radius", "k0", "x_lim"} | ({"k"} if linear else set()))
    given = set(table) - {"mass", "law", "radius"}
    if cls is PowerLawHysteresis and given == {"k", "a", "e"}:
        law = PowerLawHysteresis.with_cor(table["k"], table["a"], table["e"])
    else:
        optional = {"calibrated_to"} if cls is GrowingHysteresis else set()
        if given - optional != params:
            raise ValueError(
                f"law {table['law']!r} takes {', '.join(sorted(params))}"
                f"{' (and calibrated_to)' if optional else ''}, got "
                f"{', '.join(sorted(given)) or 'nothing'}"
            )
        law = cls(**{p: table[p] for p in params | (given & optional)})
    return Ball(table["mass"], law, table.get("radius", TENNIS_BALL_RADIUS))


def _load(spec, presets: dict, kind: str, from_table):
    """A preset by name, or the ``[kind]`` table of a TOML file built by ``from_table``."""
    name, spec = preset_or_file(spec, presets, kind)
    if name is not None:
        return presets[name]()
    data = read_toml(spec)
    if kind not in data:
        raise ValueError(f"{spec} has no [{kind}] table")
    try:
        return from_table(data[kind])
    except ValueError:  # (a wrong type said as such is one too)
        raise
    except TypeError as err:  # a value of the wrong type deep in a constructor
        raise ValueError(f"{spec}: a value in [{kind}] has the wrong type ({err})") from None


def load_racket(spec: str | os.PathLike) -> Racket:
    """A racket from a preset name or a TOML file with a ``[racket]`` table.

    Parameters
    ----------
    spec : str or os.PathLike
        A key of :data:`RACKETS`, or a ``.toml`` file (a str, or a ``pathlib.Path``).
    """
    return _load(spec, RACKETS, "racket", racket_from_table)


def load_ball(spec: str | os.PathLike) -> Ball:
    """A ball from a preset name or a TOML file with a ``[ball]`` table.

    Parameters
    ----------
    spec : str or os.PathLike
        A key of :data:`BALLS`, or a ``.toml`` file (a str, or a ``pathlib.Path``).
    """
    return _load(spec, BALLS, "ball", ball_from_table)


def racket_specs(spec: str | os.PathLike) -> tuple[dict | None, dict | None]:
    """The spec sheet a racket preset or TOML file was built from, and the sources of its
    numbers (catalogue presets only); (None, None) for a racket not built from one.

    Parameters
    ----------
    spec : str or os.PathLike
        A key of :data:`RACKETS`, or a ``.toml`` file (a str, or a ``pathlib.Path``).
    """
    name, spec = preset_or_file(spec, RACKETS, "racket")
    if name in CATALOG:
        return dict(CATALOG[name].specs), dict(CATALOG[name].sources)
    if name is not None:
        return None, None
    table = read_toml(spec).get("racket", {})
    if "specs" in table:
        return dict(table["specs"]), None
    if table.get("preset") in CATALOG:
        return dict(CATALOG[table["preset"]].specs), dict(CATALOG[table["preset"]].sources)
    return None, None
