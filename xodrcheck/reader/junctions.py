"""``<junction>`` elements to :class:`~xodrcheck.model.Junction`: connections and lane links (read with findings, as
topology needs them), and the chapter-12 parts (cross paths, priorities, controllers, road sections, boundary,
elevation grid, reference line, surface, objects), read as the file gives them. Also ``<junctionGroup>``."""

from __future__ import annotations

from lxml import etree

from xodrcheck import model
from xodrcheck.model import (
    Boundary,
    BoundarySegment,
    ConnectionEnd,
    ConnectionType,
    ContactPoint,
    CrossPath,
    CrossPathLink,
    ElementDir,
    ElementType,
    ElevationGrid,
    GridRow,
    JointSegment,
    Junction,
    JunctionController,
    JunctionGeometry,
    JunctionGroup,
    JunctionGroupType,
    JunctionLaneLink,
    JunctionPlanView,
    JunctionReference,
    JunctionType,
    LaneLayer,
    LaneSegment,
    OtherSegment,
    Priority,
    RoadPlace,
    RoadSection,
)
from xodrcheck.reader.context import LEAF, Context
from xodrcheck.reader.lanes import LAYERS, layered
from xodrcheck.reader.objects import NO_OBJECTS, ORIENTATIONS, read_objects
from xodrcheck.reader.road_records import surface
from xodrcheck.reader.roads import CONTACT_POINTS

_JUNCTION_TYPES = {t.value: t for t in JunctionType}
_CONNECTION_TYPES = {t.value: t for t in ConnectionType}
_EXACT_ELEMENT_TYPES = {t.value: t for t in ElementType}
_ELEMENT_DIRS = {d.value: d for d in ElementDir}
_GROUP_TYPES = {t.value: t for t in JunctionGroupType}
#: A boundary segment's road end: ``begin`` is the spec's own example's spelling of the start.
_ENDS = {"start": ContactPoint.START, "begin": ContactPoint.START, "end": ContactPoint.END}
_JUNCTION = frozenset(
    {
        "connection",
        "crossPath",
        "priority",
        "controller",
        "surface",
        "planView",
        "objects",
        "boundary",
        "elevationGrid",
        "roadSection",
    }
)
_CONNECTION = frozenset({"laneLink", "predecessor", "successor"})


# ------------------------------------------------------------------------------------------------------ connections
def _layer(ctx: Context, el: etree._Element, name: str) -> LaneLayer:
    return ctx.choice(el, name, LAYERS, "read as permanent, the standard's default") or LaneLayer.PERMANENT


def _lane_links(ctx: Context, el: etree._Element) -> tuple[tuple[JunctionLaneLink, ...], tuple[JunctionLaneLink, ...]]:
    """The connection's lane links between permanent-layer lanes, then those with an end on a temporary layer."""
    out = []
    temporary = []
    with_layers = layered(ctx)
    for ll in el.iterchildren("laneLink"):
        try:
            from_lane, to_lane = int(ll.get("from")), int(ll.get("to"))
        except (TypeError, ValueError):
            for name in ("from", "to"):  # report whichever is missing or not an integer
                ctx.integer(ll, name, "the lane link is ignored")
            continue
        from_layer = to_layer = LaneLayer.PERMANENT
        if with_layers and (ll.get("fromLayer") is not None or ll.get("toLayer") is not None):
            from_layer, to_layer = _layer(ctx, ll, "fromLayer"), _layer(ctx, ll, "toLayer")
        zone = ctx.opt_number(ll, "overlapZone")
        link = JunctionLaneLink(from_lane, to_lane, ll.sourceline, from_layer, to_layer, zone, ctx.facts(ll, LEAF))
        if LaneLayer.TEMPORARY in (from_layer, to_layer):
            temporary.append(link)
        else:
            out.append(link)
    return tuple(out), tuple(temporary)


def _end(ctx: Context, el: etree._Element) -> ConnectionEnd:
    """A virtual connection's ``<predecessor>`` or ``<successor>``."""
    return ConnectionEnd(
        ctx.opt_enum(el, "elementType", _EXACT_ELEMENT_TYPES),
        el.get("elementId"),
        ctx.opt_number(el, "elementS"),
        ctx.opt_enum(el, "elementDir", _ELEMENT_DIRS),
        el.sourceline,
        ctx.facts(el, LEAF),
    )


def _connection(ctx: Context, c: etree._Element) -> model.Connection:
    get = c.get
    connection_id = get("id")
    if connection_id is None:
        ctx.missing(c, "id", "the connection is kept with an empty id")
        connection_id = ""
    contact = None
    if get("contactPoint") is not None:
        contact = ctx.choice(c, "contactPoint", CONTACT_POINTS, "read as absent")
    links, temporary_links = _lane_links(ctx, c)
    predecessor = next((_end(ctx, e) for e in c.iterchildren("predecessor")), None)
    successor = next((_end(ctx, e) for e in c.iterchildren("successor")), None)
    return model.Connection(
        connection_id,
        get("incomingRoad"),
        get("connectingRoad"),
        get("linkedRoad"),
        contact,
        links,
        c.sourceline,
        temporary_links,
        ctx.opt_enum(c, "type", _CONNECTION_TYPES),
        predecessor,
        successor,
        ctx.facts(c, _CONNECTION),
    )


# ------------------------------------------------------------------------------------------------------ parts
def _cross_path_link(ctx: Context, el: etree._Element | None) -> CrossPathLink | None:
    if el is None:
        return None
    return CrossPathLink(
        ctx.opt_number(el, "s"),
        ctx.opt_integer(el, "from"),
        ctx.opt_integer(el, "to"),
        el.sourceline,
        ctx.facts(el, LEAF),
    )


def _cross_path(ctx: Context, el: etree._Element) -> CrossPath:
    start = _cross_path_link(ctx, next(el.iterchildren("startLaneLink"), None))
    end = _cross_path_link(ctx, next(el.iterchildren("endLaneLink"), None))
    return CrossPath(
        el.get("id"),
        el.get("crossingRoad"),
        el.get("roadAtStart"),
        el.get("roadAtEnd"),
        start,
        end,
        el.sourceline,
        ctx.facts(el, frozenset({"startLaneLink", "endLaneLink"})),
    )


def _road_place(ctx: Context, el: etree._Element, name: str) -> RoadPlace | None:
    """A segment's ``sStart``/``sEnd``/``contactPoint``: a road end or a number (``None``: neither)."""
    raw = el.get(name)
    if raw is None:
        return None
    word = _ENDS.get(raw.strip())
    return word if word is not None else ctx.opt_number(el, name)


def _boundary(ctx: Context, el: etree._Element) -> Boundary:
    segments: list[BoundarySegment] = []
    unknown: list[OtherSegment] = []
    for seg in el.iterchildren("segment"):
        kind = seg.get("type")
        if kind == "lane":
            lane = ctx.opt_integer(seg, "boundaryLane")
            start, end = _road_place(ctx, seg, "sStart"), _road_place(ctx, seg, "sEnd")
            segments.append(LaneSegment(seg.get("roadId"), lane, start, end, seg.sourceline, ctx.facts(seg, LEAF)))
        elif kind == "joint":
            contact = _road_place(ctx, seg, "contactPoint")
            lanes = ctx.opt_integer(seg, "jointLaneStart"), ctx.opt_integer(seg, "jointLaneEnd")
            transition = ctx.opt_number(seg, "transitionLength")
            segments.append(
                JointSegment(
                    seg.get("roadId"),
                    contact,
                    *lanes,
                    transition if transition is not None and transition > 0 else 0.0,
                    seg.sourceline,
                    ctx.facts(seg, LEAF),
                )
            )
        else:
            unknown.append(OtherSegment(kind, seg.sourceline, ctx.facts(seg, LEAF)))
    return Boundary(tuple(segments), tuple(unknown), el.sourceline, ctx.facts(el, frozenset({"segment"})))


def _heights(ctx: Context, el: etree._Element, name: str) -> tuple[float, ...] | None:
    """A ``t_junction_grid_position_list``: finite numbers separated by blanks (``()`` when absent, ``None`` when an
    item is not a number)."""
    raw = el.get(name)
    if raw is None:
        return ()
    try:
        return tuple(ctx.numbers[item] for item in raw.split())
    except ValueError:
        ctx.note_invalid(el, name, raw)
        return None


def _grid(ctx: Context, el: etree._Element) -> ElevationGrid:
    rows = tuple(
        GridRow(
            _heights(ctx, row, "center"),
            _heights(ctx, row, "left"),
            _heights(ctx, row, "right"),
            row.sourceline,
            ctx.facts(row, LEAF),
        )
        for row in el.iterchildren("elevation")
    )
    spacing = ctx.opt_number(el, "gridSpacing")
    return ElevationGrid(
        ctx.opt_number(el, "sStart"), spacing, rows, el.sourceline, ctx.facts(el, frozenset({"elevation"}))
    )


def _plan_view(ctx: Context, el: etree._Element) -> JunctionPlanView:
    geometries = []
    for g in el.iterchildren("geometry"):
        s, x, y, hdg, length = (ctx.opt_number(g, name) for name in ("s", "x", "y", "hdg", "length"))
        geometries.append(JunctionGeometry(s, x, y, hdg, length, g.sourceline, ctx.facts(g, frozenset({"line"}))))
    return JunctionPlanView(tuple(geometries), el.sourceline, ctx.facts(el, frozenset({"geometry"})))


def _priority(ctx: Context, el: etree._Element) -> Priority:
    return Priority(el.get("high"), el.get("low"), el.sourceline, ctx.facts(el, LEAF))


def _controller(ctx: Context, el: etree._Element) -> JunctionController:
    sequence = ctx.opt_integer(el, "sequence")
    return JunctionController(el.get("id"), el.get("type"), sequence, el.sourceline, ctx.facts(el, LEAF))


def _road_section(ctx: Context, el: etree._Element) -> RoadSection:
    start, end = ctx.opt_number(el, "sStart"), ctx.opt_number(el, "sEnd")
    return RoadSection(el.get("id"), el.get("roadId"), start, end, el.sourceline, ctx.facts(el, LEAF))


# ------------------------------------------------------------------------------------------------------ junctions
def build_junction(ctx: Context, el: etree._Element) -> Junction | None:
    """The junction of ``el``, or ``None`` (with a finding) when it has no id."""
    junction_id = el.get("id")
    if junction_id is None:
        ctx.missing(el, "id", "the junction is skipped (nothing could refer to it)")
        return None
    ctx.junction = junction_id
    try:
        return _junction(ctx, el, junction_id)
    finally:
        ctx.junction = None


def _junction(ctx: Context, el: etree._Element, junction_id: str) -> Junction:
    junction_type = JunctionType.DEFAULT
    if el.get("type") is not None:
        junction_type = ctx.choice(el, "type", _JUNCTION_TYPES, "read as default") or JunctionType.DEFAULT
    connections = tuple(_connection(ctx, c) for c in el.iterchildren("connection"))
    sections = tuple(_road_section(ctx, r) for r in el.iterchildren("roadSection"))
    crossing_roads = tuple(dict.fromkeys(r.road for r in sections if r.road is not None))
    main_road = el.get("mainRoad") if junction_type is JunctionType.VIRTUAL else None
    objects = NO_OBJECTS
    found_surface = None
    for child in el:
        if child.tag == "objects" and objects is NO_OBJECTS:
            objects = read_objects(ctx, junction_id, child)
        elif child.tag == "surface" and found_surface is None:
            found_surface = surface(ctx, child)
    return Junction(
        junction_id,
        el.get("name"),
        junction_type,
        connections,
        el.sourceline,
        main_road,
        crossing_roads,
        ctx.opt_number(el, "sStart"),
        ctx.opt_number(el, "sEnd"),
        ctx.opt_enum(el, "orientation", ORIENTATIONS),
        tuple(_cross_path(ctx, c) for c in el.iterchildren("crossPath")),
        tuple(_priority(ctx, p) for p in el.iterchildren("priority")),
        tuple(_controller(ctx, c) for c in el.iterchildren("controller")),
        sections,
        tuple(_boundary(ctx, b) for b in el.iterchildren("boundary")),
        tuple(_grid(ctx, g) for g in el.iterchildren("elevationGrid")),
        tuple(_plan_view(ctx, p) for p in el.iterchildren("planView")),
        found_surface,
        objects.objects,
        objects.references,
        objects.tunnels,
        objects.bridges,
        ctx.facts(el, _JUNCTION),
    )


def junction_group(ctx: Context, el: etree._Element) -> JunctionGroup:
    """A top-level ``<junctionGroup>`` and its junction references."""
    references = tuple(
        JunctionReference(r.get("junction"), r.sourceline, ctx.facts(r, LEAF))
        for r in el.iterchildren("junctionReference")
    )
    return JunctionGroup(
        el.get("id"),
        el.get("name"),
        ctx.opt_enum(el, "type", _GROUP_TYPES),
        references,
        el.sourceline,
        ctx.facts(el, frozenset({"junctionReference"})),
    )
