"""A junction's area in plan view (``J024``-``J026``): its boundary closes counter-clockwise (12.10), its reference
line reaches it (12.9) and its elevation grid covers it (12.11).

The boundary's segments are evaluated with the exact lane geometry (:mod:`xodrcheck.rules.shared.junction_shapes`). A
boundary is checked only when every segment can be placed (an unknown road or lane is ``J023``'s or the reference
rules'), and only for common junctions (a boundary elsewhere is ``J012``'s). Gaps between segments over ``gap``
(1 cm) are errors.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

import numpy as np

from xodrcheck.findings import Category, Finding, Severity
from xodrcheck.model import ContactPoint, ElementType, JunctionType, Road
from xodrcheck.rules.registry import rule
from xodrcheck.rules.shared import junction_uids as U
from xodrcheck.rules.shared.context import Context, describe_junction
from xodrcheck.rules.shared.junction_shapes import (
    boundary_pieces,
    gaps,
    grid_area,
    reference_line,
    ring,
    road_points,
    signed_area,
)
from xodrcheck.support.quantities import metres

if TYPE_CHECKING:
    from xodrcheck.model import Junction
    from xodrcheck.rules.shared.junction_shapes import Piece


def _boundaries(ctx: Context) -> Iterator[tuple[Junction, list[Piece]]]:
    """Common junctions with a boundary whose segments can all be placed, with the placed segments."""
    for j in ctx.document.junctions:
        if j.type is not JunctionType.DEFAULT or j.boundary is None or j.boundary.unknown:
            continue
        pieces = boundary_pieces(ctx, j.boundary)
        if pieces is not None:
            yield j, pieces


def _closed(ctx: Context, pieces: list[Piece]) -> bool:
    return all(gap <= ctx.tolerances.gap for _, _, gap in gaps(pieces))


def _describe(piece: Piece) -> str:
    seg = piece.segment
    kind = "lane" if hasattr(seg, "s_start") else "joint"
    return f"the {kind} segment of road {seg.road} (line {seg.line})"


@rule("J024", "boundary-not-closed", Category.JUNCTION, Severity.ERROR, uids=(U.BOUNDARY_CLOSED,))
def boundary_not_closed(ctx: Context) -> Iterator[Finding]:
    """The segments of a junction boundary do not close it: one ends away from where the next one starts.

    The segments of a ``<boundary>`` close the entire junction boundary (``junctions.boundary.segments_close_boundry``,
    12.10): each segment, in file order, ends where the next begins, and the last ends where the first begins. A lane
    segment runs along the outer border of ``boundaryLane`` from ``sStart`` to ``sEnd``; a joint crosses its road at
    ``contactPoint`` from the outer border of ``jointLaneStart`` to that of ``jointLaneEnd`` (all lanes without them).
    A gap over ``gap`` (1 cm) is an error.

    Passes (joint across road 1's end, lane -1 of connecting road 10 to road 2, joint across road 2 ...)::

        <segment type="joint" roadId="1" contactPoint="end" jointLaneStart="1" jointLaneEnd="-1"/>
        <segment type="lane" roadId="10" boundaryLane="-1" sStart="start" sEnd="end"/> ...

    Fails (the lane segment stops at s=15 of road 10, 5 m before the next joint)::

        <segment type="lane" roadId="10" boundaryLane="-1" sStart="start" sEnd="15"/>
    """
    tol = ctx.tolerances.gap
    for j, pieces in _boundaries(ctx):
        for piece, after, gap in gaps(pieces):
            if gap <= tol:
                continue
            x, y = (float(v) for v in piece.end)
            yield boundary_not_closed.finding(
                f"{describe_junction(j)}: {_describe(piece)} ends at ({x:.3f}, {y:.3f}), {gap:.3g} m from where "
                f"{_describe(after)} begins; the segments must close the boundary: make each segment end where the "
                "next one begins (add segments, or a road for them, where the junction's roads leave a gap)",
                road=piece.segment.road,
                x=x,
                y=y,
                line=piece.segment.line or None,
            )


@rule(
    "J025",
    "boundary-clockwise",
    Category.JUNCTION,
    Severity.ERROR,
    uids=(U.BOUNDARY_COUNTER_CLOCKWISE,),
)
def boundary_clockwise(ctx: Context) -> Iterator[Finding]:
    """The segments of a junction boundary run clockwise around the junction.

    The segments are ordered counter-clockwise (``junctions.boundary.segments_counter_clockwise_order``, 12.10):
    walked in file order, a closed boundary keeps the junction on its left, so its signed (shoelace) area is
    positive. Checked on boundaries that close (``boundary-not-closed`` reports the others).

    Passes (around a T junction: road 1's end, along the south edge to road 2, road 2's start, up to road 3 ...)::

        <segment type="joint" roadId="1" contactPoint="end" jointLaneStart="1" jointLaneEnd="-1"/>
        <segment type="lane" roadId="10" boundaryLane="-1" sStart="start" sEnd="end"/> ...

    Fails (the same segments in reverse order, each from its end to its start)::

        <segment type="lane" roadId="100" boundaryLane="0" sStart="end" sEnd="start"/>
        <segment type="joint" roadId="3" contactPoint="start"/> ...
    """
    for j, pieces in _boundaries(ctx):
        if len(pieces) < 2 or not _closed(ctx, pieces):
            continue
        area = signed_area(ring(pieces))
        if area < 0:
            yield boundary_clockwise.finding(
                f"{describe_junction(j)}: its boundary segments run clockwise around the junction (enclosing "
                f"{-area:.1f} m²); list them counter-clockwise, each from its start to its end in that order",
                line=(j.boundary.line if j.boundary else 0) or j.line or None,
            )


@rule(
    "J026",
    "junction-area-coverage",
    Category.JUNCTION,
    Severity.ERROR,
    uids=(U.REFLINE_MEETS_BOUNDARY, U.REFLINE_REACHES_ALL, U.GRID_COVERS_BOUNDARY),
)
def junction_area_coverage(ctx: Context) -> Iterator[Finding]:
    """A junction's reference line or elevation grid does not cover its boundary (or, without one, its roads).

    With a junction boundary (12.10) and a junction reference line (12.9), the line crosses the boundary or at least
    touches it (``junctions.geometry.correct_junction_boundry``). Every point of the junction is reached by a line
    perpendicular to the reference line (``junctions.geometry.ref_line_definition``, which asks it of every junction
    with a reference line): every boundary point lies between the normals at the line's start and end, and, for a
    junction without a boundary, every lane border point of its connecting roads does. An elevation grid is valid for
    the whole area enclosed by the boundary (``junctions.elevation_grid.valid_for_entire_boundry``, 12.11): every
    boundary point lies in a complete square of the grid (rows ``gridSpacing`` apart from ``sStart`` along the line,
    points ``gridSpacing`` apart across it). The tolerance is ``gap`` (1 cm).

    Passes (boundary x 50..70, y -3.5..10; line from (45, 0) 30 m east; grid rows at s=0..30, 15 m left, 5 m right)::

        <planView><geometry s="0" x="45" y="0" hdg="0" length="30"><line/></geometry></planView>
        <elevationGrid sStart="0" gridSpacing="5"><elevation left="0 0 0" center="0" right="0"/> ... (7 rows)

    Fails (the line ends at x=65, short of the boundary's east side at x=70)::

        <planView><geometry s="0" x="45" y="0" hdg="0" length="20"><line/></geometry></planView>
    """
    tol = ctx.tolerances.gap
    bounded = {id(j) for j, _ in _boundaries(ctx)}
    for j, pieces in _boundaries(ctx):
        line = reference_line(j)
        if line is None:
            continue
        xy = ring(pieces)
        s, t = line.frame(xy)
        inside = (s >= -tol) & (s <= line.length + tol)
        if not (inside & (np.abs(t) <= tol)).any() and not _crosses(s, t, line.length, tol):
            yield junction_area_coverage.finding(
                f"{describe_junction(j)}: its reference line (from ({line.x:.3f}, {line.y:.3f}), {metres(line.length)} "
                "m long) neither crosses nor touches the junction boundary; place the line across the junction",
                uid=U.REFLINE_MEETS_BOUNDARY,
                x=line.x,
                y=line.y,
                line=line.line or None,
            )
        if not inside.all():
            k = int(np.argmax(np.where(s < 0, -s, s - line.length)))
            yield junction_area_coverage.finding(
                f"{describe_junction(j)}: the boundary point ({xy[k, 0]:.3f}, {xy[k, 1]:.3f}) lies at s={s[k]:.3f} "
                f"along the junction reference line, outside its 0..{metres(line.length)} m, so no line perpendicular "
                "to the reference line reaches it; lengthen or move the reference line to span the junction",
                uid=U.REFLINE_REACHES_ALL,
                x=float(xy[k, 0]),
                y=float(xy[k, 1]),
                line=line.line or None,
            )
        for grid in j.grids[:1]:
            area = grid_area(grid)
            if area is None:
                continue
            out = area.outside(s, t, tol)
            if out.any():
                k = int(np.argmax(out))
                yield junction_area_coverage.finding(
                    f"{describe_junction(j)}: the boundary point ({xy[k, 0]:.3f}, {xy[k, 1]:.3f}) (s={s[k]:.3f}, "
                    f"t={t[k]:.3f} from the reference line) lies outside the elevation grid's complete squares "
                    f"({int(out.sum())} of {len(out)} boundary points do); extend the grid over the whole boundary",
                    uid=U.GRID_COVERS_BOUNDARY,
                    x=float(xy[k, 0]),
                    y=float(xy[k, 1]),
                    line=grid.line or None,
                )
    for j in ctx.document.junctions:
        if id(j) not in bounded:
            yield from _unbounded_reach(ctx, j, tol)


def _unbounded_reach(ctx: Context, j: Junction, tol: float) -> Iterator[Finding]:
    """``ref_line_definition`` on a junction without a boundary to measure: its area is then its connecting roads'
    lanes, and every lane border point of them lies between the normals at the reference line's ends."""
    line = reference_line(j)
    if line is None:
        return
    worst: tuple[float, Road, np.ndarray] | None = None
    for road in ctx.roads_in_junction.get(j.id, ()):
        xy = road_points(ctx, road)
        if xy is None or not len(xy):
            continue
        s, _ = line.frame(xy)
        beyond = np.maximum(-s, s - line.length)
        k = int(np.argmax(beyond))
        if beyond[k] > tol and (worst is None or beyond[k] > worst[0]):
            worst = (float(beyond[k]), road, np.array([xy[k, 0], xy[k, 1], s[k]]))
    if worst is None:
        return
    _, road, (x, y, s_k) = worst
    yield junction_area_coverage.finding(
        f"{describe_junction(j)}: the lane border point ({x:.3f}, {y:.3f}) of its connecting road {road.id} lies at "
        f"s={s_k:.3f} along the junction reference line, outside its 0..{metres(line.length)} m, so no line "
        "perpendicular to the reference line reaches it; lengthen or move the reference line to span the junction",
        uid=U.REFLINE_REACHES_ALL,
        road=road.id,
        x=float(x),
        y=float(y),
        line=line.line or None,
    )


def _crosses(s: np.ndarray, t: np.ndarray, length: float, tol: float) -> bool:
    """Whether the closed ring (s, t) crosses the segment t=0, 0<=s<=length: an edge changes side within it."""
    s2, t2 = np.roll(s, -1), np.roll(t, -1)
    change = (t > 0) != (t2 > 0)
    with np.errstate(divide="ignore", invalid="ignore"):
        at = np.where(change, s + (s2 - s) * (t / (t - t2)), np.nan)
    return bool(np.any(change & (at >= -tol) & (at <= length + tol)))


@rule("J029", "crossing-section-coverage", Category.JUNCTION, Severity.ERROR, uids=(U.CROSSING_COVERAGE,))
def crossing_section_coverage(ctx: Context) -> Iterator[Finding]:
    """A crossing's ``<roadSection>`` does not cover the whole area where its road overlaps the other roads.

    The ``sStart`` and ``sEnd`` of the ``<roadSection>`` elements of a crossing (``type="crossing"``) cover at least
    the area where the roads overlap (``junctions.crossing.s_start_end_coverage``, 12.8): the road's lanes between
    ``sStart`` and ``sEnd`` contain its overlap with every other road of the crossing. Uncovered overlap over
    ``overlap_area`` (m²) is an error.

    Passes (road 1 runs east along y=0, 7 m wide; rail road 2 crosses it at x=100; each section spans s=95..105)::

        <roadSection id="0" roadId="1" sStart="95" sEnd="105"/>
        <roadSection id="1" roadId="2" sStart="95" sEnd="105"/>

    Fails (road 2's section spans s=98..102, y=-2..2, but road 1 covers y=-3.5..3.5)::

        <roadSection id="1" roadId="2" sStart="98" sEnd="102"/>
    """
    from xodrcheck.rules.shared.junction_shapes import strip

    for j in ctx.document.junctions:
        if j.type is not JunctionType.CROSSING:
            continue
        roads = {}
        for section in j.road_sections:
            road = ctx.road(section.road)
            if road is not None and road.id not in roads:
                roads[road.id] = (road, strip(ctx, road, None, 0.0, float(road.length)))
        for section in j.road_sections:
            road = ctx.road(section.road)
            if road is None or section.s_start is None or section.s_end is None or roads[road.id][1] is None:
                continue
            lo, hi = sorted((section.s_start, section.s_end))
            covered = strip(ctx, road, None, lo, hi)
            yield from _uncovered(ctx, j, section, road, roads, covered)


def _uncovered(ctx: Context, j: Junction, section, road, roads, covered) -> Iterator[Finding]:
    import shapely

    mine = roads[road.id][1]
    for other_id, (_, area) in roads.items():
        if other_id == road.id or area is None:
            continue
        overlap = shapely.intersection(mine, area)
        left = overlap if covered is None else shapely.difference(overlap, covered)
        if left.area <= ctx.tolerances.overlap_area:
            continue
        point = left.representative_point()
        yield crossing_section_coverage.finding(
            f"{describe_junction(j)}: the <roadSection> of road {road.id} (s={metres(section.s_start)} to "
            f"{metres(section.s_end)}) leaves {left.area:.2f} m² of its overlap with road {other_id} uncovered, around "
            f"({point.x:.3f}, {point.y:.3f}); widen sStart..sEnd to cover the whole area where the roads overlap",
            road=road.id,
            x=float(point.x),
            y=float(point.y),
            line=section.line or None,
        )


def _zone_lanes(ctx: Context, j: Junction) -> list[tuple[Road, int, bool, float, int]] | None:
    """The two overlapping lanes a direct junction marks with ``overlapZone``: (road, lane, whether the junction is
    at the road's end, overlapZone, line); ``None`` unless one pair of links marks one exit or entry (J021)."""
    marked = [(c, ll) for c in j.connections for ll in c.all_lane_links if ll.xml.given("overlapZone")]
    if len(marked) != 2 or any(ll.overlap_zone is None for _, ll in marked):
        return None
    (c1, l1), (c2, l2) = marked
    out: list[tuple[Road, int, bool, float, int]] = []
    if c1.incoming_road == c2.incoming_road and l1.from_lane == l2.from_lane:  # an exit: the linked roads' lanes
        for c, ll in marked:
            road = ctx.road(c.linked_road)
            if road is None or c.contact_point is None or ll.overlap_zone is None:
                return None
            out.append((road, ll.to_lane, c.contact_point is ContactPoint.END, ll.overlap_zone, ll.line))
    elif c1.linked_road == c2.linked_road and l1.to_lane == l2.to_lane:  # an entry: the incoming roads' lanes
        for c, ll in marked:
            road = ctx.road(c.incoming_road)
            link = road.successor if road is not None else None
            if road is None or ll.overlap_zone is None:
                return None
            at_end = link is not None and link.names(ElementType.JUNCTION, j.id)
            out.append((road, ll.from_lane, at_end, ll.overlap_zone, ll.line))
    else:
        return None
    return out


@rule("J030", "overlap-zone-too-short", Category.JUNCTION, Severity.ERROR, uids=(U.DIRECT_OVERLAP_COVERAGE,))
def overlap_zone_too_short(ctx: Context) -> Iterator[Finding]:
    """A direct junction's ``overlapZone`` does not reach as far as its two lanes overlap.

    The value of ``overlapZone`` covers at least the overlapping area and may be larger
    (``junctions.direct.overlap_zone_coverage``, 12.6.2): measured along each of the two overlapping lanes from the
    junction (the linked roads' lanes of an exit, the incoming roads' lanes of an entry), the first ``overlapZone``
    metres contain all of the area the two lanes share. Shared area beyond both zones over ``overlap_area`` (m²) is
    an error.

    Passes (road 3 curves off road 2's lane -2 with radius 100 m: they part 26.5 m after the junction)::

        <laneLink from="-2" to="-2" overlapZone="30"/> ... <laneLink from="-2" to="-1" overlapZone="30"/>

    Fails (the zones end after 15 m, while the lanes still share space)::

        <laneLink from="-2" to="-2" overlapZone="15"/> ... <laneLink from="-2" to="-1" overlapZone="15"/>
    """
    import shapely

    from xodrcheck.rules.shared.junction_shapes import strip

    for j in ctx.document.junctions:
        lanes = _zone_lanes(ctx, j) if j.type is JunctionType.DIRECT else None
        if lanes is None:
            continue
        whole = [strip(ctx, road, lane, 0.0, float(road.length)) for road, lane, _, _, _ in lanes]
        zones = [
            strip(ctx, road, lane, road.length - zone if at_end else 0.0, road.length if at_end else zone)
            for road, lane, at_end, zone, _ in lanes
        ]
        if any(area is None for area in whole) or any(zone is None for zone in zones):
            continue
        left = shapely.difference(shapely.intersection(whole[0], whole[1]), shapely.union(zones[0], zones[1]))
        if left.area <= ctx.tolerances.overlap_area:
            continue
        point = left.representative_point()
        (a, la, _, za, line), (b, lb, _, zb, _) = lanes
        yield overlap_zone_too_short.finding(
            f"{describe_junction(j)}: lane {la} of road {a.id} (overlapZone {metres(za)} m) and lane {lb} of road "
            f"{b.id} (overlapZone {metres(zb)} m) still share {left.area:.2f} m² beyond their zones, around "
            f"({point.x:.3f}, {point.y:.3f}); make overlapZone cover the whole stretch where the lanes overlap",
            road=a.id,
            lane=la,
            x=float(point.x),
            y=float(point.y),
            line=line or None,
        )
