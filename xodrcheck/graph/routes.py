"""The shortest route between two places on lanes, with its length and polyline on the lane centres.

A place is a road, a lane id and optionally an ``s``: with ``s``, the point of the lane section holding it (a section
boundary belongs to the section starting there); without, the start of the lane (the first of its lane sections in the
direction of travel) for a route's origin and its end (the last) for a destination. A lane driven both ways may be
left either way: the shorter route wins.

Costs: a link edge costs the length of the lane it leaves; a lane change costs what it saves or adds on the way (the
first place the road marks allow it, :mod:`.build`), at least nothing, plus 1 mm, so that of two routes of one length
the one with fewer lane changes is taken. The length reported is the polyline's: the lane centres driven, and a
straight step across at each lane change.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from xodrcheck.findings import XodrError
from xodrcheck.graph import paths
from xodrcheck.graph.build import LANE_CHANGE, LINK, LaneGraph, Node
from xodrcheck.graph.lengths import CentreLine, centre_line, node_lengths
from xodrcheck.model import Document
from xodrcheck.support.quantities import metres

__all__ = ["Place", "PlaceError", "Route", "RouteStep", "parse_place", "route"]

#: What a lane change costs beyond its length, in metres: a tie-break towards fewer lane changes.
LANE_CHANGE_COST = 1e-3
#: Every edge's least cost (m): zero-length lanes still count as a step.
_STEP = 1e-9


class PlaceError(XodrError, ValueError):
    """A place that is not ``ROAD:LANE[:S]``, or names no lane of the graph."""


@dataclass(frozen=True, slots=True)
class Place:
    """``road``, ``lane`` and optionally ``s`` (absolute s on the road)."""

    road: str
    lane: int
    s: float | None = None

    def __str__(self) -> str:
        return f"{self.road}:{self.lane}" + ("" if self.s is None else f":{metres(self.s)}")


def parse_place(text: str) -> Place:
    """``ROAD:LANE[:S]`` (road ids may hold colons: the last one or two fields are the lane and s)."""
    parts = text.rsplit(":", 2)
    for count in (2, 1):
        if len(parts) < count + 1:
            continue
        road, rest = ":".join(parts[: len(parts) - count]), parts[len(parts) - count :]
        try:
            lane = int(rest[0])
            s = float(rest[1]) if count == 2 else None
        except ValueError:
            continue
        if road and (s is None or math.isfinite(s)):
            return Place(road, lane, s)
    raise PlaceError(f"{text!r} is not ROAD:LANE or ROAD:LANE:S (a road id, a lane id, an s in metres)")


@dataclass(frozen=True, slots=True)
class RouteStep:
    """One lane driven: its node, from ``s_from`` to ``s_to`` (absolute s on its road; decreasing when driven
    against s), entered by ``entered`` (``start``, ``link`` or ``lane_change``)."""

    node: Node
    s_from: float
    s_to: float
    entered: str


@dataclass(frozen=True, eq=False)
class Route:
    """A route (``found``) or, when there is none, the best partial one (``steps`` end where it stops) and why."""

    origin: Place
    destination: Place
    found: bool
    steps: tuple[RouteStep, ...]
    x: np.ndarray
    y: np.ndarray
    z: np.ndarray
    why: str = ""

    @property
    def length(self) -> float:
        return float(np.sum(np.hypot(np.diff(self.x), np.diff(self.y)))) if len(self.x) > 1 else 0.0


# ------------------------------------------------------------------------------------------------------ places
def _section_holding(document: Document, road_id: str, s: float) -> int:
    sections = document.road_by_id[road_id].lane_sections
    starts = [section.s for section in sections]
    return max(int(np.searchsorted(starts, s, side="right")) - 1, 0)


def _candidates(document: Document, graph: LaneGraph, place: Place, origin: bool) -> list[tuple[int, float]]:
    """The nodes a place may be (one per direction of travel) and the s on each."""
    road = document.road_by_id.get(place.road)
    if road is None:
        raise PlaceError(f"there is no road {place.road}")
    if not road.lane_sections:
        raise PlaceError(f"road {place.road} has no lane sections")
    out = []
    for travel in (1, -1):
        if place.s is not None:
            if not (0.0 <= place.s <= road.length):
                raise PlaceError(f"s={metres(place.s)} is not on road {place.road} (0 to {metres(road.length)})")
            k = _section_holding(document, place.road, place.s)
            node = graph.index.get((place.road, k, place.lane, travel))
            if node is not None:
                out.append((node, place.s))
            continue
        order = range(len(road.lane_sections))
        ahead = (travel > 0) == origin  # the first section driven through for an origin, the last for a destination
        for k in order if ahead else reversed(order):
            node = graph.index.get((place.road, k, place.lane, travel))
            if node is not None:
                start, end = road.lane_sections[k].s, road.section_end(k)
                out.append((node, (start if travel > 0 else end) if origin else (end if travel > 0 else start)))
                break
    if not out:
        where = "" if place.s is None else f" at s={metres(place.s)}"
        raise PlaceError(f"road {place.road} has no lane {place.lane}{where} in the lane graph (a drivable lane)")
    return out


# ------------------------------------------------------------------------------------------------------ search
def _weights(document: Document, graph: LaneGraph) -> np.ndarray:
    lengths = node_lengths(document, graph)
    src, dst = graph.source, graph.target
    change = graph.kind == 1
    w = lengths[src].copy()
    w[change] = np.maximum(graph.at[change] * (lengths[src[change]] - lengths[dst[change]]), 0.0) + LANE_CHANGE_COST
    return w + _STEP


def route(document: Document, graph: LaneGraph, origin: Place, destination: Place) -> Route:
    """The shortest route from ``origin`` to ``destination`` on ``graph`` (a graph of ``document``); raises
    :class:`PlaceError` when a place names no lane of the graph."""
    starts = _candidates(document, graph, origin, origin=True)
    goals = _candidates(document, graph, destination, origin=False)
    weights = _weights(document, graph)
    best: tuple[float, list[int], float, float] | None = None
    for start, s0 in starts:
        dist, pred = paths.shortest_from(graph, weights, start)
        for goal, s1 in goals:
            path = _path_to(graph, weights, dist, pred, start, goal, s0, s1)
            if path is not None and (best is None or path[0] < best[0]):
                best = (path[0], path[1], s0, s1)
    if best is not None:
        _, nodes, s0, s1 = best
        return _made(document, graph, origin, destination, nodes, s0, s1, True, "")
    start, s0 = starts[0]
    nodes, why = paths.best_partial(document, graph, start, [g for g, _ in goals])
    last = graph.nodes[nodes[-1]]
    end = _travel_end(document, last)
    return _made(document, graph, origin, destination, nodes, s0, end, False, why)


def _path_to(graph, weights, dist, pred, start, goal, s0, s1) -> tuple[float, list[int]] | None:
    """The cheapest path from ``start`` to ``goal`` (a loop when ``goal`` is ``start`` and ``s1`` lies behind
    ``s0``), with its cost."""
    if goal == start and (s1 - s0) * graph.nodes[start].travel >= 0:
        return 0.0, [start]
    if goal == start:  # round a loop back to the start: through the cheapest edge into it
        into = np.flatnonzero((graph.target == start) & np.isfinite(dist[graph.source]))
        if not into.size:
            return None
        k = into[np.argmin(dist[graph.source[into]] + weights[into])]
        cost = float(dist[graph.source[k]] + weights[k])
        return cost, [*paths.unwind(pred, start, int(graph.source[k])), start]
    if not np.isfinite(dist[goal]):
        return None
    return float(dist[goal]), paths.unwind(pred, start, goal)


# ------------------------------------------------------------------------------------------------------ polyline
def _travel_end(document: Document, node: Node) -> float:
    road = document.road_by_id[node.road]
    return road.section_end(node.index) if node.travel > 0 else road.lane_sections[node.index].s


def _travel_start(document: Document, node: Node) -> float:
    road = document.road_by_id[node.road]
    return road.lane_sections[node.index].s if node.travel > 0 else road.section_end(node.index)


def _is_change(graph: LaneGraph, a: int, b: int) -> bool:
    """Whether the step from node ``a`` to ``b`` is a lane change (no link joins them)."""
    kinds = graph.kind[(graph.source == a) & (graph.target == b)]
    return bool(kinds.size) and not bool(np.any(kinds == 0))


def _change_s(document: Document, graph: LaneGraph, a: int, b: int, entered: float) -> float:
    """Where a lane change from node ``a`` to ``b`` happens: the first place allowed, not before ``entered``."""
    edge = np.flatnonzero((graph.source == a) & (graph.target == b) & (graph.kind == 1))
    node = graph.nodes[a]
    start, end = _travel_start(document, node), _travel_end(document, node)
    s = start + float(graph.at[edge[0]]) * (end - start) if edge.size else start
    return max(s, entered) if node.travel > 0 else min(s, entered)


def _made(
    document: Document,
    graph: LaneGraph,
    origin: Place,
    destination: Place,
    nodes: Sequence[int],
    s0: float,
    s1: float,
    found: bool,
    why: str,
) -> Route:
    steps: list[RouteStep] = []
    pieces: list[CentreLine] = []
    entered, how = s0, "start"
    for k, i in enumerate(nodes):
        node = graph.nodes[i]
        change = k + 1 < len(nodes) and _is_change(graph, i, nodes[k + 1])
        if k + 1 == len(nodes):
            leave = s1
        elif change:
            leave = _change_s(document, graph, i, nodes[k + 1], entered)
        else:
            leave = _travel_end(document, node)
        steps.append(RouteStep(node, entered, leave, how))
        pieces.append(centre_line(document, node.road, node.index, node.lane).between(entered, leave))
        if change:
            entered, how = leave, LANE_CHANGE
        elif k + 1 < len(nodes):
            entered, how = _travel_start(document, graph.nodes[nodes[k + 1]]), LINK
    x = np.concatenate([p.x for p in pieces]) if pieces else np.zeros(0)
    y = np.concatenate([p.y for p in pieces]) if pieces else np.zeros(0)
    z = np.concatenate([p.z for p in pieces]) if pieces else np.zeros(0)
    keep = np.ones(len(x), dtype=bool)  # drop the repeated point where one lane's line ends and the next begins
    keep[1:] = (np.diff(x) != 0) | (np.diff(y) != 0)
    return Route(origin, destination, found, tuple(steps), x[keep], y[keep], z[keep], why)
