"""The parts of a ``<junction>`` beside its connections (chapter 12), read as the file gives them: a virtual
connection's ends, cross paths, priorities, controllers, road sections, boundary, elevation grid, reference line,
surface and objects; and the file's ``<junctionGroup>`` elements."""

from __future__ import annotations

from dataclasses import replace

from lxml import etree

from xodrcheck.model import (
    Boundary,
    BoundarySegment,
    ConnectionEnd,
    ContactPoint,
    CrossPath,
    CrossPathLink,
    ElevationGrid,
    GridRow,
    JointSegment,
    Junction,
    JunctionController,
    JunctionGeometry,
    JunctionGroup,
    JunctionGroupType,
    JunctionPlanView,
    JunctionReference,
    LaneSegment,
    OtherSegment,
    Priority,
    RoadPlace,
    RoadSection,
)
from xodrcheck.reader.context import ELEMENT_DIRS, LEAF, Context
from xodrcheck.reader.objects import ORIENTATIONS, read_objects
from xodrcheck.reader.road_records import surface
from xodrcheck.reader.roads import ELEMENT_TYPES

_GROUP_TYPES = {t.value: t for t in JunctionGroupType}
#: A boundary segment's road end: ``begin`` is the spec's own example's spelling of the start.
_ENDS = {"start": ContactPoint.START, "begin": ContactPoint.START, "end": ContactPoint.END}


def _end(ctx: Context, el: etree._Element) -> ConnectionEnd:
    """A virtual connection's ``<predecessor>`` or ``<successor>``."""
    return ConnectionEnd(
        ctx.opt_enum(el, "elementType", ELEMENT_TYPES),
        el.get("elementId"),
        ctx.opt_number(el, "elementS"),
        ctx.opt_enum(el, "elementDir", ELEMENT_DIRS),
        el.sourceline,
        ctx.facts(el, LEAF),
    )


def connection_ends(ctx: Context, el: etree._Element) -> tuple[ConnectionEnd | None, ConnectionEnd | None]:
    """A connection's (first) ``<predecessor>`` and ``<successor>``."""
    predecessor = next((_end(ctx, e) for e in el.iterchildren("predecessor")), None)
    successor = next((_end(ctx, e) for e in el.iterchildren("successor")), None)
    return predecessor, successor


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
            unknown.append(OtherSegment(kind, seg.get("roadId"), seg.sourceline, ctx.facts(seg, LEAF)))
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


def with_parts(ctx: Context, el: etree._Element, junction: Junction) -> Junction:
    """``junction`` with the parts of its element ``el``."""
    sections = tuple(_road_section(ctx, r) for r in el.iterchildren("roadSection"))
    objects = found_surface = None
    for child in el:
        if child.tag == "objects" and objects is None:
            objects = read_objects(ctx, junction.id, child)
        elif child.tag == "surface" and found_surface is None:
            found_surface = surface(ctx, child)
    return replace(
        junction,
        crossing_roads=tuple(dict.fromkeys(r.road for r in sections if r.road is not None)),
        s_start=ctx.opt_number(el, "sStart"),
        s_end=ctx.opt_number(el, "sEnd"),
        orientation=ctx.opt_enum(el, "orientation", ORIENTATIONS),
        cross_paths=tuple(_cross_path(ctx, c) for c in el.iterchildren("crossPath")),
        priorities=tuple(_priority(ctx, p) for p in el.iterchildren("priority")),
        controllers=tuple(_controller(ctx, c) for c in el.iterchildren("controller")),
        road_sections=sections,
        boundaries=tuple(_boundary(ctx, b) for b in el.iterchildren("boundary")),
        grids=tuple(_grid(ctx, g) for g in el.iterchildren("elevationGrid")),
        plan_views=tuple(_plan_view(ctx, p) for p in el.iterchildren("planView")),
        surface=found_surface,
        objects=() if objects is None else objects.objects,
        object_references=() if objects is None else objects.references,
        tunnels=() if objects is None else objects.tunnels,
        bridges=() if objects is None else objects.bridges,
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
