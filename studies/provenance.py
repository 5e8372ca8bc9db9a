"""Self-describing outputs: every table the command line writes gets a sidecar that records
what made it, and ``racket-impact rerun`` makes it again from that sidecar alone.

The sidecar ``<table>.meta.json`` holds the command (its arguments as typed), the inputs it
named (each racket and ball: the preset's name and, for a catalogue racket, its spec sheet
and sources; for a TOML file, the file's text, so that the run can be repeated where the
file is gone or has changed), the versions of racket-impact, Python and the numerical
libraries, and when it was written.
"""

from __future__ import annotations

import json
import platform
import tempfile
from datetime import datetime, timezone
from importlib import metadata
from pathlib import Path

SIDECAR_SUFFIX = ".meta.json"
"""Appended to a table's file name to name its sidecar."""

_LIBRARIES = ("racket-impact", "numpy", "scipy", "pandas", "numba", "matplotlib")
_INPUT_FLAGS = ("--racket", "--ball", "--a", "--b")


def sidecar_path(table_path) -> Path:
    """The sidecar of the table at ``table_path``."""
    return Path(f"{table_path}{SIDECAR_SUFFIX}")


def versions() -> dict:
    """Python's version and those of racket-impact and the libraries it computes with."""
    found = {"python": platform.python_version()}
    for name in _LIBRARIES:
        try:
            found[name] = metadata.version(name)
        except metadata.PackageNotFoundError:
            found[name] = None
    return found


def _input(spec: str) -> dict:
    """What a ``--racket``/``--ball`` value names: a preset, or a TOML file and its text."""
    from studies.config import racket_specs

    label, sep, rest = spec.partition("=")  # LABEL=PRESET_OR_TOML, as compare takes it
    target = rest if sep and label and not Path(spec).exists() else spec
    entry = {"given": spec}
    path = Path(target)
    if target.endswith(".toml") and path.is_file():
        entry["toml_file"] = str(path)
        entry["toml"] = path.read_text()
    else:
        entry["preset"] = target
    try:
        sheet, sources = racket_specs(target)
    except (ValueError, OSError):
        sheet, sources = None, None
    if sheet is not None:
        entry["spec_sheet"] = sheet
    if sources:
        entry["sources"] = sources
    return entry


def describe(argv: list[str], command: str, options: dict | None = None) -> dict:
    """The sidecar's content for a run of ``racket-impact`` with ``argv``: also every
    option's value, defaults included (``options``), and what its racket and ball name."""
    inputs = {}
    for i, word in enumerate(argv):
        if word in _INPUT_FLAGS and i + 1 < len(argv):
            inputs.setdefault(word.lstrip("-"), []).append(_input(argv[i + 1]))
    if command in ("specs", "sweetspots") and len(argv) > 1 and not argv[1].startswith("-"):
        inputs.setdefault("racket", []).append(_input(argv[1]))
    for name in ("racket", "ball"):  # the defaults, when not typed
        value = (options or {}).get(name)
        if name not in inputs and isinstance(value, str):
            inputs[name] = [_input(value)]
    return {
        "made_by": "racket-impact",
        "command": list(argv),
        "options": json.loads(json.dumps(options or {}, default=str)),
        "inputs": inputs,
        "versions": versions(),
        "written_utc": datetime.now(timezone.utc).isoformat(timespec="seconds"),
    }


def write_sidecar(table_path, description: dict) -> Path:
    """Write ``description`` beside the table at ``table_path``; returns the sidecar's path."""
    path = sidecar_path(table_path)
    path.write_text(json.dumps({**description, "table": Path(table_path).name}, indent=2))
    return path


def rerun_argv(sidecar, workdir) -> list[str]:
    """The command recorded in ``sidecar`` (a sidecar file, or the table it describes), its
    TOML inputs written to ``workdir`` from the recorded text wherever the file is gone or
    now differs.  ValueError for a file that is not a racket-impact sidecar."""
    path = Path(sidecar)
    if not path.name.endswith(SIDECAR_SUFFIX):
        path = sidecar_path(path)
    try:
        record = json.loads(path.read_text())
    except (OSError, ValueError) as err:
        raise ValueError(
            f"rerun needs a racket-impact sidecar (*{SIDECAR_SUFFIX}): {err}"
        ) from None
    if not isinstance(record, dict) or record.get("made_by") != "racket-impact":
        raise ValueError(f"{str(path)!r} is not a racket-impact sidecar")
    argv = list(record["command"])
    replaced = {}
    for entries in record.get("inputs", {}).values():
        for entry in entries:
            name = entry.get("toml_file")
            if name is None:
                continue
            current = Path(name)
            if current.is_file() and current.read_text() == entry["toml"]:
                continue
            copy = Path(workdir) / f"{len(replaced)}_{current.name}"
            copy.write_text(entry["toml"])
            replaced[entry["given"]] = entry["given"].replace(name, str(copy))
    return [replaced.get(word, word) for word in argv]


def temporary_directory():
    """A directory for the recorded TOML inputs of a rerun (removed afterwards)."""
    return tempfile.TemporaryDirectory(prefix="racket-impact-rerun-")
