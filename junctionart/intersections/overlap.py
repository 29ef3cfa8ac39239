"""Road bodies and junction areas that overlap where the map does not connect them, found and repaired before writing.

xodrcheck counts any shared area between parts the map does not connect as an overlap; a map that has one is not
drivable as drawn, so stage 3 removes a road instead (one the map can lose, where there is one).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from enum import Enum

import numpy as np
import shapely

from ..curves import sample, unit_tangents
from ..graph import Chain
from ..lanegeom import border_point, side_width
from ..opendrive import Geometry, ParamPoly3
from ..params import Params, TrafficRule
from ..scenario.roadside import roadside_width
from .model import JunctionPlan
from .overpasses import separated
from .planning import Junction
from .roads import Road
from .roadshape import contact
from .survey import Survey

INSET = 0.05  #: how far a connection lane's body stays inside its ends and borders (m)


def _lane_bodies(gs, side: float, w: float) -> list:
    """The plan-view body of each connection lane of width ``w`` on ``side`` (+1 left, -1 right) of the reference
    lines ``gs``, :data:`INSET` short of both ends and inside both borders (so that a lane merely touching a road does
    not count, while a dead end lying across the lane's first metre does: the checker counts any shared area); None
    for a lane too short for that. Each is a polygon between two offset polylines: far cheaper than a buffer, and
    valid because the generator keeps every offset line's radius above the offset. All lanes of a junction are built
    in one vectorised pass (the paramPoly3 samples with the same arithmetic as :func:`junctionart.curves.sample`)."""
    out: list = [None] * len(gs)
    keep = [k for k, g in enumerate(gs) if g.length > 2 * INSET]
    if not keep:
        return out
    geoms = [gs[k] for k in keep]
    n = np.array([max(4, int(g.length / 2.0) + 2) for g in geoms])
    owner = np.repeat(np.arange(len(geoms)), n)
    first = np.cumsum(n) - n
    last = first + n - 1
    pts = np.empty((len(owner), 2))
    cubic = np.array([isinstance(g, ParamPoly3) for g in geoms])
    for arc in np.flatnonzero(~cubic):  # U-turn arcs: few, one sample call each
        pts[first[arc] : last[arc] + 1] = sample(geoms[arc], int(n[arc]))
    if cubic.any():
        rows = cubic[owner]
        idx, at = np.flatnonzero(rows), owner[rows]
        # np.linspace(0, 1, m) for each lane, in one pass: the same step, products and exact last sample
        t = (idx - first[at]) * (1.0 / (n - 1))[at]
        t[idx == last[at]] = 1.0
        c = np.array(
            [
                [g.au, g.bu, g.cu, g.du, g.av, g.bv, g.cv, g.dv, g.x, g.y, math.cos(g.hdg), math.sin(g.hdg)]
                if isinstance(g, ParamPoly3)
                else [0.0] * 12
                for g in geoms
            ]
        )[at]
        u = c[:, 0] + t * (c[:, 1] + t * (c[:, 2] + t * c[:, 3]))
        v = c[:, 4] + t * (c[:, 5] + t * (c[:, 6] + t * c[:, 7]))
        pts[rows] = np.column_stack([c[:, 8] + c[:, 10] * u - c[:, 11] * v, c[:, 9] + c[:, 11] * u + c[:, 10] * v])
    tangent = unit_tangents(pts, first[owner], last[owner])
    # the ends move INSET along the lane (dropping the end samples instead would cut a whole step of ~2 m off)
    pts[first] += INSET * tangent[first]
    pts[last] -= INSET * tangent[last]
    normal = np.column_stack([-tangent[:, 1], tangent[:, 0]]) * side
    inner, outer = pts + INSET * normal, pts + (w - INSET) * normal
    # each ring: the lane's inner samples, then its outer samples backwards; built in one call
    reverse = (first[owner] + last[owner]) - np.arange(len(owner))  # index of the mirrored sample within each lane
    ring_owner = np.concatenate([owner, owner])
    coords = np.concatenate([inner, outer[reverse]])
    order = np.argsort(ring_owner, kind="stable")
    polygons = shapely.polygons(shapely.linearrings(coords[order], indices=ring_owner[order]))
    for i, k in enumerate(keep):
        out[k] = polygons[i]
    return out


class Part(Enum):
    """What a shape in the overlap test belongs to."""

    ROAD = "road"
    JUNCTION = "junction"


def remove_overlaps(
    view: Survey, roads: list[Road], junctions: dict[int, Junction], plans: list[JunctionPlan], p: Params
) -> None:
    """Roads and junction areas (with every connection lane) may only touch where the map connects them; otherwise
    a road is removed (one whose removal keeps the map connected when there is one)."""
    st = view.state
    lanes: dict[int, list[Geometry]] = {}
    for jp in plans:
        lanes.setdefault(jp.node, []).extend(c.geometry for c in jp.connections)
    for node, j in junctions.items():
        if j.ring is not None:  # a roundabout: its ring roads' lanes too
            lanes[node] = j.ring.lane_borders()
    for cands in overlaps(view.chains, roads, junctions, lanes, p, separated(view)):
        if any(st.touched(view.chains[c].nodes) for c in cands):
            continue
        chosen = next((c for c in cands if st.connected_without(set(view.chains[c].edges))), cands[0])
        for e in view.chains[chosen].edges:
            del st.edges[e]
        st.dirty.update(view.chains[chosen].nodes)
        ch = view.chains[chosen]
        st.repairs.append(f"removed road between nodes {ch.start} and {ch.end}: it overlapped another road or junction")


def overlaps(
    chs: list[Chain],
    roads: list[Road],
    junctions: dict[int, Junction],
    connections: dict[int, list[Geometry]],
    p: Params,
    decks: frozenset[frozenset[int]] = frozenset(),
) -> list[list[int]]:
    """For each overlap, the chains (roads) whose removal would end it, in order of preference.

    Roads are their reference lines buffered by their wider side; a junction is the convex hull of its legs' end
    cross-sections together with the body of each of its connection lanes (``connections``: their reference lines,
    the lane lying on the traffic side), since a wide turn can leave the hull. A junction with its own legs may
    touch, and so may the two roads of an overpass (``decks``: pairs of chains). Two legs of one junction (roads
    sharing an end node) meet only at its edge: they are compared by their bodies, each side as wide as its lanes
    (:func:`_leg_body`), which must not share area anywhere (a leg bent back along its neighbour does).
    """
    lines = [_reference_line(road) for road in roads]
    shapes = _road_shapes(roads, lines, p)
    owners = [(Part.ROAD, c) for c in range(len(roads))]
    for node, j in junctions.items():
        for shape in _junction_shapes(roads, j, connections.get(node, []), p):
            shapes.append(shape)
            owners.append((Part.JUNCTION, node))
    bodies: dict[int, shapely.Geometry] = {}

    def body(c: int) -> shapely.Geometry:
        if c not in bodies:
            bodies[c] = _leg_body(roads[c], lines[c], p)
        return bodies[c]

    return _overlapping(chs, np.array(shapes, dtype=object), owners, decks, body)


def _reference_line(road: Road) -> np.ndarray:
    """Points along the road's reference line, about every 5 m (each geometry's ends included)."""
    return np.concatenate([sample(e, max(2, int(e.length / 5.0) + 2)) for e in road.geometry])


def _road_shapes(roads: list[Road], lines: list[np.ndarray], p: Params) -> list:
    """Each road's reference line buffered by its wider side."""
    if not roads:
        return []
    w, mw, rs = p.lane_width, p.median_width, roadside_width(p)
    halves = []
    for road in roads:
        cfg = road.spec.lanes
        half = max(side_width(cfg.forward, cfg.median, w, mw), side_width(cfg.backward, cfg.median, w, mw))
        halves.append(max(half, _splitter_side(road, w)) + rs)
    indices = np.repeat(np.arange(len(lines)), [len(x) for x in lines])
    return list(
        shapely.buffer(shapely.linestrings(np.concatenate(lines), indices=indices), np.array(halves), cap_style="flat")
    )


def _leg_body(road: Road, line: np.ndarray, p: Params) -> shapely.Geometry:
    """The road's plan-view body with each side as wide as it gets (its widest lane count, in the middle or at
    either end, plus the roadside lanes), :data:`INSET` inside both borders: the two sides of the reference line
    ``line`` buffered apart, so that a narrow side is not drawn as wide as the other."""
    spec, w, mw, rs = road.spec, p.lane_width, p.median_width, roadside_width(p)
    forward = max(spec.lanes.forward, spec.start.forward, spec.end.forward)
    backward = max(spec.lanes.backward, spec.start.backward, spec.end.backward)
    left, right = (backward, forward) if p.traffic_rule is TrafficRule.RHT else (forward, backward)
    ref = shapely.LineString(line)
    left_width = max(side_width(left, spec.lanes.median, w, mw), _splitter_side(road, w))
    sides = [
        shapely.buffer(ref, left_width + rs - INSET, single_sided=True),
        shapely.buffer(ref, -(side_width(right, False, w, mw) + rs - INSET), single_sided=True),
    ]
    return shapely.union_all(sides)


def _splitter_side(road: Road, w: float) -> float:
    """The left side's width (lanes and splitter island) at a roundabout arm's end; 0 on other roads."""
    spec = road.spec
    splitter = max(spec.splitter_start, spec.splitter_end)
    if splitter == 0.0:
        return 0.0
    return max(spec.lanes.forward, spec.lanes.backward, *spec.start, *spec.end) * w + splitter


def _junction_shapes(roads: list[Road], j: Junction, connections: list[Geometry], p: Params) -> list:
    """The junction's area (hull of its legs' end cross-sections, kept 0.5 m inside) and its connection lanes."""
    w, mw = p.lane_width, p.median_width
    rht = p.traffic_rule is TrafficRule.RHT
    corners = []
    for key in j.keys:
        road = roads[key.chain]
        cfg, at = road.spec.lanes, contact(road.geometry, key.at_start)
        left = side_width(cfg.backward if rht else cfg.forward, cfg.median, w, mw) + roadside_width(p)
        right = side_width(cfg.forward if rht else cfg.backward, False, w, mw) + roadside_width(p)
        corners.append(border_point(at.x, at.y, at.hdg, left))
        corners.append(border_point(at.x, at.y, at.hdg, -right))
    shapes = [shapely.MultiPoint(np.array(corners)).convex_hull.buffer(-0.5)]
    side = -1.0 if rht else 1.0  # connection lanes are -1 (RHT) or 1 (LHT): right or left of their reference line
    shapes.extend(body for body in _lane_bodies(connections, side, w) if body is not None)
    return shapes


def _overlapping(
    chs: list[Chain],
    shapes: np.ndarray,
    owners: list[tuple[Part, int]],
    decks: frozenset[frozenset[int]],
    body: Callable[[int], shapely.Geometry],
) -> list[list[int]]:
    """The removal candidates of every pair of shapes sharing area (at least 0.01 m2) where the map does not connect
    their owners; two legs of one junction by their bodies (``body`` of a chain)."""
    left_i, right_i = shapely.STRtree(shapes).query(shapes)  # bounding boxes first
    # the hull and lanes of one junction overlap each other by design: drop those pairs before the exact test
    junction_of = np.array([a if kind is Part.JUNCTION else -1 for kind, a in owners])
    keep = (left_i < right_i) & ((junction_of[left_i] < 0) | (junction_of[left_i] != junction_of[right_i]))
    left_i, right_i = left_i[keep], right_i[keep]
    hit = shapely.intersects(shapes[left_i], shapes[right_i])
    found = []
    for i, j in sorted(zip(left_i[hit].tolist(), right_i[hit].tolist())):
        (ka, x), (kb, y) = owners[i], owners[j]
        cands = _candidates(chs, owners[i], owners[j])
        if ka is kb is Part.ROAD:
            if frozenset((x, y)) in decks:
                continue
            if cands is None:  # legs of one junction: their bodies, not the symmetric buffers, count
                if body(x).intersection(body(y)).area >= 0.01:
                    found.append([x, y])
                continue
        if cands is not None and shapes[i].intersection(shapes[j]).area >= 0.01:
            found.append(cands)
    return found


def _candidates(chs: list[Chain], a: tuple[Part, int], b: tuple[Part, int]) -> list[int] | None:
    """The roads whose removal separates two owners, or None where the map connects them (they may touch)."""
    (ka, x), (kb, y) = a, b
    if ka is Part.ROAD and kb is Part.ROAD:  # sharing an end node: legs of one junction, compared by their bodies
        return None if {chs[x].start, chs[x].end} & {chs[y].start, chs[y].end} else [x, y]
    if ka is Part.JUNCTION and kb is Part.JUNCTION:
        return [c for c, ch in enumerate(chs) if {ch.start, ch.end} & {x, y}]
    road, node = (x, y) if ka is Part.ROAD else (y, x)
    return None if node in (chs[road].start, chs[road].end) else [road]
