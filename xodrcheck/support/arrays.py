"""Index arithmetic on flat arrays: concatenated ranges and size-bounded batches."""

from __future__ import annotations

import numpy as np


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
