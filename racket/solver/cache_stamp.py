"""numba's on-disk cache of the solver, kept in step with the solver's sources.

numba keys a compiled function's cache on its own file alone: a kernel whose callee in
another file has changed (a ``git pull`` into an editable install, an edit) would load its old
machine code, with the old callee inside, and give the old numbers.  So the package stamps
its cache (``__pycache__``, or the folder numba uses under ``NUMBA_CACHE_DIR``) with a
digest of every source file of the solver, and drops numba's files there (``*.nbi``,
``*.nbc``) when the digest has changed: numba then compiles afresh.  Nothing is written
outside the folders where numba writes its cache anyway.  (A package numba cannot cache
beside, and so caches in the user's own folder, is not stamped.)
"""

from __future__ import annotations

import hashlib
import os
import tempfile
from pathlib import Path

STAMP = "solver-sources.sha256"
"""The stamp's file name in the package's ``__pycache__``."""


def sources_digest(folder: Path) -> str:
    """SHA-256 [hex] of the names and contents of the ``*.py`` files in ``folder``, in order.

    Parameters
    ----------
    folder : pathlib.Path
        The package's folder.
    """
    digest = hashlib.sha256()
    for path in sorted(folder.glob("*.py")):
        digest.update(path.name.encode())
        digest.update(path.read_bytes())
    return digest.hexdigest()


def cache_folders(folder: Path) -> list:
    """Where numba keeps the cache of the functions in ``folder``: its ``__pycache__``, and
    with ``NUMBA_CACHE_DIR`` set, the folder numba makes there for it (the source folder's
    absolute path under the given one).

    Parameters
    ----------
    folder : pathlib.Path
        The package's folder.
    """
    folders = [folder / "__pycache__"]
    user = os.environ.get("NUMBA_CACHE_DIR")
    if user:
        absolute = folder.resolve()
        folders.append(Path(user) / absolute.relative_to(absolute.anchor))
    return folders


def drop_stale_cache(folder: Path) -> bool:
    """Drop numba's cache of ``folder`` (:func:`cache_folders`) where the sources in
    ``folder`` changed since it was stamped, and stamp it; True if it dropped any.  A folder
    that cannot be written (a read-only install) is left as it is.

    Parameters
    ----------
    folder : pathlib.Path
        The package's folder.
    """
    digest = sources_digest(folder)
    dropped = [_drop(cache, digest) for cache in cache_folders(folder)]
    return any(dropped)


def _drop(cache: Path, digest: str) -> bool:
    """Drop numba's cache in ``cache`` unless it is stamped with ``digest``; stamp it."""
    stamp = cache / STAMP
    try:
        if stamp.is_file() and stamp.read_text() == digest:
            return False
        dropped = False
        for path in [*cache.glob("*.nbi"), *cache.glob("*.nbc")]:
            path.unlink(missing_ok=True)
            dropped = True
        cache.mkdir(parents=True, exist_ok=True)
        handle, name = tempfile.mkstemp(dir=cache, prefix=".stamp-")
        with os.fdopen(handle, "w") as out:
            out.write(digest)
        os.replace(name, stamp)  # whole or not at all, even with another process at it
        return dropped
    except OSError:
        return False
