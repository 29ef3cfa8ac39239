"""Where outlines and skeletons lie (``B018``, ``B019``, ``B034``): inside the object's bounding volume, inner outlines
sharing their points where they touch the outer one (13.1-13.3).

Everything is compared in the object's local frame (:mod:`xodrcheck.geometry.object_place`): ``<cornerLocal>``,
``<curveLocal>`` and ``<vertexLocal>`` points are given there; ``<cornerRoad>`` and ``<vertexRoad>`` points are placed
by the road's exact reference line (:meth:`~xodrcheck.rules.shared.context.Context.geometry`) and brought into it.
"""

from __future__ import annotations

import math
from collections.abc import Iterator
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from xodrcheck.findings import Basis, Category, Severity
from xodrcheck.rules.object_attributes import label
from xodrcheck.rules.object_outlines import name_of
from xodrcheck.rules.object_skeletons import polyline_name
from xodrcheck.rules.registry import NO_UID, rule
from xodrcheck.rules.shared import object_uids as U
from xodrcheck.rules.shared.context import Context
from xodrcheck.support.quantities import metres

if TYPE_CHECKING:
    from xodrcheck.geometry.object_place import Frame, Volume
    from xodrcheck.model import Outline, RoadObject, Vertex

#: Samples per metre along ``<curveLocal>`` curves (their points between the curve's ends must be inside too).
_CURVE_STEP = 0.05


@dataclass(frozen=True, slots=True)
class Points:
    """Local points of an outline or polyline: plan ``u``, ``v``, ``bottom`` and ``top`` heights, source lines."""

    u: np.ndarray
    v: np.ndarray
    bottom: np.ndarray
    top: np.ndarray
    lines: tuple[int, ...]


class Placed:
    """An object's frame and volume, computed on first use (a road point needs the road's geometry)."""

    def __init__(self, ctx: Context, obj: RoadObject):
        from xodrcheck.geometry.object_place import volume_of

        self.ctx, self.obj = ctx, obj
        self.volume = volume_of(obj)
        self._frame: Frame | None = None
        self._framed = False

    @property
    def frame(self) -> Frame | None:
        from xodrcheck.geometry.object_place import frame_of

        if not self._framed:
            geometry = self.ctx.geometry(self.obj.road)
            self._frame = None if geometry is None or not geometry.road.plan_view else frame_of(self.obj, geometry)
            self._framed = True
        return self._frame

    def road_points(self, s, t, dz) -> tuple[np.ndarray, np.ndarray, np.ndarray] | None:
        """Local ``u``, ``v``, ``z`` of road points (``None`` without frame)."""
        from xodrcheck.geometry.object_place import road_xy

        frame = self.frame
        if frame is None:
            return None
        geometry = self.ctx.geometry(self.obj.road)
        if geometry is None:  # never: the frame needs the geometry
            return None
        x, y, _ = road_xy(geometry, s, t)
        return frame.to_local(x, y, dz)

    def plan(self, u: float, v: float) -> dict:
        """``x``, ``y`` finding fields of a local point (empty without frame)."""
        frame = self.frame
        if frame is None:
            return {}
        x, y = frame.to_plan(u, v)
        return {"x": float(x), "y": float(y)}


def outline_points(placed: Placed, outline: Outline) -> Points | None:
    """An outline's points in the local frame: its corners, or its curves sampled (``None``: not placeable)."""
    from xodrcheck.geometry.object_shape import curve_points
    from xodrcheck.model import CornerLocal, CornerRoad

    if outline.curves:
        parts = []
        for curve in outline.curves:
            length = curve.length or 0.0
            found = curve_points(curve, np.linspace(0.0, length, max(math.ceil(length / _CURVE_STEP), 1) + 1))
            if found is not None:
                n = len(found[0])
                parts.append((found[0], found[1], np.full(n, curve.z), np.full(n, curve.z + curve.height), curve.line))
        if not parts:
            return None
        lines = tuple(line for (u, _v, _b, _t, line) in parts for _k in range(len(u)))
        u, v, bottom, top = (np.concatenate([p[k] for p in parts]) for k in range(4))
        return Points(u, v, bottom, top, lines)
    local = [c for c in outline.corners if isinstance(c, CornerLocal)]
    road = [c for c in outline.corners if isinstance(c, CornerRoad)]
    if local and not road:
        u, v = np.array([c.u for c in local]), np.array([c.v for c in local])
        z, h = np.array([c.z for c in local]), np.array([c.height for c in local])
        return Points(u, v, z, z + h, tuple(c.line for c in local))
    if road and not local:
        rs, rt = np.array([c.s for c in road]), np.array([c.t for c in road])
        dz, rh = np.array([c.dz for c in road]), np.array([c.height for c in road])
        low = placed.road_points(rs, rt, dz)
        high = placed.road_points(rs, rt, dz + rh)
        if low is None or high is None:
            return None
        return Points(low[0], low[1], low[2], high[2], tuple(c.line for c in road))
    return None


def _where(obj: RoadObject, placed: Placed, points: Points, k: int) -> dict:
    return {"road": obj.road, "s": obj.s, "line": points.lines[k], **placed.plan(points.u[k], points.v[k])}


def _outside_text(volume: Volume, points: Points, k: int, excess: float) -> str:
    return (
        f"lies {excess:.3g} m outside the object's bounding volume ({volume.describe()}): at u={points.u[k]:.3f}, "
        f"v={points.v[k]:.3f}, z={points.bottom[k]:.3f} to {points.top[k]:.3f} in the object's frame"
    )


@rule("B018", "outline-outside-volume", Category.OBJECT, Severity.ERROR, uids=(U.OUTLINE_INSIDE_BOX,))
def outline_outside_volume(ctx: Context):
    """A point of an object's outline lies outside the object's bounding volume.

    All points of an outline must lie inside the bounding volume (Annex F ``road.object.outline.points_inside_box``,
    13.1, 13.2): the box of ``length`` by ``width`` centred on the object's origin and turned by its ``hdg`` (or the
    cylinder of ``radius``), from the origin up to ``height``. A corner spans its ``z`` (or ``dz``) to that plus its
    ``height``; ``<curveLocal>`` curves are checked along their whole length. Within ``object_volume``; objects without
    a bounding volume (no ``length``/``width``, no ``radius``) are left alone; one finding per outline, at its point
    furthest out.

    Passes (a 4 m by 2 m box)::

        <object ... length="4" width="2" height="0.2" hdg="0"><outline id="0">
          <cornerLocal u="-2" v="-1" z="0" height="0.2" id="0"/><cornerLocal u="2" v="1" z="0" height="0.2" id="1"/>

    Fails::

        <object ... length="4" width="2" height="0.2" hdg="0"><outline id="0">
          <cornerLocal u="-2" v="-1" z="0" height="0.2" id="0"/><cornerLocal u="3" v="1" z="0" height="0.2" id="1"/>
    """
    tol = ctx.tolerances.object_volume
    for obj in ctx.road_objects():
        placed = Placed(ctx, obj)
        volume = placed.volume
        if volume is None or not obj.outlines:
            continue
        for outline in obj.outlines:
            points = outline_points(placed, outline)
            if points is None or not len(points.u):
                continue
            excess = volume.excess(points.u, points.v, points.bottom, points.top)
            k = int(np.argmax(excess))
            if excess[k] > tol:
                count = int((excess > tol).sum())
                yield outline_outside_volume.finding(
                    f"{label(obj)}: {name_of(outline)} has {count} point(s) outside the bounding volume; the one at "
                    f"line {points.lines[k]} {_outside_text(volume, points, k, float(excess[k]))}: make the volume "
                    "enclose the outline",
                    **_where(obj, placed, points, k),
                )


def _vertex_points(placed: Placed, vertices: tuple[Vertex, ...]) -> np.ndarray | None:
    """``(N, 3)`` local points of a polyline's vertices (``None``: a coordinate missing, no frame, or mixed kinds)."""
    if any(v.a is None or v.b is None or v.c is None for v in vertices) or len({v.kind for v in vertices}) != 1:
        return None
    raw = np.array([(v.a, v.b, v.c) for v in vertices], dtype=float)
    if vertices[0].local:
        return raw
    found = placed.road_points(raw[:, 0], raw[:, 1], raw[:, 2])
    return None if found is None else np.column_stack(found)


def _prism(volume: Volume, z: np.ndarray) -> tuple[np.ndarray, float, float]:
    """The volume as a prism: plan polygon (a circumscribed 64-gon for a cylinder) and its height range."""
    base = volume.corners() / math.cos(math.pi / 64) if volume.radius is not None else volume.corners()
    if volume.height is None:
        return base, float(z.min()) - 1e6, float(z.max()) + 1e6
    return base, 0.0, volume.height


def section_reaches(volume: Volume, point: np.ndarray, direction: np.ndarray, radius: float, tol: float) -> bool:
    """Whether the disc of ``radius`` around ``point``, perpendicular to ``direction``, reaches into the volume:
    the plane of the disc cuts the volume in a convex polygon, whose distance from ``point`` in the plane is at most
    ``radius`` (+ ``tol``)."""
    import shapely

    n = direction / np.linalg.norm(direction)
    base, lo, hi = _prism(volume, np.array([point[2]]))
    m = len(base)
    bottom = np.column_stack((base, np.full(m, lo)))
    top = np.column_stack((base, np.full(m, hi)))
    ends = [(bottom[i], bottom[(i + 1) % m]) for i in range(m)]
    ends += [(top[i], top[(i + 1) % m]) for i in range(m)] + [(bottom[i], top[i]) for i in range(m)]
    a = np.array([e[0] for e in ends])
    b = np.array([e[1] for e in ends])
    da, db = (a - point) @ n, (b - point) @ n
    with np.errstate(divide="ignore", invalid="ignore"):
        f = np.where(da != db, da / (da - db), 0.0)
    hits = (da * db <= 0) & (f >= 0) & (f <= 1)
    if not hits.any():
        return False
    cut = a[hits] + (b[hits] - a[hits]) * f[hits, None]
    e1 = np.cross(n, [0.0, 0.0, 1.0]) if abs(n[2]) < 0.9 else np.cross(n, [1.0, 0.0, 0.0])
    e1 /= np.linalg.norm(e1)
    e2 = np.cross(n, e1)
    flat = np.column_stack(((cut - point) @ e1, (cut - point) @ e2))
    hull = shapely.MultiPoint(flat).convex_hull
    return bool(hull.distance(shapely.Point(0.0, 0.0)) <= radius + tol)


def _reach(v: Vertex) -> float | None:
    """The radius of a vertex's cross-section that surely reaches as far as it does whatever its turn: the radius, or
    half the smaller of width and length (the standard does not say how a width-by-length section is turned)."""
    if v.radius is not None:
        return abs(v.radius)
    if v.width is not None and v.length is not None:
        return min(abs(v.width), abs(v.length)) / 2
    return None


def _boundary_outside(volume: Volume, points: np.ndarray, vertices: tuple[Vertex, ...], k: int, tol: float) -> bool:
    """Whether vertex ``k``'s cross-section stays wholly outside the volume (checked in the plane of each segment
    it ends; a vertex whose segments have no direction is taken as a ball)."""
    radius = _reach(vertices[k])
    if radius is None:
        return False
    planes = [points[j] - points[j - 1] for j in (k, k + 1) if 0 < j < len(points)]
    planes = [d for d in planes if np.linalg.norm(d) > 0]
    if not planes:
        excess = volume.excess(points[k : k + 1, 0], points[k : k + 1, 1], points[k : k + 1, 2])
        return bool(excess[0] > radius + tol)
    return not any(section_reaches(volume, points[k], d, radius, tol) for d in planes)


@rule(
    "B034",
    "skeleton-outside-volume",
    Category.OBJECT,
    Severity.ERROR,
    uids=(U.SKELETON_INSIDE_BOX, U.SKELETON_BOUNDARY_INSIDE_BOX),
)
def skeleton_outside_volume(ctx: Context):
    """A point of an object's skeleton lies outside the object's bounding volume, or its cross-section does not reach
    into the volume at all.

    All points of a skeleton polyline must lie inside the bounding volume (Annex F
    ``road.object.skeleton.points_inside_box``, 13.3), and the cross-section around each point (its radius, or width
    and length, perpendicular to the polyline) shall lie at least partly inside it (``.points_boundary_inside_box``,
    1.9). Within ``object_volume``. A width-by-length section counts as reaching the volume when the circle of half
    its smaller side does (the standard does not say how it is turned); one finding per polyline and rule.

    Passes (a pole of height 4)::

        <object ... radius="0.2" height="4"><skeleton><polyline id="1">
          <vertexLocal u="0" v="0" z="0" radius="0.15" id="1"/><vertexLocal u="0" v="0" z="4" radius="0.1" id="2"/>

    Fails (the top point is 1 m above the volume)::

        <object ... radius="0.2" height="4"><skeleton><polyline id="1">
          <vertexLocal u="0" v="0" z="0" radius="0.15" id="1"/><vertexLocal u="0" v="0" z="5" radius="0.1" id="2"/>
    """
    tol = ctx.tolerances.object_volume
    for obj in ctx.road_objects():
        placed = Placed(ctx, obj)
        volume = placed.volume
        if volume is None or obj.skeleton is None:
            continue
        for polyline in obj.skeleton.polylines:
            points = _vertex_points(placed, polyline.vertices)
            if points is None or not len(points):
                continue
            excess = volume.excess(points[:, 0], points[:, 1], points[:, 2])
            k = int(np.argmax(excess))
            if excess[k] <= tol:
                continue
            v = polyline.vertices[k]
            where = {"road": obj.road, "s": obj.s, "line": v.line, **placed.plan(points[k, 0], points[k, 1])}
            text = (
                f"{label(obj)}: the <{v.kind}> at line {v.line} of {polyline_name(polyline)} lies {excess[k]:.3g} m "
                f"outside the bounding volume ({volume.describe()}), at u={points[k, 0]:.3f}, v={points[k, 1]:.3f}, "
                f"z={points[k, 2]:.3f} in the object's frame"
            )
            yield skeleton_outside_volume.finding(
                f"{text}: make the volume enclose the skeleton", uid=U.SKELETON_INSIDE_BOX, **where
            )
            far = [
                int(j)
                for j in np.flatnonzero(excess > tol)
                if _boundary_outside(volume, points, polyline.vertices, int(j), tol)
            ]
            if far:
                j = int(far[0])
                w = polyline.vertices[j]
                yield skeleton_outside_volume.finding(
                    f"{label(obj)}: the cross-section of the <{w.kind}> at line {w.line} of {polyline_name(polyline)} "
                    f"(radius {metres(_reach(w))} m) does not reach into the bounding volume ({volume.describe()}) at "
                    "all: each point's cross-section lies at least partly inside it",
                    uid=U.SKELETON_BOUNDARY_INSIDE_BOX,
                    road=obj.road,
                    s=obj.s,
                    line=w.line,
                    **placed.plan(points[j, 0], points[j, 1]),
                )


# --------------------------------------------------------------------------------------------- inner and outer
def _plan(placed: Placed, outline: Outline) -> tuple[np.ndarray, np.ndarray, tuple[int, ...]] | None:
    """(points, boundary, lines): an outline's own points (corners, curve starts) and its boundary polyline in the
    local plan view (``None`` when it cannot be placed)."""
    if outline.curves:
        dense = outline_points(placed, outline)
        if dense is None:
            return None
        starts = np.array([(c.u, c.v) for c in outline.curves])
        boundary = np.column_stack((dense.u, dense.v))
        return starts, boundary, tuple(c.line for c in outline.curves)
    found = outline_points(placed, outline)
    if found is None:
        return None
    pts = np.column_stack((found.u, found.v))
    boundary = pts if outline.closed is False else np.vstack((pts, pts[:1]))
    return pts, boundary, found.lines


def _loose_touch(own: np.ndarray, lines: tuple[int, ...], other: tuple[np.ndarray, np.ndarray, tuple], tol: float):
    """The first of ``own`` points that lies on the other outline's boundary where that outline has no point."""
    import shapely

    pts, boundary, _ = other
    if len(boundary) < 2:
        return None
    line = shapely.LineString(boundary)
    for k, p in enumerate(own):
        if line.distance(shapely.Point(p)) <= tol and np.min(np.hypot(*(pts - p).T)) > tol:
            return k
    return None


@rule(
    "B019",
    "inner-outline-touch",
    Category.OBJECT,
    Severity.ERROR,
    uids=(U.INNER_TOUCHES_OUTER,),
    basis=Basis.PLAUSIBILITY,
)
def inner_outline_touch(ctx: Context):
    """An inner outline touches the outer outline at a point only one of them has, or lies outside it.

    Where an inner outline touches the outer outline of its object, the point is identical in both outlines (Annex F
    ``road.object.outline.inner_outline_touches_outer``, 13.2): a corner (or ``<curveLocal>`` start) of one that lies
    on the other within the ``position`` tolerance is a corner of the other too. Inner outlines lie fully inside the
    outer one (13.2; no UID). Compared in the object's plan view.

    That inner outlines lie inside the outer one is 13.2's wording without a checker rule: plausibility, a warning
    under the default profile (the rule's error under ``--profile strict`` or ``generator``).

    Passes (the inner triangle shares the outer square's corner 0,0)::

        <outline id="0" outer="true"><cornerLocal u="0" v="0" .../><cornerLocal u="4" v="0" .../>
          <cornerLocal u="4" v="4" .../><cornerLocal u="0" v="4" .../></outline>
        <outline id="1" outer="false"><cornerLocal u="0" v="0" .../><cornerLocal u="1" v="1" .../>
          <cornerLocal u="0" v="1" .../></outline>

    Fails (the inner triangle touches the outer square's edge at 2,0, where the square has no corner)::

        <outline id="1" outer="false"><cornerLocal u="2" v="0" .../><cornerLocal u="3" v="1" .../>
          <cornerLocal u="1" v="1" .../></outline>
    """
    tol = ctx.tolerances.position
    for obj in ctx.road_objects():
        outer = [o for o in obj.outlines if o.outer]
        inner = [o for o in obj.outlines if o.outer is False]
        if len(outer) != 1 or not inner:
            continue
        placed = Placed(ctx, obj)
        shell = _plan(placed, outer[0])
        if shell is None:
            continue
        for outline in inner:
            yield from _touches(obj, placed, outer[0], shell, outline, tol)


def _touches(obj: RoadObject, placed: Placed, outer: Outline, shell: tuple, outline: Outline, tol: float) -> Iterator:
    import shapely

    hole = _plan(placed, outline)
    if hole is None:
        return
    text = f"{label(obj)}: inner {name_of(outline)} touches outer {name_of(outer)}"
    # a point of one outline on the other's edge where the other has no point, either way round
    for points, other, whose, lacking in ((hole, shell, "its", "outer"), (shell, hole, "the outer outline's", "inner")):
        k = _loose_touch(points[0], points[2], other, tol)
        if k is not None:
            u, v = points[0][k]
            yield inner_outline_touch.finding(
                f"{text} at {whose} point u={u:.3f}, v={v:.3f} (line {points[2][k]}), where the {lacking} outline has "
                "no point: give both outlines this point",
                road=obj.road,
                s=obj.s,
                line=points[2][k],
                **placed.plan(u, v),
            )
    if outer.closed is False or outline.closed is False or len(shell[1]) < 4 or len(hole[1]) < 4:
        return
    area, inside = shapely.Polygon(shell[1]).buffer(tol), shapely.Polygon(hole[1])
    if area.is_valid and inside.is_valid and not area.contains(inside):
        yield inner_outline_touch.finding(
            f"{label(obj)}: inner {name_of(outline)} is not inside outer {name_of(outer)}: inner outlines lie fully "
            "inside the outer one",
            uid=NO_UID,
            road=obj.road,
            s=obj.s,
            line=outline.line,
        )
