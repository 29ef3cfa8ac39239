"""The generator's own small OpenDRIVE document model (frozen dataclasses).

Deliberately independent of :mod:`xodrcheck.model`: the checker reads what this model was written to, so a mistake
here cannot be hidden by a shared data type. Only what the generator writes is modelled. Lane-record ``s`` values are
``sOffset`` values (relative to their lane section); road-level ``s`` values are absolute.
"""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class Line:
    """A straight line of a road's plan view."""

    s: float
    x: float
    y: float
    hdg: float
    length: float


@dataclass(frozen=True)
class Arc:
    """An arc of constant curvature of a road's plan view."""

    s: float
    x: float
    y: float
    hdg: float
    length: float
    curvature: float


@dataclass(frozen=True)
class ParamPoly3:
    """A parametric cubic in the local (u, v) frame with ``pRange="normalized"`` (p from 0 to 1)."""

    s: float
    x: float
    y: float
    hdg: float
    length: float
    au: float
    bu: float
    cu: float
    du: float
    av: float
    bv: float
    cv: float
    dv: float


Geometry = Line | Arc | ParamPoly3


@dataclass(frozen=True)
class Cubic:
    """``a + b ds + c ds^2 + d ds^3`` from ``s`` on (width records: ``s`` is sOffset in the lane section)."""

    s: float
    a: float
    b: float = 0.0
    c: float = 0.0
    d: float = 0.0


@dataclass(frozen=True)
class RoadMark:
    """A lane's road mark from ``s`` on."""

    s: float  # sOffset in the lane section
    type: str  # "solid", "broken", "none", "solid solid"
    color: str = "standard"  # "standard" (white), "yellow"
    width: float = 0.12
    lane_change: str | None = None  # "none", "both", "increase", "decrease"


@dataclass(frozen=True)
class LaneHeight:
    """``<height>``: the lane's inner and outer edge raised above the road surface (a kerb, a sidewalk)."""

    s: float  # sOffset in the lane section
    inner: float
    outer: float


@dataclass(frozen=True)
class Lane:
    """A lane as written: id, type, widths, road marks, links and heights."""

    id: int
    type: str  # "driving", "median", "none", "sidewalk", "curb", "shoulder", "border"
    widths: tuple[Cubic, ...] = ()
    marks: tuple[RoadMark, ...] = ()
    predecessor: int | None = None
    successor: int | None = None
    heights: tuple[LaneHeight, ...] = ()


@dataclass(frozen=True)
class LaneSection:
    """A lane section from ``s`` on: its left, center and right lanes."""

    s: float
    left: tuple[Lane, ...]  # ordered by id ascending (1, 2, ...)
    center: Lane
    right: tuple[Lane, ...]  # ordered by id descending (-1, -2, ...)


@dataclass(frozen=True)
class Link:
    """A road's predecessor or successor: the element's type and id and the contact point."""

    element_type: str  # "road" or "junction"
    element_id: str
    contact_point: str | None = None  # "start" / "end" for roads


@dataclass(frozen=True)
class Validity:
    """``<validity>``: the lanes (ids ``from_lane`` to ``to_lane``) a signal or object applies to."""

    from_lane: int
    to_lane: int


@dataclass(frozen=True)
class SignalLink:
    """A signal's ``<reference>`` (to a signal or object it works with) or ``<dependency>`` (on a signal)."""

    element_id: str
    type: str
    element_type: str = "signal"  # references only: "signal" or "object"


@dataclass(frozen=True)
class Signal:
    """A ``<signal>`` at (s, t) of its road, valid for traffic in ``orientation`` ("+", "-" or "none")."""

    id: str
    name: str
    s: float
    t: float
    orientation: str
    dynamic: bool
    country: str
    type: str
    subtype: str
    z_offset: float
    width: float
    height: float
    h_offset: float = 0.0
    validity: tuple[Validity, ...] = ()
    dependencies: tuple[SignalLink, ...] = ()
    references: tuple[SignalLink, ...] = ()


@dataclass(frozen=True)
class Corner:
    """A ``<cornerRoad>`` of an object's outline: a point in the road's s/t frame."""

    s: float
    t: float


@dataclass(frozen=True)
class ObjectMarking:
    """A ``<marking>`` painted along an object's outline from corner to corner (13.8): ``corners`` are indices into
    the outline (written as its ``cornerRoad`` ids), in the outline's order; dashes ``line_length`` long with
    ``space_length`` gaps, ``width`` wide, centred on the outline's edges."""

    corners: tuple[int, ...]
    color: str = "white"
    width: float = 0.12
    line_length: float = 0.5
    space_length: float = 0.2
    z_offset: float = 0.0


@dataclass(frozen=True)
class RoadObject:
    """An ``<object>`` (a crosswalk) with one closed outline of road-frame corners, and markings along it."""

    id: str
    type: str
    name: str
    s: float
    t: float
    length: float | None  #: bounding box (None: no box, the outline alone gives the shape)
    width: float | None
    outline: tuple[Corner, ...]
    orientation: str = "none"
    validity: tuple[Validity, ...] = ()
    markings: tuple[ObjectMarking, ...] = ()


@dataclass(frozen=True)
class Bridge:
    """A ``<bridge>`` record: the stretch ``s`` .. ``s + length`` of its road leads over a bridge (an overpass's
    deck)."""

    id: str
    s: float
    length: float
    name: str
    type: str = "concrete"  #: concrete, steel, brick or wood (the schemas' e_bridgeType)


@dataclass(frozen=True)
class Road:
    """A road as written: plan view, lane sections, links, profiles, objects and signals."""

    id: str
    length: float
    junction: str  # "-1" outside junctions
    geometry: tuple[Geometry, ...]
    sections: tuple[LaneSection, ...]
    rule: str = "RHT"
    predecessor: Link | None = None
    successor: Link | None = None
    lane_offset: tuple[Cubic, ...] = ()
    name: str = ""
    speed_kmh: float | None = None
    road_type: str = "town"  #: the ``<type>`` written with ``speed_kmh``
    elevation: tuple[Cubic, ...] = ()  #: ``s`` absolute; empty: flat at height 0
    objects: tuple[RoadObject, ...] = ()
    signals: tuple[Signal, ...] = ()
    bridges: tuple[Bridge, ...] = ()


@dataclass(frozen=True)
class LaneLink:
    """A junction connection's lane link: the incoming lane and the connecting road's lane."""

    from_lane: int
    to_lane: int


@dataclass(frozen=True)
class Connection:
    """A junction connection: incoming road, connecting road (in a direct junction: the linked road), contact point
    and lane links."""

    id: str
    incoming_road: str
    connecting_road: str  #: written as ``linkedRoad`` in a direct junction
    contact_point: str  # "start" / "end" of the connecting (linked) road
    lane_links: tuple[LaneLink, ...]


@dataclass(frozen=True)
class JunctionController:
    """A junction's ``<controller>`` reference: the signal group ``id`` is shown green ``sequence``-th in the cycle."""

    id: str
    sequence: int


@dataclass(frozen=True)
class Junction:
    """A junction as written: id, name, connections, controllers and type ("default", written without the attribute,
    or "direct": roads linked to each other without connecting roads, OpenDRIVE 1.7+)."""

    id: str
    name: str
    connections: tuple[Connection, ...]
    controllers: tuple[JunctionController, ...] = ()
    type: str = "default"


@dataclass(frozen=True)
class Controller:
    """A ``<controller>``: a signal group whose signals always show the same state."""

    id: str
    name: str
    signals: tuple[str, ...]  #: ids of the controlled signals


@dataclass(frozen=True)
class Header:
    """The header as written: name, vendor, date and the map's extent."""

    name: str = "junctionart"
    vendor: str = "junctionart"
    date: str = ""
    north: float = 0.0
    south: float = 0.0
    east: float = 0.0
    west: float = 0.0


@dataclass(frozen=True)
class Document:
    """What the writer writes: header, roads, junctions and controllers."""

    header: Header
    roads: tuple[Road, ...]
    junctions: tuple[Junction, ...]
    controllers: tuple[Controller, ...] = ()

    def road(self, road_id: str) -> Road:
        for r in self.roads:
            if r.id == road_id:
                return r
        raise KeyError(road_id)
