"""The user's cache folder: what xodrcheck keeps between runs to start faster (results never depend on it).

``$XODRCHECK_CACHE_DIR`` (set but empty: no cache), else ``$XDG_CACHE_HOME/xodrcheck``, else ``~/.cache/xodrcheck``.
It holds the compiled XSD 1.1 schemas of OpenDRIVE 1.8 and 1.9 (:mod:`xodrcheck.schema.validate`). Loading a cache file
runs code from it, as a ``.pyc`` does, so a file is read only when its owner is the user and nobody else may write it;
nothing is written when Python is told not to write byte code (``PYTHONDONTWRITEBYTECODE``, ``-B``). A file that cannot
be read or written means building what it held, never an error.
"""

from __future__ import annotations

import contextlib
import os
import sys
from pathlib import Path


def root() -> Path | None:
    """The cache folder (``None``: no cache)."""
    folder = os.environ.get("XODRCHECK_CACHE_DIR")
    if folder is None:
        base = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
        folder = os.path.join(base, "xodrcheck")
    return Path(folder) if folder else None


def writable() -> bool:
    """Whether caches are written in this process (not when Python writes no byte code)."""
    return not sys.dont_write_bytecode


def _trusted(info: os.stat_result) -> bool:
    """Owned by the user, writable by nobody else."""
    if hasattr(os, "getuid") and info.st_uid != os.getuid():
        return False
    return not info.st_mode & 0o022


def read(path: Path) -> bytes | None:
    """The bytes of a cache file; ``None`` when it is missing, unreadable or not trusted."""
    try:
        with open(path, "rb") as stream:
            if not _trusted(os.fstat(stream.fileno())):
                return None
            return stream.read()
    except OSError:
        return None


def write(path: Path, data: bytes) -> None:
    """Replace a cache file atomically (a temporary file beside it, then a rename); silently nothing on failure."""
    tmp = path.with_name(f"{path.name}.{os.getpid()}.tmp")
    try:
        path.parent.mkdir(mode=0o700, parents=True, exist_ok=True)
        with open(tmp, "wb") as stream:
            stream.write(data)
        os.replace(tmp, path)
    except (OSError, ValueError):
        with contextlib.suppress(OSError):
            tmp.unlink()
