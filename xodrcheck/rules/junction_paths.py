"""Where a cross path's crossing road lies (``J028``, 12.5 and 12.7): its ends on the lanes it links, and the whole
road inside its junction.

Areas are plan-view lane strips of the exact lane geometry (:func:`xodrcheck.rules.shared.junction_shapes.strip`): the
lane a ``<startLaneLink>``/``<endLaneLink>`` names, around its ``s``; a virtual junction's main road between
``sStart`` and ``sEnd``; a common junction's boundary, or without one the strips of its other roads. Points further
than ``gap`` (1 cm) outside are reported. Cross paths whose roads or lanes do not exist are ``J022``'s and the
reference rules'.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING, Any

import numpy as np

from xodrcheck.findings import Category, Finding, Severity
from xodrcheck.model import JunctionType, Road
from xodrcheck.rules.registry import rule
from xodrcheck.rules.shared import junction_uids as U
from xodrcheck.rules.shared.context import Context, describe_junction
from xodrcheck.rules.shared.junction_shapes import boundary_pieces, gaps, ring, road_points, strip
from xodrcheck.rules.shared.road_ends import left_of
from xodrcheck.support.quantities import metres

if TYPE_CHECKING:
    from xodrcheck.model import CrossPath, CrossPathLink, Junction

#: How far along the linked road around a lane link's ``s`` its lane is taken, beyond the crossing road's width (m).
_MARGIN = 2.0


def _outside(area, xy: np.ndarray, tol: float) -> tuple[int, float] | None:
    """(index, distance) of the point farthest outside ``area`` by more than ``tol``; ``None`` when all are in."""
    import shapely

    if len(xy) == 0:
        return None
    distance = shapely.distance(area, shapely.points(xy))
    k = int(np.argmax(distance))
    return (k, float(distance[k])) if distance[k] > tol else None


def _end(ctx: Context, j: Junction, cp: CrossPath, crossing: Road, at_end: bool) -> Iterator[Finding]:
    link: CrossPathLink | None = cp.end if at_end else cp.start
    road = ctx.road(cp.road_at_end if at_end else cp.road_at_start)
    if link is None or road is None or link.s is None or link.from_lane is None or link.to_lane is None:
        return
    geometry = ctx.geometry(crossing.id)
    if geometry is None or ctx.usable_geometry(road) is None:
        return
    s = left_of(float(crossing.length)) if at_end else 0.0
    index = int(geometry.section_index(s)[0])
    points = road_points(ctx, crossing, s)
    if index < 0 or points is None or len(points) == 0:
        return
    width = float(np.max(np.hypot(*(points - points.mean(axis=0)).T))) * 2.0
    area = strip(ctx, road, link.from_lane, link.s - width - _MARGIN, link.s + width + _MARGIN)
    if area is None:
        return
    try:
        centre = geometry.lane_points(index, link.to_lane, np.array([s]), where="centre")
    except KeyError:
        return
    tol = ctx.tolerances.gap
    name = "end" if at_end else "start"
    where: dict[str, Any] = {"road": crossing.id, "lane": link.to_lane, "s": s, "line": link.line or cp.line or None}
    off = _outside(area, np.array([[centre.x[0], centre.y[0]]]), tol)
    if off is not None:
        yield cross_path_ends.finding(
            f"{describe_junction(j)} cross path {cp.id}: the {name} of crossing road {crossing.id} (lane "
            f"{link.to_lane} at ({centre.x[0]:.3f}, {centre.y[0]:.3f})) is {off[1]:.3g} m from lane {link.from_lane} "
            f"of road {road.id} at s={metres(link.s)}, which its <{name}LaneLink> links; make the crossing road {name} "
            "on that lane",
            uid=U.CROSS_PATH_LANE_LINKAGE,
            x=float(centre.x[0]),
            y=float(centre.y[0]),
            **where,
        )
        return
    off = _outside(area, points, tol)
    if off is not None:
        x, y = (float(v) for v in points[off[0]])
        yield cross_path_ends.finding(
            f"{describe_junction(j)} cross path {cp.id}: at its {name}, crossing road {crossing.id} reaches ({x:.3f}, "
            f"{y:.3f}), {off[1]:.3g} m outside lane {link.from_lane} of road {road.id} around s={metres(link.s)}; the "
            "crossing road's lanes must start and end fully inside the linked lanes",
            uid=U.CROSS_PATH_CONTAINED,
            x=x,
            y=y,
            **where,
        )


def _junction_area(ctx: Context, j: Junction, crossing: Road):
    """The area a cross path of the junction must lie in, and how to name it (``None``: unknown)."""
    import shapely

    if j.type is JunctionType.VIRTUAL:
        main = ctx.road(j.main_road)
        if main is None or j.s_start is None or j.s_end is None:
            return None
        lo, hi = sorted((j.s_start, j.s_end))
        area = strip(ctx, main, None, lo, hi)
        return (
            None if area is None else (area, f"main road {main.id} between sStart={metres(lo)} and sEnd={metres(hi)}")
        )
    if j.type is not JunctionType.DEFAULT:
        return None
    if j.boundary is not None:
        pieces = boundary_pieces(ctx, j.boundary)
        if pieces is not None and all(gap <= ctx.tolerances.gap for _, _, gap in gaps(pieces)):
            return shapely.make_valid(shapely.Polygon(ring(pieces))), "the junction boundary"
        return None
    crossings = {cp.crossing_road for cp in j.cross_paths}
    strips = [
        area
        for road in ctx.document.roads
        if road.junction == j.id and road.id not in crossings and road is not crossing
        if (area := strip(ctx, road, None, 0.0, float(road.length))) is not None
    ]
    return (shapely.union_all(strips), "the area of the junction's roads") if strips else None


@rule(
    "J028",
    "cross-path-placement",
    Category.JUNCTION,
    Severity.ERROR,
    uids=(
        U.CROSS_PATH_LANE_LINKAGE,
        U.CROSS_PATH_CONTAINED,
        U.CROSS_PATH_WITHIN_JUNCTION,
        U.VIRTUAL_CROSS_PATH_S_T,
    ),
)
def cross_path_ends(ctx: Context) -> Iterator[Finding]:
    """A cross path's crossing road does not start and end on the lanes it links, or leaves its junction's area.

    The start and end of the crossing road reach the lanes its ``<startLaneLink>`` and ``<endLaneLink>`` link
    (``junctions.cross_path.lane_linkage``, 12.5): the centre of lane ``to`` at the crossing road's start lies in lane
    ``from`` of ``roadAtStart`` around ``s`` (at its end: of ``roadAtEnd``); and its start and end, all its lanes, lie
    fully inside those lanes (``junctions.cross_path.start_end_contained``). Cross paths lie within the area of a common
    or virtual junction (``junctions.cross_path.within_junction_area``): inside its boundary, or without one inside its
    other roads; in a virtual junction inside the main road between ``sStart`` and ``sEnd``, whose s and t the
    crossing road does not exceed (``junctions.virtual.crossPath.cross_road_check_s_t``).

    Passes (road 75 runs 9 m south from (60, 4.5), across the junction from walking lane -2 of road 11 to that of
    road 10, both at s=10)::

        <crossPath id="6" crossingRoad="75" roadAtStart="11" roadAtEnd="10">
          <startLaneLink s="10" from="-2" to="-1"/><endLaneLink s="10" from="-2" to="-1"/></crossPath>

    Fails (the start link names s=2 of road 11, 8 m away from where road 75 starts)::

        <startLaneLink s="2" from="-2" to="-1"/>
    """
    tol = ctx.tolerances.gap
    for j in ctx.document.junctions:
        for cp in j.cross_paths:
            crossing = ctx.road(cp.crossing_road)
            if crossing is None or ctx.usable_geometry(crossing) is None:
                continue
            yield from _end(ctx, j, cp, crossing, at_end=False)
            yield from _end(ctx, j, cp, crossing, at_end=True)
            found = _junction_area(ctx, j, crossing)
            points = road_points(ctx, crossing)
            if found is None or points is None:
                continue
            off = _outside(found[0], points, tol)
            if off is None:
                continue
            x, y = (float(v) for v in points[off[0]])
            uids = (
                (U.CROSS_PATH_WITHIN_JUNCTION, U.VIRTUAL_CROSS_PATH_S_T)
                if j.type is JunctionType.VIRTUAL
                else (U.CROSS_PATH_WITHIN_JUNCTION,)
            )
            for uid in uids:
                yield cross_path_ends.finding(
                    f"{describe_junction(j)} cross path {cp.id}: crossing road {crossing.id} reaches ({x:.3f}, "
                    f"{y:.3f}), {off[1]:.3g} m outside {found[1]}; a cross path lies within its junction's area",
                    uid=uid,
                    road=crossing.id,
                    x=x,
                    y=y,
                    line=cp.line or None,
                )
