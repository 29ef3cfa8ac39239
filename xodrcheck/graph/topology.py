"""Where traffic leaving a lane goes next, read from the document's links alone.

Past the end of a lane section that traffic leaves by (its end when driving along s, its start when driving against):

* the next lane section of the road: the lanes the lane's own ``successor`` (``predecessor``) names, and those of the
  next section whose link back names it (a link either side states is followed; ``lane-link-not-reciprocal`` reports
  one side's silence);
* at a road's end, the road its link names: the same, in the lane section at the link's contact point (a link back
  from the other lane counts only where the other road links back to this one);
* a junction (default or direct): the lanes its ``laneLink`` elements lead into from this lane. In a default junction
  those of the connections whose incoming road is this road (and whose connecting road starts or ends at this end),
  and the connecting lanes whose own links name this lane (readers that walk lane links follow them; files that list
  a connecting road once, for one of its ends, rely on them); in a direct junction, whose lane links join the roads'
  lanes both ways (12.6), also those of the connections whose linked road is this road. Virtual and crossing
  junctions are not followed;
* nothing: the road ends without a link, an open edge of the map.

Traffic entering a road at one end drives away from it (``direction.entering``); inside a road it keeps its direction.
"""

from __future__ import annotations

from dataclasses import dataclass

from xodrcheck.graph.direction import entering, leaving
from xodrcheck.model import (
    Connection,
    ContactPoint,
    Document,
    ElementType,
    Junction,
    JunctionType,
    Lane,
    Road,
    RoadLink,
)
from xodrcheck.support.quantities import metres

__all__ = ["BROKEN", "JUNCTION", "OPEN", "ROAD", "SECTION", "UNFOLLOWED", "Onward", "Target", "Topology"]

#: What lies past a lane end: the next lane section, a road link, a junction, an open map edge, a link to something
#: that does not exist (or whose contact point cannot be told), a junction the graph does not follow.
SECTION, ROAD, JUNCTION, OPEN, BROKEN, UNFOLLOWED = "section", "road", "junction", "open", "broken", "unfollowed"


@dataclass(frozen=True, slots=True)
class Target:
    """A lane a link leads into: its road, lane-section index and id, and the direction traffic drives on it."""

    road: Road
    index: int
    lane: int
    travel: int


@dataclass(frozen=True, slots=True)
class Onward:
    """What lies past a lane end: the lanes the links name, what kind of place it is (``SECTION``, ``ROAD``...), and,
    when no link names a lane, why in words (``why``)."""

    targets: tuple[Target, ...]
    kind: str
    why: str = ""
    junction: str | None = None


def end_index(road: Road, end: ContactPoint) -> int:
    """The lane section at a road's ``end``."""
    return 0 if end is ContactPoint.START else len(road.lane_sections) - 1


def links_across(lane: Lane, end: ContactPoint) -> tuple[int, ...]:
    """The lane's links across ``end`` of its lane section: predecessors at the start, successors at the end."""
    return lane.predecessors if end is ContactPoint.START else lane.successors


class Topology:
    """The links of one document, indexed for :meth:`onward`."""

    def __init__(self, document: Document) -> None:
        self.roads = document.road_by_id
        self.junctions = document.junction_by_id
        self._incoming: dict[tuple[str, str], list[Connection]] = {}
        self._linked: dict[tuple[str, str], list[Connection]] = {}
        #: road id -> (road inside a junction, its end) whose link there names that road
        self._touching: dict[str, list[tuple[Road, ContactPoint]]] = {}
        for road in document.road_by_id.values():
            if road.junction is None or not road.lane_sections:
                continue
            for end in (ContactPoint.START, ContactPoint.END):
                link = road.link_at(end)
                if link is not None and link.element_type is ElementType.ROAD:
                    self._touching.setdefault(link.element_id, []).append((road, end))
        for junction in document.junctions:
            for c in junction.connections:
                if c.incoming_road is not None:
                    self._incoming.setdefault((junction.id, c.incoming_road), []).append(c)
                if junction.type is JunctionType.DIRECT and c.linked_road is not None:
                    self._linked.setdefault((junction.id, c.linked_road), []).append(c)

    def onward(self, road: Road, index: int, lane: Lane, travel: int) -> Onward:
        """Where traffic driving ``travel`` on ``lane`` (of lane section ``index`` of ``road``) goes past its end."""
        end = leaving(travel)
        last = len(road.lane_sections) - 1
        if (end is ContactPoint.END and index < last) or (end is ContactPoint.START and index > 0):
            return self._next_section(road, index, lane, travel)
        link = road.link_at(end)
        if link is None:
            return Onward((), OPEN, f"road {road.id} has no {_word(end)}: an open edge of the map")
        if link.element_type is ElementType.ROAD:
            return self._road_link(road, end, lane, link)
        junction = self.junctions.get(link.element_id)
        if junction is None:
            return Onward(
                (), BROKEN, f"road {road.id}'s {_word(end)} names junction {link.element_id}, which is missing"
            )
        if junction.type in (JunctionType.VIRTUAL, JunctionType.CROSSING):
            return Onward((), UNFOLLOWED, f"{junction.type.value} junctions are not followed", junction.id)
        if junction.type is JunctionType.DIRECT:
            return self._direct(road, end, lane, junction)
        return self._default(road, end, lane, junction)

    # ------------------------------------------------------------------------------------------------ inside a road
    def _next_section(self, road: Road, index: int, lane: Lane, travel: int) -> Onward:
        end = leaving(travel)
        j = index + 1 if end is ContactPoint.END else index - 1
        other = road.lane_sections[j]
        back_end = ContactPoint.START if end is ContactPoint.END else ContactPoint.END
        ids = dict.fromkeys(links_across(lane, end))
        ids.update((v.id, None) for v in other.lanes if v.id != 0 and lane.id in links_across(v, back_end))
        targets = tuple(Target(road, j, i, travel) for i in ids)
        why = "" if targets else f"lane {lane.id} names no {_word(end)} in the lane section at s={metres(other.s)}"
        return Onward(targets, SECTION, why)

    # ------------------------------------------------------------------------------------------------ road links
    def _road_link(self, road: Road, end: ContactPoint, lane: Lane, link: RoadLink) -> Onward:
        other = self.roads.get(link.element_id)
        if other is None or not other.lane_sections:
            what = "is missing" if other is None else "has no lanes"
            return Onward((), BROKEN, f"road {road.id}'s {_word(end)} names road {link.element_id}, which {what}")
        contact = link.contact_point or _contact_naming(other, ElementType.ROAD, road.id)
        if contact is None:
            return Onward((), BROKEN, f"which end of road {other.id} road {road.id} links to is not known")
        j = end_index(other, contact)
        ids = dict.fromkeys(links_across(lane, end))
        back = other.link_at(contact)
        if back is not None and back.names(ElementType.ROAD, road.id) and back.contact_point in (None, end):
            section = other.lane_sections[j]
            ids.update((v.id, None) for v in section.lanes if v.id != 0 and lane.id in links_across(v, contact))
        targets = tuple(Target(other, j, i, entering(contact)) for i in ids)
        why = (
            "" if targets else f"road {road.id} continues into road {other.id}, but lane {lane.id} names no lane there"
        )
        return Onward(targets, ROAD, why)

    # ------------------------------------------------------------------------------------------------ junctions
    def _default(self, road: Road, end: ContactPoint, lane: Lane, junction: Junction) -> Onward:
        connections = self._incoming.get((junction.id, road.id), [])
        targets: list[Target] = []
        for c in connections:
            other = self.roads.get(c.connecting_road or c.linked_road or "")
            if other is None or not other.lane_sections:
                continue
            contact = _contact(c, other, ElementType.ROAD, road.id)
            if contact is None:
                continue
            back = other.link_at(contact)
            if back is not None and back.names(ElementType.ROAD, road.id) and back.contact_point not in (None, end):
                continue  # the connection leaves from the road's other end
            j = end_index(other, contact)
            targets.extend(
                Target(other, j, ll.to_lane, entering(contact)) for ll in c.lane_links if ll.from_lane == lane.id
            )
        for other, contact in self._touching.get(road.id, ()):  # connecting lanes whose own links name this lane
            back = other.link_at(contact)
            if other.junction != junction.id or back is None or back.contact_point not in (None, end):
                continue
            j = end_index(other, contact)
            targets.extend(
                Target(other, j, v.id, entering(contact))
                for v in other.lane_sections[j].lanes
                if v.id != 0 and lane.id in links_across(v, contact)
            )
        targets = list(dict.fromkeys(targets))
        return Onward(tuple(targets), JUNCTION, _junction_why(junction, road, lane, connections, targets), junction.id)

    def _direct(self, road: Road, end: ContactPoint, lane: Lane, junction: Junction) -> Onward:
        connections = self._incoming.get((junction.id, road.id), [])
        targets: list[Target] = []
        for c in connections:  # this road is the incoming road: its lanes lead into the linked road's
            other = self.roads.get(c.linked_road or c.connecting_road or "")
            if other is None or not other.lane_sections:
                continue
            contact = _contact(c, other, ElementType.JUNCTION, junction.id)
            if contact is None:
                continue
            j = end_index(other, contact)
            targets.extend(
                Target(other, j, ll.to_lane, entering(contact)) for ll in c.lane_links if ll.from_lane == lane.id
            )
        reverse = self._linked.get((junction.id, road.id), [])
        for c in reverse:  # this road is the linked road: the links join its lanes to the incoming road's
            other = self.roads.get(c.incoming_road or "")
            contact = _contact(c, road, ElementType.JUNCTION, junction.id)
            if other is None or not other.lane_sections or contact is not end:
                continue
            other_end = _contact_naming(other, ElementType.JUNCTION, junction.id)
            if other_end is None:
                continue
            j = end_index(other, other_end)
            targets.extend(
                Target(other, j, ll.from_lane, entering(other_end)) for ll in c.lane_links if ll.to_lane == lane.id
            )
        why = _junction_why(junction, road, lane, [*connections, *reverse], targets)
        return Onward(tuple(targets), JUNCTION, why, junction.id)


def _contact(c: Connection, road: Road, kind: ElementType, element_id: str) -> ContactPoint | None:
    """The end of a connection's connecting (or linked) road that touches the junction: its ``contactPoint``, unless
    the road's link there does not name the incoming road (the junction) and its link at the other end does: then
    the links say where it is (``connection-contact-point`` reports the disagreement)."""
    given = c.contact_point
    named = _contact_naming(road, kind, element_id)
    if given is None:
        return named
    link = road.link_at(given)
    if named is not None and (link is None or not link.names(kind, element_id)):
        return named
    return given


def _contact_naming(road: Road, kind: ElementType, element_id: str) -> ContactPoint | None:
    """The end of ``road`` whose link names the element (the start when both do); ``None`` when neither does."""
    ends = road.ends_linked_to(kind, element_id)
    return ends[0] if ends else None


def _junction_why(junction: Junction, road: Road, lane: Lane, connections: list, targets: list) -> str:
    if targets:
        return ""
    if not connections:
        return f"road {road.id} links to junction {junction.id}, but no connection of the junction leads from it"
    if not any(c.lane_links for c in connections):
        return f"the connections of junction {junction.id} from road {road.id} have no laneLink"
    return f"no laneLink of junction {junction.id} leads from lane {lane.id} of road {road.id}"


def _word(end: ContactPoint) -> str:
    return "predecessor" if end is ContactPoint.START else "successor"
