"""Object skeletons as the file writes them (``B030``-``B033``): polylines of ``<vertexRoad>`` or ``<vertexLocal>``
points, each with a radius or a width and length across the line (13.3).

Where the vertices lie (inside the bounding volume) is :mod:`xodrcheck.rules.object_geometry`'s.
"""

from __future__ import annotations

import math
from collections.abc import Iterator
from typing import TYPE_CHECKING

from xodrcheck.findings import Category, Severity
from xodrcheck.model import VERTEX_LOCAL, VERTEX_ROAD
from xodrcheck.rules.object_attributes import at, label
from xodrcheck.rules.registry import rule
from xodrcheck.rules.shared import object_uids as U
from xodrcheck.rules.shared.context import Context

if TYPE_CHECKING:
    from xodrcheck.model import Polyline, RoadObject, Vertex


def polylines(ctx: Context) -> Iterator[tuple[RoadObject, Polyline]]:
    for obj in ctx.road_objects():
        if obj.skeleton is not None:
            for polyline in obj.skeleton.polylines:
                yield obj, polyline


def polyline_name(polyline: Polyline) -> str:
    return f"polyline {polyline.id}" if polyline.id is not None else f"the polyline at line {polyline.line}"


@rule(
    "B030",
    "skeleton-vertices-mixed",
    Category.OBJECT,
    Severity.ERROR,
    uids=(U.VERTEX_ROAD_NO_MIXING, U.VERTEX_LOCAL_NO_MIXING),
)
def skeleton_vertices_mixed(ctx: Context):
    """A skeleton ``<polyline>`` mixes ``<vertexRoad>`` and ``<vertexLocal>`` points.

    The two are mutually exclusive in one polyline (13.3.1, 13.3.2): Annex F
    ``road.object.skeleton.vertex_road.polyline_elements`` (1.8) and ``.vertex_local.no_mixing_road_local`` (1.9) say
    so from each side; one finding names each rule that applies.

    Passes::

        <polyline id="1"><vertexLocal u="0" v="0" z="0" radius="0.1" id="1"/>
          <vertexLocal u="0" v="0" z="2" radius="0.1" id="2"/></polyline>

    Fails::

        <polyline id="1"><vertexLocal u="0" v="0" z="0" radius="0.1" id="1"/>
          <vertexRoad s="5" t="-4" dz="2" radius="0.1" id="2"/></polyline>
    """
    for obj, polyline in polylines(ctx):
        kinds = {v.kind for v in polyline.vertices}
        if len(kinds) < 2:
            continue
        first = polyline.vertices[0].kind
        other = next(v for v in polyline.vertices if v.kind != first)
        for uid in (U.VERTEX_ROAD_NO_MIXING, U.VERTEX_LOCAL_NO_MIXING):
            yield skeleton_vertices_mixed.finding(
                f"{label(obj)}: {polyline_name(polyline)} mixes <vertexRoad> and <vertexLocal> (the first "
                f"<{other.kind}> at line {other.line}): a polyline's points are all in road or all in local "
                "coordinates",
                uid=uid,
                **at(ctx, obj, other.line),
            )


_MIN_UID = {VERTEX_ROAD: U.VERTEX_ROAD_MIN_AMOUNT, VERTEX_LOCAL: U.VERTEX_LOCAL_MIN_AMOUNT}


@rule(
    "B031",
    "skeleton-too-few-vertices",
    Category.OBJECT,
    Severity.ERROR,
    uids=(U.SKELETON_FOLLOWED_BY_VERTEX, *_MIN_UID.values()),
)
def skeleton_too_few_vertices(ctx: Context):
    """A skeleton ``<polyline>`` has fewer than two points of its kind.

    A polyline is two or more ``<vertexRoad>`` or two or more ``<vertexLocal>`` elements (Annex F
    ``road.object.skeleton.polyline_followed_by_vertex``, ``.vertex_road.element_min_amount``,
    ``.vertex_local.element_min_amount``, 13.3); a single point is no line. One finding names each rule broken.

    Passes::

        <polyline id="1"><vertexRoad s="5" t="-4" dz="0" radius="0.1" id="1"/>
          <vertexRoad s="5" t="-4" dz="3" radius="0.1" id="2"/></polyline>

    Fails::

        <polyline id="1"><vertexRoad s="5" t="-4" dz="0" radius="0.1" id="1"/></polyline>
    """
    for obj, polyline in polylines(ctx):
        counts = {kind: sum(1 for v in polyline.vertices if v.kind == kind) for kind in _MIN_UID}
        where = at(ctx, obj, polyline.line)
        for kind, uid in _MIN_UID.items():
            if counts[kind] == 1:
                yield skeleton_too_few_vertices.finding(
                    f"{label(obj)}: {polyline_name(polyline)} has one <{kind}>: a polyline needs at least two points",
                    uid=uid,
                    **where,
                )
        if max(counts.values()) < 2:
            found = ", ".join(f"{n} <{k}>" for k, n in counts.items() if n) or "no vertex"
            yield skeleton_too_few_vertices.finding(
                f"{label(obj)}: {polyline_name(polyline)} has {found}: a polyline is two or more <vertexRoad> or two "
                "or more <vertexLocal> elements",
                uid=U.SKELETON_FOLLOWED_BY_VERTEX,
                **where,
            )


_SIZE_UID = {VERTEX_ROAD: U.VERTEX_ROAD_SIZE, VERTEX_LOCAL: U.VERTEX_LOCAL_SIZE}


def _size(v: Vertex) -> str:
    """How a vertex gives its cross-section: ``radius``, ``box`` (width and length), ``both``, ``partial`` or
    ``none``."""
    box = v.width is not None and v.length is not None
    if v.radius is not None:
        return "both" if v.width is not None or v.length is not None else "radius"
    if box:
        return "box"
    return "partial" if v.width is not None or v.length is not None else "none"


@rule(
    "B032",
    "skeleton-vertex-size",
    Category.OBJECT,
    Severity.ERROR,
    uids=(U.SKELETON_RADIUS_OR_WIDTH_LENGTH, *_SIZE_UID.values()),
)
def skeleton_vertex_size(ctx: Context):
    """The points of a skeleton polyline do not all give their cross-section the same way.

    Each polyline uses ``radius`` for all of its points, or ``width`` and ``length`` for all of them (Annex F
    ``road.object.skeleton.use_radius_or_width_length``, 13.3): a point without either, with only one of width and
    length, or a polyline using both ways breaks it. Using ``radius`` together with ``width`` and ``length`` in one
    polyline also breaks ``.vertex_road.no_radius_with_width_length`` or ``.vertex_local.vertex_local_elements`` (by
    the kind of its points). (The schemas know only ``radius``; the standard's examples use width and length.)

    Passes::

        <vertexLocal u="0" v="0" z="0" radius="0.15" id="1"/><vertexLocal u="0" v="0" z="4" radius="0.12" id="2"/>

    Fails::

        <vertexLocal u="0" v="0" z="0" radius="0.15" id="1"/><vertexLocal u="0" v="0" z="4" width="0.3"
          length="0.3" id="2"/>
    """
    for obj, polyline in polylines(ctx):
        if not polyline.vertices:
            continue
        sizes = [_size(v) for v in polyline.vertices]
        name = f"{label(obj)}: {polyline_name(polyline)}"
        bad = next((v for v, size in zip(polyline.vertices, sizes, strict=True) if size in ("none", "partial")), None)
        mixed = "both" in sizes or {"radius", "box"} <= set(sizes)
        if mixed:
            first = next(v for v, size in zip(polyline.vertices, sizes, strict=True) if size in ("both", "box"))
            text = f"{name} uses radius and width/length (the <{first.kind}> at line {first.line})"
            for uid in sorted({_SIZE_UID[v.kind] for v in polyline.vertices}):
                yield skeleton_vertex_size.finding(
                    f"{text}: its points shall not use radius together with width and length",
                    uid=uid,
                    **at(ctx, obj, first.line),
                )
            yield skeleton_vertex_size.finding(
                f"{text}: give all its points a radius, or all of them width and length",
                uid=U.SKELETON_RADIUS_OR_WIDTH_LENGTH,
                **at(ctx, obj, first.line),
            )
        elif bad is not None:
            what = "neither radius nor width and length" if _size(bad) == "none" else "only one of width and length"
            yield skeleton_vertex_size.finding(
                f"{name}: the <{bad.kind}> at line {bad.line} has {what}: give all the polyline's points a radius, "
                "or all of them width and length",
                uid=U.SKELETON_RADIUS_OR_WIDTH_LENGTH,
                **at(ctx, obj, bad.line),
            )


def _point(v: Vertex) -> tuple[float, float, float] | None:
    return None if v.a is None or v.b is None or v.c is None else (v.a, v.b, v.c)


def _same_place(a: Vertex, b: Vertex, tol: float) -> bool:
    pa, pb = _point(a), _point(b)
    if a.kind != b.kind or pa is None or pb is None:
        return False
    return math.dist(pa, pb) <= tol


@rule(
    "B033",
    "skeleton-segment-degenerate",
    Category.OBJECT,
    Severity.INFO,
    uids=(U.SKELETON_POINTS_REQUIREMENTS,),
)
def skeleton_segment_degenerate(ctx: Context):
    """Two successive points of a skeleton polyline are at the same place: the segment between them has no
    direction.

    The points of a polyline are joined by straight lines and each point's radius (or width and length) lies
    perpendicular to that line (Annex F ``road.object.skeleton.points_requirements``, 13.3); between two points
    closer than the ``position`` tolerance there is no line to be perpendicular to. (An information, as the annex's
    wording.)

    Passes::

        <vertexLocal u="0" v="0" z="0" radius="0.15" id="1"/><vertexLocal u="0" v="0" z="4" radius="0.12" id="2"/>

    Fails::

        <vertexLocal u="0" v="0" z="0" radius="0.15" id="1"/><vertexLocal u="0" v="0" z="0" radius="0.12" id="2"/>
    """
    tol = ctx.tolerances.position
    for obj, polyline in polylines(ctx):
        for a, b in zip(polyline.vertices, polyline.vertices[1:], strict=False):
            if _same_place(a, b, tol):
                yield skeleton_segment_degenerate.finding(
                    f"{label(obj)}: in {polyline_name(polyline)} the <{b.kind}> at line {b.line} is where the one "
                    f"before it (line {a.line}) is: the segment between them has no direction for the cross-section "
                    "to be perpendicular to; remove one of them",
                    **at(ctx, obj, b.line),
                )
