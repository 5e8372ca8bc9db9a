"""``racket-impact paper``: every number of the paper reproduced, its figures written."""

from __future__ import annotations

import contextlib
import gc
import json
import os
import textwrap
import warnings
from pathlib import Path

import numpy as np

from studies import outputs
from studies.cli.files import _sidecar, check_outputs, plot_bytes
from studies.cli.options import _print_table
from studies.cli.show import WIDTH


def add_paper(sub) -> None:
    """The ``paper`` subcommand, on the subparsers ``sub``."""
    p = sub.add_parser("paper", help="reproduce every number of the paper, write its figures")
    p.add_argument(
        "--out",
        metavar="DIR",
        default="paper-figures",
        help="directory for the figures (PNG; default: paper-figures)",
    )
    p.add_argument(
        "--json",
        metavar="FILE",
        help="write the rows as JSON: claim, paper, simulated, tolerance, ok",
    )
    p.set_defaults(func=cmd_paper)


IDLE_CORES = 1.5
"""Idle cores (the machine's, less its load average over the last minute) that the paper's
figures need to be drawn on two processes of their own.  Measured on this project's 2-core
machine: 4.7-4.9 s drawn here against 5.6-6.1 s on two processes at a load of 2 (no core
idle; the processes cost 1.3 s of CPU more: the fork, and each one's fonts and kernels);
2.2 s of CPU here beside 3.9 s in the processes: an estimated 3-3.5 s on an idle machine
(not measured: the machine was never idle)."""


@contextlib.contextmanager
def _no_full_collections():
    """The garbage collector's full collections (of its oldest generation) put off while the
    block runs, the young generations still collected: ``paper`` loads numba, scipy and
    matplotlib, a few hundred thousand objects that live as long as the process, and each
    full collection walks them all to find the little garbage its figures leave (three or
    four of them: 0.37-0.69 s of collecting in a run, 0.10-0.15 s without them, on this
    project's 2-core machine, for 12 MB more at the peak, 281 MB against 269 MB).  A
    collector without a third threshold (CPython 3.14's incremental one reads two) is left
    as it collects.
    """
    young, middle, oldest = gc.get_threshold()
    gc.set_threshold(young, middle, 2**31 - 1)  # a full one after 2**31 - 1 middle ones: never
    try:
        yield
    finally:
        gc.set_threshold(young, middle, oldest)


@_no_full_collections()
def cmd_paper(args) -> int:
    """``racket-impact paper``: the claims, then the figures (on two processes of their own
    where cores are idle, :func:`_figure_pool`; a progress bar on a terminal).
    """
    from studies.paper import paper_columns
    from studies.scale import progress_bar

    check_outputs(directories=[("--out", args.out)])
    if args.json is not None and Path(args.json).suffix.lower() != ".json":
        raise ValueError(f"--json must be a file ending in .json, got {args.json!r}")
    out, figures = Path(args.out), paper_figures()
    check_outputs(
        tables=[("--json", args.json)],
        plots=[("--out", out / name) for name in figures] if out.is_dir() else [],
    )
    with _figure_pool() as workers:  # None: drawn here, after the claims
        drawn = [workers.submit(paper_figure, name) for name in figures] if workers else []
        ok = _say_claims(paper_columns(), args.json)
        outputs.directory(out)
        shown = progress_bar(drawn or list(figures), len(figures), None, "figures")
        for name, done in zip(figures, shown, strict=True):
            data, caught = done.result() if workers else paper_figure(name)
            for category, message in caught:
                warnings.warn(message, category, stacklevel=1)
            outputs.write(out / name, lambda temp, data=data: Path(temp).write_bytes(data))
    print(textwrap.fill(f"figures written to {args.out}/: {', '.join(figures)}", WIDTH))
    return 0 if ok else 1


@contextlib.contextmanager
def _figure_pool():
    """Two processes that draw the figures while the claims are computed, where that helps:
    a machine with a core idle beside this process's (:data:`IDLE_CORES`); None otherwise.
    Forked once the solver is loaded here (numba, matplotlib and the plots then imported
    once for all, the solver's threads not yet started); where there is no fork, spawned.
    """
    cores = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else os.cpu_count()
    busy = os.getloadavg()[0] if hasattr(os, "getloadavg") else 0.0
    if (cores or 1) - busy < IDLE_CORES:
        yield None
        return
    import multiprocessing  # imported for a pool alone (0.035 s)
    from concurrent.futures import ProcessPoolExecutor

    from racket.solver import load_kernel
    from studies.scale import quiet_worker

    load_kernel()
    methods = multiprocessing.get_all_start_methods()
    context = multiprocessing.get_context("fork" if "fork" in methods else "spawn")
    pool = ProcessPoolExecutor(min(2, os.cpu_count() or 1), context, quiet_worker)
    try:
        with warnings.catch_warnings():  # (3.12: "multi-threaded, fork() may deadlock"; the
            warnings.simplefilter("ignore", DeprecationWarning)  # other threads hold no lock)
            pool.submit(int)  # a fork start launches every worker now
        yield pool
    finally:
        pool.shutdown(wait=True, cancel_futures=True)


def _say_claims(table: dict, json_path) -> bool:
    """Print the claims of ``table`` (:func:`studies.paper.paper_columns`) and write them to
    ``json_path`` (if not None); whether all are within tolerance.
    """
    shown = ("claim", "paper", "simulated", "tolerance", "ok")
    _print_table({name: table[name] for name in shown})
    ok = all(table["ok"])
    print(f"\n{sum(table['ok'])} of {len(table['ok'])} claims reproduced within tolerance.")
    if json_path:
        rows = zip(*(table[name] for name in shown), strict=True)
        records = [dict(zip(shown, row, strict=True)) for row in rows]
        text = json.dumps(records, indent=2)
        outputs.write(json_path, lambda temp: Path(temp).write_text(text))
        _sidecar(json_path)
    return ok


def paper_figures() -> dict:
    """The paper's figures and the racket plots: each PNG file's name, and what draws it."""
    import matplotlib

    matplotlib.use("Agg")
    from racket import impact, paper_ball
    from studies import plots
    from studies.conditions import conditions_line, racket_details
    from studies.paper import figure_collision, free_racket
    from studies.serve import serve_what_if_columns

    racket, ball = free_racket(), paper_ball()
    said = conditions_line("paper", "paper", **racket_details(racket))
    return {
        "fig2_unhappy_on_wall.png": lambda: plots.plot_collision(
            figure_collision(None), title="Fig. 2: unhappy ball on a rigid wall"
        ),
        "fig3_soft_happy_ball.png": lambda: plots.plot_collision(
            figure_collision(2e4), title="Fig. 3: k2 = 2e4 N/m"
        ),
        "fig4_stiff_happy_ball.png": lambda: plots.plot_collision(
            figure_collision(1e5), title="Fig. 4: k2 = 1e5 N/m"
        ),
        "cor_vs_stiffness.png": plots.plot_cor_vs_stiffness,
        "cor_along_racket.png": lambda: plots.plot_cor_along_racket(
            impact(racket, ball, np.linspace(0, 0.32, 161), 10.0),
            racket,
            conditions=conditions_line("paper", "paper", 10.0, **racket_details(racket)),
        ),
        "impact_near_tip.png": lambda: plots.plot_impact(
            impact(racket, ball, 0.03, 10.0, histories=True),
            conditions=conditions_line("paper", "paper", 10.0, **racket_details(racket))
            + ", 3 cm from the tip",
        ),
        "modes.png": lambda: plots.plot_modes(
            racket, conditions=conditions_line("paper", None, **racket_details(racket))
        ),
        "serve_what_if.png": lambda: plots.plot_serve_what_if(
            serve_what_if_columns(racket, ball, eq22=False),  # its reductions alone
            conditions=f"{said} at rest, swung at 40 m/s head speed about the wrist",
        ),
    }


def paper_figure(name: str) -> tuple[bytes, list]:
    """The figure ``name`` of :func:`paper_figures` as PNG bytes, and the warnings drawing it
    raised, as (category, message) (run on a worker process).

    Parameters
    ----------
    name : str
        The figure's file name.
    """
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        data = plot_bytes(paper_figures()[name](), ".png")
    return data, [(w.category, str(w.message)) for w in caught]
