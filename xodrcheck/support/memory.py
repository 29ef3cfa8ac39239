"""Give freed memory back to the operating system between the steps of a big check.

A check parses the file with lxml, builds the model, frees the parse tree, and then runs rule after rule, each
building and dropping numpy arrays and geometry. glibc's allocator keeps most of what is freed in its heap instead of
returning it (an lxml tree is many small blocks, about ten times the file's size): the process's resident size then
grows with every step although the live data does not. :func:`release` asks the
allocator to return its free pages (``malloc_trim(0)``), which it does in milliseconds. On a C library without
``malloc_trim`` (macOS, musl) it does nothing: results never depend on it, only the process's size.
"""

from __future__ import annotations

import functools
from collections.abc import Callable


@functools.cache
def _trim() -> Callable[[int], int] | None:
    # ctypes here, not at the top, and no ctypes.util.find_library (it imports shutil, subprocess and tempfile and
    # runs ldconfig): the running program's own symbols include the C library's; glibc's soname is the fallback
    import ctypes

    trim = None
    for name in (None, "libc.so.6"):
        try:
            trim = ctypes.CDLL(name).malloc_trim
            break
        except (OSError, AttributeError, TypeError):
            continue
    if trim is None:
        return None
    trim.argtypes = [ctypes.c_size_t]
    trim.restype = ctypes.c_int
    return trim


def release() -> bool:
    """Return the allocator's free memory to the operating system; ``True`` if this C library can."""
    trim = _trim()
    if trim is None:
        return False
    trim(0)
    return True


def give_back() -> bool:
    """Free what only cycles of references still hold (the geometry caches are such cycles), then :func:`release`:
    for a step about to allocate much, so that the memory dropped before it is the system's again, not kept in the
    allocator's free lists beside the step's own large arrays."""
    import gc

    gc.collect()
    return release()


def resident_mb() -> float | None:
    """The process's resident set size in MB (Linux ``/proc``), ``None`` where it cannot be read."""
    try:
        with open("/proc/self/statm") as handle:
            pages = int(handle.read().split()[1])
    except (OSError, ValueError, IndexError):
        return None
    import os

    return pages * os.sysconf("SC_PAGE_SIZE") / 2**20
