"""The files a command writes: every path checked before any work, tables (with their
sidecars) and plots written when the run has succeeded (:mod:`studies.outputs`).
"""

from __future__ import annotations

import contextlib
import os
import re
import textwrap
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from studies import outputs
from studies.provenance import SIDECAR_SUFFIX, sidecar_path

if TYPE_CHECKING:
    import pandas as pd

TABLE_FORMATS = (".csv", ".json", ".parquet")
PLOT_FORMATS = (".png", ".svg", ".pdf")


def check_outputs(tables=(), plots=(), directories=()) -> None:
    """Check every output path before any work: a known extension (for Parquet, a library
    to write it with), an existing, writable directory, a name the directory can hold,
    nothing there but a regular file, not a symbolic link (for a table, its sidecar too), no
    table named as a sidecar (``*.meta.json``: it would overwrite one, and rerun would take
    it for one), and no file named twice.  ValueError naming the path otherwise.
    """
    seen = {}
    for paths, kinds, what in ((tables, TABLE_FORMATS, "table"), (plots, PLOT_FORMATS, "plot")):
        for flag, path in paths:
            if path is None:
                continue
            if Path(path).suffix.lower() not in kinds:
                raise ValueError(
                    f"{flag} must be a {what} file ending in {', '.join(kinds)}, got {path!r}"
                )
            if Path(path).suffix.lower() == ".parquet":
                _check_parquet(flag)
            _check_directory(flag, Path(path).parent, path)
            files = [(flag, Path(path))]
            if what == "table":
                files.append((f"{flag}'s sidecar", sidecar_path(path)))
            for name, file in files:
                _check_file(name, file)
                key = file.resolve()
                if key in seen:
                    raise ValueError(f"{name} and {seen[key]} name the same file {str(file)!r}")
                seen[key] = name
            if what == "table" and Path(path).name.lower().endswith(SIDECAR_SUFFIX):
                raise ValueError(
                    f"{flag} {str(path)!r} is named as a table's sidecar (*{SIDECAR_SUFFIX}, "
                    "written beside each table, read by rerun): name the table otherwise"
                )
    for flag, path in directories:
        if not str(path).strip():
            raise ValueError(f"{flag} must name a directory, got {str(path)!r}")
        target = Path(path)
        if target.exists() and not target.is_dir():
            raise ValueError(f"{flag} must be a directory, got the file {str(path)!r}")
        existing = next((p for p in [target, *target.parents] if p.exists()), Path("."))
        _check_directory(flag, existing, path)


def add_outputs(p, table: str = "table file", plot: str | None = None) -> None:
    """A command's ``--out`` (``table``: what its table is, said with :data:`TABLE_FORMATS`)
    and, with ``plot`` (what it shows, said with :data:`PLOT_FORMATS`), its ``--plot``, on
    the subparser ``p``.
    """
    *firsts, last = TABLE_FORMATS
    p.add_argument("--out", metavar="FILE", help=f"{table}: {', '.join(firsts)} or {last}")
    if plot is not None:
        p.add_argument("--plot", metavar="FILE", help=f"{plot} ({', '.join(PLOT_FORMATS)})")


def check_table_and_plot(args) -> None:
    """:func:`check_outputs` of a command's ``--out`` (a table) and ``--plot``, before any
    work.
    """
    check_outputs(tables=[("--out", args.out)], plots=[("--plot", args.plot)])


def write_outputs(args, table: pd.DataFrame, draw=None) -> int:
    """Write ``table`` to ``--out`` (:func:`write_table`) and the plot that ``draw()`` makes
    (its Axes) to ``--plot`` (:func:`save_plot`), each if the command line gave it; ``draw``
    is called only then (a plot imports matplotlib).  Returns 0, the command's exit status.
    """
    if args.out:
        write_table(table, args.out)
    if draw is not None and args.plot:
        save_plot(draw(), args.plot)
    return 0


def _check_parquet(flag: str) -> None:
    """A Parquet table needs an engine pandas writes it with (pyarrow, or fastparquet):
    ValueError with the fix before any work, not after it.
    """
    import importlib.util

    if not any(importlib.util.find_spec(engine) for engine in ("pyarrow", "fastparquet")):
        raise ValueError(
            f"{flag}: Parquet output needs pyarrow: pip install 'racket-impact[parquet]' "
            "(or write .csv or .json)"
        )


def _check_file(flag: str, path: Path) -> None:
    """An output file that can be replaced: a name its directory can hold, and nothing there
    yet but a writable regular file (not a directory, FIFO or device; never opened), nor a
    symbolic link (the rename would replace the link and leave the file it names stale).
    """
    try:
        longest = os.pathconf(path.parent, "PC_NAME_MAX")
    except (AttributeError, ValueError, OSError):  # no pathconf (Windows), or no such limit
        longest = -1
    if longest > 0 and len(os.fsencode(path.name)) > longest:
        raise ValueError(
            f"{flag}: the name of {str(path)!r} is longer than its directory allows "
            f"({longest} bytes)"
        )
    if path.is_symlink():
        raise ValueError(f"{flag}: {str(path)!r} is a symbolic link; name the file it links to")
    if path.exists() and not path.is_file():
        raise ValueError(f"{flag}: {str(path)!r} exists and is not a regular file")
    if path.exists() and not os.access(path, os.W_OK):
        raise ValueError(f"{flag}: {str(path)!r} is read-only")


def _check_directory(flag: str, directory: Path, path) -> None:
    directory = directory if str(directory) else Path(".")
    if not directory.is_dir():
        raise ValueError(f"{flag}: directory {str(directory)!r} of {str(path)!r} does not exist")
    if not os.access(directory, os.W_OK):
        raise ValueError(f"{flag}: directory {str(directory)!r} of {str(path)!r} is not writable")


_RUN = {}  # the command line being run (main sets it), for the tables' sidecars


def write_table(table: pd.DataFrame | dict, path: str) -> None:
    """Write ``table`` to ``path`` as CSV, JSON (records) or Parquet, by extension, and,
    when the command line writes it, its sidecar (:mod:`studies.provenance`); both are
    put in place with the run's other files (:mod:`studies.outputs`).  A table given as its
    columns (a dict, as :func:`studies.sweeps.sweep_columns` makes them) is written as the
    DataFrame of them (:func:`studies.tables.frame`) would be, a CSV without pandas.
    """
    suffix = Path(path).suffix.lower()
    if suffix not in TABLE_FORMATS:
        raise ValueError(f"table file must end in {', '.join(TABLE_FORMATS)}, got {path!r}")

    if isinstance(table, dict) and suffix != ".csv":  # JSON and Parquet: pandas writes them
        from studies.tables import frame

        table = frame(table)

    def writer(temp: str) -> None:
        if isinstance(table, dict):
            _write_csv(table, temp)
        elif suffix == ".csv":
            table.to_csv(temp, index=False)
        elif suffix == ".json":
            table.to_json(temp, orient="records", indent=2, double_precision=15)
        else:
            try:
                table.to_parquet(temp, index=False)
            except ImportError:
                raise ValueError(
                    "Parquet output needs pyarrow: pip install 'racket-impact[parquet]'"
                ) from None

    outputs.write(path, writer)
    _sidecar(path)


def _write_csv(columns: dict, path: str) -> None:
    """Write ``columns`` (name -> 1-D array) to ``path`` as CSV, byte for byte as pandas'
    ``DataFrame.to_csv(index=False)`` writes their table, without pandas: each value as
    numpy prints it (pandas' own conversion: the shortest text that reads back the same
    float), a missing float as nothing, through the standard csv writer with pandas'
    settings (a newline ends each line, quotes where a value needs them).

    Parameters
    ----------
    columns : dict
        Column name -> 1-D array (numbers, booleans, or words of dtype object).
    path : str
        The file.
    """
    import csv

    cells = []
    for values in columns.values():
        text = values.astype(str)
        if values.dtype.kind == "f":
            text[np.isnan(values)] = ""
        cells.append(text)
    with open(path, "w", newline="", encoding="utf-8") as out:
        writer = csv.writer(out, lineterminator="\n")
        writer.writerow(columns)
        writer.writerows(zip(*cells, strict=True))


def _sidecar(path) -> None:
    """The sidecar of a table the command line wrote (:mod:`studies.provenance`); the
    description is built once per command run, however many tables it writes.
    """
    if _RUN:
        from studies.provenance import describe, write_sidecar

        if "description" not in _RUN:
            _RUN["description"] = describe(
                _RUN["argv"], _RUN["command"], _RUN["options"], _RUN.get("originals"),
                _RUN.get("conditions"), _RUN.get("written_utc"),
            )  # fmt: skip
        write_sidecar(path, _RUN["description"])


_NBSP = "\u00a0"  # not whitespace to textwrap


def say_conditions(line: str) -> str:
    """Print a run's conditions (:mod:`studies.conditions`), the header line of its printed
    tables, record them for its sidecars and return them (the plots' captions); a rerun's
    temporary copies of the user's files are named as the user named them.
    """
    for copy, given in (_RUN.get("originals") or {}).items():  # a rerun's copies: the user's
        line = line.replace(copy, given)  # own files named, not the temporary ones
    if _RUN:
        _RUN["conditions"] = line
    from studies.cli.show import WIDTH

    # a number stays with the words on both sides ("at 16.5 m/s"): no wrapped line starts
    # with a number, where a reader (or a parser) would take it for a table's first row
    glued = re.sub(r" (?=-?\d)|(?<=\d) ", _NBSP, line)
    wrapped = textwrap.fill(glued, WIDTH, subsequent_indent="  ", break_on_hyphens=False)
    print(wrapped.replace(_NBSP, " "))
    return line


def save_plot(axes, path: str) -> None:
    """Save the figure holding ``axes`` as PNG, SVG or PDF, by extension, put in place with
    the run's other files (:mod:`studies.outputs`).
    """
    suffix = Path(path).suffix.lower()
    if suffix not in PLOT_FORMATS:
        raise ValueError(f"plot file must end in {', '.join(PLOT_FORMATS)}, got {path!r}")
    with _laid_out(axes, suffix) as fig:
        outputs.write(path, lambda temp: fig.savefig(temp, dpi=DPI, format=suffix[1:]))


def plot_bytes(axes, suffix: str) -> bytes:
    """The figure holding ``axes`` as the bytes of a ``suffix`` file (``.png``, ``.svg`` or
    ``.pdf``), as :func:`save_plot` writes it; the figure closed.
    """
    import io

    data = io.BytesIO()
    with _laid_out(axes, suffix) as fig:
        fig.savefig(data, dpi=DPI, format=suffix[1:])
    return data.getvalue()


DPI = 120
"""Resolution of a plot saved as PNG [dots per inch]."""


@contextlib.contextmanager
def _laid_out(axes, suffix: str):
    """The figure holding ``axes``, laid out (by its own layout engine, as the plots of
    :mod:`studies.plots` make theirs, else tight) for a ``suffix`` file; closed when the
    block ends.

    For a PNG the engine is run here once, at the saved resolution, and then set aside: the
    file is drawn once, where matplotlib would draw a figure with an engine twice to save it
    (once without rendering, to lay it out, then again, laying it out anew); the same layout,
    as both measure the text with the same (Agg) renderer.  An SVG or PDF is laid out by
    matplotlib as usual, its text measured by its own renderer.
    """
    import matplotlib.pyplot as plt

    fig = np.atleast_1d(axes)[0].figure
    try:
        engine = fig.get_layout_engine()
        if engine is None:
            fig.tight_layout()
        elif suffix == ".png":
            _lay_out_once(fig, engine)
        yield fig
    finally:
        plt.close(fig)


def _lay_out_once(fig, engine) -> None:
    """Run ``fig``'s layout ``engine`` at the saved :data:`DPI`, then fix the Axes there."""
    import matplotlib

    shown = fig.dpi
    fig.set_dpi(DPI)
    try:
        engine.execute(fig)
    finally:
        fig.set_dpi(shown)
    # None, not "none" (a placeholder engine: matplotlib would still draw twice); and with
    # the user's rcParams asking for no engine, or None would install a new one
    unset = {"figure.autolayout": False, "figure.constrained_layout.use": False}
    with matplotlib.rc_context(unset):
        fig.set_layout_engine(None)
