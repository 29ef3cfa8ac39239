"""Ids for what the scenario features add (corner roads, signals, objects, controllers): numbers after every id the
paper's stages gave, so those stay as they were, and unique across all kinds (some readers share one table)."""

from __future__ import annotations

from ..opendrive import Document


class Ids:
    """Hands out "N", "N+1", ... from one past the largest numeric road or junction id of a document."""

    def __init__(self, doc: Document) -> None:
        ids = [r.id for r in doc.roads] + [j.id for j in doc.junctions]
        used = [int(x) for x in ids if x.isdigit()]
        self._next = max(used, default=0) + 1

    def next(self) -> str:
        n = self._next
        self._next += 1
        return str(n)
