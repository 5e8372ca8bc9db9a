"""Where a racket, a ball or a bat comes from: a preset's name or a TOML file's path
(:func:`preset_or_file`, and the refusal of neither, :func:`unknown_preset`), and the TOML
file read (:func:`read_toml`), each refusal naming the file.
"""

from __future__ import annotations

import os
import sys

from common.typechecks import file_path, instance

if sys.version_info >= (3, 11):
    import tomllib
else:  # pragma: no cover
    import tomli as tomllib


def read_toml(path: str | os.PathLike) -> dict:
    """The TOML file as a dict; ValueError naming the file if it cannot be read.

    Parameters
    ----------
    path : str or os.PathLike
        The TOML file.
    """
    path = file_path("path", path)
    if "\0" in str(path):  # open() would say only "embedded null byte"
        raise ValueError(f"cannot read {str(path)!r}: a file name cannot hold a NUL byte")
    try:
        with open(path, "rb") as f:
            return tomllib.load(f)
    except OSError as err:
        raise ValueError(f"cannot read {path}: {err.strerror}") from None
    except UnicodeDecodeError:
        raise ValueError(f"{path} is not valid TOML: it is not UTF-8 text") from None
    except tomllib.TOMLDecodeError as err:
        raise ValueError(f"{path} is not valid TOML: {err}") from None


def unknown_preset(spec: str, presets, kind: str) -> str:
    """The refusal of ``spec``, neither a preset of ``kind`` (one of ``presets``) nor a
    .toml file's path.

    Parameters
    ----------
    spec : str
        What was given.
    presets : iterable of str
        The presets' names.
    kind : str
        "racket", "ball", "bat", ...
    """
    return f"unknown {kind} preset {spec!r}; presets: {', '.join(presets)} (or a .toml file)"


def preset_or_file(spec, presets: dict, kind: str) -> tuple[str | None, str | None]:
    """(name, None) for a preset, (None, path) for a file: a Path, or a str ending in .toml.

    Parameters
    ----------
    spec : str or os.PathLike
        A preset's name or a TOML file's path.
    presets : dict
        The presets, by name.
    kind : str
        "racket", "ball", "bat", ...
    """
    if isinstance(spec, os.PathLike):
        return None, file_path("spec", spec)
    what = f"a {kind} preset's name or a .toml file's path (str or os.PathLike)"
    if instance("spec", spec, str, what) in presets:
        return spec, None
    if not spec.endswith(".toml"):
        raise ValueError(unknown_preset(spec, presets, kind))
    return None, spec
