"""The OpenDRIVE document as plain, frozen, typed data.

Nothing here parses XML or evaluates geometry: :mod:`xodrcheck.reader` builds these values, :mod:`xodrcheck.geometry`
evaluates them. Every element keeps the source ``line`` it came from (0 when it was not read from a file) so findings
can point at it.

Conventions
-----------
* Lengths in metres, angles in radians, as in the standard.
* ``s`` of a record inside a lane section (width, border, road mark, speed) is the standard's ``sOffset``: relative to
the
  lane section's start. ``s`` of a road-level record (geometry, elevation, laneOffset, lane section) is absolute.
* A value the file did not give and the standard does not default is ``None``, never a made-up 0.
"""

from __future__ import annotations

import enum
from dataclasses import dataclass, field, replace
from functools import cached_property

__all__ = [
    "DIRECTED_LANE_TYPES",
    "DRIVABLE_LANE_TYPES",
    "Arc",
    "Connection",
    "ContactPoint",
    "Cubic",
    "Document",
    "ElementDir",
    "ElementType",
    "Geometry",
    "Header",
    "Junction",
    "JunctionLaneLink",
    "JunctionType",
    "Lane",
    "LaneDirection",
    "LaneHeight",
    "LaneKey",
    "LaneLayer",
    "LaneSection",
    "LaneType",
    "Line",
    "Offset",
    "PRange",
    "ParamPoly3",
    "Poly3",
    "Profile",
    "Road",
    "RoadLink",
    "RoadMark",
    "Side",
    "Speed",
    "Spiral",
    "TemporaryLanes",
    "TrafficRule",
    "document_cache",
    "lane_type_name",
]


# --------------------------------------------------------------------------------------------------------------------
# Naming a lane: one value type everywhere (findings, meshes, graphs).
# --------------------------------------------------------------------------------------------------------------------
@dataclass(frozen=True, slots=True, order=True)
class LaneKey:
    """A lane named as (road id, lane-section start s, lane id)."""

    road: str
    section_s: float
    lane: int

    def __str__(self) -> str:
        return f"{self.road}/{self.section_s:g}/{self.lane}"


# --------------------------------------------------------------------------------------------------------------------
# Enumerations
# --------------------------------------------------------------------------------------------------------------------
class ElementType(enum.Enum):
    ROAD = "road"
    JUNCTION = "junction"


class ContactPoint(enum.Enum):
    START = "start"
    END = "end"


class ElementDir(enum.Enum):
    """OpenDRIVE 1.8 ``elementDir`` of a link into a direct junction / road: ``+`` or ``-``."""

    PLUS = "+"
    MINUS = "-"


class TrafficRule(enum.Enum):
    RHT = "RHT"
    LHT = "LHT"


class PRange(enum.Enum):
    ARC_LENGTH = "arcLength"
    NORMALIZED = "normalized"


class JunctionType(enum.Enum):
    DEFAULT = "default"
    DIRECT = "direct"
    VIRTUAL = "virtual"
    CROSSING = "crossing"


class LaneLayer(enum.Enum):
    """OpenDRIVE 1.9 lane layer (11.2): every road has the permanent layer; a temporary one (roadworks) may lie on top
    of it, with its own lane offset and lane sections and priority for driving."""

    PERMANENT = "permanent"
    TEMPORARY = "temporary"


class LaneType(enum.Enum):
    """Lane types of OpenDRIVE 1.4 to 1.8 (lower-case spellings of older files map onto these)."""

    NONE = "none"
    DRIVING = "driving"
    STOP = "stop"
    SHOULDER = "shoulder"
    BIKING = "biking"
    SIDEWALK = "sidewalk"
    WALKING = "walking"
    BORDER = "border"
    RESTRICTED = "restricted"
    PARKING = "parking"
    BIDIRECTIONAL = "bidirectional"
    MEDIAN = "median"
    SPECIAL1 = "special1"
    SPECIAL2 = "special2"
    SPECIAL3 = "special3"
    ROAD_WORKS = "roadWorks"
    TRAM = "tram"
    RAIL = "rail"
    ENTRY = "entry"
    EXIT = "exit"
    OFF_RAMP = "offRamp"
    ON_RAMP = "onRamp"
    CONNECTING_RAMP = "connectingRamp"
    BUS = "bus"
    TAXI = "taxi"
    HOV = "HOV"
    MWY_ENTRY = "mwyEntry"
    MWY_EXIT = "mwyExit"
    SLIP_LANE = "slipLane"
    CURB = "curb"
    # Not in the standard: the file named a type no version defines. The reader records a finding with the raw name.
    UNKNOWN = "unknown"


#: Lane types a motor vehicle may drive on (used by rules that only concern drivable lanes).
DRIVABLE_LANE_TYPES = frozenset(
    {
        LaneType.DRIVING,
        LaneType.ENTRY,
        LaneType.EXIT,
        LaneType.OFF_RAMP,
        LaneType.ON_RAMP,
        LaneType.CONNECTING_RAMP,
        LaneType.BIDIRECTIONAL,
        LaneType.BUS,
        LaneType.TAXI,
        LaneType.HOV,
        LaneType.MWY_ENTRY,
        LaneType.MWY_EXIT,
        LaneType.SLIP_LANE,
    }
)


#: Lane types whose traffic has one direction of travel (11.3.1: the lane's side and the road's RHT/LHT give it,
#: @direction may change it): vehicle lanes and ``biking``. The others carry no directed traffic: ``none``,
#: ``border``, ``shoulder``, ``curb``, ``median`` and ``restricted`` are not driven on, ``walking``/``sidewalk``
#: lanes are walked both ways, ``parking``, ``stop`` (a hard shoulder for emergency stops), ``tram``, ``rail``,
#: ``roadWorks`` and ``special1-3`` do not state one; ``bidirectional`` carries both.
DIRECTED_LANE_TYPES = (DRIVABLE_LANE_TYPES - {LaneType.BIDIRECTIONAL}) | {LaneType.BIKING}


class LaneDirection(enum.Enum):
    """A lane's ``@direction`` (1.8, 11.3.1): ``standard`` keeps the direction its side and the road's traffic rule
    give, ``reversed`` turns it round, ``both`` allows both (it replaces the deprecated type ``bidirectional``)."""

    STANDARD = "standard"
    REVERSED = "reversed"
    BOTH = "both"


class Side(enum.Enum):
    LEFT = "left"
    CENTER = "center"
    RIGHT = "right"


# --------------------------------------------------------------------------------------------------------------------
# One cubic-profile type for width, border, laneOffset, elevation and superelevation
# --------------------------------------------------------------------------------------------------------------------
@dataclass(frozen=True, slots=True)
class Cubic:
    """One record of a piecewise cubic profile: ``f(s) = a + b ds + c ds^2 + d ds^3`` with ``ds = s - self.s``.

    ``s`` is the record's start (absolute for road-level profiles, ``sOffset`` for lane records).
    """

    s: float
    a: float
    b: float
    c: float
    d: float
    line: int = 0


#: A piecewise cubic profile: records sorted by ``s`` as the file gave them (the reader reports unsorted ones).
Profile = tuple[Cubic, ...]


# --------------------------------------------------------------------------------------------------------------------
# Plan view
# --------------------------------------------------------------------------------------------------------------------
@dataclass(frozen=True, slots=True)
class Line:
    """A straight line of the plan view (``<line>``)."""

    s: float
    x: float
    y: float
    hdg: float
    length: float
    line: int = 0


@dataclass(frozen=True, slots=True)
class Arc:
    """An arc of constant curvature of the plan view (``<arc>``)."""

    s: float
    x: float
    y: float
    hdg: float
    length: float
    curvature: float
    line: int = 0


@dataclass(frozen=True, slots=True)
class Spiral:
    """A clothoid of the plan view (``<spiral>``): curvature linear in s from ``curv_start`` to ``curv_end``."""

    s: float
    x: float
    y: float
    hdg: float
    length: float
    curv_start: float
    curv_end: float
    line: int = 0


@dataclass(frozen=True, slots=True)
class Poly3:
    """Cubic ``v(u) = a + b u + c u^2 + d u^3`` in the local (u, v) frame (deprecated in 1.6, still read)."""

    s: float
    x: float
    y: float
    hdg: float
    length: float
    a: float
    b: float
    c: float
    d: float
    line: int = 0


@dataclass(frozen=True, slots=True)
class ParamPoly3:
    """A parametric cubic of the plan view (``<paramPoly3>``): u and v cubic in a parameter p."""

    s: float
    x: float
    y: float
    hdg: float
    length: float
    aU: float
    bU: float
    cU: float
    dU: float
    aV: float
    bV: float
    cV: float
    dV: float
    p_range: PRange = PRange.NORMALIZED
    line: int = 0


Geometry = Line | Arc | Spiral | Poly3 | ParamPoly3


# --------------------------------------------------------------------------------------------------------------------
# Links
# --------------------------------------------------------------------------------------------------------------------
@dataclass(frozen=True, slots=True)
class RoadLink:
    """A road's ``predecessor`` or ``successor``."""

    element_type: ElementType
    element_id: str
    contact_point: ContactPoint | None = None
    element_s: float | None = None
    element_dir: ElementDir | None = None
    line: int = 0


# --------------------------------------------------------------------------------------------------------------------
# Lanes
# --------------------------------------------------------------------------------------------------------------------
@dataclass(frozen=True, slots=True)
class RoadMark:
    """A lane's road mark from ``s`` (its ``sOffset``) on (``<roadMark>``)."""

    s: float  # sOffset
    type: str
    weight: str | None = None
    color: str | None = None
    width: float | None = None
    lane_change: str | None = None
    line: int = 0


@dataclass(frozen=True, slots=True)
class Speed:
    """A lane's speed limit from ``s`` (its ``sOffset``) on (``<speed>``)."""

    s: float  # sOffset
    max: float
    unit: str | None = None
    line: int = 0


@dataclass(frozen=True, slots=True)
class LaneHeight:
    """A lane's ``<height>`` (11.7.3): from ``s`` (``sOffset``) on, the lane's inner and outer border are raised by
    ``inner`` and ``outer`` metres along the road's h-axis (normal to the superelevated surface)."""

    s: float  # sOffset
    inner: float
    outer: float
    line: int = 0


@dataclass(frozen=True, slots=True)
class Lane:
    """One lane of a lane section: id, type, links, width or border laws, road marks, speeds, heights."""

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
    """A lane section from ``s`` on: its left, center and right lanes."""

    s: float
    single_side: bool | None = None
    left: tuple[Lane, ...] = ()  # in file order; use ``lanes`` for id order
    center: tuple[Lane, ...] = ()
    right: tuple[Lane, ...] = ()
    line: int = 0
    #: 1.9 ``@length`` (11.4): the section ends at ``s + length`` (before the next section starts or the road ends);
    #: ``None``: it lasts until the next section or the road's end.
    length: float | None = None

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
class TemporaryLanes:
    """A road's temporary lane layer (1.9, 11.2: ``<lanes layer="temporary">``): its own lane offset and lane sections,
    which may leave gaps (a section with ``length`` ends there; before the first section there is none)."""

    lane_offset: Profile = ()
    lane_sections: tuple[LaneSection, ...] = ()
    line: int = 0


# --------------------------------------------------------------------------------------------------------------------
# Roads
# --------------------------------------------------------------------------------------------------------------------
@dataclass(frozen=True, slots=True)
class Road:
    """A road: reference line (plan view), profiles, lane offset, lane sections and links."""

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
    objects: int = 0  # counted records
    signals: int = 0
    line: int = 0
    #: The temporary lane layer (1.9); ``lane_offset`` and ``lane_sections`` above are the permanent layer's.
    temporary_lanes: TemporaryLanes | None = None

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
        return replace(self, lane_offset=layer.lane_offset, lane_sections=layer.lane_sections, temporary_lanes=None)


# --------------------------------------------------------------------------------------------------------------------
# Junctions
# --------------------------------------------------------------------------------------------------------------------
@dataclass(frozen=True, slots=True)
class JunctionLaneLink:
    """A ``<laneLink>`` of a junction connection: the incoming lane and the connecting (or linked) lane."""

    from_lane: int
    to_lane: int
    line: int = 0
    #: 1.9 ``fromLayer``/``toLayer`` (12.4): the layers of the incoming and of the connecting (or linked) lane.
    from_layer: LaneLayer = LaneLayer.PERMANENT
    to_layer: LaneLayer = LaneLayer.PERMANENT


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


@dataclass(frozen=True, slots=True)
class Junction:
    """A ``<junction>``: id, name, type and connections."""

    id: str
    name: str | None = None
    type: JunctionType = JunctionType.DEFAULT
    connections: tuple[Connection, ...] = ()
    line: int = 0
    #: A virtual junction's ``mainRoad`` (12.7): the road it lies on, which runs through it.
    main_road: str | None = None
    #: The roads a crossing's ``<roadSection>`` elements name (12.8): they cross each other in it.
    crossing_roads: tuple[str, ...] = ()

    @property
    def incoming_roads(self) -> tuple[str, ...]:
        """Distinct incoming road ids in order of first appearance (the junction's legs)."""
        seen: dict[str, None] = {}
        for c in self.connections:
            if c.incoming_road is not None:
                seen.setdefault(c.incoming_road, None)
        return tuple(seen)


# --------------------------------------------------------------------------------------------------------------------
# Header and document
# --------------------------------------------------------------------------------------------------------------------
@dataclass(frozen=True, slots=True)
class Offset:
    """The header's ``offset`` element (1.5+): the map is shifted by (x, y, z) and rotated by hdg."""

    x: float = 0.0
    y: float = 0.0
    z: float = 0.0
    hdg: float = 0.0


@dataclass(frozen=True, slots=True)
class Header:
    """The file's ``<header>``: OpenDRIVE revision, name, version, date, vendor, extent and georeference."""

    rev_major: int | None
    rev_minor: int | None
    name: str | None = None
    version: str | None = None
    date: str | None = None
    vendor: str | None = None
    north: float | None = None
    south: float | None = None
    east: float | None = None
    west: float | None = None
    geo_reference: str | None = None
    offset: Offset | None = None
    line: int = 0

    @property
    def version_tuple(self) -> tuple[int, int] | None:
        if self.rev_major is None or self.rev_minor is None:
            return None
        return (self.rev_major, self.rev_minor)


def document_cache(document: Document) -> dict:
    """A dict that lives and dies with ``document``, for what is derived from it (geometry, meshes, footprints).

    Kept in the instance's ``__dict__`` (not a field: equality, ``repr`` and ``dataclasses.replace`` ignore it), so a
    cached value that refers back to its document (an overlap index does) is freed with it; a module-level cache keyed
    by ``id(document)`` would keep both alive for the whole process."""
    return document.__dict__.setdefault("_derived", {})


@dataclass(frozen=True)
class Document:
    """A whole OpenDRIVE file. ``roads`` and ``junctions`` keep file order; the ``*_by_id`` maps keep the first of
    duplicated ids (duplicates are reported by the reference rules)."""

    header: Header | None
    roads: tuple[Road, ...] = ()
    junctions: tuple[Junction, ...] = ()
    controllers: int = 0
    source: str | None = None
    extras: dict[str, int] = field(default_factory=dict, compare=False)  # counts of other top-level elements

    @cached_property
    def road_by_id(self) -> dict[str, Road]:
        out: dict[str, Road] = {}
        for road in self.roads:
            out.setdefault(road.id, road)
        return out

    @cached_property
    def junction_by_id(self) -> dict[str, Junction]:
        out: dict[str, Junction] = {}
        for junction in self.junctions:
            out.setdefault(junction.id, junction)
        return out

    @property
    def version(self) -> tuple[int, int] | None:
        return None if self.header is None else self.header.version_tuple
