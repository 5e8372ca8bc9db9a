"""The command-line tests' scaffolding: ``racket-impact`` run in this process, its status and
its output captured, and the checks every command's runs share (a run that succeeds, one that
writes its table and its sidecar, one that warns, a refusal in one line that writes nothing,
the help)."""

import contextlib
import io
import json
from pathlib import Path

from studies.cli import main

COMPILING = "compiling the solver"
"""The one-off notice of a first run that compiles the kernel (not a line of a refusal)."""


def run_main(argv) -> tuple[int, str, str]:
    """``main(argv)``'s status, stdout and stderr (the parser's own exits as their status)."""
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        try:
            status = main(list(argv))
        except SystemExit as done:
            status = done.code
    return status, out.getvalue(), err.getvalue()


def run_ok(argv) -> tuple[str, str]:
    """The stdout and stderr of ``main(argv)``, which must succeed (status 0)."""
    status, out, err = run_main(argv)
    assert status == 0, err
    return out, err


def run_writing(argv, folder: Path, table: str, plot: str | None = None) -> dict:
    """``main(argv)`` with ``--out folder/table`` (and ``--plot folder/plot``), which must
    succeed: its ``out`` and ``err``, the ``folder`` and the paths of its ``table`` and
    ``plot``."""
    paths = {"table": folder / table, "plot": folder / plot if plot else None}
    extra = ["--out", str(paths["table"]), *(["--plot", str(paths["plot"])] if plot else [])]
    out, err = run_ok([*argv, *extra])
    return {"out": out, "err": err, "folder": folder, **paths}


def sidecar(run: dict) -> dict:
    """The sidecar written beside the table of ``run`` (a :func:`run_writing`), whose
    conditions the run printed (in its header, unwrapped)."""
    table = run["table"]
    record = json.loads(table.with_name(f"{table.name}.meta.json").read_text())
    said = " ".join(run["out"].split("\n  "))  # the header line, unwrapped
    assert record["conditions"] in said
    return record


def warning(argv) -> str:
    """The stderr of ``main(argv)``, which must succeed with a warning."""
    _, err = run_ok(argv)
    assert "warning" in err, err
    return err


def refusal(argv, *, quiet=True, notice=False, folder: Path | None = None) -> str:
    """The one line with which ``main(argv)`` refuses: status 2, no traceback and, if
    ``quiet``, nothing on stdout; with ``notice``, beside a first run's compile notice; with
    a ``folder``, nothing written in it."""
    before = sorted(folder.rglob("*")) if folder is not None else None
    status, out, err = run_main(argv)
    lines = [line for line in err.strip().splitlines() if not notice or COMPILING not in line]
    assert status == 2 and (out == "" or not quiet), err
    assert len(lines) == 1 and "Traceback" not in err, err
    if folder is not None:
        assert sorted(folder.rglob("*")) == before, "a refused run wrote a file"
    return lines[0]


def help_text(command: str) -> str:
    """``racket-impact command --help``, its white space folded (status 0)."""
    out, _ = run_ok([command, "--help"])
    return " ".join(out.split())
