"""The interactive page's cards and tables (HTML, :mod:`shiny.ui`): the headline numbers of
rackets A and B and B - A (the serve with spin, a groundstroke with spin, power, sweet area,
feel, the rackets), each card with what it was computed for; a line in the place of a racket
that could not be built; where to hit on each racket [cm from the tip].
"""

from __future__ import annotations

from shiny import ui

from common.units import IN2, MPH
from racket.stroke import RPM
from studies.face.maps import SWEET_FRACTION
from studies.page.strokes import GROUNDSTROKE_RATIO, PAGE_GROUNDSTROKE, PAGE_SERVES

SIDES = ("A", "B")
"""The page's rackets."""


def _row(label: str, cells, diff: bool = False):
    """A table row: ``cells`` are (text, tooltip, id) triples."""
    kind = "diff" if diff else "value"
    return ui.tags.tr(
        ui.tags.th(label),
        *(ui.tags.td(ui.tags.span(t, id=i, title=tip), class_=kind) for t, tip, i in cells),
    )


def _metric(card_id: str, title: str, note: str, columns, sides, digits, si=None, small=""):
    """A headline card: one column per quantity (``columns``: its header with unit), a row
    per racket built (``sides``: side -> its values) and, with both, B - A (the difference
    of the numbers shown, each rounded to ``digits``); ``si`` (factor, unit) per column puts
    the SI value in each number's tooltip; ``small`` (the conditions) below.  A header's
    newline breaks its line (its unit under its words, for a card of many columns).
    """
    si = si or [None] * len(columns)
    rows = []
    for side, values in sides.items():
        key = side.lower()
        rows.append(
            _row(
                side,
                [
                    (
                        f"{v:.{d}f}",
                        "" if s is None else f"{v * s[0]:.{d}f} {s[1]}",
                        f"{card_id}_{key}_{k}",
                    )
                    for k, (v, d, s) in enumerate(zip(values, digits, si, strict=True))
                ],
            )
        )
    if len(sides) == 2:
        a, b = sides.values()
        diffs = [round(y, d) - round(x, d) for x, y, d in zip(a, b, digits, strict=True)]
        rows.append(
            _row(
                "B − A",
                [
                    (f"{v:+.{d}f}", "B minus A", f"{card_id}_diff_{k}")
                    for k, (v, d) in enumerate(zip(diffs, digits, strict=True))
                ],
                diff=True,
            )
        )
    head = ui.tags.tr(
        ui.tags.th(""),
        *(ui.tags.th(*_lines(c), class_="unit text-end") for c in columns),
    )
    return ui.card(
        ui.card_header(ui.div(ui.tags.b(title), ui.div(note, class_="small text-muted"))),
        ui.tags.table(ui.tags.thead(head), ui.tags.tbody(*rows)),
        ui.div(small, class_="conditions", id=f"{card_id}_conditions"),
        id=card_id,
        class_="metric",
    )


def _lines(text: str) -> list:
    """``text``'s lines, a line break between each."""
    lines = []
    for line in text.split("\n"):
        lines += [ui.tags.br(), line] if lines else [line]
    return lines


def built_sides(r) -> dict:
    """The rackets of results ``r`` that were built, by side.

    Parameters
    ----------
    r : PageResults
        The page's results (:func:`studies.page.dashboard.page_results`).
    """
    return {side: one for side, one in zip(SIDES, (r.a, r.b), strict=True) if one is not None}


def error_cards(r):
    """One line per racket of results ``r`` that could not be built, in its place.

    Parameters
    ----------
    r : PageResults
        The page's results (:func:`studies.page.dashboard.page_results`).
    """
    return [
        ui.div(line, id=f"error_{side.lower()}", class_="alert alert-danger py-2 mb-2")
        for side, line in r.errors.items()
    ]


def headline_cards(r, swing_mph: float):
    """The headline cards and the rackets' own numbers for results ``r``.

    Parameters
    ----------
    r : PageResults
        The page's results (:func:`studies.page.dashboard.page_results`).
    swing_mph : float
        The page's racket-head speed [mph], as the serve card says it.
    """
    built = built_sides(r)
    said = r.conditions

    def pick(*keys):
        return {side: [one.summary[k] for k in keys] for side, one in built.items()}

    def each(key: str, size: float, unit: str, digits: int = 1) -> str:
        return ", ".join(
            f"{side} {one.summary[key] * size:.{digits}f} {unit}" for side, one in built.items()
        )

    rpm, mph = (RPM, "rad/s"), (MPH, "m/s")
    flat, kick = PAGE_SERVES
    serve = _metric(
        "card_serve",
        "Serve: speed and spin",
        f"the {flat} and the {kick} at {swing_mph:.0f} mph head speed, each one stroke of "
        "racket-impact stroke: its speed and its spin",
        [f"{flat}\n[mph]", "its spin\n[rpm]", f"{kick}\n[mph]", "its spin\n[rpm]"],
        pick("flat_serve_mph", "flat_serve_spin_rpm", "kick_serve_mph", "kick_serve_spin_rpm"),
        [1, 0, 1, 0],
        [mph, rpm, mph, rpm],
        small=f"the serve head-on without spin is the plot's; {said['serve_spin']}",
    )
    groundstroke = _metric(
        "card_groundstroke",
        "Groundstroke: speed and spin",
        f"a {PAGE_GROUNDSTROKE} at {GROUNDSTROKE_RATIO * swing_mph:.0f} mph head speed (the "
        f"page's times {GROUNDSTROKE_RATIO:.2f}, the presets' ratio)",
        ["speed [mph]", "spin [rpm]", "launch [deg]"],
        pick("forehand_mph", "forehand_spin_rpm", "forehand_launch_deg"),
        [1, 0, 1],
        [mph, rpm, None],
        small=f"spin < 0: backspin; launch above the horizontal; {said['groundstroke']}",
    )
    power = _metric(
        "card_power",
        "Power at the centre",
        "the incoming ball at the string centre",
        ["e_A [-]", "exit [mph]"],
        pick("e_A_centre", "exit_centre_mph"),
        [3, 1],
        [None, (MPH, "m/s")],
        small=f"e_A: rebound ratio off the racket at rest; exit: ball speed off the swing; "
        f"{said['power']}",
    )
    cm2_in2 = 1e-4 / IN2  # [in^2 per cm^2]
    within = f"where e_A is within {100 * SWEET_FRACTION:g} % of its largest"
    sweet = _metric(
        "card_sweet",
        "Sweet area",
        within,
        ["area [cm²]"],
        pick("sweet_area_cm2"),
        [1],
        [(cm2_in2, "in²")],
        small=f"{each('sweet_area_cm2', cm2_in2, 'in²')}; {said['sweet']}",
    )
    feel = _metric(
        "card_feel",
        "Feel at the hand",
        "accelerations at the hand [×g]: the shock, and the ringing after the ball has left; "
        "a centre hit, as the feel command says",
        ["shock", "ring"],
        pick("feel_shock_g", "feel_vibration_g"),
        [1, 0],
        small="; ".join(
            [
                *(
                    f"{side}: rings at {one.summary['feel_hz']:.0f} Hz, {one.summary['feel_mode']}"
                    for side, one in built.items()
                ),
                said["feel"],
            ]
        ),
    )
    taped = " with lead tape" if "effort_head_taped_mph" in (r.a.summary if r.a else {}) else ""
    spec = _metric(
        "card_racket",
        "The rackets",
        "; ".join(
            f"{side}: {one.name}{taped if side == 'A' else ''}" for side, one in built.items()
        ),
        [
            "mass [g]",
            "balance [cm from the butt]",
            "swingweight [kg cm²]",
            "twistweight [kg cm²]",
            "f1 [Hz]",
        ],
        pick("mass_g", "balance_cm", "swingweight_kgcm2", "twistweight_kgcm2", "f1_hz"),
        [0, 1, 0, 1, 0],
        small=f"swingweight about 10 cm from the butt; {said['racket']}",
    )
    return ui.div(
        *error_cards(r),
        ui.layout_column_wrap(serve, groundstroke, width="400px", fill=False),
        ui.layout_column_wrap(power, sweet, feel, width="240px", fill=False),
        spec,
        id="numbers-text",
    )


def spots_table(r):
    """The "Where to hit" table of results ``r``: a row per spot, its name, then where it
    is on each racket built [cm from the tip]; every header over its column, aligned as it.

    Parameters
    ----------
    r : PageResults
        The page's results (:func:`studies.page.dashboard.page_results`).
    """
    built = built_sides(r)
    spots = {side: one.spots.set_index("spot")["from_tip_cm"] for side, one in built.items()}
    names = list(dict.fromkeys(n for s in spots.values() for n in s.index))
    head = ui.tags.tr(
        ui.tags.th("spot", class_="words"),
        *(ui.tags.th(f"{side}: {one.name}", class_="number") for side, one in built.items()),
    )
    rows = [
        ui.tags.tr(
            ui.tags.td(name, class_="words"),
            *(ui.tags.td(_cm(spots[side], name), class_="number") for side in built),
        )
        for name in names
    ]
    return ui.div(
        ui.tags.table(
            ui.tags.thead(head), ui.tags.tbody(*rows), class_="racket-table", id="spots-table"
        ),
        ui.div(r.conditions["spots"], class_="conditions"),
    )


def _cm(column, name: str) -> str:
    """Where the spot ``name`` is in ``column`` [cm], one decimal ("" if not on this
    racket; each, when it is there twice, as a mode's two nodes).
    """
    if name not in column.index:
        return ""
    values = column.loc[[name]]
    return ", ".join(f"{v:.1f}" for v in values)
