"""What a check function receives: the document, the configuration, the raw file and cached lookups.

A rule is a function ``rule(ctx: Context) -> Iterable[Finding]``. Everything here is computed on first use and cached
for the other rules of the same file, so a rule pays only for what it asks.
"""

from __future__ import annotations

import dataclasses
import math
import time
from collections.abc import Iterator, Mapping
from dataclasses import dataclass
from functools import cached_property
from typing import TYPE_CHECKING

from xodrcheck.config import Config, Tolerances
from xodrcheck.findings import Finding
from xodrcheck.model import (
    DIRECTED_LANE_TYPES,
    Connection,
    ContactPoint,
    Document,
    ElementType,
    Junction,
    JunctionType,
    Lane,
    LaneDirection,
    LaneSection,
    Road,
    TrafficRule,
)

if TYPE_CHECKING:  # pragma: no cover
    from lxml import etree

    from xodrcheck.geometry.lanes import RoadGeometry
    from xodrcheck.model import RoadObject


def travel_direction(road: Road, lane: Lane) -> int | None:
    """+1 when traffic on the lane runs along increasing s, -1 against it; ``None`` where no one direction applies.

    11.3.1: in right-hand traffic the right lanes (negative ids) run along s and the left lanes against it, in
    left-hand traffic the other way round; ``@direction="reversed"`` (1.8) turns the lane's direction round. No
    direction applies to the centre lane, to a lane whose type carries no directed traffic (sidewalk, shoulder,
    border, curb, median, none...: :data:`~xodrcheck.model.DIRECTED_LANE_TYPES`) or to a lane open both ways
    (``@direction="both"``, type ``bidirectional``).
    """
    if lane.id == 0 or lane.type not in DIRECTED_LANE_TYPES or lane.direction is LaneDirection.BOTH:
        return None
    along = (lane.id < 0) == (road.rule is TrafficRule.RHT)
    if lane.direction is LaneDirection.REVERSED:
        along = not along
    return 1 if along else -1


@dataclass(frozen=True, slots=True)
class Neighbour:
    """A road touching another road's end.

    ``contact`` is the end of ``road`` that touches; ``connection`` is the junction connection through which they
    touch (``None`` for a direct road link).
    """

    road: Road
    contact: ContactPoint
    connection: Connection | None = None
    junction: Junction | None = None


class Context:
    """One file being checked. Build it with the reader's document; rules only read from it."""

    def __init__(
        self,
        document: Document,
        config: Config | None = None,
        path: str | None = None,
        data: bytes | None = None,
        deadline: float | None = None,
        *,
        tree: etree._ElementTree | None = None,
    ) -> None:
        self.document = document
        self.config = config or Config()
        self.path = path
        #: The file's bytes, parsed for :attr:`tree` when the caller passes no tree (``None``: a document built in
        #: memory, or the reader's tree given).
        self.data = data
        #: ``time.monotonic()`` value after which expensive rules should stop (``None``: no limit).
        self.deadline = deadline
        self._geometry: Mapping[str, RoadGeometry] | None = None
        self._widths: dict[tuple[int, int, int, float], float | None] = {}
        self._positions: dict[tuple, tuple[float, float, float] | None] = {}
        if tree is not None:  # the reader's tree of these bytes (:func:`xodrcheck.reader.read_keeping_tree`)
            self.__dict__["_tree"] = tree

    # ---------------------------------------------------------------------------------------------------- basics
    @property
    def tolerances(self) -> Tolerances:
        return self.config.tolerances

    @property
    def version(self) -> tuple[int, int] | None:
        return self.document.version

    def version_at_least(self, minor: int) -> bool:
        """True when the file declares OpenDRIVE 1.``minor`` or later."""
        v = self.version
        return v is not None and v >= (1, minor)

    def out_of_time(self) -> bool:
        return self.deadline is not None and time.monotonic() > self.deadline

    @property
    def tree(self) -> etree._ElementTree | None:
        """The file's XML tree for schema validation: the reader's tree when the caller passed it, else :attr:`data`
        parsed on first use (:func:`xodrcheck.reader.parse_tree`: namespaces kept); ``None`` when there are no bytes
        or they are not well-formed (the reader reports why). The schema rules run first and the runner then drops it
        (:meth:`release_tree`); every other rule reads the document."""
        if "_tree" not in self.__dict__:
            from xodrcheck.reader import parse_tree

            self.__dict__["_tree"] = None if self.data is None else parse_tree(self.data)
        return self.__dict__["_tree"]

    def release_tree(self) -> None:
        """Drop :attr:`tree` and the bytes it was parsed from, so that the tree (about 900 bytes per element) never
        lies under the geometry rules' caches."""
        self.__dict__["_tree"] = None
        self.data = None

    def road_objects(self) -> Iterator[RoadObject]:
        """The ``<object>`` records of the document's roads, road by road in file order (a junction's own objects
        stand on no road's reference line)."""
        for road in self.document.roads:
            yield from road.objects

    # ---------------------------------------------------------------------------------------------------- geometry
    def geometry(self, road_id: str) -> RoadGeometry | None:
        """The evaluated geometry of a road (lazy, cached per road); ``None`` for an unknown road."""
        if self._geometry is None:
            from xodrcheck.geometry.lanes import geometry_of

            self._geometry = geometry_of(self.document)
        return self._geometry.get(road_id)

    def usable_geometry(self, road: Road) -> RoadGeometry | None:
        """The road's geometry when it can be evaluated: a plan view, lane sections and a positive length, and the
        road is the one its id looks up (of a duplicated id only the first; R001 reports the others)."""
        if not road.plan_view or not road.lane_sections or not road.length > 0 or not math.isfinite(road.length):
            return None
        if self.document.road_by_id.get(road.id) is not road:
            return None
        return self.geometry(road.id)

    def release_geometry(self) -> None:
        """Drop every road's evaluated geometry and its caches (built again when next asked for): the rules that mesh
        the whole map make room for the mesh."""
        from xodrcheck.model import document_cache

        self._geometry = None
        document_cache(self.document).pop("geometry", None)

    def usable_sections(self) -> Iterator[tuple[Road, RoadGeometry, int, LaneSection]]:
        """Each lane section of each road whose :meth:`usable_geometry` there is: the road, its geometry, the
        section's index and the section, in document order."""
        for road in self.document.roads:
            geometry = self.usable_geometry(road)
            if geometry is None:
                continue
            for index, section in enumerate(road.lane_sections):
                yield road, geometry, index, section

    def road_geometry(self, road: Road) -> RoadGeometry:
        """The evaluated geometry of a road of the document (every road's id has one; with a duplicated id, that of
        the first road of the id, as :meth:`geometry` gives)."""
        geometry = self.geometry(road.id)
        if geometry is None:
            raise KeyError(f"road {road.id!r} is not a road of the document")
        return geometry

    def lane_width(self, road: Road, section_index: int, lane_id: int, s: float) -> float | None:
        """Width of a lane at absolute ``s`` of its section (``None`` when the lane gives neither width nor border).

        Width records are evaluated directly; a lane described by border records needs the road geometry. Cached
        per (road, section, lane, ``s``): the lane rules ask for the same lane ends many times.
        """
        key = (id(road), section_index, lane_id, s)
        if key not in self._widths:
            self._widths[key] = self._lane_width(road, section_index, lane_id, s)
        return self._widths[key]

    def _lane_width(self, road: Road, section_index: int, lane_id: int, s: float) -> float | None:
        section = road.lane_sections[section_index]
        lane = section.lane(lane_id)
        if lane is None or lane_id == 0:
            return None
        import numpy as np

        if lane.widths:
            from xodrcheck.geometry import profile

            return float(profile.evaluate(lane.widths, np.array([s]), origin=section.s)[0])
        if lane.borders:
            geometry = self.geometry(road.id)
            if geometry is None or lane_id not in geometry.placed_lane_ids(section_index):
                return None  # a lane on the wrong side has no place in the road (lane-id-sequence reports it)
            inner, outer = geometry.inner_outer(section_index, lane_id, np.array([s]))
            return float(abs(np.asarray(outer)[0] - np.asarray(inner)[0]))
        return None

    def width_at_end(self, road: Road, section_index: int, lane_id: int, end: ContactPoint) -> float | None:
        """Width of a lane at the start or end of its lane section."""
        s = road.lane_sections[section_index].s if end is ContactPoint.START else road.section_end(section_index)
        return self.lane_width(road, section_index, lane_id, s)

    def zero_width_at(self, road: Road, section_index: int, lane_id: int, end: ContactPoint) -> bool | None:
        """Whether a lane has (numerically) zero width at its section's start or end; ``None`` when unknown."""
        width = self.width_at_end(road, section_index, lane_id, end)
        return None if width is None else abs(width) < self.tolerances.zero_width

    # ---------------------------------------------------------------------------------------------------- places
    def position(
        self, road_id: str, s: float, lane: int | None = None, section_s: float | None = None
    ) -> tuple[float, float, float] | None:
        """Inertial (x, y, z) of a place named by road and ``s``, evaluated exactly once and cached: the centre of
        ``lane`` (raised by its height) in the lane section starting at ``section_s`` (default: the section containing
        ``s``), or the reference line at ``s`` (z: the elevation) without a lane, for lane 0 or for a lane the section
        does not place. ``None`` for an unknown road, a road without a plan view or a point that is not finite."""
        key = (road_id, s, lane, section_s)
        if key not in self._positions:
            self._positions[key] = self._position(road_id, s, lane, section_s)
        return self._positions[key]

    def _position(
        self, road_id: str, s: float, lane: int | None, section_s: float | None
    ) -> tuple[float, float, float] | None:
        geometry = self.geometry(road_id)
        if geometry is None or not geometry.road.plan_view or not math.isfinite(s):
            return None
        import numpy as np

        from xodrcheck.rules.shared.places import lane_placed, points_at

        return points_at(geometry, np.array([float(s)]), lane_placed(geometry, s, lane, section_s))[0]

    def known_position(self, key: tuple) -> bool:
        """Whether :meth:`position` has the place ``(road_id, s, lane, section_s)`` already."""
        return key in self._positions

    def remember_position(self, key: tuple, point: tuple[float, float, float] | None) -> None:
        """Keep a place evaluated elsewhere (:func:`.places.locate_all`) as :meth:`position` would."""
        self._positions[key] = point

    def locate_all(self, findings: list[Finding]) -> list[Finding]:
        """:meth:`locate` of every finding (places on one lane evaluated together:
        :func:`xodrcheck.rules.shared.places.locate_all`)."""
        from xodrcheck.rules.shared.places import locate_all

        return locate_all(self, findings)

    def locate(self, finding: Finding) -> Finding:
        """``finding`` with x, y and z filled in from its road, ``s`` and lane (:meth:`position`) when it names a place
        but not its coordinates; otherwise unchanged."""
        if finding.x is not None or finding.road is None or finding.s is None:
            return finding
        found = self.position(finding.road, finding.s, finding.lane, finding.section_s)
        if found is None:
            return finding
        x, y, z = found
        return dataclasses.replace(finding, x=x, y=y, z=z if math.isfinite(z) else None)

    @staticmethod
    def end_at(road: Road, end: ContactPoint | None) -> dict:
        """Finding location fields of a road's start or end: ``s`` (0 or the road's length) and ``section_s`` of the
        lane section there (empty for an unknown end)."""
        if end is None:
            return {}
        out: dict = {"s": 0.0 if end is ContactPoint.START else float(road.length)}
        index = Context.section_index_at(road, end)
        if index is not None:
            out["section_s"] = road.lane_sections[index].s
        return out

    # ---------------------------------------------------------------------------------------------------- lookups
    def road(self, road_id: str | None) -> Road | None:
        return None if road_id is None else self.document.road_by_id.get(road_id)

    def junction(self, junction_id: str | None) -> Junction | None:
        return None if junction_id is None else self.document.junction_by_id.get(junction_id)

    def junction_of(self, road: Road) -> Junction | None:
        """The junction a road belongs to (its ``junction`` attribute), if that junction exists."""
        return self.junction(road.junction)

    @cached_property
    def roads_in_junction(self) -> dict[str, tuple[Road, ...]]:
        """Junction id -> roads whose ``junction`` attribute names it."""
        out: dict[str, list[Road]] = {}
        for road in self.document.roads:
            if road.junction is not None:
                out.setdefault(road.junction, []).append(road)
        return {k: tuple(v) for k, v in out.items()}

    @cached_property
    def junction_link_ends(self) -> dict[str, tuple[tuple[Road, ContactPoint], ...]]:
        """Junction id -> (road, end) of every road end whose predecessor or successor names that junction, in
        document order (one pass over the roads instead of one per junction)."""
        out: dict[str, list[tuple[Road, ContactPoint]]] = {}
        for road in self.document.roads:
            for end in (ContactPoint.START, ContactPoint.END):
                link = road.link_at(end)
                if link is not None and link.element_type is ElementType.JUNCTION and link.element_id is not None:
                    out.setdefault(link.element_id, []).append((road, end))
        return {k: tuple(v) for k, v in out.items()}

    @cached_property
    def connections_by_incoming(self) -> dict[tuple[str, str], tuple[Connection, ...]]:
        """(junction id, incoming road id) -> the junction's connections from that road."""
        out: dict[tuple[str, str], list[Connection]] = {}
        for junction in self.document.junctions:
            for c in junction.connections:
                if c.incoming_road is not None:
                    out.setdefault((junction.id, c.incoming_road), []).append(c)
        return {k: tuple(v) for k, v in out.items()}

    @cached_property
    def junction_lane_targets(self) -> dict[tuple[str, ContactPoint], frozenset[int]]:
        """(connecting or linked road id, contact point) -> lanes some junction laneLink leads into there."""
        out: dict[tuple[str, ContactPoint], set[int]] = {}
        for junction in self.document.junctions:
            for c in junction.connections:
                target = self.connected_road_id(c)
                if target is not None and c.contact_point is not None:
                    out.setdefault((target, c.contact_point), set()).update(ll.to_lane for ll in c.lane_links)
        return {k: frozenset(v) for k, v in out.items()}

    @staticmethod
    def section_index_at(road: Road, end: ContactPoint) -> int | None:
        """Index of the lane section at a road's start or end (``None`` when the road has none)."""
        if not road.lane_sections:
            return None
        return 0 if end is ContactPoint.START else len(road.lane_sections) - 1

    def section_at(self, road: Road, end: ContactPoint) -> LaneSection | None:
        index = self.section_index_at(road, end)
        return None if index is None else road.lane_sections[index]

    def lane_at(self, road: Road, end: ContactPoint, lane_id: int) -> Lane | None:
        section = self.section_at(road, end)
        return None if section is None else section.lane(lane_id)

    @staticmethod
    def connected_road_id(connection: Connection) -> str | None:
        """The road a connection leads into: ``connectingRoad`` (default junctions) or ``linkedRoad`` (direct)."""
        return connection.connecting_road if connection.connecting_road is not None else connection.linked_road

    def incoming_contact(self, junction: Junction, connection: Connection) -> ContactPoint | None:
        """Which end of the connection's incoming road touches the junction.

        The incoming road's own link to the junction decides; when it links to the junction at both ends (or at
        neither), the connecting road's link back to the incoming road at the connection's contact point decides.
        """
        incoming = self.road(connection.incoming_road)
        if incoming is None:
            return None
        ends = incoming.ends_linked_to(ElementType.JUNCTION, junction.id)
        if len(ends) == 1:
            return ends[0]
        connecting = self.road(self.connected_road_id(connection))
        if connecting is not None and connection.contact_point is not None:
            back = connecting.link_at(connection.contact_point)
            if back is not None and back.names(ElementType.ROAD, incoming.id) and back.contact_point is not None:
                return back.contact_point
        return ends[0] if ends else None

    def neighbours(self, road: Road, end: ContactPoint) -> tuple[Neighbour, ...]:
        """The roads touching ``road`` at ``end``.

        A link to a road gives that road at the link's contact point. A link to a junction gives, for each connection
        whose incoming road is ``road`` (and touches the junction at ``end``), the connecting road (or, in a direct
        junction, the linked road) at the connection's contact point; a direct junction also gives the incoming road
        of each connection whose linked road is ``road`` at ``end``. Unknown targets give nothing (the reference rules
        report them).
        """
        link = road.link_at(end)
        if link is None:
            return ()
        if link.element_type is ElementType.ROAD:
            target = self.road(link.element_id)
            if target is None or link.contact_point is None:
                return ()
            return (Neighbour(target, link.contact_point),)
        junction = self.junction(link.element_id)
        if junction is None:
            return ()
        out = []
        for connection in self.connections_by_incoming.get((junction.id, road.id), ()):
            target = self.road(self.connected_road_id(connection))
            if target is None or connection.contact_point is None:
                continue
            if self.incoming_contact(junction, connection) is not end:
                continue
            out.append(Neighbour(target, connection.contact_point, connection, junction))
        if junction.type is JunctionType.DIRECT:  # a direct junction's links run both ways: also as the linked road
            for connection in junction.connections:
                if connection.linked_road != road.id or connection.contact_point is not end:
                    continue
                incoming = self.road(connection.incoming_road)
                contact = self.incoming_contact(junction, connection) if incoming is not None else None
                if incoming is not None and contact is not None:
                    out.append(Neighbour(incoming, contact, connection, junction))
        return tuple(out)


def describe_junction(junction: Junction) -> str:
    """How messages name a junction: its type (none for a common junction) and id, ``direct junction 111``."""
    kind = "" if junction.type is JunctionType.DEFAULT else f"{junction.type.value} "
    return f"{kind}junction {junction.id}"


def written_id(connection: Connection) -> str | None:
    """A connection's id as written (``None``: the file gives none; the reader keeps it as ``""``)."""
    return connection.id if connection.id or connection.xml.given("id") else None
