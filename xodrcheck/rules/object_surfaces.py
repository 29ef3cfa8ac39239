"""Objects with a CRG surface (``B050``-``B056``): high-resolution road-surface features such as manhole covers and
patches, described by an OpenCRG file in the object's local frame (13.13), and objects set perpendicular to the road.

Bounding volumes are placed by the road's exact reference line (:mod:`xodrcheck.geometry.object_place`); roads' lane
areas come from the overlap rules' footprints (:mod:`xodrcheck.mesh.footprint`, built once per file and shared).
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Callable, Iterator
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from xodrcheck.findings import Category, Severity
from xodrcheck.rules.object_attributes import at, label
from xodrcheck.rules.registry import rule
from xodrcheck.rules.shared import object_uids as U
from xodrcheck.rules.shared.context import Context
from xodrcheck.support.quantities import metres

if TYPE_CHECKING:  # pragma: no cover
    import shapely

    from xodrcheck.geometry.lanes import RoadGeometry
    from xodrcheck.geometry.object_place import Instance, Volume
    from xodrcheck.model import RoadObject


def surface_objects(ctx: Context) -> Iterator[RoadObject]:
    for obj in ctx.road_objects():
        if obj.surfaces:
            yield obj


@rule("B050", "surface-object-shape", Category.OBJECT, Severity.ERROR, uids=(U.SURFACE_ANGULAR_ONLY,))
def surface_object_shape(ctx: Context):
    """An object with a ``<surface>`` is not an angular box: it is circular, has outlines, or has no box at all.

    Only objects with angular bounding volumes (``length`` and ``width``) may contain ``<surface>`` elements; circular
    objects and objects with outlines shall not (Annex F ``road.object.surface.only_for_angular_boxes``, 13.13): the
    CRG grid covers the box in the object's ``u``/``v`` frame.

    Passes::

        <object id="1" type="roadSurface" subtype="manhole" ... length="0.8" width="0.8" height="0"><surface>
          <CRG file="manhole.crg" hideRoadSurfaceCRG="false" zScale="1"/></surface></object>

    Fails::

        <object id="1" type="roadSurface" subtype="manhole" ... radius="0.4" height="0"><surface>
          <CRG file="manhole.crg" hideRoadSurfaceCRG="false" zScale="1"/></surface></object>
    """
    for obj in surface_objects(ctx):
        if obj.radius is not None:
            why = "is circular (radius)"
        elif obj.outlines:
            why = "has outlines"
        elif obj.length is None or obj.width is None:
            why = "has no angular bounding volume (length and width)"
        else:
            continue
        yield surface_object_shape.finding(
            f"{label(obj)} has a <surface> but {why}: only objects with a box of length and width may carry a CRG "
            "surface",
            **at(ctx, obj, obj.surfaces[0].line),
        )


@rule("B051", "surface-crg-count", Category.OBJECT, Severity.ERROR, uids=(U.SURFACE_ONE_CRG,))
def surface_crg_count(ctx: Context):
    """An object references more than one CRG file.

    An object shall not reference more than one CRG file (Annex F ``road.object.surface.only_one_crg_file``, 13.13):
    one ``<surface>`` with one ``<CRG>``.

    Passes::

        <surface><CRG file="patch.crg" hideRoadSurfaceCRG="false" zScale="1"/></surface>

    Fails::

        <surface><CRG file="patch.crg" hideRoadSurfaceCRG="false" zScale="1"/>
          <CRG file="crack.crg" hideRoadSurfaceCRG="false" zScale="1"/></surface>
    """
    for obj in surface_objects(ctx):
        crgs = [c for s in obj.surfaces for c in s.crgs]
        if len(crgs) > 1:
            files = ", ".join(repr(c.file) for c in crgs)
            yield surface_crg_count.finding(
                f"{label(obj)} references {len(crgs)} CRG files ({files}): an object has one CRG surface; split it "
                "into one object per CRG file",
                **at(ctx, obj, crgs[1].line),
            )


@rule(
    "B052",
    "surface-repeated-continuously",
    Category.OBJECT,
    Severity.ERROR,
    uids=(U.SURFACE_DISCRETE_REPEAT,),
)
def surface_repeated_continuously(ctx: Context):
    """An object with a ``<surface>`` is repeated continuously (``distance="0"``).

    Objects with ``<surface>`` elements may repeat discretely, but not continuously (Annex F
    ``road.object.surface.repeat_discretely_not_continously``, 13.4, 13.13): a CRG grid is not extruded along a road.

    Passes::

        <repeat s="10" length="40" distance="10" tStart="1" tEnd="1" zOffsetStart="0" zOffsetEnd="0"/>

    Fails::

        <repeat s="10" length="40" distance="0" tStart="1" tEnd="1" zOffsetStart="0" zOffsetEnd="0"/>
    """
    for obj in surface_objects(ctx):
        for r in obj.repeats:
            if r.distance == 0:
                yield surface_repeated_continuously.finding(
                    f"{label(obj)} has a <surface>, but the <repeat> at line {r.line} has distance 0 (a continuous "
                    "object): repeat it with a distance greater than 0",
                    **at(ctx, obj, r.line),
                )


# ----------------------------------------------------------------------------------------------- where they lie
@dataclass(frozen=True, slots=True)
class Box:
    """One placed bounding volume of a surface object: plan-view polygon and height range (inertial)."""

    obj: RoadObject
    instance: Instance
    polygon: shapely.Polygon
    low: float
    high: float


def surface_boxes(ctx: Context) -> list[Box]:
    """Every placed bounding volume of the file's surface objects (each instance of a repeated one, thinned where
    instances pile up: :func:`_thinned`), which the surface rules compare. Cached."""
    cache = ctx.__dict__.get("_surface_boxes")
    if cache is not None:
        return cache
    out: list[Box] = []
    for obj in surface_objects(ctx):
        from xodrcheck.geometry.object_place import instances  # here: a file without objects loads no objects.place

        geometry = ctx.geometry(obj.road)
        if geometry is None or not geometry.road.plan_view:
            continue
        for _, run in itertools.groupby(instances(obj), key=lambda inst: inst.line):
            out.extend(_thinned(_placed_boxes(obj, geometry, list(run))))
    ctx.__dict__["_surface_boxes"] = out
    return out


def _placed_boxes(obj: RoadObject, geometry: RoadGeometry, run: list[Instance]) -> list[Box]:
    """The plan-view boxes (or 64-gons of cylinders) of instances, all evaluated at once on the road's exact reference
    line; an instance where the road has no reference line is left out."""
    import shapely

    from xodrcheck.geometry.object_place import road_xy

    volumes = [inst.volume for inst in run if inst.volume is not None]
    run = [inst for inst in run if inst.volume is not None]
    s = np.array([inst.s for inst in run])
    x, y, road_hdg = road_xy(geometry, s, np.array([inst.t for inst in run]))
    base = geometry.elevation(s) + np.array([inst.z_offset for inst in run])
    heading = road_hdg + (obj.hdg or 0.0)
    out = []
    for circular in (False, True):  # boxes, then cylinders (4 and 64 corners)
        ks = [k for k, v in enumerate(volumes) if (v.radius is not None) is circular and np.isfinite(x[k] + y[k])]
        if not ks:
            continue
        local = np.stack([volumes[k].corners() for k in ks])
        c, n = np.cos(heading[ks])[:, None], np.sin(heading[ks])[:, None]
        px = x[ks][:, None] + c * local[:, :, 0] - n * local[:, :, 1]
        py = y[ks][:, None] + n * local[:, :, 0] + c * local[:, :, 1]
        polygons = shapely.polygons(np.stack((px, py), axis=-1))
        for k, polygon in zip(ks, polygons, strict=True):
            low = float(base[k])
            out.append(Box(obj, run[k], polygon, low, low + (volumes[k].height or 0.0)))
    out.sort(key=lambda box: box.instance.s)
    return out


def _thinned(run: list[Box]) -> list[Box]:
    """The boxes of one ``<repeat>``, thinned where its instances pile up (a ``distance`` far below the object's
    size, or instances past the road's end, all placed at its last point): a box is left out when its centre lies
    within half the inscribed radius of the last box kept (the last box is always kept). Kept boxes leave no gap
    and overlap where the instances do, so the rules' verdicts stand, but a point lies under a few boxes instead of
    thousands (10 000 instances 1 mm apart would otherwise make 10^8 pairs to compare)."""
    import shapely

    if len(run) < 3:
        return run
    centres = shapely.get_coordinates(shapely.centroid(np.array([box.polygon for box in run]))).tolist()
    inner = [_inner_radius(box.instance.volume) / 2 for box in run]
    kept = [0]
    for k in range(1, len(run) - 1):
        last = kept[-1]
        if math.dist(centres[k], centres[last]) > inner[last]:
            kept.append(k)
    kept.append(len(run) - 1)
    return [run[k] for k in kept]


def _inner_radius(volume: Volume | None) -> float:
    """Half the smaller side of a box, the radius of a cylinder."""
    if volume is None:
        return 0.0
    return volume.radius if volume.radius is not None else min(volume.length, volume.width) / 2


@rule("B053", "surface-volumes-overlap", Category.OBJECT, Severity.ERROR, uids=(U.SURFACE_NO_BOX_OVERLAP,))
def surface_volumes_overlap(ctx: Context):
    """The bounding volumes of two objects with a ``<surface>`` overlap.

    The bounding volumes of objects with ``<surface>`` elements shall not overlap (Annex F
    ``road.object.surface.no_bounding_box_overlap``, 13.13): where two CRG surfaces cover the same ground, the road's
    height there is not defined. Boxes are compared in plan view (their shared area over ``object_volume`` squared)
    and in height (from the road's elevation plus ``zOffset`` up to ``height``, within ``object_volume``); each
    instance of a discretely repeated object counts.

    Passes (two 1 m patches 2 m apart)::

        <object id="1" type="roadSurface" s="10" t="1" ... length="1" width="1" height="0"><surface>...</surface>
        <object id="2" type="roadSurface" s="12" t="1" ... length="1" width="1" height="0"><surface>...</surface>

    Fails (0.5 m apart: they overlap by half)::

        <object id="1" type="roadSurface" s="10" t="1" ... length="1" width="1" height="0"><surface>...</surface>
        <object id="2" type="roadSurface" s="10.5" t="1" ... length="1" width="1" height="0"><surface>...</surface>
    """
    boxes = surface_boxes(ctx)
    if len(boxes) < 2:
        return
    import shapely  # here: the boxes' polygons are shapely's, so it is loaded already

    tol = ctx.tolerances.object_volume
    tree = shapely.STRtree([b.polygon for b in boxes])
    pairs = tree.query([b.polygon for b in boxes], predicate="intersects")
    reported: set[tuple[str, str, str, str]] = set()
    for i, j in zip(*pairs, strict=True):
        if i >= j:
            continue
        a, b = boxes[int(i)], boxes[int(j)]
        key = (a.obj.road, a.obj.id, b.obj.road, b.obj.id)
        if key in reported or a.low > b.high + tol or b.low > a.high + tol:
            continue
        shared = a.polygon.intersection(b.polygon)
        if shared.area <= tol * tol:
            continue
        reported.add(key)
        point = shared.representative_point()
        same = a.obj is b.obj
        other = "another instance of it" if same else f"road {b.obj.road} object {b.obj.id} (line {b.obj.line})"
        yield surface_volumes_overlap.finding(
            f"{label(a.obj)} (at s={metres(a.instance.s)}) has a <surface> whose bounding volume overlaps that of "
            f"{other} (at s={metres(b.instance.s)}) by {shared.area:.3g} m2: CRG surfaces of objects shall not cover "
            "the same ground",
            road=a.obj.road,
            s=a.instance.s,
            x=float(point.x),
            y=float(point.y),
            line=a.instance.line,
        )


def _crossed_roads(ctx: Context, box: Box, wanted: Callable[[str], bool] | None = None) -> dict[str, float]:
    """Road id -> plan-view area of the road's lanes under a surface box (the box's height range within
    ``clearance`` of the lane surface there), for the roads ``wanted`` asks about (all by default): lanes of other
    roads are passed over before their areas and heights are computed."""
    from xodrcheck.mesh.footprint import overlap_index, sample_points

    index = overlap_index(ctx.document, ctx.tolerances.chord, ctx.out_of_time, ctx.tolerances.max_turns)
    footprints, lanes = index.footprints, index.surfaces.lanes
    out: dict[str, float] = {}
    for k in footprints.tree.query(box.polygon, predicate="intersects"):
        road = lanes[int(k)].road
        if wanted is not None and not wanted(road):
            continue
        shared = footprints.polygons[int(k)].intersection(box.polygon)
        if shared.area <= ctx.tolerances.object_volume**2:
            continue
        z, _ = footprints.heights(int(k), sample_points(shared))
        if np.nanmin(np.abs(z - box.low)) >= ctx.tolerances.clearance:
            continue
        out[road] = out.get(road, 0.0) + float(shared.area)
    return out


@rule(
    "B054",
    "surface-object-not-referenced",
    Category.OBJECT,
    Severity.ERROR,
    uids=(U.SURFACE_REFERENCE_ON_OVERLAP,),
)
def surface_object_not_referenced(ctx: Context):
    """An object with a ``<surface>`` lies over the lanes of a road that does not reference it.

    An object with a ``<surface>`` element shall be referenced on all roads it overlaps, with the ``<object>`` on one
    road and an ``<objectReference>`` to its id on each other road (Annex F
    ``road.object.surface.object_reference_on_overlap``, 13.10, 13.13): a reader evaluating that road's surface would
    otherwise miss the CRG. Overlap: the object's bounding volume shares more than ``object_volume`` squared with the
    road's lane footprints, within ``clearance`` in height.

    Passes (road 2 crosses the patch of road 1)::

        <road id="2" ...><objects><objectReference id="patch" s="5" t="0" orientation="none"/></objects></road>

    Fails::

        <road id="2" ...><objects/></road>
    """
    boxes = surface_boxes(ctx)
    if not boxes:
        return
    referenced = {(road.id, r.id) for road in ctx.document.roads for r in road.object_references}
    reported: set[tuple[str, str]] = set()
    for box in boxes:
        if ctx.out_of_time():
            return

        def wanted(road: str, obj: RoadObject = box.obj) -> bool:
            return road != obj.road and (road, obj.id) not in referenced and (road, obj.id) not in reported

        for road, area in sorted(_crossed_roads(ctx, box, wanted).items()):
            key = (road, box.obj.id)
            reported.add(key)
            point = box.polygon.centroid
            yield surface_object_not_referenced.finding(
                f"{label(box.obj)} has a <surface> that covers {area:.3g} m2 of road {road}'s lanes, but road {road} "
                f'has no <objectReference id="{box.obj.id}">: reference the object on every road it overlaps',
                road=box.obj.road,
                s=box.instance.s,
                x=float(point.x),
                y=float(point.y),
                line=box.obj.line,
            )


@dataclass(frozen=True, slots=True)
class RoadCrg:
    """A road's ``<surface><CRG>`` record: where it applies along the road and how."""

    road: str
    s_start: float
    s_end: float
    mode: str | None
    line: int


def _road_crgs(ctx: Context) -> dict[str, list[RoadCrg]]:
    """Road id -> the road's surface CRGs (10.6) with both ends; ``mode`` as the file wrote it."""
    out: dict[str, list[RoadCrg]] = {}
    for road in ctx.document.roads:
        for crg in () if road.surface is None else road.surface.crgs:
            start, end = crg.s_start, crg.s_end
            if start is None or end is None:
                continue
            mode = crg.mode.value if crg.mode is not None else crg.xml.text("mode")
            lo, hi = min(start, end), max(start, end)
            out.setdefault(road.id, []).append(RoadCrg(road.id, lo, hi, mode, crg.line))
    return out


@rule(
    "B055",
    "surface-hides-road-crg",
    Category.OBJECT,
    Severity.ERROR,
    uids=(),
    partial={
        U.SURFACE_HIDE_ROAD_CRG: "the road CRG's extent across the road is in the CRG file, which is not read: its "
        "area is taken as the road's lanes from sStart to sEnd"
    },
)
def surface_hides_road_crg(ctx: Context):
    """An object's CRG hides a road surface CRG that is not ``attached``.

    Where a road surface CRG with any mode other than ``attached`` covers an object's bounding volume, the object's
    ``hideRoadSurfaceCRG`` shall be false (Annex F ``road.object.surface.crg_hidden_on_object_overlap``, 13.13, Table
    109: hiding an ``attached0``, ``genuine`` or ``global`` road CRG is not allowed - they carry the whole road height).
    The road CRG covers its road's lanes from ``sStart`` to ``sEnd``; the object lies on its own road and on the roads
    that reference it (``<objectReference>``, at their ``s``), where its box overlaps the road's lane footprints.

    Passes::

        <road ...><surface><CRG file="road.crg" sStart="0" sEnd="100" orientation="same" mode="genuine" .../>
        ...<object ...><surface><CRG file="patch.crg" hideRoadSurfaceCRG="false" zScale="1"/></surface></object>

    Fails::

        <road ...><surface><CRG file="road.crg" sStart="0" sEnd="100" orientation="same" mode="genuine" .../>
        ...<object ...><surface><CRG file="patch.crg" hideRoadSurfaceCRG="true" zScale="1"/></surface></object>
    """
    road_crgs = _road_crgs(ctx)
    if not road_crgs:
        return
    placed_on: dict[str, dict[str, float]] = {}  # object id -> road -> s of the object's origin on that road
    for ref in (r for road in ctx.document.roads for r in road.object_references):
        if ref.id is not None and ref.s is not None:
            placed_on.setdefault(ref.id, {})[ref.road] = ref.s
    for box in surface_boxes(ctx):
        hiding = [c for s in box.obj.surfaces for c in s.crgs if c.hide_road_surface_crg is not False]
        if not hiding or box.obj.s is None:
            continue
        lo_x, lo_y, hi_x, hi_y = box.polygon.bounds
        reach = math.hypot(hi_x - lo_x, hi_y - lo_y) / 2
        origins = {**placed_on.get(box.obj.id, {}), box.obj.road: box.obj.s}
        on_crg = {road for road in origins if road in road_crgs}
        crossed = set(_crossed_roads(ctx, box, on_crg.__contains__)) if on_crg else set()
        for road in sorted(crossed & set(origins)):
            s_at = origins[road] + box.instance.s - box.obj.s
            crg = next(
                (
                    c
                    for c in road_crgs.get(road, ())
                    if c.mode != "attached" and c.s_start - reach <= s_at <= c.s_end + reach
                ),
                None,
            )
            if crg is None:
                continue
            yield surface_hides_road_crg.finding(
                f"{label(box.obj)}: its CRG (line {hiding[0].line}) hides the road surface (hideRoadSurfaceCRG "
                f"{'true' if hiding[0].hide_road_surface_crg else 'not given: true'}) over road {road}'s CRG in "
                f"mode {crg.mode or '(none)'} (line {crg.line}), which carries the whole road height: set "
                'hideRoadSurfaceCRG="false"',
                uid=U.SURFACE_HIDE_ROAD_CRG,
                road=box.obj.road,
                s=box.instance.s,
                line=hiding[0].line,
            )


@rule("B056", "perp-to-road-skewed", Category.OBJECT, Severity.WARNING, uids=(U.SURFACE_SKEWED_CRG,))
def perp_to_road_skewed(ctx: Context):
    """An object set perpendicular to the road (``perpToRoad="true"``) is not small against the curvature of the
    road's elevation there.

    To avoid skewed CRG surfaces, ``perpToRoad`` should only be used for objects smaller than the local radius of
    curvature of the road elevation (Annex F ``road.object.surface.avoid_skewed_crg_surfacees``, 13.1, 13.13): the
    object's extent (its box's diagonal, its cylinder's diameter) is compared with the smallest radius of curvature of
    the elevation profile (``|z''| / (1 + z'^2)^1.5``) over the stretch of road it covers.

    Passes (flat road)::

        <object id="1" type="roadSurface" ... length="2" width="2" height="0" perpToRoad="true">

    Fails (a crest of radius 1 m: elevation c = 0.5)::

        <elevation s="0" a="0" b="0" c="-0.5" d="0"/>...<object ... length="2" width="2" perpToRoad="true">
    """
    from xodrcheck.geometry.object_place import volume_of
    from xodrcheck.geometry.profile import Piecewise

    for obj in ctx.road_objects():
        volume = volume_of(obj)
        road = ctx.road(obj.road)
        if not obj.perp_to_road or volume is None or obj.s is None or road is None or not road.elevation:
            continue
        size = 2 * volume.radius if volume.radius is not None else math.hypot(volume.length, volume.width)
        s = np.linspace(max(obj.s - size / 2, 0.0), min(obj.s + size / 2, road.length), 41)
        _, d1, d2 = Piecewise(road.elevation).jet(s)
        curvature = np.abs(d2) / (1.0 + d1 * d1) ** 1.5
        k = int(np.argmax(curvature))
        if curvature[k] > 0 and size >= 1.0 / curvature[k]:
            yield perp_to_road_skewed.finding(
                f"{label(obj)} is {size:.3g} m across and set perpendicular to the road (perpToRoad), but the road's "
                f"elevation bends with a radius of {1.0 / curvature[k]:.3g} m at s={s[k]:.3g}: the object (and its "
                "CRG) would be skewed; use pitch and roll, or a smaller object",
                **at(ctx, obj),
            )
