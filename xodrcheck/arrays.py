"""Array helpers the geometry needs that numpy's own would make slow to start.

:func:`unique` is ``np.unique(values)``: numpy's version first asks ``np.ma.is_masked(values)``, which imports
``numpy.ma`` (tens of milliseconds, about a tenth of checking a small file) although no array here is masked.
"""

from __future__ import annotations

import numpy as np

#: Array kinds (bool, signed, unsigned, float) whose unique values are computed here; other kinds go to numpy.
_KINDS = "biuf"


def unique(values: np.ndarray) -> np.ndarray:
    """The sorted unique values of ``values`` (flattened), the same array as ``np.unique(values)``: numpy's sorting
    algorithm (so of ``-0.0`` and ``0.0`` the same one is kept) and one NaN for all NaNs.
    ``tests/xodrcheck/test_arrays.py`` compares the two."""
    aux = np.asanyarray(values)
    if aux.dtype.kind not in _KINDS or type(aux) is not np.ndarray:
        return np.unique(aux)
    aux = aux.flatten()
    aux.sort()
    keep = np.empty(aux.shape, dtype=bool)
    keep[:1] = True
    if aux.dtype.kind == "f" and aux.shape[0] > 0 and np.isnan(aux[-1]):  # NaNs sort last: keep the first of them
        first_nan = int(np.searchsorted(aux, aux[-1], side="left"))
        if first_nan > 0:
            keep[1:first_nan] = aux[1:first_nan] != aux[: first_nan - 1]
        keep[first_nan] = True
        keep[first_nan + 1 :] = False
    else:
        keep[1:] = aux[1:] != aux[:-1]
    return aux[keep]


def ranges(starts, counts) -> np.ndarray:
    """Concatenated ``arange(start, start + count)`` for each pair (empty for no pairs)."""
    counts = np.asarray(counts, dtype=np.int64)
    if counts.size == 0:
        return np.zeros(0, dtype=np.int64)
    offsets = np.repeat(np.asarray(starts, dtype=np.int64) - np.cumsum(counts) + counts, counts)
    return offsets + np.arange(counts.sum(), dtype=np.int64)


def batches(sizes: list[int], limit: int) -> list[tuple[int, int]]:
    """Consecutive ranges ``[lo, hi)`` of ``sizes`` whose sums stay within ``limit`` (a range holds at least one)."""
    out, lo, total = [], 0, 0
    for i, n in enumerate(sizes):
        if i > lo and total + n > limit:
            out.append((lo, i))
            lo, total = i, 0
        total += n
    if lo < len(sizes):
        out.append((lo, len(sizes)))
    return out
