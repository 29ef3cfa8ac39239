"""Lanes (chapter 11): a road's lane layers, their lane sections, the lanes and every record a lane holds.

Records inside a lane keep ``s`` = their ``sOffset`` (relative to the lane section's start). The records the geometry
needs (width, border, height) and the lane's identity and links are read with findings for what is wrong; the others
(access, material, rule, visibility, the road mark's details, the 1.8 attributes) are read as the file gives them:
``None`` for a value that is absent or not of its type (:attr:`XmlFacts.invalid <xodrcheck.model.facts.XmlFacts>`
keeps its text), the schema rule reports them.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

from xodrcheck.model.enums import DRIVABLE_LANE_TYPES, LaneAdvisory, LaneDirection, LaneLayer, LaneType, Side
from xodrcheck.model.facts import XmlFacts, facts_field
from xodrcheck.model.planview import Profile

if TYPE_CHECKING:  # pragma: no cover - loaded when a file has them
    from xodrcheck.model.lane_records import (
        LaneAccess,
        LaneMaterial,
        LaneRule,
        LaneVisibility,
        RoadMarkExplicit,
        RoadMarkSway,
        RoadMarkType,
    )

__all__ = ["Lane", "LaneHeight", "LaneKey", "LaneLinks", "LaneSection", "Lanes", "RoadMark", "Speed", "lane_type_name"]


@dataclass(frozen=True, slots=True, order=True)
class LaneKey:
    """A lane named as (road id, lane-section start s, lane id): one value type everywhere (findings, meshes,
    graphs)."""

    road: str
    section_s: float
    lane: int

    def __str__(self) -> str:
        return f"{self.road}/{self.section_s:g}/{self.lane}"


@dataclass(frozen=True, slots=True)
class RoadMark:
    """A lane's road mark from ``s`` (its ``sOffset``) on (``<roadMark>``): its kind and look, and the stripes of its
    ``<type>``, ``<explicit>`` and ``<sway>`` children."""

    s: float  # sOffset
    type: str
    weight: str | None = None
    color: str | None = None
    width: float | None = None
    lane_change: str | None = None
    line: int = 0
    material: str | None = None
    height: float | None = None
    type_lines: RoadMarkType | None = None
    explicit: RoadMarkExplicit | None = None
    sways: tuple[RoadMarkSway, ...] = ()
    xml: XmlFacts = facts_field()


# --------------------------------------------------------------------------------------------------------- lane records
@dataclass(frozen=True, slots=True)
class Speed:
    """A lane's speed limit from ``s`` (its ``sOffset``) on (``<speed>``)."""

    s: float  # sOffset
    max: float
    unit: str | None = None
    line: int = 0
    xml: XmlFacts = facts_field()


@dataclass(frozen=True, slots=True)
class LaneHeight:
    """A lane's ``<height>`` (11.7.3): from ``s`` (``sOffset``) on, the lane's inner and outer border are raised by
    ``inner`` and ``outer`` metres along the road's h-axis (normal to the superelevated surface)."""

    s: float  # sOffset
    inner: float
    outer: float
    line: int = 0
    xml: XmlFacts = facts_field()


@dataclass(frozen=True, slots=True)
class LaneLinks:
    """A lane's ``<link>`` element: where it is (the lane ids it names are the lane's ``predecessors``,
    ``successors`` and their temporary-layer twins; ``xml.children`` shows an empty one)."""

    line: int = 0
    xml: XmlFacts = facts_field()


# --------------------------------------------------------------------------------------------------------- lanes
@dataclass(frozen=True, slots=True)
class Lane:
    """One lane of a lane section: id, type, links, width or border laws, road marks, speeds, heights, and the
    records and attributes that say how it may be used."""

    id: int
    type: LaneType
    level: bool = False
    predecessors: tuple[int, ...] = ()
    successors: tuple[int, ...] = ()
    widths: Profile = ()
    borders: Profile = ()
    road_marks: tuple[RoadMark, ...] = ()
    speeds: tuple[Speed, ...] = ()
    type_name: str = ""  # the type as spelled in the file (meaningful when ``type`` is UNKNOWN)
    line: int = 0
    heights: tuple[LaneHeight, ...] = ()
    #: Links to lanes of the temporary layer (1.9 ``layer="temporary"``); ``predecessors`` and ``successors`` name
    #: lanes of the permanent layer, the default of a link whatever layer the lane itself is on (11.6).
    temporary_predecessors: tuple[int, ...] = ()
    temporary_successors: tuple[int, ...] = ()
    #: ``@direction`` (1.8 on; ``None`` when absent or in an older file: the standard direction).
    direction: LaneDirection | None = None
    access: tuple[LaneAccess, ...] = ()
    materials: tuple[LaneMaterial, ...] = ()
    rules: tuple[LaneRule, ...] = ()
    visibilities: tuple[LaneVisibility, ...] = ()
    #: The ``<link>`` element (``None``: the lane has none).
    link: LaneLinks | None = None
    #: 1.8 attributes (``None``: not given, or not a value of their type).
    advisory: LaneAdvisory | None = None
    dynamic_lane_type: bool | None = None
    dynamic_lane_direction: bool | None = None
    road_works: bool | None = None
    xml: XmlFacts = facts_field()

    @property
    def side(self) -> Side:
        return Side.LEFT if self.id > 0 else Side.RIGHT if self.id < 0 else Side.CENTER

    @property
    def drivable(self) -> bool:
        return self.type in DRIVABLE_LANE_TYPES


def lane_type_name(lane: Lane) -> str:
    """The lane's type as the standard spells it; an unknown type as the file spelled it."""
    if lane.type is LaneType.UNKNOWN and lane.type_name:
        return lane.type_name
    return lane.type.value


@dataclass(frozen=True, slots=True)
class LaneSection:
    """A lane section from ``s`` on: its left, center and right lanes (``xml.children`` gives the order of
    ``<left>``, ``<center>`` and ``<right>`` in the file)."""

    s: float
    single_side: bool | None = None
    left: tuple[Lane, ...] = ()  # in file order; use ``lanes`` for id order
    center: tuple[Lane, ...] = ()
    right: tuple[Lane, ...] = ()
    line: int = 0
    #: 1.9 ``@length`` (11.4): the section ends at ``s + length`` (before the next section starts or the road ends);
    #: ``None``: it lasts until the next section or the road's end. Read from 1.9 files only (``xml`` tells whether
    #: an older file gives one).
    length: float | None = None
    xml: XmlFacts = facts_field()

    @property
    def lanes(self) -> tuple[Lane, ...]:
        """All lanes ordered by id, from the leftmost (highest id) to the rightmost (lowest)."""
        return tuple(sorted((*self.left, *self.center, *self.right), key=lambda lane: -lane.id))

    def lane(self, lane_id: int) -> Lane | None:
        for lane in (*self.left, *self.center, *self.right):
            if lane.id == lane_id:
                return lane
        return None


@dataclass(frozen=True, slots=True)
class Lanes:
    """One ``<lanes>`` element: a lane layer's lane offset and lane sections. A road's temporary layer (1.9, 11.2:
    ``<lanes layer="temporary">``) may leave gaps (a section with ``length`` ends there; before the first section
    there is none)."""

    lane_offset: Profile = ()
    lane_sections: tuple[LaneSection, ...] = ()
    line: int = 0
    layer: LaneLayer = LaneLayer.PERMANENT
    xml: XmlFacts = facts_field()
