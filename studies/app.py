"""The interactive page: ``racket-impact app`` (Shiny for Python), for a coach comparing two
rackets.

Why Shiny: its reactive graph recomputes only what a changed control feeds, it draws the
project's own matplotlib figures server-side (no second plotting stack), and its JavaScript
and CSS ship inside the Python package, so the page works offline.  The page only arranges
controls and outputs; :mod:`studies.dashboard` computes and :mod:`studies.plots_page` draws.
Speeds are in mph (m/s in the tooltip and small text).
"""

from __future__ import annotations

import errno
import os
import socket
import threading

import pandas as pd
from shiny import App, reactive, render, ui

from ball import DEFAULT_BALL
from common.units import IN2, MPH
from racket import CATALOG
from studies.config import BALLS
from studies.dashboard import MY_SHEET, PageInputs, page_results
from studies.maps import SWEET_FRACTION

DEFAULT_PORT = 8050
"""The page's default port (``mkdocs serve``, the docs, takes 8000)."""

_CLOCK = ["3 and 9", "2 and 10", "12", "6"]
_WARM = threading.Event()
_STYLE = """
.metric td, .metric th { padding: 0.1rem 0.4rem; white-space: nowrap; }
.metric .value { font-size: 1.35rem; font-weight: 600; text-align: right; }
.metric .diff { font-size: 1.05rem; text-align: right; }
.metric .unit { color: #6c757d; }
.metric table { width: 100%; }
.racket-table { font-size: 0.9rem; width: 100%; }
.racket-table td, .racket-table th { padding: 0.1rem 0.5rem; text-align: right; }
"""


def _warm_up() -> None:
    """Compile the solver (once per machine: numba caches it on disk) and note when done."""
    from racket.solver import load_kernel

    load_kernel()
    _WARM.set()


def _controls():
    choices = {name: name for name in [*CATALOG, MY_SHEET]}
    sheet = ui.panel_conditional(
        f"input.racket === '{MY_SHEET}' || input.racket_b === '{MY_SHEET}'",
        ui.tags.b("My spec sheet"),
        ui.input_numeric("mass_g", "Strung mass [g]", 300, min=230, max=380, step=1),
        ui.input_numeric("balance_cm", "Balance [cm from the butt]", 33, min=30, max=37, step=0.1),
        ui.input_numeric("swingweight", "Swingweight [kg cm²]", 315, min=270, max=370, step=1),
        ui.input_numeric("head", "Head size [in²]", 100, min=85, max=120, step=1),
        ui.input_radio_buttons(
            "stiffness", "Frame stiffness given as", {"f1": "frequency f1", "ra": "RA"}
        ),
        ui.panel_conditional(
            "input.stiffness === 'f1'",
            ui.input_numeric("f1", "Frame frequency f1 [Hz]", 150, min=100, max=200, step=1),
        ),
        ui.panel_conditional(
            "input.stiffness === 'ra'",
            ui.input_numeric("ra", "RA (f1 from the TWU regression)", 66, min=50, max=80, step=1),
        ),
    )
    return [
        ui.input_select("racket", "Racket A", choices, selected="pure-drive-2021"),
        ui.input_select("racket_b", "Racket B", choices, selected="pro-staff-97l-cv"),
        sheet,
        ui.input_slider("lead_g", "Lead tape on A, per side [g]", 0, 15, 0, step=0.5),
        ui.input_select("lead_at", "Lead at (o'clock)", _CLOCK),
        ui.input_slider("swing", "Racket-head speed [mph]", 20, 150, 70, step=1),
        ui.input_slider("ball_speed", "Incoming ball speed [mph]", 10, 80, 37, step=1),
        ui.input_slider("tension", "Tension, both [lb]", 40, 70, 55, step=1),
        ui.input_select("ball", "Ball", list(BALLS), selected=DEFAULT_BALL),
        ui.input_slider("pivot", "Swing pivot [cm from the butt, - beyond]", -20, 10, -5, step=1),
    ]


def _card(plot_id: str, title: str, height: str = "380px"):
    return ui.card(ui.card_header(title), ui.output_plot(plot_id, height=height))


app_ui = ui.page_sidebar(
    ui.sidebar(*_controls(), width=300),
    ui.tags.style(_STYLE),
    ui.output_ui("status"),
    ui.output_ui("cards"),
    ui.output_ui("notes"),
    ui.layout_columns(
        _card("serve_plot", "Serve speed against head speed (string centre)"),
        _card("exit_plot", "Ball speed off the strings along the racket (the swing)"),
        col_widths=[6, 6],
    ),
    ui.layout_columns(
        _card("face_a", "Sweet area of A (e_A over the face)", "600px"),
        _card("face_b", "Sweet area of B (e_A over the face)", "600px"),
        col_widths=[6, 6],
    ),
    ui.layout_columns(
        _card("power_plot", "Rebound ratio e_A along the racket (racket at rest)"),
        ui.card(ui.card_header("Where to hit [cm from the butt]"), ui.output_table("spots")),
        col_widths=[6, 6],
    ),
    title="racket-impact: two rackets side by side",
)


def _row(label: str, cells, diff: bool = False):
    """A table row: ``cells`` are (text, tooltip, id) triples."""
    kind = "diff" if diff else "value"
    return ui.tags.tr(
        ui.tags.th(label),
        *(ui.tags.td(ui.tags.span(t, id=i, title=tip), class_=kind) for t, tip, i in cells),
    )


def _metric(card_id: str, title: str, note: str, columns, a, b, digits, si=None, small=""):
    """A headline card: one column per quantity (``columns``: its header with unit), rows
    A, B and B - A (the difference of the numbers shown, each rounded to ``digits``);
    ``si`` (factor, unit) per column puts the SI value in each number's tooltip.
    """
    si = si or [None] * len(columns)
    rows = []
    for label, values, key in (("A", a, "a"), ("B", b, "b")):
        rows.append(_row(label, [
            (f"{v:.{d}f}", "" if s is None else f"{v * s[0]:.{d}f} {s[1]}", f"{card_id}_{key}_{k}")
            for k, (v, d, s) in enumerate(zip(values, digits, si, strict=True))
        ]))  # fmt: skip
    diffs = [round(y, d) - round(x, d) for x, y, d in zip(a, b, digits, strict=True)]
    rows.append(_row("B − A", [
        (f"{v:+.{d}f}", "B minus A", f"{card_id}_diff_{k}")
        for k, (v, d) in enumerate(zip(diffs, digits, strict=True))
    ], diff=True))  # fmt: skip
    head = ui.tags.tr(ui.tags.th(""), *(ui.tags.th(c, class_="unit text-end") for c in columns))
    return ui.card(
        ui.card_header(ui.div(ui.tags.b(title), ui.div(note, class_="small text-muted"))),
        ui.tags.table(ui.tags.thead(head), ui.tags.tbody(*rows)),
        ui.div(small, class_="small text-muted") if small else None,
        id=card_id,
        class_="metric",
    )


def _cards(r, swing_mph: float):
    """The headline cards and the rackets' own numbers for results ``r``."""
    a, b = r.a.summary, r.b.summary

    def pick(*keys):
        return [a[k] for k in keys], [b[k] for k in keys]

    serve = _metric(
        "card_serve", "Serve speed", f"off the string centre at {swing_mph:.0f} mph head speed",
        ["serve [mph]"], *pick("serve_mph"), [1], [(MPH, "m/s")],
        small=f"A {a['serve_mph'] * MPH:.1f} m/s, B {b['serve_mph'] * MPH:.1f} m/s",
    )  # fmt: skip
    power = _metric(
        "card_power", "Power at the centre", "the incoming ball at the string centre",
        ["e_A [-]", "exit [mph]"], *pick("e_A_centre", "exit_centre_mph"), [3, 1],
        [None, (MPH, "m/s")],
        small="e_A: rebound ratio off the racket at rest; exit: ball speed off the swing",
    )  # fmt: skip
    cm2_in2 = 1e-4 / IN2  # [in^2 per cm^2]
    within = f"where e_A is within {100 * SWEET_FRACTION:g} % of its largest"
    sweet_in2 = [s["sweet_area_cm2"] * cm2_in2 for s in (a, b)]
    sweet = _metric(
        "card_sweet", "Sweet area", within, ["area [cm²]"], *pick("sweet_area_cm2"), [1],
        [(cm2_in2, "in²")], small=f"A {sweet_in2[0]:.1f} in², B {sweet_in2[1]:.1f} in²",
    )  # fmt: skip
    feel = _metric(
        "card_feel", "Feel at the hand", "strongest vibration of the handle, centre hit",
        ["[Hz]", "peak [×g]"], *pick("feel_hz", "feel_peak_g"), [0, 0],
        small=f"A: {a['feel_mode']}; B: {b['feel_mode']}",
    )  # fmt: skip
    taped = " with lead tape" if "effort_head_taped_mph" in a else ""
    spec = _metric(
        "card_racket", "The rackets", f"A: {r.a.name}{taped}; B: {r.b.name}",
        ["mass [g]", "balance [cm]", "swingweight [kg cm²]", "twistweight [kg cm²]", "f1 [Hz]"],
        *pick("mass_g", "balance_cm", "swingweight_kgcm2", "twistweight_kgcm2", "f1_hz"),
        [0, 1, 0, 1, 0], small="balance from the butt; swingweight about 10 cm from the butt",
    )  # fmt: skip
    return ui.div(
        ui.layout_column_wrap(serve, power, sweet, feel, width="240px", fill=False),
        spec,
        id="numbers-text",
    )


def _inputs(input) -> PageInputs:
    """The page's controls as :class:`studies.dashboard.PageInputs`."""
    return PageInputs(
        racket=input.racket(),
        racket_b=input.racket_b(),
        mass_g=input.mass_g() or 300.0,
        balance_cm=input.balance_cm() or 33.0,
        swingweight_kgcm2=input.swingweight() or 315.0,
        head_size_in2=input.head() or 100.0,
        f1_hz=(input.f1() or 150.0) if input.stiffness() == "f1" else None,
        ra=(input.ra() or 66.0) if input.stiffness() == "ra" else None,
        lead_g=input.lead_g(),
        lead_at=input.lead_at(),
        ball=input.ball(),
        tension_lb=input.tension(),
        ball_speed_mph=input.ball_speed(),
        swing_mph=input.swing(),
        pivot_cm_from_butt=input.pivot(),
    )


def server(input, output, session):
    """The page's reactive outputs (Shiny's server function)."""

    @render.ui
    def status():
        if not _WARM.is_set():
            reactive.invalidate_later(1.0)
            return ui.div(
                "Warming up: compiling the solver (once per machine, about 15 s)...",
                id="warming-up",
                class_="alert alert-warning",
            )
        return ui.div("Ready.", id="ready", class_="text-muted small")

    @reactive.calc
    def results():
        if not _WARM.is_set():
            reactive.invalidate_later(1.0)
            return None
        try:
            return page_results(_inputs(input))
        except ValueError as err:
            return str(err)

    def ready():
        r = results()
        return None if r is None or isinstance(r, str) else r

    @render.ui
    def cards():
        r = results()
        if r is None:
            return ui.div()
        if isinstance(r, str):
            return ui.div(r, id="numbers-text", class_="alert alert-danger")
        return _cards(r, input.swing())

    @render.ui
    def notes():
        r = ready()
        if r is None:
            return ui.div()
        s = r.a.summary
        notes = [ui.div(f"Note: {w}", class_="text-warning small") for w in r.warnings]
        for side in (r.a, r.b):
            if "f1_from_ra" in side.summary:
                notes.insert(0, ui.div(side.summary["f1_from_ra"], class_="text-muted small"))
        if "effort_head_taped_mph" in s:  # lead tape: the swing at equal effort
            notes.insert(0, ui.div(
                f"A at equal effort (a heavier swingweight swings slower, Cross and Bower 2006): "
                f"without the tape {s['effort_head_untaped_mph']:.1f} mph head speed, "
                f"{s['effort_exit_untaped_mph']:.1f} mph off the centre; with it "
                f"{s['effort_head_taped_mph']:.1f} mph, {s['effort_exit_taped_mph']:.1f} mph",
                id="equal-effort", class_="small",
            ))  # fmt: skip
        return ui.div(*notes, id="notes")

    def labels(r):
        return {f"A: {r.a.name}": r.a, f"B: {r.b.name}": r.b}

    @render.plot(alt="serve speed against racket-head speed, rackets A and B")
    def serve_plot():
        from studies.plots_page import plot_serve_speeds

        r = ready()
        if r is None:
            return None
        serves = {k: v.serves for k, v in labels(r).items()}
        return plot_serve_speeds(serves, input.swing()).figure

    @render.plot(alt="ball speed off the swung strings along the racket, A and B")
    def exit_plot():
        from studies.plots_page import plot_along_racket

        r = ready()
        if r is None:
            return None
        tables = {k: v.along for k, v in labels(r).items()}
        ylabel = f"ball speed off the strings [mph] (swing {input.swing():.0f} mph)"
        return plot_along_racket(tables, "exit_speed_swung_mph", ylabel, mph=True).figure

    @render.plot(alt="e_A along the racket, A and B")
    def power_plot():
        from studies.plots_page import plot_along_racket

        r = ready()
        if r is None:
            return None
        tables = {k: v.along for k, v in labels(r).items()}
        return plot_along_racket(tables, "e_A", "rebound ratio e_A [-]").figure

    def face(side: str):
        from studies.plots_page import plot_face_map_page

        r = ready()
        if r is None:
            return None
        one = r.a if side == "A" else r.b
        speed = input.ball_speed()
        title = f"{side}: {one.name}\nball at {speed:.0f} mph ({speed * MPH:.1f} m/s)"
        return plot_face_map_page(one.face, title).figure

    @render.plot(alt="e_A over the string face of racket A")
    def face_a():
        return face("A")

    @render.plot(alt="e_A over the string face of racket B")
    def face_b():
        return face("B")

    @render.table
    def spots():
        r = ready()
        if r is None:
            return None
        a, b = (s.spots.set_index("spot")["from_butt_cm"] for s in (r.a, r.b))
        table = pd.DataFrame({"A": a, "B": b}).reset_index(names="spot")
        return table.round(1)


app = App(app_ui, server)


def run(host: str = "127.0.0.1", port: int = DEFAULT_PORT, announce=print) -> None:
    """Serve the page at http://host:port (blocks); the solver warms up meanwhile.

    The port is bound first; only then is ``announce`` called with the page's address, so
    an address that is announced is one that answers.

    Parameters
    ----------
    host : str
        Address to serve on.
    port : int
        Port; in use, a ``ValueError`` of one line before anything is announced.
    announce : callable
        Called with the page's URL once the port is bound (default: print it).
    """
    import uvicorn

    try:
        socket.getaddrinfo(host, port, type=socket.SOCK_STREAM)
    except socket.gaierror as err:
        raise ValueError(f"host must be an address of this machine, got {host!r} "
                         f"({err.strerror})") from None  # fmt: skip
    try:
        sock = socket.create_server((host, port), backlog=2048)
    except OSError as err:
        hint = "another server there? choose another with --port"
        if err.errno != errno.EADDRINUSE:
            hint = "is the host an address of this machine?"
        raise ValueError(
            f"port {port} on {host} cannot be served: {os.strerror(err.errno)} ({hint})"
        ) from None
    with sock:
        announce(f"http://{host}:{sock.getsockname()[1]}")
        threading.Thread(target=_warm_up, daemon=True).start()
        config = uvicorn.Config(app, log_level="warning")
        uvicorn.Server(config).run(sockets=[sock])
