"""Roads (chapter 10): links, plan view, profiles, lane layers, and the road's other records (:mod:`.road_records`,
:mod:`.surface`), objects and signals.

The reference line, profiles, lanes and links are read with findings for what is wrong (a record that cannot be used
is left out); the road's other records are read as the file gives them (``None``: absent or not of its type, the
schema rule reports it).
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import TYPE_CHECKING

from xodrcheck.model.enums import ContactPoint, ElementDir, ElementType, TrafficRule
from xodrcheck.model.facts import UnreadLink, XmlFacts, facts_field
from xodrcheck.model.lanes import Lanes, LaneSection
from xodrcheck.model.planview import Geometry, Profile

if TYPE_CHECKING:  # pragma: no cover - loaded when a file has them
    from xodrcheck.model.objects import Bridge, ObjectReference, RoadObject, Tunnel
    from xodrcheck.model.road_records import Railroad, RoadType, Shape
    from xodrcheck.model.signals import Signal, SignalReference
    from xodrcheck.model.surface import CrossSectionSurface, Surface

__all__ = ["Road", "RoadLink"]


@dataclass(frozen=True, slots=True)
class RoadLink:
    """A road's ``predecessor`` or ``successor``."""

    element_type: ElementType
    element_id: str
    contact_point: ContactPoint | None = None
    element_s: float | None = None
    element_dir: ElementDir | None = None
    line: int = 0
    xml: XmlFacts = facts_field()

    def names(self, element_type: ElementType, element_id: str | None) -> bool:
        """Whether the link leads to the road or junction ``element_id`` (by ``element_type``)."""
        return self.element_type is element_type and self.element_id == element_id


@dataclass(frozen=True, slots=True)
class Road:
    """A road: reference line (plan view), profiles, lane layers, links, and what stands on it."""

    id: str
    length: float
    junction: str | None = None  # None for "-1" (not inside a junction)
    name: str | None = None
    rule: TrafficRule = TrafficRule.RHT
    predecessor: RoadLink | None = None
    successor: RoadLink | None = None
    plan_view: tuple[Geometry, ...] = ()
    elevation: Profile = ()
    superelevation: Profile = ()
    lane_offset: Profile = ()
    lane_sections: tuple[LaneSection, ...] = ()
    objects: tuple[RoadObject, ...] = ()
    signals: tuple[Signal, ...] = ()
    line: int = 0
    #: The temporary lane layer (1.9); ``lane_offset`` and ``lane_sections`` above are the permanent layer's.
    temporary_lanes: Lanes | None = None
    #: The permanent layer's ``<lanes>`` (the same offset and sections as above; ``None``: the road has none).
    lanes: Lanes | None = None
    types: tuple[RoadType, ...] = ()
    shapes: tuple[Shape, ...] = ()
    cross_section_surface: CrossSectionSurface | None = None
    surface: Surface | None = None
    railroad: Railroad | None = None
    object_references: tuple[ObjectReference, ...] = ()
    tunnels: tuple[Tunnel, ...] = ()
    bridges: tuple[Bridge, ...] = ()
    signal_references: tuple[SignalReference, ...] = ()
    xml: XmlFacts = facts_field()
    #: Links the reader could not read (without elementType or elementId): not links, facts about the file.
    unread_links: tuple[UnreadLink, ...] = ()

    def link_at(self, end: ContactPoint) -> RoadLink | None:
        """The road's link at ``end``: its predecessor at the start, its successor at the end."""
        return self.predecessor if end is ContactPoint.START else self.successor

    def ends_linked_to(self, element_type: ElementType, element_id: str) -> list[ContactPoint]:
        """The road's ends (start first) whose link leads to the road or junction ``element_id``."""
        return [
            end
            for end in (ContactPoint.START, ContactPoint.END)
            if (link := self.link_at(end)) is not None and link.names(element_type, element_id)
        ]

    def section_end(self, index: int) -> float:
        """End s of lane section ``index`` (the next section's start or the road length; earlier when the section
        has a 1.9 ``length``)."""
        sections = self.lane_sections
        end = sections[index + 1].s if index + 1 < len(sections) else self.length
        length = sections[index].length
        return end if length is None else min(end, sections[index].s + length)

    def temporary_layer(self) -> Road | None:
        """The road seen through its temporary lane layer: the same road with the temporary layer's lane offset and
        lane sections (what :class:`xodrcheck.geometry.lanes.RoadGeometry` evaluates); ``None`` without one."""
        layer = self.temporary_lanes
        if layer is None:
            return None
        return replace(
            self, lane_offset=layer.lane_offset, lane_sections=layer.lane_sections, temporary_lanes=None, lanes=layer
        )
