"""Junctions (chapter 12): connections and their lane links, read with findings for what is wrong (topology and
lane geometry use them), and the junction's other parts (:mod:`.junction_parts`)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

from xodrcheck.model.enums import ConnectionType, ContactPoint, JunctionType, LaneLayer, Orientation
from xodrcheck.model.facts import XmlFacts, facts_field

if TYPE_CHECKING:  # pragma: no cover - loaded when a file has them
    from xodrcheck.model.junction_parts import (
        Boundary,
        ConnectionEnd,
        CrossPath,
        ElevationGrid,
        JunctionController,
        JunctionPlanView,
        Priority,
        RoadSection,
    )
    from xodrcheck.model.objects import Bridge, ObjectReference, RoadObject, Tunnel
    from xodrcheck.model.surface import Surface

__all__ = ["Connection", "Junction", "JunctionLaneLink"]


@dataclass(frozen=True, slots=True)
class JunctionLaneLink:
    """A ``<laneLink>`` of a junction connection: the incoming lane and the connecting (or linked) lane."""

    from_lane: int
    to_lane: int
    line: int = 0
    #: 1.9 ``fromLayer``/``toLayer`` (12.4): the layers of the incoming and of the connecting (or linked) lane.
    from_layer: LaneLayer = LaneLayer.PERMANENT
    to_layer: LaneLayer = LaneLayer.PERMANENT
    #: A direct junction's ``overlapZone`` (1.8, 12.6.2; ``None``: absent or not a number).
    overlap_zone: float | None = None
    xml: XmlFacts = facts_field()


@dataclass(frozen=True, slots=True)
class Connection:
    """A junction's ``<connection>``: the incoming road, the connecting (or linked) road, the contact point and lane
    links."""

    id: str
    incoming_road: str | None
    connecting_road: str | None = None  # default junctions
    linked_road: str | None = None  # direct junctions (1.7+)
    contact_point: ContactPoint | None = None
    lane_links: tuple[JunctionLaneLink, ...] = ()  # between lanes of the permanent layer (every link before 1.9)
    line: int = 0
    #: 1.9 links with an end on a temporary lane layer (``fromLayer`` or ``toLayer="temporary"``)
    temporary_lane_links: tuple[JunctionLaneLink, ...] = ()
    #: ``@type`` (1.7+; ``None``: absent, a regular connection, or not a connection type).
    type: ConnectionType | None = None
    predecessor: ConnectionEnd | None = None
    successor: ConnectionEnd | None = None
    xml: XmlFacts = facts_field()

    @property
    def all_lane_links(self) -> tuple[JunctionLaneLink, ...]:
        """The lane links of both lane layers, in file order."""
        if not self.temporary_lane_links:
            return self.lane_links
        return tuple(sorted(self.lane_links + self.temporary_lane_links, key=lambda link: link.line))


@dataclass(frozen=True, slots=True)
class Junction:
    """A ``<junction>``: id, name, type, connections and the junction's other parts. The parts a junction has at most
    once (boundary, elevation grid, reference line) are kept as every element the file gives, in order."""

    id: str
    name: str | None = None
    type: JunctionType = JunctionType.DEFAULT
    connections: tuple[Connection, ...] = ()
    line: int = 0
    #: ``mainRoad`` as the file gives it: a virtual junction's main road (12.7), which runs through it (another type
    #: has none: the schema reports one given there).
    main_road: str | None = None
    #: The roads a crossing's ``<roadSection>`` elements name (12.8): they cross each other in it.
    crossing_roads: tuple[str, ...] = ()
    #: A virtual junction's range on its main road and its orientation, as given on any junction (``None``: absent
    #: or not of its type).
    s_start: float | None = None
    s_end: float | None = None
    orientation: Orientation | None = None
    cross_paths: tuple[CrossPath, ...] = ()
    priorities: tuple[Priority, ...] = ()
    controllers: tuple[JunctionController, ...] = ()
    road_sections: tuple[RoadSection, ...] = ()
    boundaries: tuple[Boundary, ...] = ()
    grids: tuple[ElevationGrid, ...] = ()
    plan_views: tuple[JunctionPlanView, ...] = ()
    surface: Surface | None = None
    objects: tuple[RoadObject, ...] = ()
    object_references: tuple[ObjectReference, ...] = ()
    tunnels: tuple[Tunnel, ...] = ()
    bridges: tuple[Bridge, ...] = ()
    xml: XmlFacts = facts_field()

    @property
    def incoming_roads(self) -> tuple[str, ...]:
        """Distinct incoming road ids in order of first appearance (the junction's legs)."""
        seen: dict[str, None] = {}
        for c in self.connections:
            if c.incoming_road is not None:
                seen.setdefault(c.incoming_road, None)
        return tuple(seen)

    @property
    def boundary(self) -> Boundary | None:
        return self.boundaries[0] if self.boundaries else None

    @property
    def grid(self) -> ElevationGrid | None:
        return self.grids[0] if self.grids else None

    @property
    def plan_view(self) -> JunctionPlanView | None:
        return self.plan_views[0] if self.plan_views else None
