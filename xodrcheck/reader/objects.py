"""A road's (or junction's) ``<objects>`` to :mod:`xodrcheck.model.objects` records: objects with their outlines,
skeletons, markings, borders, repeats, materials, surfaces and validities; object references, tunnels, bridges.

Read as the file gives them (the schema rule reports bad values). What OpenDRIVE 1.9 added is read only from 1.9
files on (and from files of unknown version, read as 1.9): ``<curveLocal>`` shapes need no gate (no earlier schema has
them), but an ``<outline>`` without ``outer`` is outer only in 1.9 ("Omitting @outer shall default to @outer=true",
13.2), and ``invalidated``/``temporary`` and a validity's ``layer`` are read from 1.9 on.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TypeVar

from lxml import etree

from xodrcheck.model import (
    CORNER_LOCAL,
    CORNER_ROAD,
    CURVE_LOCAL,
    VERTEX_LOCAL,
    VERTEX_ROAD,
    Arc,
    Bridge,
    CornerLocal,
    CornerReference,
    CornerRoad,
    CurveLocal,
    CurveShape,
    LaneLayer,
    LaneValidity,
    Line,
    Marking,
    Markings,
    ObjectBorder,
    ObjectCrg,
    ObjectMaterial,
    ObjectReference,
    ObjectSurface,
    Orientation,
    Outline,
    OutlinePoint,
    ParamPoly3,
    ParkingSpace,
    Polyline,
    PRange,
    Repeat,
    RoadObject,
    RoadStructure,
    Skeleton,
    Tunnel,
    Vertex,
    XmlFacts,
)
from xodrcheck.reader.context import LEAF, Context
from xodrcheck.reader.lanes import LAYERS, layered

ORIENTATIONS = {o.value: o for o in Orientation}
_P_RANGES = {p.value: p for p in PRange}
_PARAM_POLY3 = ("aU", "bU", "cU", "dU", "aV", "bV", "cV", "dV")
_POINTS = frozenset({CORNER_ROAD, CORNER_LOCAL, CURVE_LOCAL})
_VERTICES = {VERTEX_ROAD: ("s", "t", "dz"), VERTEX_LOCAL: ("u", "v", "z")}
_VALIDITY = frozenset({"validity"})
_POLYLINE = frozenset(_VERTICES)
_S = TypeVar("_S", bound=RoadStructure)
_REFERENCES = frozenset({"cornerReference"})
_OUTLINE = _POINTS | {"markings"}
_CURVE_SHAPES = ("line", "arc", "paramPoly3")
_OBJECT = frozenset(
    {
        "repeat",
        "outline",
        "outlines",
        "material",
        "validity",
        "parkingSpace",
        "markings",
        "borders",
        "skeleton",
        "surface",
    }
)
#: The optional numbers of a ``<repeat>``: attribute -> field.
_REPEAT_EXTRAS = {
    "bT": "bt",
    "cT": "ct",
    "dT": "dt",
    "zOffsetStart": "z_offset_start",
    "zOffsetEnd": "z_offset_end",
    "lengthStart": "length_start",
    "lengthEnd": "length_end",
    "widthStart": "width_start",
    "widthEnd": "width_end",
    "heightStart": "height_start",
    "heightEnd": "height_end",
    "radiusStart": "radius_start",
    "radiusEnd": "radius_end",
}


def _numbers(ctx: Context, el: etree._Element, names: tuple[str, ...]) -> tuple[float, ...] | None:
    values = [ctx.opt_number(el, name) for name in names]
    found = tuple(v for v in values if v is not None)
    return found if len(found) == len(values) else None


def validities(ctx: Context, el: etree._Element) -> tuple[LaneValidity, ...]:
    """The ``<validity>`` children of ``el`` (lanes ``None`` when not integers; ``layer`` read from 1.9 on)."""
    out = []
    for v in el.iterchildren("validity"):
        from_lane, to_lane = ctx.opt_integer(v, "fromLane"), ctx.opt_integer(v, "toLane")
        layer = LaneLayer.PERMANENT
        if layered(ctx):
            layer = ctx.opt_enum(v, "layer", LAYERS) or LaneLayer.PERMANENT
        out.append(LaneValidity(from_lane, to_lane, layer, v.sourceline, ctx.facts(v, LEAF)))
    return tuple(out)


# ------------------------------------------------------------------------------------------------------ outlines
def _shape(ctx: Context, kind: etree._Element, u: float, v: float, hdg: float, span: float) -> CurveShape | None:
    line = kind.sourceline
    if kind.tag == "line":
        return Line(0.0, u, v, hdg, span, line, ctx.facts(kind, LEAF))
    if kind.tag == "arc":
        curvature = ctx.opt_number(kind, "curvature")
        return None if curvature is None else Arc(0.0, u, v, hdg, span, curvature, line, ctx.facts(kind, LEAF))
    c = _numbers(ctx, kind, _PARAM_POLY3)
    p_range = _P_RANGES.get(kind.get("pRange", "normalized"))
    if p_range is None:
        ctx.note_invalid(kind, "pRange", kind.get("pRange", ""))
    if c is None or p_range is None:
        return None
    au, bu, cu, du, av, bv, cv, dv = c
    return ParamPoly3(0.0, u, v, hdg, span, au, bu, cu, du, av, bv, cv, dv, p_range, line, ctx.facts(kind, LEAF))


def _curve(ctx: Context, el: etree._Element) -> tuple[CurveLocal | None, int | None, XmlFacts]:
    """The curve (``None`` when its ``u``, ``v``, ``z`` or ``height`` does not parse), its id and facts."""
    head = _numbers(ctx, el, ("u", "v", "z", "height"))
    hdg = ctx.opt_number(el, "hdg") or 0.0
    length = ctx.opt_number(el, "length")
    ident = ctx.opt_integer(el, "id")
    facts = ctx.facts(el, frozenset(_CURVE_SHAPES))
    if head is None:
        return None, ident, facts
    span = length if length is not None and length > 0 else 0.0
    kind = next(el.iterchildren(*_CURVE_SHAPES), None)
    shape = None if kind is None else _shape(ctx, kind, head[0], head[1], hdg, span)
    curve = CurveLocal(head[0], head[1], head[2], head[3], hdg, length, shape, ident, el.sourceline, facts)
    return curve, ident, facts


def _corner(ctx: Context, el: etree._Element) -> tuple[CornerRoad | CornerLocal | None, int | None, XmlFacts]:
    """The corner (``None`` when a number does not parse), its id and facts."""
    names = ("s", "t", "dz", "height") if el.tag == CORNER_ROAD else ("u", "v", "z", "height")
    c = _numbers(ctx, el, names)
    ident = ctx.opt_integer(el, "id")
    facts = ctx.facts(el, LEAF)
    if c is None:
        return None, ident, facts
    kind = CornerRoad if el.tag == CORNER_ROAD else CornerLocal
    return kind(c[0], c[1], c[2], c[3], ident, el.sourceline, facts), ident, facts


def _references(ctx: Context, el: etree._Element) -> tuple[CornerReference, ...]:
    return tuple(
        CornerReference(ctx.opt_integer(r, "id"), r.sourceline, ctx.facts(r, LEAF))
        for r in el.iterchildren("cornerReference")
    )


def _marking(ctx: Context, el: etree._Element) -> Marking:
    n = ctx.opt_number
    return Marking(
        el.get("color"),
        el.get("side"),
        n(el, "width"),
        n(el, "zOffset"),
        n(el, "spaceLength"),
        n(el, "lineLength"),
        n(el, "startOffset"),
        n(el, "stopOffset"),
        el.get("weight"),
        _references(ctx, el),
        el.sourceline,
        ctx.facts(el, _REFERENCES),
    )


def _markings(ctx: Context, el: etree._Element) -> Markings:
    found = tuple(_marking(ctx, m) for m in el.iterchildren("marking"))
    return Markings(found, el.sourceline, ctx.facts(el, frozenset({"marking"})))


def _outline(ctx: Context, el: etree._Element, wrapped: bool) -> Outline:
    corners: list[CornerRoad | CornerLocal] = []
    curves: list[CurveLocal] = []
    points: list[OutlinePoint] = []
    markings = None
    for child in el:
        tag = child.tag
        if tag == CURVE_LOCAL:
            curve, ident, facts = _curve(ctx, child)
            if curve is not None:
                curves.append(curve)
            points.append(OutlinePoint(tag, ident, child.sourceline, facts))
        elif tag in _POINTS:
            corner, ident, facts = _corner(ctx, child)
            if corner is not None:
                corners.append(corner)
            points.append(OutlinePoint(tag, ident, child.sourceline, facts))
        elif tag == "markings" and markings is None:
            markings = _markings(ctx, child)
    outer = ctx.opt_boolean(el, "outer")
    if outer is None and el.get("outer") is None and layered(ctx):
        outer = True
    return Outline(
        ctx.opt_integer(el, "id"),
        outer,
        ctx.opt_boolean(el, "closed"),
        el.get("fillType"),
        el.get("laneType"),
        tuple(corners),
        tuple(curves),
        el.sourceline,
        tuple(points),
        markings,
        wrapped,
        ctx.facts(el, _OUTLINE),
    )


# ------------------------------------------------------------------------------------------------------ other parts
def _repeat(ctx: Context, el: etree._Element) -> Repeat | None:
    head = _numbers(ctx, el, ("s", "length", "distance", "tStart", "tEnd"))
    extra = {field: ctx.opt_number(el, name) for name, field in _REPEAT_EXTRAS.items()}
    detach = ctx.opt_boolean(el, "detachFromReferenceLine")
    facts = ctx.facts(el, LEAF)
    if head is None:
        return None
    s, length, distance, t_start, t_end = head
    return Repeat(s, length, distance, t_start, t_end, line=el.sourceline, detach=detach, xml=facts, **extra)


def _skeleton(ctx: Context, el: etree._Element) -> Skeleton:
    polylines = []
    for poly in el.iterchildren("polyline"):
        vertices = []
        for v in poly.iterchildren(VERTEX_ROAD, VERTEX_LOCAL):
            a, b, c = (ctx.opt_number(v, name) for name in _VERTICES[v.tag])
            size = (ctx.opt_number(v, "radius"), ctx.opt_number(v, "width"), ctx.opt_number(v, "length"))
            ident, crossing = ctx.opt_integer(v, "id"), ctx.opt_boolean(v, "intersectionPoint")
            vertices.append(Vertex(v.tag, a, b, c, *size, ident, crossing, v.sourceline, ctx.facts(v, LEAF)))
        ident = ctx.opt_integer(poly, "id")
        polylines.append(Polyline(ident, tuple(vertices), poly.sourceline, ctx.facts(poly, _POLYLINE)))
    return Skeleton(tuple(polylines), el.sourceline, ctx.facts(el, frozenset({"polyline"})))


def _borders(ctx: Context, el: etree._Element) -> tuple[ObjectBorder, ...]:
    out = []
    for b in el.iterchildren("border"):
        out.append(
            ObjectBorder(
                ctx.opt_integer(b, "outlineId"),
                b.get("type"),
                ctx.opt_number(b, "width"),
                ctx.opt_boolean(b, "useCompleteOutline"),
                _references(ctx, b),
                b.sourceline,
                ctx.facts(b, _REFERENCES),
            )
        )
    return tuple(out)


def _material(ctx: Context, el: etree._Element) -> ObjectMaterial:
    return ObjectMaterial(
        el.get("surface"),
        ctx.opt_number(el, "friction"),
        ctx.opt_number(el, "roughness"),
        el.get("roadMarkColor"),
        el.sourceline,
        ctx.facts(el, LEAF),
    )


def _surface(ctx: Context, el: etree._Element) -> ObjectSurface:
    crgs = tuple(
        ObjectCrg(
            c.get("file"),
            ctx.opt_boolean(c, "hideRoadSurfaceCRG"),
            ctx.opt_number(c, "zScale"),
            c.sourceline,
            ctx.facts(c, LEAF),
        )
        for c in el.iterchildren("CRG")
    )
    return ObjectSurface(crgs, el.sourceline, ctx.facts(el, frozenset({"CRG"})))


# ------------------------------------------------------------------------------------------------------ objects
def _object(ctx: Context, owner: str, el: etree._Element) -> RoadObject | None:
    """The object of ``el``; ``None`` when it has no id (nothing could refer to it)."""
    object_id = el.get("id")
    if object_id is None:
        return None
    outlines = [_outline(ctx, o, False) for o in el.iterchildren("outline")]
    wrappers = list(el.iterchildren("outlines"))
    for group in wrappers:
        outlines.extend(_outline(ctx, o, True) for o in group.iterchildren("outline"))
    repeats = tuple(r for r in (_repeat(ctx, child) for child in el.iterchildren("repeat")) if r is not None)
    skeleton = next((_skeleton(ctx, s) for s in el.iterchildren("skeleton")), None)
    markings = tuple(_markings(ctx, m) for m in el.iterchildren("markings"))
    borders = tuple(b for group in el.iterchildren("borders") for b in _borders(ctx, group))
    materials = tuple(_material(ctx, m) for m in el.iterchildren("material"))
    surfaces = tuple(_surface(ctx, s) for s in el.iterchildren("surface"))
    parking = next(
        (
            ParkingSpace(p.get("access"), p.get("restrictions"), p.sourceline, ctx.facts(p, LEAF))
            for p in el.iterchildren("parkingSpace")
        ),
        None,
    )
    found = validities(ctx, el)
    invalidated = temporary = None
    if layered(ctx):
        invalidated, temporary = ctx.opt_boolean(el, "invalidated"), ctx.opt_boolean(el, "temporary")
    n = ctx.opt_number
    return RoadObject(
        owner,
        object_id,
        el.get("type"),
        n(el, "s"),
        n(el, "t"),
        n(el, "zOffset"),
        hdg=n(el, "hdg"),
        length=n(el, "length"),
        width=n(el, "width"),
        radius=n(el, "radius"),
        height=n(el, "height"),
        invalidated=invalidated,
        temporary=temporary,
        outlines=tuple(outlines),
        repeats=repeats,
        validities=found,
        line=el.sourceline,
        orientation=ctx.opt_enum(el, "orientation", ORIENTATIONS),
        subtype=el.get("subtype"),
        name=el.get("name"),
        pitch=n(el, "pitch"),
        roll=n(el, "roll"),
        perp_to_road=ctx.opt_boolean(el, "perpToRoad"),
        valid_length=n(el, "validLength"),
        outlines_line=wrappers[0].sourceline if wrappers else None,
        skeleton=skeleton,
        markings=markings,
        borders=borders,
        materials=materials,
        surfaces=surfaces,
        dynamic=_yes_no(ctx, el, "dynamic"),
        parking_space=parking,
        xml=ctx.facts(el, _OBJECT),
    )


_YES_NO = {"yes": True, "no": False}


def _yes_no(ctx: Context, el: etree._Element, name: str) -> bool | None:
    return ctx.opt_enum(el, name, _YES_NO)


def _reference(ctx: Context, owner: str, el: etree._Element) -> ObjectReference:
    n = ctx.opt_number
    return ObjectReference(
        owner,
        el.get("id"),
        n(el, "s"),
        n(el, "t"),
        n(el, "zOffset"),
        n(el, "validLength"),
        ctx.opt_enum(el, "orientation", ORIENTATIONS),
        validities(ctx, el),
        el.sourceline,
        ctx.facts(el, _VALIDITY),
    )


def _structure(ctx: Context, owner: str, el: etree._Element, kind: type[_S], numbers: tuple[str, ...] = ()) -> _S:
    """A ``<tunnel>`` or ``<bridge>`` as ``kind``; ``numbers`` name the numeric attributes only ``kind`` has (read
    after ``s`` and ``length``)."""
    n = ctx.opt_number
    found = validities(ctx, el)
    s, length = n(el, "s"), n(el, "length")
    own = {name: n(el, name) for name in numbers}
    return kind(
        owner,
        el.get("id"),
        s,
        length,
        el.get("type"),
        el.get("name"),
        found,
        el.sourceline,
        ctx.facts(el, _VALIDITY),
        **own,
    )


def _tunnel(ctx: Context, owner: str, el: etree._Element) -> Tunnel:
    return _structure(ctx, owner, el, Tunnel, ("lighting", "daylight"))


def _bridge(ctx: Context, owner: str, el: etree._Element) -> Bridge:
    return _structure(ctx, owner, el, Bridge)


@dataclass(frozen=True, slots=True)
class Objects:
    """What one ``<objects>`` element holds, each kind in file order."""

    objects: tuple[RoadObject, ...] = ()
    references: tuple[ObjectReference, ...] = ()
    tunnels: tuple[Tunnel, ...] = ()
    bridges: tuple[Bridge, ...] = ()


NO_OBJECTS = Objects()


def read_objects(ctx: Context, owner: str, el: etree._Element) -> Objects:
    """The records of an ``<objects>`` element of road (or junction) ``owner``."""
    objects: list[RoadObject] = []
    references: list[ObjectReference] = []
    tunnels: list[Tunnel] = []
    bridges: list[Bridge] = []
    for child in el:
        tag = child.tag
        if tag == "object":
            obj = _object(ctx, owner, child)
            if obj is not None:
                objects.append(obj)
        elif tag == "objectReference":
            references.append(_reference(ctx, owner, child))
        elif tag == "tunnel":
            tunnels.append(_tunnel(ctx, owner, child))
        elif tag == "bridge":
            bridges.append(_bridge(ctx, owner, child))
    return Objects(tuple(objects), tuple(references), tuple(tunnels), tuple(bridges))
