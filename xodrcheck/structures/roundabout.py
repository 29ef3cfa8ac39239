"""The ``roundabout`` kind: a closed ring of one-way roads through junctions where arms join it, read from the file.

A ring is a cycle of one-way roads outside junctions (every driving lane of a road drives the same way), each leading
into the next: through a junction (a flow of :mod:`.flows` from its lane to the next road's lane) or by a road link.
Among them, a *roundabout* is a ring that turns one way all round (its heading changes monotonically by 360 degrees,
junction passages included), is round (form factor ``4 pi area / perimeter^2`` at least :data:`ROUNDNESS`: a circle
1, a square 0.785; and every point of its reference lines within :data:`CIRCLE` of the radius of the least-squares
circle through them, which a stadium-shaped turnaround loop between two carriageways is not), no wider than
:data:`LARGEST` and has at least three arms. This is what SUMO's ``netconvert`` looks for (a loop of one-way edges with
three or more attachments and a form factor over 0.6) and what CARLA's Town03 and the generator's roundabouts are:
ring roads between arm junctions. Its junctions are the ring's junctions.

An *arm* is a road end touching a ring junction that is not part of the ring; one-way arm roads shorter than the
ring's diameter whose far ends meet the same junction (an arm split into an entry and an exit road round a splitter
island, as in Town03) are one arm.

Measures: ``arms``; ``radius``, the outer radius (m) of the circulating carriageway (the mean distance of the ring
roads' outermost driving-lane border from the ring's centre, a least-squares circle through the ring's reference
lines); ``ring_lanes``, driving lanes of the ring roads (the most any ring road has, as a median over them);
``arm_angle``, the smallest angle (degrees) between neighbouring arms' directions out of the ring (each arm's road's
heading where it meets its junction, pointing away; a split arm's two averaged).
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np

from xodrcheck.analysis.metrics import leg_ends
from xodrcheck.geometry.lanes import geometry_of
from xodrcheck.model import ContactPoint, Document, ElementType, Junction, Road

from . import Kind, Measure, Structure
from .flows import flows, leads_in

KIND = Kind(
    "roundabout",
    "a one-way ring round an island, arms joining it at junctions",
    (
        Measure("arms", "", 2.5, 6.5, 4, "arms (roads joining the ring)"),
        Measure("radius", "m", 5.0, 65.0, 24, "outer radius of the circulating carriageway"),
        Measure("ring_lanes", "", 0.5, 4.5, 4, "circulating lanes"),
        Measure("arm_angle", "deg", 0.0, 120.0, 24, "smallest angle between neighbouring arms"),
    ),
)

#: Smallest form factor of a roundabout's ring.
ROUNDNESS = 0.8
#: Largest deviation of a ring's reference lines from their least-squares circle, as a share of its radius.
CIRCLE = 0.2
#: Largest equivalent radius (m) of a roundabout's ring.
LARGEST = 150.0
#: Most roads and junction passages a ring may have.
MOST_PIECES = 48
#: Heading steps (rad) against the ring's sense that still count as turning one way (sampling, straight pieces).
SLACK = 1e-3

#: A one-way road in the direction traffic drives: (road id, end traffic leaves by).
Piece = tuple[str, ContactPoint]


def _one_way(road: Road) -> ContactPoint | None:
    """The end traffic leaves ``road`` by, when every driving lane of it drives the same way; None otherwise."""
    if road.junction is not None:
        return None
    ways = {
        leads_in(road, ContactPoint.END, lane.id)
        for section in road.lane_sections
        for lane in section.lanes
        if lane.id != 0 and lane.drivable
    }
    if len(ways) != 1:
        return None
    return ContactPoint.END if ways.pop() else ContactPoint.START


def _continuations(document: Document, free: Sequence[Junction]) -> dict[str, list[tuple[str, str | None, str]]]:
    """One-way road -> the one-way roads traffic continues on from its exit: (road, junction or None, the piece
    driven in between: a connecting road's id, or '' for a road link)."""
    exits = {r.id: end for r in document.roads if (end := _one_way(r)) is not None}
    if len(exits) < 3:
        return {}
    out: dict[str, list[tuple[str, str | None, str]]] = {r: [] for r in exits}
    roads = document.road_by_id
    touched = {
        link.element_id
        for r in exits
        for link in (roads[r].predecessor, roads[r].successor)
        if link is not None and link.element_type is ElementType.JUNCTION
    }
    for junction in free:
        if junction.id not in touched:
            continue
        for f in flows(document, junction):
            a, b = f.source, f.target
            if exits.get(a.road) is a.end and b.road in exits and exits[b.road] is b.end.opposite and a.road != b.road:
                entry = (b.road, junction.id, f.via or "")
                if entry not in out[a.road]:
                    out[a.road].append(entry)
    for r, end in exits.items():
        link = roads[r].successor if end is ContactPoint.END else roads[r].predecessor
        if (
            link is not None
            and link.element_type is ElementType.ROAD
            and link.element_id in exits
            and link.contact_point is not None
            and exits[link.element_id] is link.contact_point.opposite
        ):
            out[r].append((link.element_id, None, ""))
    return out


def _cycle(start: str, graph: dict[str, list[tuple[str, str | None, str]]]) -> list[tuple[str, str | None, str]]:
    """The shortest cycle of ``graph`` through ``start`` (breadth first): its steps, each (road, junction, piece)
    arriving at the road; empty when there is none within :data:`MOST_PIECES`."""
    back: dict[str, tuple[str, tuple[str, str | None, str]]] = {}
    frontier = [start]
    for _ in range(MOST_PIECES):
        nxt = []
        for road in frontier:
            for step in graph.get(road, ()):
                target = step[0]
                if target == start:
                    path = [step]
                    at = road
                    while at != start:
                        prev, arrived = back[at]
                        path.append(arrived)
                        at = prev
                    return path[::-1]
                if target not in back:
                    back[target] = (road, step)
                    nxt.append(target)
        if not nxt:
            return []
        frontier = nxt
    return []


def _path(document: Document, start: str, steps: list[tuple[str, str | None, str]]) -> tuple[np.ndarray, np.ndarray]:
    """Points and headings along the ring's reference lines in the driving direction: from ``start`` through each
    step's junction passage (its connecting road) and road, back to ``start``."""
    roads = document.road_by_id
    sequence: list[tuple[str, ContactPoint]] = []  # (road, the end traffic leaves it by)
    previous = start
    for road_id, _, via in [(start, None, ""), *steps]:
        if via:
            link = roads[via].predecessor
            entered_at_start = link is not None and link.names(ElementType.ROAD, previous)
            sequence.append((via, ContactPoint.END if entered_at_start else ContactPoint.START))
        leave = _one_way(roads[road_id])
        if leave is not None and (road_id != start or not sequence):
            sequence.append((road_id, leave))
        previous = road_id
    geometries = geometry_of(document)
    pts, hdgs = [], []
    for rid, leave in sequence:
        road = roads[rid]
        pose = geometries[rid].reference(np.linspace(0.0, road.length, max(3, min(200, int(road.length) + 2))))
        xy, h = np.column_stack([pose.x, pose.y]), np.asarray(pose.hdg, dtype=float)
        if leave is ContactPoint.START:
            xy, h = xy[::-1], h[::-1] + math.pi
        pts.append(xy)
        hdgs.append(h)
    return np.concatenate(pts), np.concatenate(hdgs)


def _turning(hdgs: np.ndarray) -> tuple[float, bool]:
    """Total heading change along the ring and whether it turns one way throughout."""
    steps = np.diff(hdgs)
    steps = (steps + math.pi) % (2 * math.pi) - math.pi
    total = float(steps.sum())
    sense = 1.0 if total >= 0 else -1.0
    return total, bool((sense * steps >= -SLACK).all())


def _form_factor(points: np.ndarray) -> float:
    """``4 pi area / perimeter^2`` of the closed polyline ``points`` (shoelace area)."""
    x, y = points[:, 0], points[:, 1]
    area = 0.5 * abs(float(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1))))
    perimeter = float(np.hypot(*(np.roll(points, -1, axis=0) - points).T).sum())
    return 4 * math.pi * area / perimeter**2 if perimeter > 0 else 0.0


def _circular(points: np.ndarray) -> bool:
    """Whether ``points`` lie within :data:`CIRCLE` of a circle no larger than :data:`LARGEST`."""
    centre, radius = _circle(points)
    if not 0.0 < radius <= LARGEST:
        return False
    return bool((np.abs(np.hypot(points[:, 0] - centre[0], points[:, 1] - centre[1]) / radius - 1.0) <= CIRCLE).all())


def _circle(points: np.ndarray) -> tuple[np.ndarray, float]:
    """Least-squares circle (centre, radius) through ``points``."""
    x, y = points[:, 0], points[:, 1]
    a = np.column_stack([x, y, np.ones_like(x)])
    b = x * x + y * y
    (cx2, cy2, c), *_ = np.linalg.lstsq(a, b, rcond=None)
    centre = np.array([cx2 / 2, cy2 / 2])
    return centre, float(math.sqrt(max(c + centre @ centre, 0.0)))


def _arms(
    document: Document, junctions: list[str], ring: set[str], radius: float
) -> list[list[tuple[str, ContactPoint]]]:
    """The ring's arms: road ends touching its junctions outside the ring, an entry and an exit road meeting at one
    junction beyond taken together (module docstring)."""
    roads = document.road_by_id
    by_id = {j.id: j for j in document.junctions}
    ends = [e for j in junctions for e in leg_ends(document, by_id[j]) if e[0] not in ring]
    ends = list(dict.fromkeys(ends))
    group = list(range(len(ends)))

    def find(i: int) -> int:
        while group[i] != i:
            i = group[i]
        return i

    far: dict[str, int] = {}
    for i, (rid, end) in enumerate(ends):
        road = roads[rid]
        link = road.successor if end is ContactPoint.START else road.predecessor
        beyond = link.element_id if link is not None and link.element_type is ElementType.JUNCTION else None
        split = beyond is not None and _one_way(road) is not None and road.length <= 2 * radius
        key = f"junction {beyond}" if split else rid
        if key in far:
            group[find(i)] = find(far[key])
        else:
            far[key] = i
    out: dict[int, list[tuple[str, ContactPoint]]] = {}
    for i, e in enumerate(ends):
        out.setdefault(find(i), []).append(e)
    return list(out.values())


def _measures(document: Document, points: np.ndarray, ring_roads: list[str], arms: list) -> tuple:
    """(arms, radius, ring lanes, arm angle) of a ring whose reference lines pass ``points``."""
    geometries = geometry_of(document)
    roads = document.road_by_id
    centre, _ = _circle(points)
    radii, lanes = [], []
    for rid in ring_roads:
        road, geo = roads[rid], geometries[rid]
        counts = []
        for index, section in enumerate(road.lane_sections):
            driving = [lane.id for lane in section.lanes if lane.id != 0 and lane.drivable]
            counts.append(len(driving))
            s0, s1 = section.s, road.section_end(index)
            if not driving or s1 - s0 <= 1e-6:
                continue
            s = np.linspace(s0, s1, max(3, min(100, int(s1 - s0) + 2)))
            far = max(
                (geo.lane_points(index, lid, s, where="outer") for lid in driving), key=lambda p: _reach(p, centre)
            )
            radii.append(_reach(far, centre))
        lanes.append(max(counts, default=0))
    angles = []
    for arm in arms:  # each arm's direction out of the ring: its reference line's, averaged over a split arm's two
        out = np.zeros(2)
        for rid, end in arm:
            at = 0.0 if end is ContactPoint.START else roads[rid].length
            hdg = float(geometries[rid].reference(np.array([at])).hdg[0]) + (
                0.0 if end is ContactPoint.START else math.pi
            )
            out += (math.cos(hdg), math.sin(hdg))
        angles.append(math.atan2(float(out[1]), float(out[0])))
    order = np.sort(np.degrees(np.asarray(angles)) % 360.0)
    gaps = np.diff(np.append(order, order[0] + 360.0)) if len(order) > 1 else np.array([math.nan])
    radius = float(np.median(radii)) if radii else math.nan
    return float(len(arms)), radius, float(np.median(lanes)) if lanes else math.nan, float(gaps.min())


def _reach(points, centre: np.ndarray) -> float:
    return float(np.hypot(np.asarray(points.x) - centre[0], np.asarray(points.y) - centre[1]).mean())


def recognise(document: Document, free: Sequence[Junction]) -> list[Structure]:
    graph = _continuations(document, free)
    out: list[Structure] = []
    used: set[str] = set()
    order = {j.id: k for k, j in enumerate(document.junctions)}
    for start in sorted(graph):
        if start in used:
            continue
        steps = _cycle(start, graph)
        junctions = [j for _, j, _ in steps if j is not None]
        ring = {start, *(road for road, _, _ in steps)}
        if len(junctions) < 3 or ring & used or len(set(junctions)) != len(junctions):
            continue
        points, hdgs = _path(document, start, steps)
        total, one_way = _turning(hdgs)
        if not one_way or abs(abs(total) - 2 * math.pi) > 0.2 or _form_factor(points) < ROUNDNESS:
            continue
        if not _circular(points):
            continue
        arms = _arms(document, junctions, ring, _circle(points)[1])
        if len(arms) < 3:
            continue
        values = _measures(document, points, sorted(ring), arms)
        used |= ring
        names = KIND.names
        ids = tuple(sorted(junctions, key=lambda j: order[j]))
        out.append(Structure(KIND.name, ids, tuple(zip(names, values))))
    return out
