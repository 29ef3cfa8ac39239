"""A whole OpenDRIVE file: header, roads, junctions and the file's other top-level elements, and where each element
of the file is (for reports that point into it by XPath)."""

from __future__ import annotations

from array import array
from collections import Counter
from dataclasses import dataclass, field
from functools import cached_property
from typing import TYPE_CHECKING

from xodrcheck.model.facts import NO_FACTS, XmlFacts
from xodrcheck.model.header import Header
from xodrcheck.model.junctions import Junction
from xodrcheck.model.roads import Road

if TYPE_CHECKING:  # pragma: no cover - loaded when a file has them
    from xodrcheck.model.ids import IdTable
    from xodrcheck.model.junction_parts import JunctionGroup
    from xodrcheck.model.railroad import Station
    from xodrcheck.model.signals import Controller, VmsGroup

__all__ = ["Document", "ElementTable", "document_cache"]


class ElementTable:
    """Every element of the file in document order: the line it starts on, its number of children and its tag.
    What a report needs to point into the file: :meth:`xpath` gives the XPath of the element that starts first on a
    line, as ``lxml``'s ``getpath`` writes it (``/OpenDRIVE/road[3]/lanes/laneSection[2]``). About 12 bytes an
    element; the index behind :meth:`xpath` is built on its first call."""

    __slots__ = ("_index", "counts", "lines", "tag_names", "tags")

    def __init__(self, lines: array, counts: array, tags: array, tag_names: tuple[str, ...]) -> None:
        self.lines = lines
        self.counts = counts
        self.tags = tags
        self.tag_names = tag_names
        self._index: tuple[dict[int, int], array, array] | None = None

    def __len__(self) -> int:
        return len(self.lines)

    def _positions(self) -> tuple[dict[int, int], array, array]:
        """Line -> first element on it; each element's parent (-1 for the root); and its position among its parent's
        children of its tag (1-based; 0 when it is the only one, which an XPath leaves unnumbered)."""
        if self._index is None:
            n = len(self.lines)
            parents = array("i", bytes(4 * n))
            nth = array("i", bytes(4 * n))
            first: dict[int, int] = {}
            same: dict[tuple[int, int], list[int]] = {}
            open_elements: list[list[int]] = []  # [element, children still to come], innermost last
            for i in range(n):
                first.setdefault(self.lines[i], i)
                parent = -1
                if open_elements:
                    top = open_elements[-1]
                    parent = top[0]
                    top[1] -= 1
                    if not top[1]:
                        open_elements.pop()
                parents[i] = parent
                same.setdefault((parent, self.tags[i]), []).append(i)
                if self.counts[i]:
                    open_elements.append([i, self.counts[i]])
            for siblings in same.values():
                if len(siblings) > 1:
                    for k, i in enumerate(siblings, 1):
                        nth[i] = k
            self._index = (first, parents, nth)
        return self._index

    def xpath(self, line: int) -> str | None:
        """The XPath of the first element that starts on ``line`` (``None``: no element does)."""
        first, parents, nth = self._positions()
        i = first.get(line)
        if i is None:
            return None
        steps = []
        while i >= 0:
            name = self.tag_names[self.tags[i]]
            steps.append(f"{name}[{nth[i]}]" if nth[i] else name)
            i = parents[i]
        return "/" + "/".join(reversed(steps))


def document_cache(document: Document) -> dict:
    """A dict that lives and dies with ``document``, for what is derived from it (geometry, meshes, footprints).

    Kept in the instance's ``__dict__`` (not a field: equality, ``repr`` and ``dataclasses.replace`` ignore it), so a
    cached value that refers back to its document (an overlap index does) is freed with it; a module-level cache keyed
    by ``id(document)`` would keep both alive for the whole process."""
    return document.__dict__.setdefault("_derived", {})


@dataclass(frozen=True)
class Document:
    """A whole OpenDRIVE file. ``roads`` and ``junctions`` keep file order; the ``*_by_id`` maps keep the first of
    duplicated ids (duplicates are reported by the reference rules). ``xml`` holds the facts of the ``<OpenDRIVE>``
    element (its unknown children: elements that are not OpenDRIVE at the top level)."""

    header: Header | None
    roads: tuple[Road, ...] = ()
    junctions: tuple[Junction, ...] = ()
    controllers: tuple[Controller, ...] = ()
    source: str | None = None
    junction_groups: tuple[JunctionGroup, ...] = ()
    stations: tuple[Station, ...] = ()
    vms_groups: tuple[VmsGroup, ...] = ()
    xml: XmlFacts = field(default=NO_FACTS, compare=False, repr=False)
    #: Every element of the file (``None`` for a document built in code).
    elements: ElementTable | None = field(default=None, compare=False, repr=False)
    #: The ids the file defines and names, as written (``None`` for a document built in code).
    ids: IdTable | None = field(default=None, compare=False, repr=False)

    @cached_property
    def road_by_id(self) -> dict[str, Road]:
        out: dict[str, Road] = {}
        for road in self.roads:
            out.setdefault(road.id, road)
        return out

    @cached_property
    def junction_by_id(self) -> dict[str, Junction]:
        out: dict[str, Junction] = {}
        for junction in self.junctions:
            out.setdefault(junction.id, junction)
        return out

    @property
    def version(self) -> tuple[int, int] | None:
        return None if self.header is None else self.header.version_tuple

    @property
    def extras(self) -> dict[str, int]:
        """Counts of the top-level elements that are not OpenDRIVE, by tag."""
        return dict(Counter(unknown.tag for unknown in self.xml.unknown))
