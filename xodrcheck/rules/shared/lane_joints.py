"""Joints between lane sections: where the lanes of one lane section end and those of another begin.

A *joint* is between two lane sections of a road, or at a road link between two roads. Seen from one side, a joint
is (this road, section, end) touching (the other road, section, end); lane links at that end (``predecessor`` at a
start, ``successor`` at an end) name lanes of the other side. Joints into a junction are the junction's (its
``laneLink`` elements, see :mod:`xodrcheck.rules.junction`); a connecting road's own links to the roads it joins are
joints like any other. The lane-link rules of :mod:`.lane`, :mod:`.lane_attributes` and :mod:`.lane_links` walk them.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator
from dataclasses import dataclass

from xodrcheck.model import ContactPoint, ElementType, Lane, LaneSection, Road
from xodrcheck.rules.shared.context import Context, travel_direction
from xodrcheck.support.quantities import metres

#: The lane link that crosses each end: ``predecessor`` at a start, ``successor`` at an end.
WORD = {ContactPoint.START: "predecessor", ContactPoint.END: "successor"}


@dataclass(frozen=True, slots=True)
class Side:
    """One side of a joint: a lane section of a road, at its start or end."""

    road: Road
    index: int
    end: ContactPoint

    @property
    def section(self) -> LaneSection:
        return self.road.lane_sections[self.index]

    @property
    def s(self) -> float:
        return self.section.s if self.end is ContactPoint.START else self.road.section_end(self.index)

    def links(self, lane: Lane) -> tuple[int, ...]:
        """The lane's links across this end."""
        return lane.predecessors if self.end is ContactPoint.START else lane.successors

    def describe(self) -> str:
        return f"road {self.road.id} lane section s={metres(self.section.s)}"

    def where(self, lane_id: int) -> dict:
        return {"road": self.road.id, "lane": lane_id, "section_s": self.section.s, "s": self.s}


@dataclass(frozen=True, slots=True)
class Joint:
    """Where a lane meets another across a lane-section boundary or a road link: both sides and whether the links
    agree."""

    mine: Side
    other: Side
    #: Whether the other side's links at this joint point back here (always inside a road; at a road link when the
    #: other road links back to this one).
    mutual: bool

    @property
    def same_orientation(self) -> bool:
        """Whether the two sides' s run the same way through the joint (an end meeting a start)."""
        return self.mine.end is not self.other.end


def joints(ctx: Context) -> Iterator[Joint]:
    """Every joint, once from each side that has lanes."""
    for road in ctx.document.roads:
        sections = road.lane_sections
        for i in range(len(sections) - 1):
            yield Joint(Side(road, i, ContactPoint.END), Side(road, i + 1, ContactPoint.START), True)
            yield Joint(Side(road, i + 1, ContactPoint.START), Side(road, i, ContactPoint.END), True)
        if not sections:
            continue
        for end in (ContactPoint.START, ContactPoint.END):
            link = road.link_at(end)
            if link is None or link.element_type is not ElementType.ROAD or link.contact_point is None:
                continue
            target = ctx.road(link.element_id)
            if target is None or not target.lane_sections:
                continue
            back = target.link_at(link.contact_point)
            mutual = back is not None and back.names(ElementType.ROAD, road.id)
            index, target_index = ctx.section_index_at(road, end), ctx.section_index_at(target, link.contact_point)
            if index is None or target_index is None:  # both roads have lane sections (checked above)
                continue
            yield Joint(Side(road, index, end), Side(target, target_index, link.contact_point), mutual)


def side_lanes(section: LaneSection) -> tuple[Lane, ...]:
    return tuple(lane for lane in section.lanes if lane.id != 0)


def pair_key(a: Side, a_id: int, b: Side, b_id: int) -> frozenset:
    return frozenset({(a.road.id, a.index, a.end, a_id), (b.road.id, b.index, b.end, b_id)})


def linked_lane_pairs(ctx: Context, keep: Callable[[Joint, Lane, Lane], bool]) -> Iterator[tuple[Joint, Lane, Lane]]:
    """Each pair of lanes a lane link joins across a joint, where ``keep(joint, lane, target)`` holds: once for the
    pair (seen from the first side whose link ``keep`` takes), however many sides name the link."""
    seen: set = set()
    for joint in joints(ctx):
        mine, other = joint.mine, joint.other
        for lane in side_lanes(mine.section):
            for target_id in mine.links(lane):
                target = other.section.lane(target_id)
                if target is None or not keep(joint, lane, target):
                    continue
                key = pair_key(mine, lane.id, other, target_id)
                if key in seen:
                    continue
                seen.add(key)
                yield joint, lane, target


def opposed(road: Road, lane: Lane, other_road: Road, other: Lane, same_orientation: bool) -> bool:
    """Whether a link joins lanes whose traffic runs opposite ways through the joint (``lane-link-direction``): the
    link names a lane on the wrong side of lane 0 (or the wrong contact point), and the other link rules leave that
    link to it, one finding for one cause. Lanes without one direction of traffic are never opposed."""
    a, b = travel_direction(road, lane), travel_direction(other_road, other)
    return a is not None and b is not None and (a == b) != same_orientation
