"""The interactive page: ``racket-impact app`` (Shiny for Python).

Why Shiny: its reactive graph recomputes only what a changed control feeds, it draws the
project's own matplotlib figures server-side (no second plotting stack), and its JavaScript
and CSS ship inside the Python package, so the page works offline.  The page only arranges
controls and outputs; :mod:`studies.dashboard` computes.
"""

from __future__ import annotations

import threading

from shiny import App, reactive, render, ui

from ball import DEFAULT_BALL
from racket import CATALOG
from studies.config import BALLS
from studies.dashboard import MY_SHEET, PageInputs, page_results

_CLOCK = ["3 and 9", "2 and 10", "12", "6"]
_WARM = threading.Event()


def _warm_up() -> None:
    """Compile the solver (once per machine: numba caches it on disk) and note when done."""
    from racket.solver import load_kernel

    load_kernel()
    _WARM.set()


def _controls():
    racket = ui.input_select(
        "racket",
        "Racket",
        {name: name for name in [*CATALOG, MY_SHEET]},
        selected="pure-drive-2021",
    )
    sheet = ui.panel_conditional(
        f"input.racket === '{MY_SHEET}'",
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
        racket,
        sheet,
        ui.input_slider("lead_g", "Lead tape per side [g]", 0, 15, 0, step=0.5),
        ui.input_select("lead_at", "Lead at (o'clock)", _CLOCK),
        ui.input_select("ball", "Ball", list(BALLS), selected=DEFAULT_BALL),
        ui.input_slider("tension", "Tension [lb]", 40, 65, 55, step=1),
        ui.input_slider("ball_speed", "Incoming ball speed [m/s]", 5, 30, 16.5, step=0.5),
        ui.input_slider("swing", "Racket-head speed [mph]", 20, 100, 50, step=1),
        ui.input_slider("pivot", "Pivot [cm from the butt, - beyond]", -20, 10, -5, step=1),
    ]


app_ui = ui.page_sidebar(
    ui.sidebar(*_controls(), width=320),
    ui.output_ui("status"),
    ui.output_ui("numbers"),
    ui.layout_columns(
        ui.card(ui.card_header("Along the racket"), ui.output_plot("along", height="420px")),
        ui.card(ui.card_header("The string face"), ui.output_plot("face", height="520px")),
        col_widths=[7, 5],
    ),
    ui.layout_columns(
        ui.card(ui.card_header("Sweet spots"), ui.output_table("spots")),
        ui.card(
            ui.card_header("Serve, one swing: centre and 5 cm towards the tip"),
            ui.output_table("serve"),
        ),
        col_widths=[7, 5],
    ),
    title="racket-impact",
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
        inputs = PageInputs(
            racket=input.racket(),
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
            ball_speed=input.ball_speed(),
            swing_mph=input.swing(),
            pivot_cm_from_butt=input.pivot(),
        )
        try:
            return page_results(inputs)
        except ValueError as err:
            return str(err)

    @render.ui
    def numbers():
        r = results()
        if r is None:
            return ui.div()
        if isinstance(r, str):
            return ui.div(r, id="numbers-text", class_="alert alert-danger")
        s = r.summary
        racket = (
            f"{s['mass_g']:.0f} g, balance {s['balance_cm']:.1f} cm, swingweight "
            f"{s['swingweight_kgcm2']:.0f}, twistweight {s['twistweight_kgcm2']:.1f}, f1 "
            f"{s['f1_hz']:.0f} Hz"
        )
        notes = [ui.div(f"Note: {w}", class_="text-warning small") for w in r.warnings]
        if "f1_from_ra" in s:
            notes.insert(0, ui.div(s["f1_from_ra"], class_="text-muted small"))
        if "effort_head_taped_mph" in s:  # lead tape: the swing at equal effort
            notes.insert(0, ui.div(
                f"At equal effort (a heavier swingweight swings slower, Cross and Bower 2006): "
                f"without the tape {s['effort_head_untaped_mph']:.1f} mph head speed, "
                f"{s['effort_exit_untaped_mph']:.1f} mph off the centre; with it "
                f"{s['effort_head_taped_mph']:.1f} mph, {s['effort_exit_taped_mph']:.1f} mph",
                id="equal-effort", class_="small",
            ))  # fmt: skip
        return ui.div(
            ui.tags.b(racket),
            ui.br(),
            f"e_A at the centre {s['e_A_centre']:.3f}, at 3 o'clock {s['e_A_3_oclock']:.3f}; "
            f"largest {s['largest_e_A']:.3f} at {s['largest_e_A_from_butt_cm']:.1f} cm from the "
            f"butt; sweet area {s['sweet_area_cm2']:.1f} cm²; serve {s['serve_centre_mph']:.1f} "
            f"mph at the centre, {s['serve_tipward_mph']:.1f} mph 5 cm towards the tip",
            *notes,
            id="numbers-text",
        )

    @render.plot(alt="e, e_A and the swung exit speed along the racket")
    def along():
        r = results()
        if r is None or isinstance(r, str):
            return None
        from studies.plots import plot_cor_along_racket

        ax = plot_cor_along_racket(r.along, r.racket)
        twin = ax.twinx()
        x_cm = 100 * r.along["position_from_tip_m"]
        twin.plot(x_cm, r.along["exit_speed_swung_mph"], color="C2", label="exit speed, swung")
        twin.set_ylabel("exit speed of the swing [mph]", color="C2")
        return ax.figure

    @render.plot(alt="e_A over the string face")
    def face():
        r = results()
        if r is None or isinstance(r, str):
            return None
        from studies.plots import plot_face_map

        return plot_face_map(r.face).figure

    @render.table
    def spots():
        r = results()
        if r is None or isinstance(r, str):
            return None
        return r.spots.drop(columns="meaning").round(3)

    @render.table
    def serve():
        r = results()
        if r is None or isinstance(r, str):
            return None
        columns = ["position_from_butt_cm", "point_speed_mph", "serve_simulated_mph"]
        return r.serve[columns].round(1)


app = App(app_ui, server)


def run(host: str = "127.0.0.1", port: int = 8000) -> None:
    """Serve the page at http://host:port (blocks); the solver warms up meanwhile."""
    import uvicorn

    threading.Thread(target=_warm_up, daemon=True).start()
    uvicorn.run(app, host=host, port=port, log_level="warning")
