"""Map invariants: a snapshot of what a map is (counts, lane graph, extent, findings) and the differences between two.

A snapshot is a small JSON object meant to be committed beside a map and compared on every change of the tool that
writes the map (``xodrcheck snapshot``, ``xodrcheck diff``, the ``xodr_snapshot`` pytest fixture). It holds:

* counts of roads (and of roads inside junctions), junctions by type, lane sections, lanes by type (counted once per
  lane section, centre lanes excluded) and the legs histogram of the junctions
  (:func:`xodrcheck.analysis.info.junction_legs`);
* the total length of the lanes: every lane's centre line, measured on the sampled polyline, summed (m);
* the lane graph: its number of links and a hash of its topology (every lane link between lane sections, across road
  links and every junction laneLink, as unordered pairs of lanes named ``road/section index/lane id``; see
  :func:`lane_links`), so a dropped, added or re-targeted link changes the hash whatever the order of the file;
* the bounding box of the lane borders (:func:`xodrcheck.analysis.info.bounding_box`);
* the findings of a full check, counted by code;
* reachability (:mod:`xodrcheck.graph.invariants`): the lane graph's strongly connected parts, the entries and exits
  at the map's open edges and the (entry, exit) pairs no route joins, so that ``diff`` names a route that vanished
  (snapshots written before these were kept compare without them).

Lengths and coordinates are stored rounded to the millimetre and compared with the position and length tolerances
(:class:`xodrcheck.config.Tolerances`), so numerical noise between platforms is no change.
"""

from __future__ import annotations

import hashlib
import math
from collections import Counter
from collections.abc import Iterator, Mapping
from dataclasses import dataclass, fields
from pathlib import Path
from typing import Any

import numpy as np

from xodrcheck.analysis.info import bounding_box, map_counts
from xodrcheck.check import check
from xodrcheck.config import Config, Tolerances
from xodrcheck.findings import XodrError
from xodrcheck.geometry.lanes import geometry_of
from xodrcheck.graph.invariants import KEYS as REACH_KEYS
from xodrcheck.graph.invariants import reach_differences, reach_invariants
from xodrcheck.model import ContactPoint, Document, ElementType, Road
from xodrcheck.reader import read

__all__ = [
    "FORMAT",
    "NotReadWhole",
    "Snapshot",
    "SnapshotError",
    "differences",
    "lane_length",
    "lane_links",
    "snapshot_of",
    "topology_hash",
]


#: Version of the snapshot format (a snapshot of another version cannot be compared).
FORMAT = 1
_DECIMALS = 3


class SnapshotError(XodrError, ValueError):
    """A snapshot file that cannot be used (not JSON, wrong format or version, missing keys)."""


@dataclass(frozen=True)
class Snapshot:
    """The invariants of one map (see the module docstring). Mappings are sorted by key."""

    roads: int
    junction_roads: int
    junctions: int
    junctions_by_type: Mapping[str, int]
    legs: Mapping[str, int]
    lane_sections: int
    lanes: int
    lanes_by_type: Mapping[str, int]
    lane_length: float
    lane_links: int
    topology: str
    bbox: tuple[float, float, float, float] | None
    findings: Mapping[str, int]
    #: reachability invariants (:data:`xodrcheck.graph.invariants.KEYS`); ``None`` in an older snapshot
    strong_components: int | None = None
    entries: tuple[str, ...] | None = None
    exits: tuple[str, ...] | None = None
    unroutable: tuple[tuple[str, str], ...] | None = None

    def to_json(self) -> dict:
        data: dict[str, object] = {"format": FORMAT}
        for f in fields(self):
            value = getattr(self, f.name)
            data[f.name] = (
                [list(v) if isinstance(v, tuple) else v for v in value]
                if isinstance(value, tuple)
                else dict(value)
                if isinstance(value, Mapping)
                else value
            )
        return data

    @classmethod
    def from_json(cls, data) -> Snapshot:
        """A snapshot from its JSON object; :class:`SnapshotError` when it is not one of this format."""
        if not isinstance(data, dict):
            raise SnapshotError("a snapshot is a JSON object")
        if data.get("format") != FORMAT:
            raise SnapshotError(f"snapshot format {data.get('format')!r}, this xodrcheck reads format {FORMAT}")
        optional = set(REACH_KEYS)
        names = [f.name for f in fields(cls)]
        missing = [n for n in names if n not in data and n not in optional]
        if missing:
            raise SnapshotError(f"snapshot lacks {', '.join(missing)}")
        try:
            values: dict[str, Any] = {n: data.get(n) for n in names}
            for n in ("junctions_by_type", "legs", "lanes_by_type", "findings"):
                values[n] = {str(k): int(v) for k, v in sorted(dict(values[n]).items())}
            for n in ("roads", "junction_roads", "junctions", "lane_sections", "lanes", "lane_links"):
                values[n] = int(values[n])
            values["lane_length"] = float(values["lane_length"])
            values["topology"] = str(values["topology"])
            box = values["bbox"]
            values["bbox"] = None if box is None else tuple(float(v) for v in box)
            if values["bbox"] is not None and len(values["bbox"]) != 4:
                raise ValueError("bbox needs four numbers")
            if values["entries"] is not None:
                values["strong_components"] = int(values["strong_components"])
                values["entries"] = tuple(str(v) for v in values["entries"])
                values["exits"] = tuple(str(v) for v in values["exits"])
                values["unroutable"] = tuple((str(a), str(b)) for a, b in values["unroutable"])
        except (TypeError, ValueError, AttributeError) as exc:
            raise SnapshotError(f"malformed snapshot: {exc}") from None
        return cls(**values)


# ------------------------------------------------------------------------------------------------------ lane graph
def _end_index(road: Road, end: ContactPoint) -> int:
    return 0 if end is ContactPoint.START else len(road.lane_sections) - 1


def _node(road: Road, index: int, lane: int) -> str:
    return f"{road.id}/{index}/{lane}"


def lane_links(document: Document) -> set[tuple[str, str, str]]:
    """Every lane link of the document as ``(lane, lane, kind)``, the two lanes named ``road/section index/lane``
    in sorted order: kind ``lane`` for lane predecessors and successors (inside a road and across road links; a link
    given from both sides counts once), ``junction`` for junction laneLinks."""
    edges: set[tuple[str, str, str]] = set()

    def add(a: str, b: str, kind: str = "lane") -> None:
        edges.add((a, b, kind) if a <= b else (b, a, kind))

    by_id = document.road_by_id
    for road in document.roads:
        sections = road.lane_sections
        for i, section in enumerate(sections):
            for lane in (*section.left, *section.right):
                for end, targets in ((ContactPoint.START, lane.predecessors), (ContactPoint.END, lane.successors)):
                    if (i > 0 and end is ContactPoint.START) or (i < len(sections) - 1 and end is ContactPoint.END):
                        j = i - 1 if end is ContactPoint.START else i + 1
                        for t in targets:
                            add(_node(road, i, lane.id), _node(road, j, t))
                        continue
                    link = road.predecessor if end is ContactPoint.START else road.successor
                    if link is None or link.element_type is not ElementType.ROAD or link.contact_point is None:
                        continue
                    other = by_id.get(link.element_id)
                    if other is None or not other.lane_sections:
                        continue
                    for t in targets:
                        add(_node(road, i, lane.id), _node(other, _end_index(other, link.contact_point), t))
    for junction in document.junctions:
        for c in junction.connections:
            incoming = by_id.get(c.incoming_road) if c.incoming_road is not None else None
            target = by_id.get(c.connecting_road or c.linked_road or "")
            if incoming is None or target is None or not incoming.lane_sections or not target.lane_sections:
                continue
            at_end = incoming.successor is not None and incoming.successor.element_id == junction.id
            i = _end_index(incoming, ContactPoint.END if at_end else ContactPoint.START)
            j = _end_index(target, c.contact_point or ContactPoint.START)
            for ll in c.lane_links:
                add(_node(incoming, i, ll.from_lane), _node(target, j, ll.to_lane), "junction")
    return edges


def topology_hash(edges: set[tuple[str, str, str]]) -> str:
    """A short, order-independent hash of a set of lane links."""
    text = "\n".join(" ".join(edge) for edge in sorted(edges))
    return hashlib.sha256(text.encode()).hexdigest()[:16]


# ------------------------------------------------------------------------------------------------------ measures
def lane_length(document: Document, tolerances: Tolerances) -> float:
    """Sum of the lengths of every lane's centre line (m), on polylines within the chord tolerance."""
    total = 0.0
    geometry = geometry_of(document)
    for road in document.roads:
        rg = geometry.get(road.id)
        if rg is None or rg.road is not road or not road.plan_view or not (road.length > 0):
            continue
        for index in range(len(road.lane_sections)):
            start, end = road.lane_sections[index].s, road.section_end(index)
            if not end > start:
                continue
            s = rg.sample_s(index, chord=tolerances.chord, max_step=tolerances.max_step)
            for side in rg.side_lanes(index):
                for lane in side.lanes:
                    p = rg.lane_points(index, lane.id, s, "centre")
                    steps = np.hypot(np.diff(p.x), np.diff(p.y))
                    total += float(np.sum(steps[np.isfinite(steps)]))
    return total


def _rounded(value: float) -> float:
    return round(value, _DECIMALS) if math.isfinite(value) else value


class NotReadWhole(XodrError, ValueError):
    """The map cannot be read whole (``why``: the reader's finding), so it has no snapshot."""

    def __init__(self, why: str) -> None:
        super().__init__(f"it cannot be read whole: {why}")
        self.why = why


def snapshot_of(source: str | Path | bytes, config: Config | None = None) -> Snapshot:
    """Read ``source`` (a path or a file's bytes), check it and take its snapshot.

    Raises :class:`xodrcheck.findings.ReadError` when it cannot be opened at all and :class:`ValueError` when it
    cannot be read whole (not well-formed, not OpenDRIVE: :meth:`~xodrcheck.reader.ReadResult.not_whole`), so that a
    snapshot never describes part of a file."""
    config = config or Config()
    result = read(source, max_bytes=config.tolerances.max_file_bytes)
    why = result.not_whole()
    if why is not None:
        raise NotReadWhole(why)
    doc = result.document
    assert doc is not None  # not_whole() says so when there is no document
    counts = map_counts(doc)
    legs = counts.pop("junctions_by_legs")
    edges = lane_links(doc)
    box = bounding_box(doc, config.tolerances)
    report = check(source, config=config)
    return Snapshot(
        **counts,
        legs={str(k): v for k, v in legs.items()},
        lane_length=_rounded(lane_length(doc, config.tolerances)),
        lane_links=len(edges),
        topology=topology_hash(edges),
        bbox=None
        if box is None
        else (_rounded(box.min_x), _rounded(box.min_y), _rounded(box.max_x), _rounded(box.max_y)),
        findings=dict(sorted(Counter(f.code for f in report.findings).items())),
        **reach_invariants(doc),
    )


# ------------------------------------------------------------------------------------------------------ differences
_COUNTS = (
    ("roads", "roads"),
    ("junction_roads", "roads inside junctions"),
    ("junctions", "junctions"),
    ("lane_sections", "lane sections"),
    ("lanes", "lanes"),
    ("lane_links", "lane links"),
)
_HISTOGRAMS = (
    ("junctions_by_type", "junctions of type", ""),
    ("legs", "junctions with", " legs"),
    ("lanes_by_type", "lanes of type", ""),
    ("findings", "findings", ""),
)


def differences(old: Snapshot, new: Snapshot, tolerances: Tolerances | None = None) -> Iterator[str]:
    """Readable lines saying what changed from ``old`` to ``new`` (nothing when the map's invariants are the same).

    Lengths compare within ``length_abs`` and coordinates within ``position`` (plus the storage rounding)."""
    tol = tolerances or Tolerances()
    slack = 0.5 * 10.0**-_DECIMALS + 1e-9
    for name, label in _COUNTS:
        a, b = getattr(old, name), getattr(new, name)
        if a != b:
            yield f"{label}: {a} -> {b} ({b - a:+d})"
    for name, label, unit in _HISTOGRAMS:
        a, b = getattr(old, name), getattr(new, name)
        for key in sorted(set(a) | set(b)):
            if a.get(key, 0) != b.get(key, 0):
                yield f"{label} {key}{unit}: {a.get(key, 0)} -> {b.get(key, 0)}"
    if abs(old.lane_length - new.lane_length) > tol.length_abs + slack or (
        math.isfinite(old.lane_length) != math.isfinite(new.lane_length)
    ):
        yield f"total lane length: {old.lane_length:.3f} m -> {new.lane_length:.3f} m"
    if old.topology != new.topology:
        yield f"lane graph topology changed (hash {old.topology} -> {new.topology})"
    yield from reach_differences({k: getattr(old, k) for k in REACH_KEYS}, {k: getattr(new, k) for k in REACH_KEYS})
    if (old.bbox is None) != (new.bbox is None):
        yield f"bounding box: {_box(old.bbox)} -> {_box(new.bbox)}"
    elif old.bbox is not None and new.bbox is not None:
        moved = [abs(a - b) > tol.position + slack for a, b in zip(old.bbox, new.bbox)]
        if any(moved):
            yield f"bounding box: {_box(old.bbox)} -> {_box(new.bbox)}"


def _box(box) -> str:
    if box is None:
        return "none"
    return f"x {box[0]:.3f}..{box[2]:.3f}, y {box[1]:.3f}..{box[3]:.3f}"
