"""Traffic through one junction, lane by lane: which leg's lane feeds which other leg's lane, read from the file.

A *flow* is one lane link followed in the direction traffic drives: from a drivable lane of one leg (a road end
touching the junction) that leads into it, to a drivable lane of another leg that leads out, through a connecting
road (common junction) or directly (direct junction, 12.6). Which lanes lead into a junction follows from the traffic
rule: under right-hand traffic right lanes drive along ``s`` (into the junction at the road's end), left lanes
against it (into it at the road's start); left-hand traffic the other way round. A connecting road's lane is followed
from section to section by its lane links to the outside road at its other end. Links between lanes nobody drives on
(kerbs and sidewalks carried round a corner) are not flows.
"""

from __future__ import annotations

from dataclasses import dataclass

from xodrcheck.model import (
    DRIVABLE_LANE_TYPES,
    ContactPoint,
    Document,
    ElementType,
    Junction,
    JunctionType,
    Lane,
    LaneType,
    Road,
    TrafficRule,
)
from xodrcheck.rules.shared.context import travel_direction

#: Lane types of ramps and of the lanes beside a main road that lead to or from them (11.8).
RAMP_TYPES = frozenset({LaneType.OFF_RAMP, LaneType.ON_RAMP, LaneType.CONNECTING_RAMP})
SIDE_TYPES = frozenset({LaneType.EXIT, LaneType.ENTRY, LaneType.MWY_EXIT, LaneType.MWY_ENTRY})


@dataclass(frozen=True, slots=True)
class LaneEnd:
    """A lane of a road at one of its ends."""

    road: str
    end: ContactPoint
    lane: int


@dataclass(frozen=True, slots=True)
class Flow:
    """Traffic from ``source`` (a lane leading into the junction) to ``target`` (a lane leading out), through the
    connecting road ``via`` (None in a direct junction); ``types``: the lane types met, source first."""

    source: LaneEnd
    target: LaneEnd
    via: str | None
    types: tuple[LaneType, ...]


def lane_at(road: Road, end: ContactPoint, lane_id: int) -> Lane | None:
    """Lane ``lane_id`` of the lane section at ``end`` of ``road``."""
    if not road.lane_sections:
        return None
    section = road.lane_sections[0] if end is ContactPoint.START else road.lane_sections[-1]
    return section.lane(lane_id)


def leads_in(road: Road, end: ContactPoint, lane_id: int) -> bool:
    """Whether traffic on lane ``lane_id`` drives towards ``end`` of ``road`` (module docstring): the lane's direction
    of travel (:func:`~xodrcheck.rules.shared.context.travel_direction`: its side, the traffic rule and a 1.8
    ``direction``), and for a lane without one (``both``, a shoulder...) the direction of its side."""
    lane = lane_at(road, end, lane_id)
    direction = None if lane is None else travel_direction(road, lane)
    if direction is None:
        direction = 1 if (lane_id < 0) == (road.rule is not TrafficRule.LHT) else -1
    return (direction > 0) == (end is ContactPoint.END)


def junction_end(road: Road, junction_id: str) -> ContactPoint | None:
    """The end of ``road`` whose link names the junction (``None`` when neither does)."""
    for link, end in ((road.successor, ContactPoint.END), (road.predecessor, ContactPoint.START)):
        if link is not None and link.names(ElementType.JUNCTION, junction_id):
            return end
    return None


def _through(road: Road, start: ContactPoint, lane_id: int) -> tuple[int, list[LaneType]] | None:
    """The id, at the other end, of lane ``lane_id`` entered at ``start`` of ``road`` (followed through its lane
    sections) and the lane types on the way."""
    sections = road.lane_sections if start is ContactPoint.START else road.lane_sections[::-1]
    forward = start is ContactPoint.START
    types: list[LaneType] = []
    lane_now: int | None = lane_id
    for k, section in enumerate(sections):
        lane = section.lane(lane_now) if lane_now is not None else None
        if lane is None:
            return None
        types.append(lane.type)
        if k + 1 < len(sections):
            nxt = lane.successors if forward else lane.predecessors
            lane_now = nxt[0] if nxt else None
    return (lane_now, types) if lane_now is not None else None


def _beyond(document: Document, road: Road, start: ContactPoint, lane_id: int) -> tuple[LaneEnd, list[LaneType]] | None:
    """Where lane ``lane_id`` of connecting road ``road``, entered at ``start``, continues on the outside road."""
    through = _through(road, start, lane_id)
    if through is None:
        return None
    last_id, types = through
    link = road.successor if start is ContactPoint.START else road.predecessor
    if link is None or link.element_type is not ElementType.ROAD or link.contact_point is None:
        return None
    other = document.road_by_id.get(link.element_id)
    end_lane = lane_at(road, ContactPoint.END if start is ContactPoint.START else ContactPoint.START, last_id)
    if other is None or end_lane is None:
        return None
    ids = end_lane.successors if start is ContactPoint.START else end_lane.predecessors
    if not ids:
        return None
    target = lane_at(other, link.contact_point, ids[0])
    if target is None:
        return None
    return LaneEnd(other.id, link.contact_point, ids[0]), [*types, target.type]


def flows(document: Document, junction: Junction) -> list[Flow]:
    """Every flow through ``junction`` that the file describes completely, in connection and lane-link order."""
    return [
        f
        for f in _all_links(document, junction)
        if f.types[0] in DRIVABLE_LANE_TYPES and f.types[-1] in DRIVABLE_LANE_TYPES
    ]


def _all_links(document: Document, junction: Junction) -> list[Flow]:
    roads = document.road_by_id
    out: list[Flow] = []
    for c in junction.connections:
        incoming = roads.get(c.incoming_road) if c.incoming_road is not None else None
        if incoming is None or c.contact_point is None:
            continue
        in_end = junction_end(incoming, junction.id)
        if in_end is None:
            continue
        if junction.type is JunctionType.DIRECT:
            linked = roads.get(c.linked_road) if c.linked_road is not None else None
            if linked is None:
                continue
            for ll in c.lane_links:
                a, b = LaneEnd(incoming.id, in_end, ll.from_lane), LaneEnd(linked.id, c.contact_point, ll.to_lane)
                la, lb = lane_at(incoming, in_end, a.lane), lane_at(linked, b.end, b.lane)
                if la is None or lb is None:
                    continue
                if leads_in(incoming, in_end, a.lane):
                    out.append(Flow(a, b, None, (la.type, lb.type)))
                elif leads_in(linked, b.end, b.lane):
                    out.append(Flow(b, a, None, (lb.type, la.type)))
            continue
        connecting = roads.get(c.connecting_road) if c.connecting_road is not None else None
        if connecting is None:
            continue
        for ll in c.lane_links:
            a = LaneEnd(incoming.id, in_end, ll.from_lane)
            la = lane_at(incoming, in_end, a.lane)
            beyond = _beyond(document, connecting, c.contact_point, ll.to_lane)
            if la is None or beyond is None:
                continue
            b, types = beyond
            if leads_in(incoming, in_end, a.lane):
                out.append(Flow(a, b, connecting.id, (la.type, *types)))
            else:
                out.append(Flow(b, a, connecting.id, (*types[::-1], la.type)))
    return out
