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
import os
import platform
import stat
import tempfile
from datetime import datetime, timezone
from importlib import metadata
from pathlib import Path

SIDECAR_SUFFIX = ".meta.json"
"""Appended to a table's file name to name its sidecar."""

SIDECAR_LIMIT = 1_000_000
"""The largest sidecar ``rerun`` reads [bytes] (one is a few kB)."""

NAME_LIMIT = 255
"""The longest name of a recorded TOML file ``rerun`` takes [bytes] (file systems' limit)."""

TEXT = "text (no NUL, no lone surrogate)"
"""What every string of a sidecar's command and inputs must be."""

_LIBRARIES = ("racket-impact", "numpy", "scipy", "pandas", "numba", "matplotlib")
_INPUTS = ("racket", "ball", "a", "b", "bat")
"""The options that name rackets, balls and bats (presets or TOML files)."""


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
    argv: list[str],
    command: str,
    options: dict | None = None,
    originals: dict | None = None,
    conditions: str | None = None,
    written_utc: str | None = None,
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
    conditions : str, optional
        What the table was computed for, in one line: racket, ball, speeds, support, grip,
        strings (:mod:`studies.conditions`), the header line of the printed table.
    written_utc : str, optional
        When the run was made (ISO 8601, UTC); default now.  A rerun keeps the time of the
        run it reproduces, so that its sidecar is the same record, byte for byte.
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
        **({"conditions": conditions} if conditions else {}),
        "options": json.loads(json.dumps(options, default=str)),
        "inputs": inputs,
        "versions": versions(),
        "written_utc": written_utc or datetime.now(timezone.utc).isoformat(timespec="seconds"),
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
    from studies.outputs import write

    path = sidecar_path(table_path)
    text = json.dumps({**description, "table": Path(table_path).name}, indent=2)
    write(path, lambda temp: Path(temp).write_text(text))
    return path


def read_sidecar(path) -> dict:
    """A sidecar's record, checked as untrusted input (anyone can edit or send one): a
    regular file of at most :data:`SIDECAR_LIMIT` bytes of UTF-8 JSON, made by
    racket-impact, with a command (a non-empty list of strings) and the inputs it named
    (each a list of entries whose ``given``, ``toml_file``, ``toml`` and ``preset`` are
    strings, a ``toml_file`` with its ``toml`` text and a name of at most
    :data:`NAME_LIMIT` bytes).  Every string of the command and the inputs is text a file
    or a command line can hold: no NUL, no lone surrogate.  ValueError naming the file as
    given and the first bad key otherwise.

    Parameters
    ----------
    path : str or Path
        The sidecar file.
    """
    shown = repr(str(path))
    try:  # never blocks: a FIFO is opened without waiting for a writer, then refused
        handle = os.open(path, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0))
    except OSError as err:
        raise ValueError(
            f"rerun needs a racket-impact sidecar (*{SIDECAR_SUFFIX}): {shown}: {err.strerror}"
        ) from None
    if not stat.S_ISREG(os.fstat(handle).st_mode):  # a directory, a FIFO, a device
        os.close(handle)
        raise ValueError(f"rerun needs a racket-impact sidecar file: {shown} is not a file")
    with open(handle, "rb") as file:
        data = file.read(SIDECAR_LIMIT + 1)
    if len(data) > SIDECAR_LIMIT:
        raise ValueError(f"{shown} is larger than a sidecar may be ({SIDECAR_LIMIT} bytes)")
    try:
        record = json.loads(data.decode("utf-8"))
    except UnicodeDecodeError:
        raise ValueError(f"{shown} is not a racket-impact sidecar: not UTF-8 text") from None
    except (ValueError, RecursionError) as err:
        raise ValueError(f"{shown} is not a racket-impact sidecar: not JSON ({err})") from None
    if not isinstance(record, dict) or record.get("made_by") != "racket-impact":
        raise ValueError(f"{shown} is not a racket-impact sidecar (no made_by: racket-impact)")

    def bad(key: str, what: str):
        return ValueError(f"{shown}: {key} must be {what}")

    command = record.get("command")
    if not isinstance(command, list) or not command:
        raise bad("command", "a non-empty list of strings")
    if not all(isinstance(word, str) for word in command):
        raise bad("command", "a list of strings")
    if not all(_text(word) for word in command):
        raise bad("command", f"a list of {TEXT}")
    for key, kind in (("options", dict), ("versions", dict), ("written_utc", str), ("table", str),
                      ("conditions", str)):  # fmt: skip
        if key in record and not isinstance(record[key], kind):
            raise bad(key, f"a {'JSON object' if kind is dict else 'string'}")
    inputs = record.get("inputs")
    if not isinstance(inputs, dict):
        raise bad("inputs", "a JSON object")
    for name, entries in inputs.items():
        if name not in _INPUTS:
            raise bad(f"inputs.{name}", f"one of {', '.join(_INPUTS)} (an unknown input)")
        if not isinstance(entries, list):
            raise bad(f"inputs.{name}", "a list")
        for i, entry in enumerate(entries):
            where = f"inputs.{name}[{i}]"
            if not isinstance(entry, dict):
                raise bad(where, "a JSON object")
            for key in ("given", "toml_file", "toml", "preset"):
                if key in entry and not isinstance(entry[key], str):
                    raise bad(f"{where}.{key}", "a string")
                if key in entry and not _text(entry[key]):
                    raise bad(f"{where}.{key}", TEXT)
            if "toml_file" in entry:
                if "toml" not in entry:
                    raise bad(f"{where}.toml", "the text of its toml_file")
                name = Path(entry["toml_file"]).name
                if name in ("", ".", "..") or len(name.encode()) > NAME_LIMIT:
                    raise bad(f"{where}.toml_file", f"a file name of at most {NAME_LIMIT} bytes")
    return record


def _text(value: str) -> bool:
    """Whether ``value`` is :data:`TEXT`: UTF-8 encodable, without NUL."""
    try:
        value.encode()
    except UnicodeEncodeError:
        return False
    return "\0" not in value


def rerun_argv(sidecar, workdir) -> tuple[list[str], dict, str | None]:
    """The command recorded in a sidecar (checked by :func:`read_sidecar`), its TOML inputs
    always taken from the recorded text (written to ``workdir``, never the file now at the
    recorded path), the map from those copies' paths to the paths first given (for
    :func:`describe`), and the time the recorded run was made (its ``written_utc``, None if
    the sidecar has none).  ValueError for a file that is not a racket-impact sidecar, or a
    command naming a TOML file whose text the sidecar does not hold.

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
    record = read_sidecar(path)
    replaced = {}
    for entries in record["inputs"].values():
        for entry in entries:
            name = entry.get("toml_file")
            if name is None or name in replaced.values():
                continue
            copy = Path(workdir) / str(len(replaced)) / Path(name).name
            copy.parent.mkdir()
            copy.write_text(entry["toml"], encoding="utf-8")
            replaced[str(copy)] = name
    to_copies = {name: copy for copy, name in replaced.items()}
    argv = []
    for word in record["command"]:
        argv.append(_restored(word, to_copies))
        if word.endswith(".toml") and argv[-1] == word:
            raise ValueError(
                f"{str(path)!r}: inputs holds no text for {word!r}, which command names"
            )
    return argv, replaced, record.get("written_utc")


def temporary_directory():
    """A directory for the recorded TOML inputs of a rerun (removed afterwards)."""
    return tempfile.TemporaryDirectory(prefix="racket-impact-rerun-")
