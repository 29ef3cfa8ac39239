"""The parts of a ``<junction>`` the model leaves out, as plain frozen typed data built from the file's XML.

:class:`xodrcheck.model.Junction` keeps what topology and lane geometry need (connections and their lane links).
Chapter 12 of ASAM OpenDRIVE 1.8/1.9 adds more: the virtual junction's ``mainRoad``/``sStart``/``sEnd`` (12.7),
cross paths (12.5), priorities (12.4.1), junction controllers (12.14), a crossing's road sections (12.8), the junction
reference line (``<planView>``, 12.9), the boundary and its segments (12.10) and the elevation grid (12.11). This
module reads them, with their source lines, once per file (:func:`read_junctions`); rules get them from
:func:`junction_parts`, cached per check context.

Values that do not parse are ``None`` (the schema rule reports them); nothing here reports findings. Tags are matched
by local name (``{*}tag``). A boundary segment's ``sStart``/``sEnd``/``contactPoint`` may be a number or ``start``/
``end`` (``t_grEqZeroOrContactPoint``); the spec's own example writes ``begin`` for the start, read as ``start``.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

from lxml import etree

from xodrcheck.xmlvalues import integer, local, number, numbers

if TYPE_CHECKING:  # pragma: no cover
    from xodrcheck.rules.context import Context

#: A position along a road: a number (s), or one of its ends (``"start"``, ``"end"``).
RoadPlace = float | str


@dataclass(frozen=True, slots=True)
class LaneLinkXml:
    """A connection's ``<laneLink>`` as written (lane ids and overlap zone)."""

    from_lane: int | None
    to_lane: int | None
    overlap_zone: float | None
    #: Whether the element has an ``overlapZone`` attribute at all (even one that does not parse).
    has_overlap_zone: bool
    line: int


@dataclass(frozen=True, slots=True)
class ConnectionXml:
    """A junction ``<connection>`` as written (for the rules about its attributes and children)."""

    id: str | None
    #: ``type`` as written (``None``: absent, a regular connection).
    type: str | None
    incoming_road: str | None
    connecting_road: str | None
    linked_road: str | None
    contact_point: str | None
    lane_links: tuple[LaneLinkXml, ...]
    #: Tags of the connection's ``<predecessor>``/``<successor>`` children (virtual connections, 12.7.2), with the
    #: ``elementType`` each names and its line.
    ends: tuple[tuple[str, str | None, int], ...]
    line: int


@dataclass(frozen=True, slots=True)
class CrossPathLink:
    """A cross path's ``<startLaneLink>`` or ``<endLaneLink>``: lane ``from`` of the road at that end, at ``s``, to
    lane ``to`` of the crossing road."""

    s: float | None
    from_lane: int | None
    to_lane: int | None
    line: int


@dataclass(frozen=True, slots=True)
class CrossPath:
    """A junction's ``<crossPath>``: the crossing road and the roads at its start and end."""

    id: str | None
    crossing_road: str | None
    road_at_start: str | None
    road_at_end: str | None
    start: CrossPathLink | None
    end: CrossPathLink | None
    line: int


@dataclass(frozen=True, slots=True)
class Priority:
    """A junction's ``<priority>``: the road with the higher and the road with the lower priority."""

    high: str | None
    low: str | None
    line: int


@dataclass(frozen=True, slots=True)
class RoadSection:
    """A junction boundary's or a direct junction's ``<roadSection>``: a road between two s positions."""

    id: str | None
    road: str | None
    s_start: float | None
    s_end: float | None
    line: int


@dataclass(frozen=True, slots=True)
class LaneSegment:
    """A boundary ``<segment type="lane">``: along the outer edge of ``lane`` of ``road`` from ``s_start`` to
    ``s_end`` (numbers or road ends)."""

    road: str | None
    lane: int | None
    s_start: RoadPlace | None
    s_end: RoadPlace | None
    line: int


@dataclass(frozen=True, slots=True)
class JointSegment:
    """A boundary ``<segment type="joint">``: across ``road`` at its ``contact`` end, from the outer edge of
    ``lane_start`` to that of ``lane_end`` (``None``: the outermost lane, all lanes crossed)."""

    road: str | None
    contact: RoadPlace | None
    lane_start: int | None
    lane_end: int | None
    transition_length: float
    line: int


Segment = LaneSegment | JointSegment


@dataclass(frozen=True, slots=True)
class Boundary:
    """A junction's ``<boundary>``: its segments, in file order."""

    segments: tuple[Segment, ...]
    #: Segments whose ``type`` is neither ``lane`` nor ``joint`` (tag line, type as written).
    unknown: tuple[tuple[int, str | None], ...]
    line: int


@dataclass(frozen=True, slots=True)
class GridRow:
    """One ``<elevation>`` of an elevation grid: z on the junction reference line and to its left and right (inside
    out). ``None`` for a list that does not parse."""

    center: tuple[float, ...] | None
    left: tuple[float, ...] | None
    right: tuple[float, ...] | None
    line: int


@dataclass(frozen=True, slots=True)
class ElevationGrid:
    """A junction's ``<elevationGrid>``: start, spacing and rows of heights."""

    s_start: float | None
    spacing: float | None
    rows: tuple[GridRow, ...]
    line: int


@dataclass(frozen=True, slots=True)
class PlanGeometry:
    """A ``<geometry>`` of a junction reference line: its start, heading, length and the tags of its shape
    children (``line``, ``arc``, ...)."""

    s: float | None
    x: float | None
    y: float | None
    hdg: float | None
    length: float | None
    shapes: tuple[str, ...]
    line: int


@dataclass(frozen=True, slots=True)
class PlanView:
    """A junction's own ``<planView>`` (the junction's reference line): its geometries."""

    geometries: tuple[PlanGeometry, ...]
    line: int


@dataclass(frozen=True, slots=True)
class JunctionParts:
    """One ``<junction>`` element with the chapter-12 parts the model does not hold."""

    id: str | None
    #: ``type`` as written; ``"default"`` when absent (12.2).
    type: str
    line: int
    #: Attributes as written (virtual junctions, 12.7).
    main_road: str | None
    s_start_raw: str | None
    s_end_raw: str | None
    orientation: str | None
    connections: tuple[ConnectionXml, ...]
    cross_paths: tuple[CrossPath, ...]
    priorities: tuple[Priority, ...]
    #: (id, line) of each ``<controller>`` child (12.14).
    controllers: tuple[tuple[str | None, int], ...]
    road_sections: tuple[RoadSection, ...]
    boundaries: tuple[Boundary, ...]
    grids: tuple[ElevationGrid, ...]
    plan_views: tuple[PlanView, ...]
    #: Local names of the junction's child elements, in file order, with their lines.
    children: tuple[tuple[str, int], ...]

    @property
    def s_start(self) -> float | None:
        return number(self.s_start_raw)

    @property
    def s_end(self) -> float | None:
        return number(self.s_end_raw)

    @property
    def boundary(self) -> Boundary | None:
        return self.boundaries[0] if self.boundaries else None

    @property
    def grid(self) -> ElevationGrid | None:
        return self.grids[0] if self.grids else None

    @property
    def plan_view(self) -> PlanView | None:
        return self.plan_views[0] if self.plan_views else None

    def describe(self) -> str:
        kind = "" if self.type == "default" else f"{self.type} "
        return f"{kind}junction {self.id}"


# ------------------------------------------------------------------------------------------------------- parsing
_ENDS = {"start": "start", "begin": "start", "end": "end"}


def road_place(text: str | None) -> RoadPlace | None:
    """``sStart``/``sEnd``/``contactPoint`` of a segment: ``"start"``, ``"end"`` or a number (``None``: neither)."""
    if text is None:
        return None
    word = _ENDS.get(text.strip())
    return word if word is not None else number(text)


def _children(el: etree._Element, tag: str):
    return el.iterchildren(f"{{*}}{tag}")


def _connection(el: etree._Element) -> ConnectionXml:
    get = el.get
    links = tuple(
        LaneLinkXml(
            integer(ll.get("from")),
            integer(ll.get("to")),
            number(ll.get("overlapZone")),
            ll.get("overlapZone") is not None,
            ll.sourceline or 0,
        )
        for ll in _children(el, "laneLink")
    )
    ends = tuple(
        (local(child), child.get("elementType"), child.sourceline or 0)
        for child in el
        if local(child) in ("predecessor", "successor")
    )
    return ConnectionXml(
        get("id"),
        get("type"),
        get("incomingRoad"),
        get("connectingRoad"),
        get("linkedRoad"),
        get("contactPoint"),
        links,
        ends,
        el.sourceline or 0,
    )


def _cross_path_link(el: etree._Element | None) -> CrossPathLink | None:
    if el is None:
        return None
    return CrossPathLink(number(el.get("s")), integer(el.get("from")), integer(el.get("to")), el.sourceline or 0)


def _cross_path(el: etree._Element) -> CrossPath:
    start = next(_children(el, "startLaneLink"), None)
    end = next(_children(el, "endLaneLink"), None)
    return CrossPath(
        el.get("id"),
        el.get("crossingRoad"),
        el.get("roadAtStart"),
        el.get("roadAtEnd"),
        _cross_path_link(start),
        _cross_path_link(end),
        el.sourceline or 0,
    )


def _boundary(el: etree._Element) -> Boundary:
    segments: list[Segment] = []
    unknown: list[tuple[int, str | None]] = []
    for seg in _children(el, "segment"):
        kind = seg.get("type")
        line = seg.sourceline or 0
        if kind == "lane":
            segments.append(
                LaneSegment(
                    seg.get("roadId"),
                    integer(seg.get("boundaryLane")),
                    road_place(seg.get("sStart")),
                    road_place(seg.get("sEnd")),
                    line,
                )
            )
        elif kind == "joint":
            transition = number(seg.get("transitionLength"))
            segments.append(
                JointSegment(
                    seg.get("roadId"),
                    road_place(seg.get("contactPoint")),
                    integer(seg.get("jointLaneStart")),
                    integer(seg.get("jointLaneEnd")),
                    transition if transition is not None and transition > 0 else 0.0,
                    line,
                )
            )
        else:
            unknown.append((line, kind))
    return Boundary(tuple(segments), tuple(unknown), el.sourceline or 0)


def _grid(el: etree._Element) -> ElevationGrid:
    rows = tuple(
        GridRow(
            numbers(row.get("center")),
            numbers(row.get("left")),
            numbers(row.get("right")),
            row.sourceline or 0,
        )
        for row in _children(el, "elevation")
    )
    return ElevationGrid(number(el.get("sStart")), number(el.get("gridSpacing")), rows, el.sourceline or 0)


def _plan_view(el: etree._Element) -> PlanView:
    geometries = tuple(
        PlanGeometry(
            number(g.get("s")),
            number(g.get("x")),
            number(g.get("y")),
            number(g.get("hdg")),
            number(g.get("length")),
            tuple(name for child in g if (name := local(child))),
            g.sourceline or 0,
        )
        for g in _children(el, "geometry")
    )
    return PlanView(geometries, el.sourceline or 0)


def read_junction(el: etree._Element) -> JunctionParts:
    """The parts of one ``<junction>`` element."""
    get = el.get
    return JunctionParts(
        id=get("id"),
        type=get("type") or "default",
        line=el.sourceline or 0,
        main_road=get("mainRoad"),
        s_start_raw=get("sStart"),
        s_end_raw=get("sEnd"),
        orientation=get("orientation"),
        connections=tuple(_connection(c) for c in _children(el, "connection")),
        cross_paths=tuple(_cross_path(c) for c in _children(el, "crossPath")),
        priorities=tuple(Priority(p.get("high"), p.get("low"), p.sourceline or 0) for p in _children(el, "priority")),
        controllers=tuple((c.get("id"), c.sourceline or 0) for c in _children(el, "controller")),
        road_sections=tuple(
            RoadSection(r.get("id"), r.get("roadId"), number(r.get("sStart")), number(r.get("sEnd")), r.sourceline or 0)
            for r in _children(el, "roadSection")
        ),
        boundaries=tuple(_boundary(b) for b in _children(el, "boundary")),
        grids=tuple(_grid(g) for g in _children(el, "elevationGrid")),
        plan_views=tuple(_plan_view(p) for p in _children(el, "planView")),
        children=tuple((name, child.sourceline or 0) for child in el if (name := local(child))),
    )


def read_junctions(root: etree._Element) -> tuple[JunctionParts, ...]:
    """Every ``<junction>`` of an ``<OpenDRIVE>`` element, in file order."""
    return tuple(read_junction(el) for el in _children(root, "junction"))


def junction_parts(ctx: Context) -> tuple[JunctionParts, ...]:
    """The file's junctions as :class:`JunctionParts`, built once per check context (empty when the file is not
    well-formed XML or was built in memory)."""

    def build() -> tuple[JunctionParts, ...]:
        tree = ctx.tree
        return () if tree is None else read_junctions(tree.getroot())

    return ctx.xml_view("junction_elements.parts", build)
