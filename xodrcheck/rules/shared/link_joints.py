"""Joints for the contact rules (``K1xx``, :mod:`xodrcheck.rules.link`): which road ends touch, which lanes are linked
across them, where linked lanes touch, how far the surfaces step in height there, and how a finding at a joint names
its place and its junction rule.

A *joint* is a pair of road ends that touch: a road link between two roads, or, in a junction, an incoming road's end
and a connection's connecting (or linked) road at the connection's contact point (:meth:`Context.neighbours`).
"""

from __future__ import annotations

import math
from collections.abc import Iterator
from dataclasses import dataclass, field

from xodrcheck.findings import Severity
from xodrcheck.model import ContactPoint, ElementType, JunctionType, Road
from xodrcheck.rules.registry import NO_UID
from xodrcheck.rules.shared import junction_uids as JU
from xodrcheck.rules.shared.context import Context, Neighbour
from xodrcheck.rules.shared.road_ends import EndPoint, RoadEnd, end_s, reference_end, road_end


def joints(ctx: Context, once: bool = True) -> Iterator[tuple[Road, ContactPoint, Neighbour]]:
    """Pairs of touching road ends (road, its end, the neighbour at the other end): each pair once, or with ``once``
    false once per way it is declared (a road link, and each junction connection)."""
    seen: set[tuple] = set()
    for road in ctx.document.roads:
        if ctx.usable_geometry(road) is None:
            continue
        for end in (ContactPoint.START, ContactPoint.END):
            for neighbour in ctx.neighbours(road, end):
                if ctx.usable_geometry(neighbour.road) is None:
                    continue
                pair = frozenset({(road.id, end), (neighbour.road.id, neighbour.contact)})
                key = (pair, None if once or neighbour.connection is None else neighbour.connection.id)
                if len(pair) < 2 or key in seen:
                    continue
                seen.add(key)
                yield road, end, neighbour


def location(road: Road, end: ContactPoint, point: EndPoint, line: int, lane: int | None = None) -> dict:
    """The location fields of a finding at ``road``'s ``end`` (its end section), at ``point``."""
    index = 0 if end is ContactPoint.START else len(road.lane_sections) - 1
    return {
        "road": road.id,
        "lane": lane,
        "section_s": road.lane_sections[index].s,
        "s": end_s(road, end),
        "x": point.x,
        "y": point.y,
        "z": point.z if math.isfinite(point.z) else None,
        "line": line or road.line or None,
    }


def joint_line(road: Road, end: ContactPoint, neighbour: Neighbour) -> int:
    """The source line that declares the joint: the junction connection's, else the road link's (0: none)."""
    if neighbour.connection is not None:
        return neighbour.connection.line
    link = road.link_at(end)
    return link.line if link is not None else 0


def describe_joint(road: Road, end: ContactPoint, neighbour: Neighbour) -> str:
    """The joint in words, for a finding's message."""
    junction, connection = neighbour.junction, neighbour.connection
    via = f" (junction {junction.id}, connection {connection.id})" if connection and junction else ""
    return f"the {end.value} of road {road.id} and the {neighbour.contact.value} of road {neighbour.road.id}{via}"


def junction_uid(
    ctx: Context, road: Road, neighbour: Neighbour, severity: Severity | None, direct: str = JU.DIRECT_SMOOTH
) -> str:
    """The junction rule an error at a junction joint enforces: the linked lanes of a common junction's connection
    (from the incoming road into the connecting road, and from the connecting road on) fit smoothly
    (``junctions.connection.smooth_fit``), those of a direct junction too (``direct``); other road links and warnings
    name none."""
    junction = neighbour.junction or ctx.junction_of(road) or ctx.junction_of(neighbour.road)
    if severity is not Severity.ERROR or junction is None:
        return NO_UID
    if junction.type is JunctionType.DIRECT:
        return direct
    return JU.CONNECTION_SMOOTH_FIT if junction.type is JunctionType.DEFAULT else NO_UID


def in_junction(ctx: Context, road: Road) -> bool:
    """Whether ``road`` belongs to a junction the file has."""
    return road.junction is not None and ctx.junction(road.junction) is not None


def lane_pairs(road: Road, end: ContactPoint, neighbour: Neighbour) -> list[tuple[int, int, int]]:
    """(lane of ``road``, lane of the neighbour, source line) for every lane link across the joint."""
    if neighbour.connection is not None:
        connection = neighbour.connection
        if connection.incoming_road == road.id:
            return [(ll.from_lane, ll.to_lane, ll.line) for ll in connection.lane_links]
        return [(ll.to_lane, ll.from_lane, ll.line) for ll in connection.lane_links]
    pairs: dict[tuple[int, int], int] = {}
    index = 0 if end is ContactPoint.START else len(road.lane_sections) - 1
    for lane in road.lane_sections[index].lanes:
        for other in lane.predecessors if end is ContactPoint.START else lane.successors:
            pairs.setdefault((lane.id, other), lane.line)
    back = neighbour.road.link_at(neighbour.contact)
    if back is not None and back.names(ElementType.ROAD, road.id):
        other_index = 0 if neighbour.contact is ContactPoint.START else len(neighbour.road.lane_sections) - 1
        for lane in neighbour.road.lane_sections[other_index].lanes:
            links = lane.predecessors if neighbour.contact is ContactPoint.START else lane.successors
            for mine in links:
                pairs.setdefault((mine, lane.id), lane.line)
    return [(a, b, line) for (a, b), line in pairs.items() if a != 0 and b != 0]


def _plan_distance(p: EndPoint, q: EndPoint) -> float:
    return math.hypot(p.x - q.x, p.y - q.y)


def touching(mine: RoadEnd, lane: int, theirs: RoadEnd, other: int) -> tuple[tuple[EndPoint, EndPoint], ...] | None:
    """The touching points of two linked lanes (ASAM OpenDRIVE Annex D.1.1) as two pairs: each edge of ``lane`` (inner,
    outer; raised by lane height) with the edge of ``other`` it meets, in the order that fits best in plan view (a
    start-to-start link meets inner with outer). ``None`` when a lane is not there."""
    inner_a, outer_a = mine.edge(lane, "inner"), mine.edge(lane, "outer")
    inner_b, outer_b = theirs.edge(other, "inner"), theirs.edge(other, "outer")
    if inner_a is None or outer_a is None or inner_b is None or outer_b is None:
        return None
    straight = ((inner_a, inner_b), (outer_a, outer_b))
    crossed = ((inner_a, outer_b), (outer_a, inner_b))
    return min(straight, crossed, key=lambda pairs: max(_plan_distance(p, q) for p, q in pairs))


def border_gap(mine: RoadEnd, lane: int, theirs: RoadEnd, other: int) -> tuple[float, EndPoint] | None:
    """The larger plan-view distance of the two linked lanes' touching points, and ``lane``'s outer edge point."""
    pairs = touching(mine, lane, theirs, other)
    if pairs is None:
        return None
    return max(_plan_distance(p, q) for p, q in pairs), pairs[1][0]


@dataclass
class Step:
    """The largest height difference found at one joint, and how many contacts there step."""

    road: Road
    end: ContactPoint
    neighbour: Neighbour
    size: float = 0.0
    lane: int | None = None
    other: int | None = None
    points: tuple[EndPoint, EndPoint] | None = None
    line: int = 0
    lanes: set[tuple[int, int]] = field(default_factory=set)

    def add(self, dz: float, pair: tuple[EndPoint, EndPoint], lanes: tuple[int, int] | None, line: int, tol: float):
        if not dz > tol:  # NaN (a damaged elevation) too
            return
        if lanes is not None:
            self.lanes.add(lanes)
        if dz > self.size:
            self.size, self.points, self.line = dz, pair, line
            self.lane, self.other = lanes if lanes is not None else (None, None)


def height_steps(ctx: Context, tol: float) -> Iterator[Step]:
    """Per joint (pair of touching road ends), the height differences above ``tol`` between the reference lines (road
    links outside junctions) and between the touching points of every pair of linked lanes."""
    steps: dict[frozenset, Step] = {}
    for road, end, neighbour in joints(ctx, once=False):
        key = frozenset({(road.id, end), (neighbour.road.id, neighbour.contact)})
        step = steps.get(key)
        if step is None:
            step = steps[key] = Step(road, end, neighbour)
            if neighbour.connection is None and not in_junction(ctx, road) and not in_junction(ctx, neighbour.road):
                here = reference_end(ctx, road, end)
                there = reference_end(ctx, neighbour.road, neighbour.contact)
                if here is not None and there is not None:
                    line = joint_line(road, end, neighbour)
                    step.add(abs(here.z - there.z), (here, there), None, line, tol)
        mine, theirs = road_end(ctx, road, end), road_end(ctx, neighbour.road, neighbour.contact)
        flipped = step.road is not road  # the joint seen from its other road: keep the first road's view
        for lane, other, line in lane_pairs(road, end, neighbour):
            pairs = touching(mine, lane, theirs, other)
            if pairs is None:
                continue
            for p, q in pairs:
                pair, lanes = ((q, p), (other, lane)) if flipped else ((p, q), (lane, other))
                step.add(abs(p.z - q.z), pair, lanes, line or joint_line(road, end, neighbour), tol)
    yield from (step for step in steps.values() if step.points is not None)
