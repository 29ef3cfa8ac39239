"""The lane graph of a document: a node per lane of a lane section and direction of travel, an edge per way on.

Nodes are the lanes of every road's lane sections (the permanent lane layer) whose type is among ``lane_types``
(default: the types a motor vehicle drives on, :data:`~xodrcheck.model.DRIVABLE_LANE_TYPES`) and that have a width
somewhere (:func:`zero_wide`: a lane whose width records are all zero carries no traffic), once per direction
traffic drives on them (:func:`~xodrcheck.graph.direction.travels`: twice for a lane used both ways). Edges:

* ``link``: traffic leaves the lane at its end and enters the lane a link names (:mod:`.topology`), when that lane is a
  node driven the same way. ``at`` is 1: the whole lane is driven first;
* ``lane_change`` (``lane_changes=True``): to the neighbouring lane of the same lane section driven the same way,
  where the road mark between them allows it (:mod:`.marks`). ``at`` is the fraction of the lane section, in the
  direction of travel, before the first place the mark allows it.

Each node also keeps what lies past its end when no link edge leaves it (:class:`Stop`): an open edge of the map or
why traffic cannot go on. Geometry is not read here: lengths and polylines are :mod:`.lengths`'s.
"""

from __future__ import annotations

import itertools
from collections.abc import Iterable
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from xodrcheck.graph import marks, topology
from xodrcheck.graph.direction import leaving, travels
from xodrcheck.model import (
    DRIVABLE_LANE_TYPES,
    ContactPoint,
    Document,
    Lane,
    LaneKey,
    LaneSection,
    LaneType,
    Road,
    document_cache,
    lane_type_name,
)
from xodrcheck.support.quantities import metres

if TYPE_CHECKING:  # pragma: no cover
    from scipy.sparse import csr_matrix

__all__ = ["LANE_CHANGE", "LINK", "LaneGraph", "Node", "Stop", "lane_graph", "matrix", "zero_wide"]

LINK, LANE_CHANGE = "link", "lane_change"
#: Edge kinds by their code in :attr:`LaneGraph.kind`.
KINDS = (LINK, LANE_CHANGE)

#: Why no link edge leaves a node (:attr:`Stop.kind`), beside the place kinds of :mod:`.topology`: its links name lanes
#: that do not exist, that traffic drives the other way, or whose type is not in the graph.
MISSING, AGAINST, OTHER_TYPE = "missing", "against", "other-type"


@dataclass(frozen=True, slots=True)
class Node:
    """A lane of a lane section, driven one way: ``travel`` +1 along s, -1 against it."""

    key: LaneKey
    index: int
    travel: int
    type: str
    junction: str | None

    @property
    def road(self) -> str:
        return self.key.road

    @property
    def lane(self) -> int:
        return self.key.lane

    def describe(self) -> str:
        return f"road {self.key.road} lane {self.key.lane} (lane section s={metres(self.key.section_s)})"


@dataclass(frozen=True, slots=True)
class Stop:
    """What stops traffic at a node's end when no link edge leaves it: ``kind`` (``open`` for an open edge of the map,
    or why not) and ``why`` in words."""

    kind: str
    why: str


@dataclass(frozen=True, eq=False)
class LaneGraph:
    """Nodes, edges as parallel arrays (``source``, ``target``, ``kind`` as an index into :data:`KINDS`, ``at``) and,
    for each node without a link edge onward, its :class:`Stop`. ``starts_open`` marks the nodes whose traffic enters
    the map at an open edge (their lane begins where a road starts without a link)."""

    nodes: tuple[Node, ...]
    source: np.ndarray
    target: np.ndarray
    kind: np.ndarray
    at: np.ndarray
    stops: dict[int, Stop]
    starts_open: frozenset[int]
    lane_changes: bool
    #: (road id, lane-section index, lane id, travel) -> node
    index: dict[tuple[str, int, int, int], int]

    def out_edges(self, node: int) -> np.ndarray:
        """Indices of the edges leaving ``node``."""
        return np.flatnonzero(self.source == node)

    def ends_open(self, node: int) -> bool:
        """Whether traffic on ``node`` leaves the map at an open edge."""
        stop = self.stops.get(node)
        return stop is not None and stop.kind == topology.OPEN


def lane_graph(
    document: Document, lane_changes: bool = True, lane_types: Iterable[LaneType] | None = None
) -> LaneGraph:
    """The lane graph of ``document`` (cached with it for the default lane types)."""
    types = DRIVABLE_LANE_TYPES if lane_types is None else frozenset(lane_types)
    key = ("lane graph", lane_changes, types)
    cache = document_cache(document)
    found = cache.get(key)
    if found is None:
        found = cache[key] = _build(document, lane_changes, types)
    return found


def zero_wide(lane: Lane) -> bool:
    """Whether a lane is zero wide all along its section by its records alone: no ``<border>`` and every ``<width>``
    polynomial zero (or none at all). No vehicle drives on it; it is no node."""
    return not lane.borders and all(w.a == 0 and w.b == 0 and w.c == 0 and w.d == 0 for w in lane.widths)


def _nodes(document: Document, types: frozenset[LaneType]) -> list[tuple[Node, Road, Lane]]:
    out = []
    for road_id, road in document.road_by_id.items():
        for index, section in enumerate(road.lane_sections):
            for lane in section.lanes:
                if lane.type not in types or zero_wide(lane):
                    continue
                key = LaneKey(road_id, section.s, lane.id)
                for travel in travels(road, lane):
                    out.append((Node(key, index, travel, lane_type_name(lane), road.junction), road, lane))
    return out


def _build(document: Document, lane_changes: bool, types: frozenset[LaneType]) -> LaneGraph:
    built = _nodes(document, types)
    nodes = tuple(node for node, _, _ in built)
    index = {(n.key.road, n.index, n.key.lane, n.travel): i for i, n in enumerate(nodes)}
    links = topology.Topology(document)
    edges: dict[tuple[int, int, int], float] = {}
    stops: dict[int, Stop] = {}
    starts_open = set()
    for i, (node, road, lane) in enumerate(built):
        onward = links.onward(road, node.index, lane, node.travel)
        found = [index.get((t.road.id, t.index, t.lane, t.travel)) for t in onward.targets]
        for j in found:
            if j is not None:
                edges[(i, j, 0)] = 1.0
        if not any(j is not None for j in found):
            stops[i] = _stop(onward, lane, types)
        if _starts_open(road, node):
            starts_open.add(i)
    if lane_changes:
        for road in document.road_by_id.values():
            for k, section in enumerate(road.lane_sections):
                _lane_changes(road, k, section, index, edges)
    keys = list(edges)
    return LaneGraph(
        nodes,
        np.array([a for a, _, _ in keys], dtype=np.int64),
        np.array([b for _, b, _ in keys], dtype=np.int64),
        np.array([c for _, _, c in keys], dtype=np.int8),
        np.array(list(edges.values()), dtype=float),
        stops,
        frozenset(starts_open),
        lane_changes,
        index,
    )


def _stop(onward: topology.Onward, lane: Lane, types: frozenset[LaneType]) -> Stop:
    """Why no link edge leaves a lane whose links name ``onward``'s targets (or none)."""
    if not onward.targets:
        return Stop(onward.kind, onward.why)
    named = []
    for t in onward.targets:
        section = t.road.lane_sections[t.index]
        other = section.lane(t.lane) if t.lane != 0 else None
        named.append((t, other))
    where = ", ".join(f"lane {t.lane} of road {t.road.id}" for t, _ in named)
    if all(other is None for _, other in named):
        return Stop(MISSING, f"lane {lane.id} links to {where}, which does not exist")
    if all(other is None or other.type not in types for _, other in named):
        kinds = ", ".join(sorted({lane_type_name(o) for _, o in named if o is not None}))
        return Stop(OTHER_TYPE, f"lane {lane.id} continues only into {where} ({kinds})")
    return Stop(AGAINST, f"lane {lane.id} links to {where}, where traffic drives the other way")


def _starts_open(road: Road, node: Node) -> bool:
    """Whether the node's traffic comes from an open edge: its lane section is the first it drives through on a road
    whose link at that end is missing."""
    start = leaving(-node.travel)
    first = 0 if start is ContactPoint.START else len(road.lane_sections) - 1
    link = road.predecessor if start is ContactPoint.START else road.successor
    return node.index == first and link is None


def _lane_changes(
    road: Road, k: int, section: LaneSection, index: dict, edges: dict[tuple[int, int, int], float]
) -> None:
    """Lane-change edges between neighbouring lanes of lane section ``k`` driven the same way."""
    length = max(road.section_end(k) - section.s, 0.0)
    ids = [lane.id for lane in section.lanes if lane.id != 0]
    pairs = [(a, b) for a, b in itertools.pairwise(ids) if a - b == 1 or (a == 1 and b == -1)]
    for a, b in pairs:
        for travel in (1, -1):
            u, v = index.get((road.id, k, a, travel)), index.get((road.id, k, b, travel))
            if u is None or v is None:
                continue
            for x, y, frm, to in ((u, v, a, b), (v, u, b, a)):
                stretches = marks.crossable(section, length, frm, to)
                if not stretches:
                    continue
                if length <= 0:
                    at = 0.0
                elif travel > 0:
                    at = min(s0 for s0, _ in stretches) / length
                else:
                    at = (length - max(s1 for _, s1 in stretches)) / length
                edges[(x, y, 1)] = at


def matrix(graph: LaneGraph, weights: np.ndarray | None = None) -> csr_matrix:
    """The graph as a sparse matrix: one entry per (source, target), the least weight of the edges joining them
    (1 without ``weights``)."""
    from scipy.sparse import csr_matrix

    n = len(graph.nodes)
    w = np.ones(len(graph.source)) if weights is None else np.asarray(weights, dtype=float)
    order = np.lexsort((w, graph.target, graph.source))
    src, dst, w = graph.source[order], graph.target[order], w[order]
    first = np.ones(len(src), dtype=bool)
    first[1:] = (src[1:] != src[:-1]) | (dst[1:] != dst[:-1])
    return csr_matrix((w[first], (src[first], dst[first])), shape=(n, n))
