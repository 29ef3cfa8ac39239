"""Counts of the work a check does where it could grow faster than the file: how many things its costly steps were
handed (mesh vertices built, pieces united and coordinates intersected by GEOS...).

The counts are what bounds a check's cost in tests (counted, not timed: the same on any machine): a hostile document
checks within a fixed amount of each kind of work (``tests/fuzz``' slow documents). Counting is a dictionary update per
costly call, never per sample.
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Iterator
from contextlib import contextmanager

__all__ = ["COUNTS", "add", "counting"]

#: Work done in this process so far, by kind (``"mesh vertices"``, ``"union coordinates"``...).
COUNTS: Counter[str] = Counter()


def add(kind: str, amount: int = 1) -> None:
    """Count ``amount`` units of work of ``kind``."""
    COUNTS[kind] += int(amount)


@contextmanager
def counting() -> Iterator[Counter[str]]:
    """The work done inside the ``with`` block: the counter it yields is filled when the block ends."""
    before = COUNTS.copy()
    done: Counter[str] = Counter()
    try:
        yield done
    finally:
        done.update(COUNTS)
        done.subtract(before)
        for kind in [k for k, n in done.items() if n <= 0]:
            del done[kind]
