"""The interactive page: ``racket-impact app`` (Shiny for Python), for a coach comparing two
rackets.

Why Shiny: its reactive graph recomputes only what a changed control feeds, it draws the
project's own matplotlib figures server-side (no second plotting stack), and its JavaScript
and CSS ship inside the Python package, so the page works offline.  The page only arranges
controls and outputs; :mod:`studies.page.dashboard` computes and :mod:`studies.page.plots` draws.
Its controls start at the command line's defaults (:class:`studies.page.dashboard.PageInputs`),
every card and plot says what it was computed for, positions are in cm from the tip (the
balance, as spec sheets give it, from the butt).  Speeds are in mph (m/s in the tooltip
and small text).  A plot is drawn again only when what it draws changes
(:func:`studies.page.plots.page_plots`), and while the server works on a change the status
line says so (:data:`BUSY`) in place of "Ready.".
"""

from __future__ import annotations

import errno
import os
import pickle
import socket
import threading

from shiny import App, reactive, render, ui

from common.typechecks import asked_by_caller
from racket import CATALOG
from racket.solver import COMPILE_SECONDS
from racket.swing import ARM_REACH
from studies.config import BALLS
from studies.page.cards import built_sides, error_cards, headline_cards, spots_table
from studies.page.dashboard import HEAD_SPEED_MAX_MPH, MY_SHEET, PageInputs, page_results
from studies.page.guard import ERROR_OUTPUT, PageGuard
from studies.page.inputs import LABELS, LEAD_CLOCKS, STIFFNESS, page_inputs
from studies.page.plots import PLOTS, page_plots
from studies.page.strings import STRING_WORDS

DEFAULT_PORT = 8050
"""The page's default port (``mkdocs serve``, the docs, takes 8000)."""

BUSY = "Recalculating: the numbers and plots below are for the controls as they were..."
"""What the status line says while the server works on a change, in place of "Ready."."""

_WARM = threading.Event()
# The status line says BUSY, not "Ready.", while Shiny marks the page's root `shiny-busy`:
# from the server's taking a change until it has computed every output the change alters
# (sent at once, in one message).
_STYLE = """
.metric td, .metric th { padding: 0.1rem 0.4rem; white-space: nowrap; }
.metric .value { font-size: 1.35rem; font-weight: 600; text-align: right; }
.metric .diff { font-size: 1.05rem; text-align: right; }
.metric .unit { color: #6c757d; }
.metric table { width: 100%; }
.conditions { color: #6c757d; font-size: 0.8rem; white-space: normal; }
.racket-table { font-size: 0.9rem; width: 100%; }
.racket-table td, .racket-table th { padding: 0.1rem 0.5rem; }
.racket-table .number { text-align: right; }
.racket-table .words { text-align: left; }
html.shiny-busy #ready, html:not(.shiny-busy) #busy { display: none; }
#busy { color: #b35c00; font-weight: 600; }
"""


def _warm_up() -> None:
    """Compile the solver and the ball's grip on the strings (the strokes with spin), once per
    machine (numba caches them on disk), and note when done.
    """
    from racket import STROKES, hit
    from racket.presets import paper_ball, paper_racket
    from racket.solver import load_kernel

    load_kernel()
    hit(STROKES["volley"], paper_racket(), paper_ball())
    _WARM.set()


def _controls():
    """The sidebar's controls, each starting at its default in
    :class:`studies.page.dashboard.PageInputs` (the command line's).
    """
    start = PageInputs()
    choices = {name: name for name in [*CATALOG, MY_SHEET]}
    label = LABELS
    sheet = ui.panel_conditional(
        f"input.racket === '{MY_SHEET}' || input.racket_b === '{MY_SHEET}'",
        ui.tags.b("My spec sheet"),
        ui.input_numeric("mass_g", label["mass_g"], start.mass_g, min=230, max=380, step=1),
        ui.input_numeric(
            "balance_cm", label["balance_cm"], start.balance_cm, min=30, max=37, step=0.1
        ),
        ui.input_numeric(
            "swingweight",
            label["swingweight"],
            start.swingweight_kgcm2,
            min=270,
            max=370,
            step=1,
        ),
        ui.input_numeric("head", label["head"], start.head_size_in2, min=85, max=120, step=1),
        ui.input_radio_buttons("stiffness", label["stiffness"], STIFFNESS),
        ui.panel_conditional(
            "input.stiffness === 'f1'",
            ui.input_numeric("f1", label["f1"], start.f1_hz, min=100, max=200, step=1),
        ),
        ui.panel_conditional(
            "input.stiffness === 'ra'",
            ui.input_numeric(
                "ra", f"{label['ra']} (f1 from the TWU regression)", 66, min=50, max=80, step=1
            ),
        ),
    )
    farthest = 100 * (CATALOG[start.racket].specs["length_m"] + ARM_REACH)
    return [
        ui.input_select("racket", label["racket"], choices, selected=start.racket),
        ui.input_select("racket_b", label["racket_b"], choices, selected=start.racket_b),
        sheet,
        ui.input_slider("lead_g", label["lead_g"], 0, 15, start.lead_g, step=0.5),
        ui.input_select("lead_at", label["lead_at"], list(LEAD_CLOCKS), selected=start.lead_at),
        ui.input_slider("swing", label["swing"], 20, HEAD_SPEED_MAX_MPH, start.swing_mph, step=1),
        ui.input_slider("ball_speed", label["ball_speed"], 10, 80, start.ball_speed_mph, step=0.1),
        ui.input_slider("tension", label["tension"], 40, 70, start.tension_lb, step=1),
        ui.input_select("string", label["string"], STRING_WORDS, selected=start.string),
        ui.input_checkbox("played", label["played"], start.played),
        ui.input_select("ball", label["ball"], list(BALLS), selected=start.ball),
        ui.input_checkbox("at_wrist", label["at_wrist"], start.pivot_cm_from_tip is None),
        ui.panel_conditional(
            "!input.at_wrist",
            ui.input_slider("pivot", label["pivot"], 40, round(farthest), 74, step=0.5),
        ),
    ]


def _card(plot_id: str, title: str, height: str = "380px"):
    return ui.card(ui.card_header(title), ui.output_plot(plot_id, height=height))


app_ui = ui.page_sidebar(
    ui.sidebar(*_controls(), width=300),
    ui.tags.style(_STYLE),
    ui.output_ui(ERROR_OUTPUT),  # a message the server turned away (studies.page.guard)
    ui.output_ui("status"),
    ui.output_ui("cards"),
    ui.output_ui("notes"),
    ui.layout_columns(
        _card("serve_plot", "Serve head-on, no spin: speed against head speed (string centre)"),
        _card("exit_plot", "Ball speed off the strings along the racket (the swing)"),
        col_widths=[6, 6],
    ),
    ui.layout_columns(
        ui.card(
            ui.card_header("Sweet area of A (e_A over the face)"),
            ui.output_ui("face_a_error"),
            ui.output_plot("face_a", height="600px"),
        ),
        ui.card(
            ui.card_header("Sweet area of B (e_A over the face)"),
            ui.output_ui("face_b_error"),
            ui.output_plot("face_b", height="600px"),
        ),
        col_widths=[6, 6],
    ),
    ui.layout_columns(
        _card("power_plot", "Rebound ratio e_A along the racket (racket at rest)"),
        ui.card(ui.card_header("Where to hit [cm from the tip]"), ui.output_ui("spots")),
        col_widths=[6, 6],
    ),
    title="racket-impact: two rackets side by side",
)


def _sent(input) -> dict:
    """The values the browser sent for the page's controls, by input id (one it did not
    send left out), as they came: :func:`studies.page.inputs.page_inputs` checks them.
    """
    return {name: input[name]() for name in LABELS if input[name].is_set()}


def server(input, output, session):
    """The page's reactive outputs (Shiny's server function)."""

    @output(suspend_when_hidden=False)  # shown even if the browser said nothing of it
    @render.ui
    def status():
        if not _WARM.is_set():
            reactive.invalidate_later(1.0)
            return ui.div(
                "Warming up: compiling the solver (once per machine, about "
                f"{COMPILE_SECONDS:g} s)...",
                id="warming-up",
                class_="alert alert-warning",
            )
        return ui.div(
            ui.span("Ready.", id="ready", class_="text-muted"),
            ui.span(BUSY, id="busy"),
            id="status-line",
            class_="small",
        )

    @reactive.calc
    def inputs():  # the controls, or the one line refusing them
        try:
            return page_inputs(_sent(input))
        except ValueError as err:
            return str(err)

    @reactive.calc
    def results():
        if isinstance(inputs(), str):
            return inputs()
        if not _WARM.is_set():
            reactive.invalidate_later(1.0)
            return None
        try:
            with asked_by_caller():  # the page asked about its controls, in their own words
                return page_results(inputs())
        except ValueError as err:
            return str(err)

    def ready():
        r = results()
        return None if r is None or isinstance(r, str) else r

    @output(suspend_when_hidden=False)  # an error card even for a message without controls
    @render.ui
    def cards():
        r = results()
        if r is None:
            return ui.div()
        if isinstance(r, str):
            return ui.div(r, id="numbers-text", class_="alert alert-danger")
        if not built_sides(r):
            return ui.div(*error_cards(r), id="numbers-text")
        return headline_cards(r, inputs().swing_mph)

    @render.ui
    def notes():
        r = ready()
        if r is None:
            return ui.div()
        notes = [ui.div(f"Note: {w}", class_="text-warning small") for w in r.warnings]
        for one in built_sides(r).values():
            if "f1_from_ra" in one.summary:
                notes.insert(0, ui.div(one.summary["f1_from_ra"], class_="text-muted small"))
        s = r.a.summary if r.a is not None else {}
        if "effort_head_taped_mph" in s:  # lead tape: the swing at equal effort
            said = (
                "A at equal effort (a heavier swingweight swings slower, Cross and Bower 2006): "
                f"without the tape {s['effort_head_untaped_mph']:.1f} mph head speed, "
                f"{s['effort_exit_untaped_mph']:.1f} mph off the centre; with it "
                f"{s['effort_head_taped_mph']:.1f} mph, {s['effort_exit_taped_mph']:.1f} mph"
            )
            notes.insert(0, ui.div(said, id="equal-effort", class_="small"))
        return ui.div(*notes, id="notes")

    @reactive.calc
    def drawn():  # what each plot draws (studies.page.plots.page_plots)
        r = ready()
        return {} if r is None else page_plots(r, inputs().swing_mph)

    def kept(name: str):
        # what plot ``name`` draws, kept as a value set anew only when it changes in value
        # (its pickle): the plot is drawn again only then (a new swing leaves the face maps
        # and e_A along the racket as they were)
        value = reactive.value((None, None))

        @reactive.effect(priority=1)  # before the outputs of the same flush read it
        def _follow():
            new = drawn().get(name)
            said = None if new is None else pickle.dumps(new)
            with reactive.isolate():
                changed = value.get()[0] != said
            if changed:
                value.set((said, new))

        return lambda: value.get()[1]

    now = {name: kept(name) for name in PLOTS}

    def plot(name: str):
        arguments = now[name]()
        return None if arguments is None else PLOTS[name](**arguments).figure

    @render.plot(alt="serve speed against racket-head speed, rackets A and B")
    def serve_plot():
        return plot("serve_plot")

    @render.plot(alt="ball speed off the swung strings along the racket, A and B")
    def exit_plot():
        return plot("exit_plot")

    @render.plot(alt="e_A along the racket, A and B")
    def power_plot():
        return plot("power_plot")

    @render.plot(alt="e_A over the string face of racket A")
    def face_a():
        return plot("face_a")

    @render.plot(alt="e_A over the string face of racket B")
    def face_b():
        return plot("face_b")

    def face_error(side: str):
        r = ready()
        if r is None or side not in r.errors:
            return ui.div()
        return ui.div(r.errors[side], class_="alert alert-danger py-2 mb-0")

    @render.ui
    def face_a_error():
        return face_error("A")

    @render.ui
    def face_b_error():
        return face_error("B")

    @render.ui
    def spots():
        r = ready()
        return ui.div() if r is None or not built_sides(r) else spots_table(r)


app = PageGuard(App(app_ui, server))


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
        raise ValueError(
            f"host must be an address of this machine, got {host!r} ({err.strerror})"
        ) from None
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
