"""Fixes of junction connections (``J002``, ``R012``): a ``contactPoint`` at the wrong end of the connecting road or
missing, and a ``laneLink`` naming a lane the road does not have where the lane meant is plain from the geometry."""

from __future__ import annotations

import math
from collections.abc import Callable, Iterator
from functools import partial

from xodrcheck.findings import Finding
from xodrcheck.fix import places
from xodrcheck.fix.edits import Edit, set_attribute
from xodrcheck.fix.registry import Repair, Skip, fixer
from xodrcheck.fix.workspace import Workspace
from xodrcheck.fix.xmltext import Element
from xodrcheck.model import Connection, ContactPoint, ElementType, Junction, JunctionLaneLink, JunctionType, Road

#: How far along the road (m) a point may lie from a road's end and still be at that end (lanes are matched across
#: the road; this only tells the ends that meet from the far end).
_AT_END = 0.5


def connection_at(ws: Workspace, finding: Finding) -> tuple[Junction, Connection] | None:
    """The connection a finding points at (by its line; the finding's road is one of the connection's)."""
    for junction in ws.document.junctions:
        for c in junction.connections:
            roads = (c.incoming_road, c.connecting_road, c.linked_road)
            if finding.line and finding.line in (c.line, *(ll.line for ll in c.lane_links)) and finding.road in roads:
                return junction, c
    return None


def _nearer_end(ws: Workspace, road: Road, incoming: Road, incoming_end: ContactPoint) -> ContactPoint | None:
    """The end of ``road`` that lies at the incoming road's junction end: within the roads' width of it, and nearer
    than the other end by at least the ``gap`` tolerance (``None`` when the geometry does not tell)."""
    there = places.end_pose(ws, incoming, incoming_end)
    ends = {end: places.end_pose(ws, road, end) for end in (ContactPoint.START, ContactPoint.END)}
    if there is None or any(p is None for p in ends.values()):
        return None
    distance = {end: math.hypot(p[0] - there[0], p[1] - there[1]) for end, p in ends.items() if p is not None}
    near = min(distance, key=lambda end: distance[end])
    far = distance[near.opposite]
    width = max(places.width_at(ws, road, near), places.width_at(ws, incoming, incoming_end), ws.tolerances.gap)
    return near if distance[near] <= width and far >= distance[near] + ws.tolerances.gap else None


@fixer("J002", "set-connection-contact-point", safe=True, bound="moves nothing")
def set_connection_contact_point(ws: Workspace, findings: list[Finding]) -> Iterator[Repair | Skip]:
    """Sets a default junction connection's ``contactPoint`` to the end of the connecting road that meets the
    incoming road, where it names the other end or none.

    The end must be told twice: the connecting road's own link at that end names the incoming road, and the
    geometry puts that end at the incoming road's junction end (the other end clearly farther). Then the connection
    describes the path the roads already make; nothing moves.
    """
    for finding in findings:
        found = connection_at(ws, finding)
        if found is None:
            continue
        junction, c = found
        incoming, target = ws.road(c.incoming_road), ws.road(c.connecting_road)
        if junction.type is not JunctionType.DEFAULT or incoming is None or target is None:
            yield Skip(finding, "only connections of default junctions with both roads present are fixed")
            continue
        linked = target.ends_linked_to(ElementType.ROAD, incoming.id)
        ends = incoming.ends_linked_to(ElementType.JUNCTION, junction.id)
        if len(linked) != 1 or len(ends) != 1 or linked[0] is c.contact_point:
            yield Skip(finding, f"road {target.id}'s links do not tell which of its ends meets road {incoming.id}")
            continue
        if _nearer_end(ws, target, incoming, ends[0]) is not linked[0]:
            yield Skip(
                finding,
                f"the geometry does not confirm that road {target.id}'s {linked[0].value} meets road {incoming.id}",
            )
            continue
        element = ws.connection_element(junction, c)
        if element is None:
            yield Skip(finding, "the <connection> is not found in the file")
            continue
        was = c.contact_point.value if c.contact_point is not None else "none"
        yield Repair(
            (finding,),
            (set_attribute(ws.text, element, "contactPoint", linked[0].value),),
            f"junction {junction.id} connection {c.id}: contactPoint {was} -> {linked[0].value}",
            scope=(element.start, element.end),
        )


def lane_link_at(c: Connection, finding: Finding) -> JunctionLaneLink | None:
    found = [ll for ll in c.lane_links if ll.line == finding.line]
    return found[0] if len(found) == 1 else None


def lane_link_repair(
    ws: Workspace,
    finding: Finding,
    where: tuple[Junction, Connection, JunctionLaneLink],
    edits: Callable[[Element], tuple[Edit, ...]],
    action: str,
) -> Repair | Skip:
    """The repair of a finding on one junction ``laneLink``: ``edits`` of its element, said as ``action`` after the
    junction and connection; a skip where the element is not found in the file."""
    junction, c, ll = where
    element = ws.lane_link_element(junction, c, ll)
    if element is None:
        return Skip(finding, "the <laneLink> is not found in the file")
    return Repair((finding,), edits(element), f"junction {junction.id} connection {c.id}: {action}")


@fixer("R012", "correct-junction-lane-link", safe=True, bound="moves nothing")
def correct_junction_lane_link(ws: Workspace, findings: list[Finding]) -> Iterator[Repair | Skip]:
    """Corrects a junction ``laneLink`` whose ``from`` (``to``) names a lane the incoming (connecting) road does not
    have at the junction, to the one lane there that holds the other lane's centre.

    The other end of the link is a lane that exists; its centre point at the joint must lie inside exactly one lane of
    this road's end (not within a millimetre of a border), and the link so made must not be there already. That lane
    is the one the connection's author meant. Where no lane holds it but ``from`` and ``to`` read the other way round
    name two lanes that meet there, the two are swapped. Nothing moves.
    """
    for finding in findings:
        found = connection_at(ws, finding)
        if found is None:
            continue
        junction, c = found
        ll = lane_link_at(c, finding)
        incoming, target = ws.road(c.incoming_road), ws.road(c.connecting_road or c.linked_road)
        ends = incoming.ends_linked_to(ElementType.JUNCTION, junction.id) if incoming is not None else []
        if ll is None or incoming is None or target is None or c.contact_point is None or len(ends) != 1:
            yield Skip(finding, "the laneLink, its roads or their ends at the junction are not plain")
            continue
        fix_to = finding.road == target.id and finding.lane == ll.to_lane
        if fix_to:
            known, wrong = (incoming, ends[0], ll.from_lane), (target, c.contact_point, "to")
        elif finding.road == incoming.id and finding.lane == ll.from_lane:
            known, wrong = (target, c.contact_point, ll.to_lane), (incoming, ends[0], "from")
        else:
            continue
        road, end, attribute = wrong
        held = _holding(ws, known, road, end)
        swapped = _swapped(ws, c, ll, incoming, ends[0], target)
        if held is not None:
            new = (ll.from_lane, held) if fix_to else (held, ll.to_lane)
            changes = {attribute: held}
        elif swapped:
            new, changes = (ll.to_lane, ll.from_lane), {"from": ll.to_lane, "to": ll.from_lane}
        else:
            yield Skip(finding, f"no single lane of road {road.id} holds lane {known[2]}'s centre at the joint")
            continue
        if any((other.from_lane, other.to_lane) == new for other in c.lane_links):
            yield Skip(finding, f"the connection links lane {new[0]} to lane {new[1]} already")
            continue
        yield lane_link_repair(
            ws,
            finding,
            (junction, c, ll),
            partial(_set_all, ws, changes),
            f"laneLink from {ll.from_lane} to {ll.to_lane} -> from {new[0]} to {new[1]}",
        )


def _set_all(ws: Workspace, changes: dict[str, int], element: Element) -> tuple[Edit, ...]:
    return tuple(set_attribute(ws.text, element, name, str(value)) for name, value in changes.items())


def _centre(ws: Workspace, road: Road, end: ContactPoint, lane_id: int) -> tuple[float, float] | None:
    side = places.side_at(road, end)
    return None if side is None else places.lane_centre(ws, road, side[0], side[1], lane_id)


def _held(ws: Workspace, road: Road, end: ContactPoint, point: tuple[float, float] | None) -> list[int] | None:
    side = places.side_at(road, end)
    if side is None or point is None:
        return None
    return places.lanes_holding(ws, road, side[0], side[1], point, _AT_END)


def _holding(ws: Workspace, known: tuple[Road, ContactPoint, int], road: Road, end: ContactPoint) -> int | None:
    """The one lane of ``road`` at ``end`` that holds the centre of the known lane at the joint, if there is one."""
    held = _held(ws, road, end, _centre(ws, *known))
    return held[0] if held is not None and len(held) == 1 else None


def _swapped(
    ws: Workspace, c: Connection, ll: JunctionLaneLink, incoming: Road, in_end: ContactPoint, target: Road
) -> bool:
    """Whether ``from`` and ``to`` read the other way round name two lanes that exist and meet at the joint."""
    assert c.contact_point is not None
    here = _centre(ws, incoming, in_end, ll.to_lane)
    if _centre(ws, target, c.contact_point, ll.from_lane) is None or here is None:
        return False
    return _held(ws, target, c.contact_point, here) == [ll.from_lane]
