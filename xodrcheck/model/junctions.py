"""Junctions (chapter 12): connections and their lane links, and the parts of 1.8/1.9 junctions - cross paths,
priorities, controllers, road sections, the boundary, the elevation grid, the junction's reference line - and the
file's junction groups.

Connections and lane links, which topology and lane geometry use, are read with findings for what is wrong; the other
parts as the file gives them (``None``: absent or not of its type, the schema rule reports it). A boundary segment's
``sStart``/``sEnd``/``contactPoint`` may be a number or a road end (``t_grEqZeroOrContactPoint``; the spec's own
example writes ``begin`` for the start, read as the start).
"""

from __future__ import annotations

from dataclasses import dataclass

from xodrcheck.model.enums import (
    ConnectionType,
    ContactPoint,
    ElementDir,
    ElementType,
    JunctionGroupType,
    JunctionType,
    LaneLayer,
    Orientation,
)
from xodrcheck.model.facts import XmlFacts, facts_field
from xodrcheck.model.objects import Bridge, ObjectReference, RoadObject, Tunnel
from xodrcheck.model.surface import Surface

__all__ = [
    "Boundary",
    "BoundarySegment",
    "Connection",
    "ConnectionEnd",
    "CrossPath",
    "CrossPathLink",
    "ElevationGrid",
    "GridRow",
    "JointSegment",
    "Junction",
    "JunctionController",
    "JunctionGeometry",
    "JunctionGroup",
    "JunctionLaneLink",
    "JunctionPlanView",
    "JunctionReference",
    "LaneSegment",
    "OtherSegment",
    "Priority",
    "RoadPlace",
    "RoadSection",
]

#: A position along a road: a number (s), or one of its ends.
RoadPlace = float | ContactPoint


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
class ConnectionEnd:
    """A virtual connection's ``<predecessor>`` or ``<successor>`` (12.7.2): the road it joins at ``element_s``
    (``element_type`` ``None``: absent or neither road nor junction)."""

    element_type: ElementType | None
    element_id: str | None
    element_s: float | None = None
    element_dir: ElementDir | None = None
    line: int = 0
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


@dataclass(frozen=True, slots=True)
class CrossPathLink:
    """A cross path's ``<startLaneLink>`` or ``<endLaneLink>``: lane ``from`` of the road at that end, at ``s``, to
    lane ``to`` of the crossing road."""

    s: float | None
    from_lane: int | None
    to_lane: int | None
    line: int = 0
    xml: XmlFacts = facts_field()


@dataclass(frozen=True, slots=True)
class CrossPath:
    """A junction's ``<crossPath>`` (12.5): the crossing road and the roads at its start and end."""

    id: str | None
    crossing_road: str | None
    road_at_start: str | None
    road_at_end: str | None
    start: CrossPathLink | None = None
    end: CrossPathLink | None = None
    line: int = 0
    xml: XmlFacts = facts_field()


@dataclass(frozen=True, slots=True)
class Priority:
    """A junction's ``<priority>`` (12.4.1): the road with the higher and the road with the lower priority."""

    high: str | None
    low: str | None
    line: int = 0
    xml: XmlFacts = facts_field()


@dataclass(frozen=True, slots=True)
class JunctionController:
    """A junction's ``<controller>`` (12.14): a controller of the file that controls it."""

    id: str | None
    type: str | None = None
    sequence: int | None = None
    line: int = 0
    xml: XmlFacts = facts_field()


@dataclass(frozen=True, slots=True)
class RoadSection:
    """A crossing's ``<roadSection>`` (12.8): a road between two s positions."""

    id: str | None
    road: str | None
    s_start: float | None
    s_end: float | None
    line: int = 0
    xml: XmlFacts = facts_field()


@dataclass(frozen=True, slots=True)
class LaneSegment:
    """A boundary ``<segment type="lane">``: along the outer edge of ``lane`` of ``road`` from ``s_start`` to
    ``s_end`` (numbers or road ends)."""

    road: str | None
    lane: int | None
    s_start: RoadPlace | None
    s_end: RoadPlace | None
    line: int = 0
    xml: XmlFacts = facts_field()


@dataclass(frozen=True, slots=True)
class JointSegment:
    """A boundary ``<segment type="joint">``: across ``road`` at its ``contact`` end, from the outer edge of
    ``lane_start`` to that of ``lane_end`` (``None``: the outermost lane, all lanes crossed). ``transition_length``
    is 0 when absent or not positive."""

    road: str | None
    contact: RoadPlace | None
    lane_start: int | None
    lane_end: int | None
    transition_length: float = 0.0
    line: int = 0
    xml: XmlFacts = facts_field()


@dataclass(frozen=True, slots=True)
class OtherSegment:
    """A boundary ``<segment>`` whose ``type`` is neither ``lane`` nor ``joint`` (``None``: absent)."""

    type: str | None
    line: int = 0
    xml: XmlFacts = facts_field()


BoundarySegment = LaneSegment | JointSegment


@dataclass(frozen=True, slots=True)
class Boundary:
    """A junction's ``<boundary>`` (12.10): its segments in file order, and those of no known type."""

    segments: tuple[BoundarySegment, ...] = ()
    unknown: tuple[OtherSegment, ...] = ()
    line: int = 0
    xml: XmlFacts = facts_field()


@dataclass(frozen=True, slots=True)
class GridRow:
    """One ``<elevation>`` of an elevation grid: z on the junction reference line and to its left and right (inside
    out). ``None`` for a list that does not parse; ``()`` for one absent."""

    center: tuple[float, ...] | None
    left: tuple[float, ...] | None
    right: tuple[float, ...] | None
    line: int = 0
    xml: XmlFacts = facts_field()


@dataclass(frozen=True, slots=True)
class ElevationGrid:
    """A junction's ``<elevationGrid>`` (12.11): start, spacing and rows of heights."""

    s_start: float | None
    spacing: float | None
    rows: tuple[GridRow, ...] = ()
    line: int = 0
    xml: XmlFacts = facts_field()


@dataclass(frozen=True, slots=True)
class JunctionGeometry:
    """A ``<geometry>`` of a junction's reference line: its start, heading and length; ``xml.children`` names its
    shape elements (one ``<line>`` is allowed)."""

    s: float | None
    x: float | None
    y: float | None
    hdg: float | None
    length: float | None
    line: int = 0
    xml: XmlFacts = facts_field()

    @property
    def shapes(self) -> tuple[str, ...]:
        """The tags of its child elements (its shapes)."""
        return self.xml.children


@dataclass(frozen=True, slots=True)
class JunctionPlanView:
    """A junction's own ``<planView>`` (12.9, the junction's reference line): its geometries."""

    geometries: tuple[JunctionGeometry, ...] = ()
    line: int = 0
    xml: XmlFacts = facts_field()


@dataclass(frozen=True, slots=True)
class Junction:
    """A ``<junction>``: id, name, type, connections and the junction's other parts. The parts a junction has at most
    once (boundary, elevation grid, reference line) are kept as every element the file gives, in order."""

    id: str
    name: str | None = None
    type: JunctionType = JunctionType.DEFAULT
    connections: tuple[Connection, ...] = ()
    line: int = 0
    #: A virtual junction's ``mainRoad`` (12.7): the road it lies on, which runs through it.
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


@dataclass(frozen=True, slots=True)
class JunctionReference:
    """A junction group's ``<junctionReference>``: a junction of the group."""

    junction: str | None
    line: int = 0
    xml: XmlFacts = facts_field()


@dataclass(frozen=True, slots=True)
class JunctionGroup:
    """A ``<junctionGroup>`` (12.15): junctions that make one larger crossing (a roundabout, say)."""

    id: str | None
    name: str | None = None
    type: JunctionGroupType | None = None
    junctions: tuple[JunctionReference, ...] = ()
    line: int = 0
    xml: XmlFacts = facts_field()
