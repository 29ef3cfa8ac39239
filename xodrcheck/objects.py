"""Road objects as plain, frozen, typed data, built from the file's XML (``<road><objects><object>``), with the geometry
OpenDRIVE 1.9 added to them: outlines of ``<curveLocal>`` curves (13.2.3) and repetition along a cubic ``t`` (13.4).

What an object holds here is what its position and shape need, plus 1.9's ``invalidated`` and ``temporary`` flags and
the lane layer of its lane validity; rules that need more read it from ``ctx.tree``. Values that do not parse are
``None`` (the schema rule reports them); nothing here reports findings. :func:`read_objects` builds the objects of a
whole file; a rule gets them from :attr:`xodrcheck.rules.context.Context.objects`, built once per file.

Geometry, in the object's local ``u``/``v`` frame (13.2.2: origin at the object's position, ``u`` along its heading):

* a ``<cornerLocal>`` outline is its corners, joined by straight lines;
* a ``<curveLocal>`` starts at ``(u, v)`` with heading ``hdg`` and runs ``length`` along a line, an arc or a
  paramPoly3 (``pRange`` normalized: ``p`` in [0, 1]; arcLength: ``p`` in [0, length]), exactly as the plan-view
  element of the same kind (:func:`xodrcheck.geometry.planview.evaluate_element`, the one evaluator of those shapes);
* a ``<cornerRoad>`` outline is in road ``s``/``t`` and is not evaluated here;
* a ``<repeat>``'s ``t`` is the cubic ``tStart + bT ds + cT ds^2 + dT ds^3`` (``ds`` from the repeat's ``s``) when
  any of ``bT``, ``cT``, ``dT`` is given (1.9), else linear from ``tStart`` to ``tEnd`` (:attr:`Repeat.t_profile`, a
  :class:`~xodrcheck.model.Cubic` evaluated by :mod:`xodrcheck.geometry.profile`).

An ``<outline>`` without ``outer`` is an outer outline in 1.9 files (13.2: "Omitting @outer shall default to
@outer=true"); before 1.9 the standard gave no default and :attr:`Outline.outer` is ``None``.
"""

from __future__ import annotations

import math
from collections.abc import Iterator
from dataclasses import dataclass

import numpy as np
from lxml import etree

from xodrcheck.model import Arc, Cubic, LaneLayer, Line, ParamPoly3, PRange

#: The shapes a ``<curveLocal>`` may have, as plan-view elements starting at ``s = 0``.
CurveShape = Line | Arc | ParamPoly3

_BOOLEANS = {"true": True, "1": True, "false": False, "0": False}
_LAYERS = {layer.value: layer for layer in LaneLayer}
_P_RANGES = {"arcLength": PRange.ARC_LENGTH, "normalized": PRange.NORMALIZED}
_PARAM_POLY3 = ("aU", "bU", "cU", "dU", "aV", "bV", "cV", "dV")


@dataclass(frozen=True, slots=True)
class CornerRoad:
    s: float
    t: float
    dz: float
    height: float
    id: int | None = None
    line: int = 0


@dataclass(frozen=True, slots=True)
class CornerLocal:
    u: float
    v: float
    z: float
    height: float
    id: int | None = None
    line: int = 0


@dataclass(frozen=True, slots=True)
class CurveLocal:
    """A ``<curveLocal>`` (1.9): ``shape`` starts at (``u``, ``v``) with heading ``hdg``; ``None`` when its shape
    element is missing or does not parse. ``length`` ``None``: the file gave none (the curve "shall extend up to the
    next <curveLocal>")."""

    u: float
    v: float
    z: float
    height: float
    hdg: float
    length: float | None
    shape: CurveShape | None
    id: int | None = None
    line: int = 0


@dataclass(frozen=True, slots=True)
class Outline:
    id: int | None = None
    outer: bool | None = None
    closed: bool | None = None
    fill_type: str | None = None
    lane_type: str | None = None
    corners: tuple[CornerRoad | CornerLocal, ...] = ()
    curves: tuple[CurveLocal, ...] = ()
    line: int = 0


@dataclass(frozen=True, slots=True)
class Repeat:
    s: float
    length: float
    distance: float
    t_start: float
    t_end: float
    bt: float | None = None
    ct: float | None = None
    dt: float | None = None
    line: int = 0

    @property
    def t_profile(self) -> Cubic:
        """``t`` along the repeat as one cubic record starting at ``s`` (see the module docstring)."""
        if self.bt is None and self.ct is None and self.dt is None:
            slope = (self.t_end - self.t_start) / self.length if self.length > 0 else 0.0
            return Cubic(self.s, self.t_start, slope, 0.0, 0.0, self.line)
        return Cubic(self.s, self.t_start, self.bt or 0.0, self.ct or 0.0, self.dt or 0.0, self.line)


@dataclass(frozen=True, slots=True)
class LaneValidity:
    from_lane: int
    to_lane: int
    layer: LaneLayer = LaneLayer.PERMANENT  # 1.9
    line: int = 0


@dataclass(frozen=True, slots=True)
class RoadObject:
    road: str
    id: str
    type: str | None
    s: float | None
    t: float | None
    z_offset: float | None
    hdg: float | None = None
    length: float | None = None
    width: float | None = None
    radius: float | None = None
    height: float | None = None
    invalidated: bool | None = None  # 1.9
    temporary: bool | None = None  # 1.9
    outlines: tuple[Outline, ...] = ()
    repeats: tuple[Repeat, ...] = ()
    validities: tuple[LaneValidity, ...] = ()
    line: int = 0


# ------------------------------------------------------------------------------------------------------------ reading
def _children(el: etree._Element, name: str) -> Iterator[etree._Element]:
    """Children named ``name`` whatever their namespace (``ctx.tree`` keeps a file's default namespace)."""
    for child in el:
        if isinstance(child.tag, str) and etree.QName(child).localname == name:
            yield child


def _number(el: etree._Element, name: str) -> float | None:
    raw = el.get(name)
    try:
        value = float(raw)  # type: ignore[arg-type]
    except (TypeError, ValueError):
        return None
    return value if math.isfinite(value) else None


def _integer(el: etree._Element, name: str) -> int | None:
    try:
        return int(el.get(name))  # type: ignore[arg-type]
    except (TypeError, ValueError):
        return None


def _boolean(el: etree._Element, name: str) -> bool | None:
    raw = el.get(name)
    return None if raw is None else _BOOLEANS.get(raw.strip())


def _numbers(el: etree._Element, names: tuple[str, ...]) -> tuple[float, ...] | None:
    values = tuple(_number(el, name) for name in names)
    return None if any(v is None for v in values) else values  # type: ignore[return-value]


def _curve(el: etree._Element) -> CurveLocal | None:
    head = _numbers(el, ("u", "v", "z", "height"))
    if head is None:
        return None
    hdg = _number(el, "hdg") or 0.0
    length = _number(el, "length")
    span = length if length is not None and length > 0 else 0.0
    u, v = head[0], head[1]
    shape: CurveShape | None = None
    for kind in el:
        name = etree.QName(kind).localname if isinstance(kind.tag, str) else ""
        if name == "line":
            shape = Line(0.0, u, v, hdg, span, kind.sourceline or 0)
        elif name == "arc":
            curvature = _number(kind, "curvature")
            shape = None if curvature is None else Arc(0.0, u, v, hdg, span, curvature, kind.sourceline or 0)
        elif name == "paramPoly3":
            c = _numbers(kind, _PARAM_POLY3)
            p_range = _P_RANGES.get(kind.get("pRange", "normalized"))
            if c is None or p_range is None:
                shape = None
            else:
                au, bu, cu, du, av, bv, cv, dv = c
                shape = ParamPoly3(0.0, u, v, hdg, span, au, bu, cu, du, av, bv, cv, dv, p_range, kind.sourceline or 0)
        else:
            continue
        break
    return CurveLocal(u, v, head[2], head[3], hdg, length, shape, _integer(el, "id"), el.sourceline or 0)


def _outline(el: etree._Element, layered: bool) -> Outline:
    corners: list[CornerRoad | CornerLocal] = []
    curves = []
    for child in el:
        name = etree.QName(child).localname if isinstance(child.tag, str) else ""
        if name == "cornerRoad":
            c = _numbers(child, ("s", "t", "dz", "height"))
            if c is not None:
                corners.append(CornerRoad(c[0], c[1], c[2], c[3], _integer(child, "id"), child.sourceline or 0))
        elif name == "cornerLocal":
            c = _numbers(child, ("u", "v", "z", "height"))
            if c is not None:
                corners.append(CornerLocal(c[0], c[1], c[2], c[3], _integer(child, "id"), child.sourceline or 0))
        elif name == "curveLocal":
            curve = _curve(child)
            if curve is not None:
                curves.append(curve)
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
        el.sourceline or 0,
    )


def _repeat(el: etree._Element) -> Repeat | None:
    head = _numbers(el, ("s", "length", "distance", "tStart", "tEnd"))
    if head is None:
        return None
    s, length, distance, t_start, t_end = head
    return Repeat(
        s, length, distance, t_start, t_end, _number(el, "bT"), _number(el, "cT"), _number(el, "dT"), el.sourceline or 0
    )


def _validity(el: etree._Element, layered: bool) -> LaneValidity | None:
    from_lane, to_lane = _integer(el, "fromLane"), _integer(el, "toLane")
    if from_lane is None or to_lane is None:
        return None
    layer = _LAYERS.get(el.get("layer") or "permanent") if layered else LaneLayer.PERMANENT
    return LaneValidity(from_lane, to_lane, layer or LaneLayer.PERMANENT, el.sourceline or 0)


def _object(road_id: str, el: etree._Element, layered: bool) -> RoadObject | None:
    object_id = el.get("id")
    if object_id is None:
        return None
    outlines = [_outline(o, layered) for o in _children(el, "outline")]
    for group in _children(el, "outlines"):
        outlines.extend(_outline(o, layered) for o in _children(group, "outline"))
    repeats = tuple(r for r in (_repeat(child) for child in _children(el, "repeat")) if r is not None)
    validities = tuple(v for v in (_validity(child, layered) for child in _children(el, "validity")) if v is not None)
    invalidated, temporary = (_boolean(el, "invalidated"), _boolean(el, "temporary")) if layered else (None, None)
    return RoadObject(
        road_id,
        object_id,
        el.get("type"),
        _number(el, "s"),
        _number(el, "t"),
        _number(el, "zOffset"),
        _number(el, "hdg"),
        _number(el, "length"),
        _number(el, "width"),
        _number(el, "radius"),
        _number(el, "height"),
        invalidated,
        temporary,
        tuple(outlines),
        repeats,
        validities,
        el.sourceline or 0,
    )


def read_objects(root: etree._Element, version: tuple[int, int] | None) -> dict[str, tuple[RoadObject, ...]]:
    """Road id -> the road's objects in file order (roads without objects are left out), from the ``<OpenDRIVE>``
    element of a file declaring ``version`` (``None``: unknown, read as 1.9)."""
    layered = version is None or version >= (1, 9)
    out: dict[str, tuple[RoadObject, ...]] = {}
    for road in _children(root, "road"):
        road_id = road.get("id")
        if road_id is None:
            continue
        found = [
            obj
            for objects in _children(road, "objects")
            for obj in (_object(road_id, el, layered) for el in _children(objects, "object"))
            if obj is not None
        ]
        if found:
            out[road_id] = out.get(road_id, ()) + tuple(found)
    return out


# ----------------------------------------------------------------------------------------------------------- geometry
def curve_points(curve: CurveLocal, ds) -> tuple[np.ndarray, np.ndarray, np.ndarray] | None:
    """``u``, ``v`` and heading of a ``<curveLocal>`` at distances ``ds`` along it (clamped to ``[0, length]``);
    ``None`` when its shape or length is unknown."""
    if curve.shape is None or curve.length is None:
        return None
    from xodrcheck.geometry.planview import evaluate_element

    pose = evaluate_element(curve.shape, np.clip(np.asarray(ds, dtype=float), 0.0, curve.length))
    return pose.x, pose.y, pose.hdg


def curve_end(curve: CurveLocal) -> tuple[float, float, float] | None:
    """``u``, ``v`` and heading where a ``<curveLocal>`` ends (``None``: shape or length unknown): the next curve of a
    continuous outline starts there (13.2.3)."""
    found = curve_points(curve, [curve.length if curve.length is not None else 0.0])
    return None if found is None else (float(found[0][0]), float(found[1][0]), float(found[2][0]))


def outline_uv(outline: Outline, step: float = 0.1) -> tuple[np.ndarray, np.ndarray] | None:
    """The outline as a polyline in the object's ``u``/``v`` frame: its ``<cornerLocal>`` points, or its
    ``<curveLocal>`` curves sampled at most ``step`` metres apart (each curve's end included); ``None`` for a
    ``<cornerRoad>`` outline or a curve whose shape or length is unknown."""
    if outline.curves:
        us, vs = [], []
        for curve in outline.curves:
            length = curve.length or 0.0
            n = max(math.ceil(length / step), 1) + 1
            found = curve_points(curve, np.linspace(0.0, length, n))
            if found is None:
                return None
            us.append(found[0])
            vs.append(found[1])
        return np.concatenate(us), np.concatenate(vs)
    if outline.corners and all(isinstance(c, CornerLocal) for c in outline.corners):
        return (
            np.array([c.u for c in outline.corners]),  # type: ignore[union-attr]
            np.array([c.v for c in outline.corners]),  # type: ignore[union-attr]
        )
    return None


def repeat_t(repeat: Repeat, s) -> np.ndarray:
    """``t`` of a repeat at road ``s`` (within ``[s, s + length]``), from :attr:`Repeat.t_profile`."""
    from xodrcheck.geometry import profile

    return profile.evaluate((repeat.t_profile,), np.asarray(s, dtype=float))
