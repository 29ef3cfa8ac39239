"""Reading road objects from the file's XML (``<road><objects>``) into :mod:`xodrcheck.objects.model`.

Element names are matched whatever their namespace (``ctx.tree`` keeps a file's default namespace). What OpenDRIVE
1.9 added is read only from 1.9 files on (and from files of unknown version, read as 1.9): ``<curveLocal>`` shapes
need no gate (no earlier schema has them), but an ``<outline>`` without ``outer`` is outer only in 1.9 ("Omitting
@outer shall default to @outer=true", 13.2), and ``invalidated``/``temporary`` and a validity's ``layer`` are read
from 1.9 on. Before 1.9 the standard gave ``outer`` no default: :attr:`Outline.outer` stays ``None``.
"""

from __future__ import annotations

from collections.abc import Iterator

from lxml import etree

from xodrcheck.model import Arc, LaneLayer, Line, ParamPoly3, PRange
from xodrcheck.objects.model import (
    CORNER_LOCAL,
    CORNER_ROAD,
    CURVE_LOCAL,
    VERTEX_LOCAL,
    VERTEX_ROAD,
    Border,
    CornerLocal,
    CornerReference,
    CornerRoad,
    CurveLocal,
    CurveShape,
    LaneValidity,
    Marking,
    Markings,
    Material,
    ObjectCrg,
    ObjectReference,
    Outline,
    OutlinePoint,
    Polyline,
    Repeat,
    RoadObject,
    RoadObjects,
    Skeleton,
    Structure,
    Surface,
    Vertex,
)
from xodrcheck.xmlvalues import integer, number

_BOOLEANS = {"true": True, "1": True, "false": False, "0": False}
_LAYERS = {layer.value: layer for layer in LaneLayer}
_P_RANGES = {"arcLength": PRange.ARC_LENGTH, "normalized": PRange.NORMALIZED}
_PARAM_POLY3 = ("aU", "bU", "cU", "dU", "aV", "bV", "cV", "dV")
_POINTS = (CORNER_ROAD, CORNER_LOCAL, CURVE_LOCAL)


def _name(el: etree._Element) -> str:
    return etree.QName(el).localname if isinstance(el.tag, str) else ""


def _children(el: etree._Element, name: str) -> Iterator[etree._Element]:
    """Children named ``name`` whatever their namespace."""
    for child in el:
        if isinstance(child.tag, str) and etree.QName(child).localname == name:
            yield child


def _number(el: etree._Element, name: str) -> float | None:
    return number(el.get(name))


def _integer(el: etree._Element, name: str) -> int | None:
    return integer(el.get(name))


def _boolean(el: etree._Element, name: str) -> bool | None:
    raw = el.get(name)
    return None if raw is None else _BOOLEANS.get(raw.strip())


def _numbers(el: etree._Element, names: tuple[str, ...]) -> tuple[float, ...] | None:
    values = tuple(_number(el, name) for name in names)
    found = tuple(v for v in values if v is not None)
    return found if len(found) == len(values) else None


def _line(el: etree._Element) -> int:
    return el.sourceline or 0


# ------------------------------------------------------------------------------------------------------- outlines
def _shape(kind: etree._Element, u: float, v: float, hdg: float, span: float) -> CurveShape | None:
    name = _name(kind)
    if name == "line":
        return Line(0.0, u, v, hdg, span, _line(kind))
    if name == "arc":
        curvature = _number(kind, "curvature")
        return None if curvature is None else Arc(0.0, u, v, hdg, span, curvature, _line(kind))
    c = _numbers(kind, _PARAM_POLY3)
    p_range = _P_RANGES.get(kind.get("pRange", "normalized"))
    if c is None or p_range is None:
        return None
    au, bu, cu, du, av, bv, cv, dv = c
    return ParamPoly3(0.0, u, v, hdg, span, au, bu, cu, du, av, bv, cv, dv, p_range, _line(kind))


def _curve(el: etree._Element) -> CurveLocal | None:
    head = _numbers(el, ("u", "v", "z", "height"))
    if head is None:
        return None
    hdg = _number(el, "hdg") or 0.0
    length = _number(el, "length")
    span = length if length is not None and length > 0 else 0.0
    kind = next((k for k in el if _name(k) in ("line", "arc", "paramPoly3")), None)
    shape = None if kind is None else _shape(kind, head[0], head[1], hdg, span)
    return CurveLocal(head[0], head[1], head[2], head[3], hdg, length, shape, _integer(el, "id"), _line(el))


def _references(el: etree._Element) -> tuple[CornerReference, ...]:
    return tuple(CornerReference(_integer(r, "id"), _line(r)) for r in _children(el, "cornerReference"))


def _marking(el: etree._Element) -> Marking:
    return Marking(
        el.get("color"),
        el.get("side"),
        _number(el, "width"),
        _number(el, "zOffset"),
        _number(el, "spaceLength"),
        _number(el, "lineLength"),
        _number(el, "startOffset"),
        _number(el, "stopOffset"),
        el.get("weight"),
        _references(el),
        _line(el),
    )


def _markings(el: etree._Element) -> Markings:
    return Markings(tuple(_marking(m) for m in _children(el, "marking")), _line(el))


def _corner(child: etree._Element, name: str) -> CornerRoad | CornerLocal | None:
    if name == CORNER_ROAD:
        c = _numbers(child, ("s", "t", "dz", "height"))
        return None if c is None else CornerRoad(c[0], c[1], c[2], c[3], _integer(child, "id"), _line(child))
    c = _numbers(child, ("u", "v", "z", "height"))
    return None if c is None else CornerLocal(c[0], c[1], c[2], c[3], _integer(child, "id"), _line(child))


def _outline(el: etree._Element, layered: bool, wrapped: bool) -> Outline:
    corners: list[CornerRoad | CornerLocal] = []
    curves: list[CurveLocal] = []
    points: list[OutlinePoint] = []
    markings = None
    for child in el:
        name = _name(child)
        if name in _POINTS:
            points.append(OutlinePoint(name, _integer(child, "id"), child.get("id"), _line(child)))
            if name == CURVE_LOCAL:
                curve = _curve(child)
                if curve is not None:
                    curves.append(curve)
            elif (corner := _corner(child, name)) is not None:
                corners.append(corner)
        elif name == "markings" and markings is None:
            markings = _markings(child)
    outer = _boolean(el, "outer")
    if outer is None and el.get("outer") is None and layered:
        outer = True
    return Outline(
        _integer(el, "id"),
        outer,
        _boolean(el, "closed"),
        el.get("fillType"),
        el.get("laneType"),
        tuple(corners),
        tuple(curves),
        _line(el),
        tuple(points),
        markings,
        wrapped,
        el.get("id"),
    )


# ------------------------------------------------------------------------------------------- other object parts
def _repeat(el: etree._Element) -> Repeat | None:
    head = _numbers(el, ("s", "length", "distance", "tStart", "tEnd"))
    if head is None:
        return None
    s, length, distance, t_start, t_end = head
    n = _number
    return Repeat(
        s,
        length,
        distance,
        t_start,
        t_end,
        bt=n(el, "bT"),
        ct=n(el, "cT"),
        dt=n(el, "dT"),
        line=_line(el),
        z_offset_start=n(el, "zOffsetStart"),
        z_offset_end=n(el, "zOffsetEnd"),
        length_start=n(el, "lengthStart"),
        length_end=n(el, "lengthEnd"),
        width_start=n(el, "widthStart"),
        width_end=n(el, "widthEnd"),
        height_start=n(el, "heightStart"),
        height_end=n(el, "heightEnd"),
        radius_start=n(el, "radiusStart"),
        radius_end=n(el, "radiusEnd"),
        detach=_boolean(el, "detachFromReferenceLine"),
    )


def _validity(el: etree._Element, layered: bool) -> LaneValidity | None:
    from_lane, to_lane = _integer(el, "fromLane"), _integer(el, "toLane")
    if from_lane is None or to_lane is None:
        return None
    layer = _LAYERS.get(el.get("layer") or "permanent") if layered else LaneLayer.PERMANENT
    return LaneValidity(from_lane, to_lane, layer or LaneLayer.PERMANENT, _line(el))


def _validities(el: etree._Element, layered: bool) -> tuple[LaneValidity, ...]:
    found = (_validity(child, layered) for child in _children(el, "validity"))
    return tuple(v for v in found if v is not None)


def _skeleton(el: etree._Element) -> Skeleton:
    polylines = []
    for poly in _children(el, "polyline"):
        vertices = []
        for v in poly:
            kind = _name(v)
            if kind not in (VERTEX_ROAD, VERTEX_LOCAL):
                continue
            names = ("s", "t", "dz") if kind == VERTEX_ROAD else ("u", "v", "z")
            a, b, c = (_number(v, name) for name in names)
            extra = (_number(v, "radius"), _number(v, "width"), _number(v, "length"), _integer(v, "id"))
            vertices.append(Vertex(kind, a, b, c, *extra, _boolean(v, "intersectionPoint"), _line(v)))
        polylines.append(Polyline(_integer(poly, "id"), tuple(vertices), _line(poly)))
    return Skeleton(tuple(polylines), _line(el))


def _borders(el: etree._Element) -> Iterator[Border]:
    for group in _children(el, "borders"):
        for b in _children(group, "border"):
            yield Border(
                _integer(b, "outlineId"),
                b.get("type"),
                _number(b, "width"),
                _boolean(b, "useCompleteOutline"),
                _references(b),
                _line(b),
            )


def _materials(el: etree._Element) -> tuple[Material, ...]:
    return tuple(
        Material(m.get("surface"), _number(m, "friction"), _number(m, "roughness"), m.get("roadMarkColor"), _line(m))
        for m in _children(el, "material")
    )


def _surfaces(el: etree._Element) -> tuple[Surface, ...]:
    return tuple(
        Surface(
            tuple(
                ObjectCrg(c.get("file"), _boolean(c, "hideRoadSurfaceCRG"), _number(c, "zScale"), _line(c))
                for c in _children(surface, "CRG")
            ),
            _line(surface),
        )
        for surface in _children(el, "surface")
    )


def _object(road_id: str, el: etree._Element, layered: bool) -> RoadObject | None:
    object_id = el.get("id")
    if object_id is None:
        return None
    outlines = [_outline(o, layered, False) for o in _children(el, "outline")]
    wrappers = list(_children(el, "outlines"))
    for group in wrappers:
        outlines.extend(_outline(o, layered, True) for o in _children(group, "outline"))
    repeats = tuple(r for r in (_repeat(child) for child in _children(el, "repeat")) if r is not None)
    invalidated, temporary = (_boolean(el, "invalidated"), _boolean(el, "temporary")) if layered else (None, None)
    skeleton = next((_skeleton(s) for s in _children(el, "skeleton")), None)
    n = _number
    return RoadObject(
        road_id,
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
        validities=_validities(el, layered),
        line=_line(el),
        orientation=el.get("orientation"),
        subtype=el.get("subtype"),
        name=el.get("name"),
        pitch=n(el, "pitch"),
        roll=n(el, "roll"),
        perp_to_road=_boolean(el, "perpToRoad"),
        valid_length=n(el, "validLength"),
        outlines_line=_line(wrappers[0]) if wrappers else None,
        skeleton=skeleton,
        markings=tuple(_markings(m) for m in _children(el, "markings")),
        borders=tuple(_borders(el)),
        materials=_materials(el),
        surfaces=_surfaces(el),
        attributes=frozenset(str(k) for k in el.attrib),
    )


def _reference(road_id: str, el: etree._Element, layered: bool) -> ObjectReference:
    return ObjectReference(
        road_id,
        el.get("id"),
        _number(el, "s"),
        _number(el, "t"),
        _number(el, "zOffset"),
        _number(el, "validLength"),
        el.get("orientation"),
        _validities(el, layered),
        _line(el),
    )


def _structure(road_id: str, el: etree._Element, layered: bool) -> Structure:
    return Structure(
        _name(el),
        road_id,
        el.get("id"),
        _number(el, "s"),
        _number(el, "length"),
        el.get("type"),
        el.get("name"),
        _validities(el, layered),
        _line(el),
    )


# ------------------------------------------------------------------------------------------------------------ roads
def read_road_objects(root: etree._Element, version: tuple[int, int] | None) -> dict[str, RoadObjects]:
    """Road id -> everything in the road's ``<objects>`` (roads without any are left out), from the ``<OpenDRIVE>``
    element of a file declaring ``version`` (``None``: unknown, read as 1.9). A road id given twice merges."""
    layered = version is None or version >= (1, 9)
    out: dict[str, RoadObjects] = {}
    for road in _children(root, "road"):
        road_id = road.get("id")
        if road_id is None:
            continue
        objects: list[RoadObject] = []
        references: list[ObjectReference] = []
        structures: list[Structure] = []
        for group in _children(road, "objects"):
            for el in group:
                name = _name(el)
                if name == "object" and (obj := _object(road_id, el, layered)) is not None:
                    objects.append(obj)
                elif name == "objectReference":
                    references.append(_reference(road_id, el, layered))
                elif name in ("tunnel", "bridge"):
                    structures.append(_structure(road_id, el, layered))
        if objects or references or structures:
            old = out.get(road_id, RoadObjects(road_id))
            out[road_id] = RoadObjects(
                road_id,
                old.objects + tuple(objects),
                old.references + tuple(references),
                old.structures + tuple(structures),
            )
    return out


def read_objects(root: etree._Element, version: tuple[int, int] | None) -> dict[str, tuple[RoadObject, ...]]:
    """Road id -> the road's objects in file order (roads without objects are left out); see
    :func:`read_road_objects`."""
    return {road: found.objects for road, found in read_road_objects(root, version).items() if found.objects}
