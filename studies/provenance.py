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
_INPUTS = ("racket", "ball", "a", "b")
"""The options that name rackets and balls (presets or TOML files)."""


def sidecar_path(table_path) -> Path:
    """The sidecar of a table.

    Parameters
    ----------
    table_path : str or Path
        The table's file.
    """
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


def _restored(word: str, originals: dict) -> str:
    """``word`` with a rerun copy's path put back to the path first given: only where the
    whole word is the path, or the part after an ``=`` is (``--flag=PATH``,
    ``LABEL=PATH``), so that ``b.toml`` never rewrites ``bb.toml``.
    """
    for copy, original in originals.items():
        if word == copy:
            return original
        for i, char in enumerate(word):
            if char == "=" and word[i + 1 :] == copy:
                return word[: i + 1] + original
    return word


def _input(spec: str, originals: dict | None = None) -> dict:
    """What a ``--racket``/``--ball`` value names: a preset, or a TOML file and its text
    (read from the rerun's copy, ``originals`` mapping copies to the paths first given).
    """
    copies = {original: copy for copy, original in (originals or {}).items()}
    from studies.config import racket_specs

    label, sep, rest = spec.partition("=")  # LABEL=PRESET_OR_TOML, as compare takes it
    target = rest if sep and label and not Path(spec).exists() else spec
    entry = {"given": spec}
    path = Path(copies.get(target, target))
    if target.endswith(".toml") and path.is_file():
        entry["toml_file"] = target
        entry["toml"] = path.read_text()
    else:
        entry["preset"] = target
    try:
        sheet, sources = racket_specs(str(path))
    except (ValueError, OSError):
        sheet, sources = None, None
    if sheet is not None:
        entry["spec_sheet"] = sheet
    if sources:
        entry["sources"] = sources
    return entry


def describe(
    argv: list[str], command: str, options: dict | None = None, originals: dict | None = None
) -> dict:
    """The sidecar's content for a run of ``racket-impact``.

    Parameters
    ----------
    argv : list of str
        The command's arguments, as typed.
    command : str
        The subcommand.
    options : dict, optional
        Every option's value, defaults included (recorded too).
    originals : dict, optional
        For a rerun: the recorded TOML copies' paths -> the paths first given, so that the
        new sidecar names the user's files, not the rerun's temporary copies.
    """
    originals = originals or {}
    argv = [_restored(word, originals) for word in argv]
    options = dict(options or {})
    inputs = {}
    for name in _INPUTS:  # typed or the defaults, as parsed (LABEL=FILE for compare)
        value = options.get(name)
        if isinstance(value, str):
            options[name] = _restored(value, originals)
            inputs[name] = [_input(options[name], originals)]
        elif isinstance(value, list) and all(isinstance(v, str) for v in value):
            options[name] = [_restored(v, originals) for v in value]
            inputs[name] = [_input(v, originals) for v in options[name]]
    return {
        "made_by": "racket-impact",
        "command": list(argv),
        "options": json.loads(json.dumps(options, default=str)),
        "inputs": inputs,
        "versions": versions(),
        "written_utc": datetime.now(timezone.utc).isoformat(timespec="seconds"),
    }


def write_sidecar(table_path, description: dict) -> Path:
    """Write a sidecar beside a table; returns the sidecar's path.

    Parameters
    ----------
    table_path : str or Path
        The table's file.
    description : dict
        What :func:`describe` returned.
    """
    path = sidecar_path(table_path)
    path.write_text(json.dumps({**description, "table": Path(table_path).name}, indent=2))
    return path


def rerun_argv(sidecar, workdir) -> tuple[list[str], dict]:
    """The command recorded in a sidecar, its TOML inputs written to ``workdir`` from the
    recorded text wherever the file is gone or now differs, and the map from those copies'
    paths to the paths first given (for :func:`describe`).  ValueError for a file that is
    not a racket-impact sidecar.

    Parameters
    ----------
    sidecar : str or Path
        A sidecar file, or the table it describes.
    workdir : str or Path
        Where to write the recorded TOML inputs.
    """
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
            copy = Path(workdir) / str(len(replaced)) / current.name
            copy.parent.mkdir()
            copy.write_text(entry["toml"])
            replaced[str(copy)] = name
    to_copies = {name: copy for copy, name in replaced.items()}
    return [_restored(word, to_copies) for word in argv], replaced


def temporary_directory():
    """A directory for the recorded TOML inputs of a rerun (removed afterwards)."""
    return tempfile.TemporaryDirectory(prefix="racket-impact-rerun-")
