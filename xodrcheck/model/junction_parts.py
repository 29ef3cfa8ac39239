"""The parts of 1.8/1.9 junctions beside connections (chapter 12): a virtual connection's ends, cross paths,
priorities, controllers, road sections, the boundary and its segments, the elevation grid, the junction's reference
line; and junction groups. Read as the file gives them (``None``: absent or not of its type, the schema rule reports
it). A boundary segment's ``sStart``/``sEnd``/``contactPoint`` may be a number or a road end
(``t_grEqZeroOrContactPoint``; the spec's own example writes ``begin`` for the start, read as the start).
"""

from __future__ import annotations

from dataclasses import dataclass

from xodrcheck.model.enums import ContactPoint, ElementDir, ElementType, JunctionGroupType
from xodrcheck.model.facts import XmlFacts, facts_field

__all__ = [
    "Boundary",
    "BoundarySegment",
    "ConnectionEnd",
    "CrossPath",
    "CrossPathLink",
    "ElevationGrid",
    "GridRow",
    "JointSegment",
    "JunctionController",
    "JunctionGeometry",
    "JunctionGroup",
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
    """A boundary ``<segment>`` whose ``type`` is neither ``lane`` nor ``joint`` (``None``: absent), on ``road``."""

    type: str | None
    road: str | None = None
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
