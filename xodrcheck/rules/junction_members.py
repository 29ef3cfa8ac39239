"""The roads a junction's parts name (``J020``-``J023``): direct junctions' roads and overlap zones, cross paths'
roads and lanes, boundary segments' roads.

* A direct junction connects one road on one side with several roads on the other (12.6), and marks one pair of
  overlapping lanes with ``overlapZone``.
* A cross path's crossing road belongs to the junction and connects walking or biking lanes (12.5); its own elevation
  is disregarded.
* A boundary has a segment at the end of every road that touches the junction, and segments run only along roads
  that touch the junction or belong to it (roads added to close it, 12.10).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from xodrcheck.findings import Category, Severity
from xodrcheck.model import ContactPoint, JunctionType, Lane, LaneType, Road
from xodrcheck.rules.junction_roles import legs
from xodrcheck.rules.registry import rule
from xodrcheck.rules.shared import junction_uids as U
from xodrcheck.rules.shared.context import Context, describe_junction, written_id
from xodrcheck.support.quantities import metres

if TYPE_CHECKING:
    from xodrcheck.model import CrossPath, Junction


# ---------------------------------------------------------------------------------------------------- direct junctions
@rule("J020", "direct-junction-shape", Category.JUNCTION, Severity.ERROR, uids=(U.DIRECT_CONNECTIVITY,))
def direct_junction_shape(ctx: Context):
    """A direct junction does not connect one road on one side with several roads on the other.

    A direct junction models an entry or an exit: one road splits into several, or several merge into one
    (``junctions.direct.road_connectivity``, 12.6). Its connections (incoming road - linked road) must all share one
    road, and join it to at least two others. Several roads on both sides (crossing traffic, Figure 92) need a common
    junction; a single pair of roads needs no junction.

    Passes (road 1 splits into roads 2 and 3)::

        <junction id="111" type="direct">
          <connection id="0" incomingRoad="1" linkedRoad="3" contactPoint="start">...
          <connection id="1" incomingRoad="1" linkedRoad="2" contactPoint="start">...

    Fails (roads 1 and 4 both continue on roads 2 and 3)::

        <connection id="0" incomingRoad="1" linkedRoad="2" .../><connection id="1" incomingRoad="4" linkedRoad="3" .../>
    """
    for junction in ctx.document.junctions:
        if junction.type is not JunctionType.DIRECT:
            continue
        pairs = {
            frozenset((c.incoming_road, c.linked_road))
            for c in junction.connections
            if c.incoming_road is not None and c.linked_road is not None and c.incoming_road != c.linked_road
        }
        if not pairs:
            continue
        shared = frozenset.intersection(*pairs)
        others = {road for pair in pairs for road in pair} - shared
        if len(shared) >= 1 and len(others) >= 2:
            continue
        shown = ", ".join(f"{a}-{b}" for a, b in sorted(tuple(sorted(p)) for p in pairs))
        why = (
            "they join only two roads"
            if len(pairs) == 1
            else "no road is in every connection: there are several roads on both sides"
        )
        yield direct_junction_shape.finding(
            f"direct junction {junction.id} connects roads {shown}: {why}; a direct junction joins one road on one "
            "side to several roads on the other (an entry or an exit)",
            line=junction.line or None,
        )


@rule("J021", "direct-overlap-zones", Category.JUNCTION, Severity.ERROR, uids=(U.DIRECT_OVERLAP_EXCLUSIVE,))
def direct_overlap_zones(ctx: Context):
    """A direct junction's ``overlapZone`` attributes do not mark one pair of overlapping lanes.

    Only one pair of ``<laneLink>`` elements has ``overlapZone`` (``junctions.direct.overlap_zone_exclusivity``,
    12.6): the two links of the overlapping lanes, which leave the same lane of one road (an exit: equal ``from``) or
    enter the same lane of one road (an entry: equal ``to``, 12.6.2). One link alone, more than two, or two links that
    do not overlap are reported.

    Passes (lane -3 of road 1 continues on road 2 or turns onto road 3: they overlap)::

        <connection id="0" incomingRoad="1" linkedRoad="3" contactPoint="start">
          <laneLink from="-3" to="-1" overlapZone="41"/>...
        <connection id="1" incomingRoad="1" linkedRoad="2" contactPoint="start">
          <laneLink from="-3" to="-3" overlapZone="40"/>...

    Fails (a single link with overlapZone)::

        <laneLink from="-3" to="-1" overlapZone="41"/>
    """
    for j in ctx.document.junctions:
        if j.type is not JunctionType.DIRECT:
            continue
        marked = [(c, ll) for c in j.connections for ll in c.all_lane_links if ll.xml.given("overlapZone")]
        if not marked:
            continue
        if len(marked) == 2:
            (c1, l1), (c2, l2) = marked
            exit_ = c1.incoming_road == c2.incoming_road and l1.from_lane == l2.from_lane
            entry = c1.linked_road == c2.linked_road and l1.to_lane == l2.to_lane
            if (exit_ or entry) and c1 is not c2:
                continue
        shown = "; ".join(
            f"connection {written_id(c)} laneLink {ll.from_lane} -> {ll.to_lane} (line {ll.line})" for c, ll in marked
        )
        why = (
            "one link alone marks no pair"
            if len(marked) == 1
            else f"{len(marked)} links have one"
            if len(marked) > 2
            else "the two links do not leave the same lane of one road or enter the same lane of one road"
        )
        c, ll = marked[-1]
        yield direct_overlap_zones.finding(
            f"{describe_junction(j)}: overlapZone on {shown}: {why}; give overlapZone to the one pair of links whose "
            "lanes overlap",
            road=c.linked_road,
            line=ll.line or c.line or None,
        )


# ---------------------------------------------------------------------------------------------------- cross paths
_CROSSING_TYPES = (LaneType.WALKING, LaneType.BIKING)


def lane_at_s(road: Road, lane_id: int | None, s: float | None) -> Lane | None:
    """The lane ``lane_id`` of the lane section containing ``s`` (the last section starting at or before it)."""
    if lane_id is None or s is None or not road.lane_sections:
        return None
    index = 0
    for k, section in enumerate(road.lane_sections):
        if section.s <= s:
            index = k
    return road.lane_sections[index].lane(lane_id)


def cross_path_lanes(ctx: Context, cp: CrossPath) -> list[tuple[str, Road, Lane | None, int | None, float, int]]:
    """(what, road, lane, lane id, s, line) of the four lanes a cross path names: the lane it leaves at the road at its
    start, its crossing road's lane there, and the same at its end. Roads that do not exist are left out."""
    out = []
    crossing = ctx.road(cp.crossing_road)
    for which, road_id, link in (("start", cp.road_at_start, cp.start), ("end", cp.road_at_end, cp.end)):
        if link is None:
            continue
        line = link.line or cp.line
        road = ctx.road(road_id)
        if road is not None and link.s is not None:
            out.append(
                (
                    f"lane {link.from_lane} of road {road.id} at s={metres(link.s)} ({which})",
                    road,
                    lane_at_s(road, link.from_lane, link.s),
                    link.from_lane,
                    link.s,
                    line,
                )
            )
        if crossing is not None and crossing.lane_sections:
            s = 0.0 if which == "start" else crossing.length
            out.append(
                (
                    f"lane {link.to_lane} of crossing road {crossing.id} at its {which}",
                    crossing,
                    lane_at_s(crossing, link.to_lane, s),
                    link.to_lane,
                    s,
                    line,
                )
            )
    return out


def _has_elevation(road: Road) -> bool:
    return any(abs(c) > 0 for e in road.elevation for c in (e.a, e.b, e.c, e.d))


@rule(
    "J022",
    "cross-path-roads",
    Category.JUNCTION,
    Severity.ERROR,
    uids=(U.CROSS_PATH_JUNCTION_ID, U.CROSS_PATH_LANE_TYPES, U.CROSS_PATH_ELEVATION),
)
def cross_path_roads(ctx: Context):
    """A cross path's crossing road is not the junction's, or it connects lanes that are not for walking or biking.

    A cross path's crossing road belongs to the junction: its ``junction`` attribute is the junction's id
    (``junctions.cross_path.correct_junction_id``, 12.5; a crossing road the file does not define is
    ``undefined-reference``'s). Cross paths connect only lanes of ``type="walking"`` or
    ``"biking"`` (``junctions.cross_path.only_connect_correct_type``): the lanes its ``<startLaneLink>`` and
    ``<endLaneLink>`` name, of the roads at its ends and of the crossing road. The crossing road's own elevation is
    disregarded (``junctions.cross_path.disregard_cross_road_evelation``, a statement, reported as an info where the
    road has one).

    Passes::

        <road id="75" junction="10"> ... <lane id="1" type="walking">...
        <crossPath id="6" crossingRoad="75" roadAtStart="46" roadAtEnd="45">
          <startLaneLink s="0.5" from="3" to="1"/><endLaneLink s="0.25" from="-3" to="1"/></crossPath>

    Fails (road 75 says it is in no junction)::

        <road id="75" junction="-1"> ...
    """
    for j in ctx.document.junctions:
        for cp in j.cross_paths:
            at = f"{describe_junction(j)} cross path {cp.id}"
            crossing = ctx.road(cp.crossing_road)
            if crossing is not None and crossing.junction != j.id:  # a road that does not exist: undefined-reference
                belongs = (
                    'is in no junction (junction="-1")'
                    if crossing.junction is None
                    else f"says it belongs to junction {crossing.junction}"
                )
                yield cross_path_roads.finding(
                    f"{at}: crossing road {cp.crossing_road} {belongs}; a crossing road is part of its junction "
                    f'(junction="{j.id}")',
                    uid=U.CROSS_PATH_JUNCTION_ID,
                    road=cp.crossing_road,
                    line=cp.line or j.line or None,
                )
            for what, road, lane, _, s, line in cross_path_lanes(ctx, cp):
                if lane is None or lane.type in _CROSSING_TYPES:
                    continue
                hint = " (sidewalk is the deprecated name of walking)" if lane.type is LaneType.SIDEWALK else ""
                yield cross_path_roads.finding(
                    f"{at} connects {what}, of type {lane.type.value}{hint}: cross paths only connect lanes of type "
                    "walking or biking",
                    uid=U.CROSS_PATH_LANE_TYPES,
                    road=road.id,
                    lane=lane.id,
                    s=s,
                    line=line or None,
                )
            if crossing is not None and _has_elevation(crossing):
                yield cross_path_roads.finding(
                    f"{at}: crossing road {crossing.id} has an elevation profile, which is disregarded: a cross "
                    "path lies on the roads it crosses",
                    uid=U.CROSS_PATH_ELEVATION,
                    severity=Severity.INFO,
                    road=crossing.id,
                    line=crossing.line or None,
                )


# ---------------------------------------------------------------------------------------------------- boundary roads
def _reaches(j: Junction, road: Road, end: ContactPoint | None) -> bool:
    """Whether a boundary segment of the junction reaches the road's end (``None``: either end)."""
    from xodrcheck.model import JointSegment

    boundary = j.boundary
    if boundary is None:
        return False
    wanted = {end} if end is not None else {ContactPoint.START, ContactPoint.END}
    for seg in boundary.segments:
        if seg.road != road.id:
            continue
        places = {seg.contact} if isinstance(seg, JointSegment) else {seg.s_start, seg.s_end}
        for place in places:
            if place in wanted:
                return True
            if isinstance(place, float) and any(
                abs(place - (0.0 if w is ContactPoint.START else road.length)) <= 1e-6 * max(1.0, road.length)
                for w in wanted
            ):
                return True
    return False


@rule(
    "J023",
    "boundary-roads",
    Category.JUNCTION,
    Severity.ERROR,
    uids=(U.BOUNDARY_EACH_ROAD, U.BOUNDARY_CLOSE_GAP_WITH_NEW_ROADS),
)
def boundary_roads(ctx: Context):
    """A junction boundary misses a road that touches the junction, or runs along a road that is not the junction's.

    The boundary's segments reach the start or end of every road connected to the junction
    (``junctions.boundary.segments_for_each_conn_road``, 12.10): each road linked to the junction has a segment at
    its end there (a joint across it, or a lane segment ending there). Where the existing roads do not close the
    boundary, additional roads are defined for the missing segments (``junctions.boundary.close_gap_with_new_roads``):
    every segment names a road that touches the junction or belongs to it (an added road has ``junction`` set to the
    junction's id; a road the file does not define is ``undefined-reference``'s).

    Passes::

        <boundary><segment type="joint" roadId="1" contactPoint="end"/> ...
          <segment type="lane" roadId="10" boundaryLane="-2" sStart="start" sEnd="end"/> ...</boundary>

    Fails (no segment reaches road 3, which ends at the junction)::

        <road id="3" junction="-1"><link><successor elementType="junction" elementId="100"/></link> ...
    """
    for j in ctx.document.junctions:
        boundary = j.boundary
        if boundary is None or j.type is not JunctionType.DEFAULT:
            continue
        touching = legs(ctx, j)
        for road_id, end in touching.items():
            road = ctx.road(road_id)
            if road is None or _reaches(j, road, end):
                continue
            where = f"its {end.value}" if end is not None else "its end"
            yield boundary_roads.finding(
                f"{describe_junction(j)}: no boundary segment reaches road {road.id} at {where}, where it meets the "
                "junction; add a joint segment across it",
                uid=U.BOUNDARY_EACH_ROAD,
                road=road.id,
                **ctx.end_at(road, end),
                line=boundary.line or j.line or None,
            )
        for seg in boundary.segments:
            road = ctx.road(seg.road)
            if road is not None and (road.id in touching or road.junction == j.id):
                continue
            if road is None and seg.road is not None:
                continue  # a road that does not exist: undefined-reference (ids.only_ref_defined_ids)
            what = (
                "names no road"
                if road is None
                else f"runs along road {road.id}, which neither touches the junction nor belongs to it"
            )
            yield boundary_roads.finding(
                f"{describe_junction(j)}: a boundary segment {what}; where the junction's roads do not close the "
                f'boundary, add a road for the missing segment, with junction="{j.id}"',
                uid=U.BOUNDARY_CLOSE_GAP_WITH_NEW_ROADS,
                road=seg.road,
                line=seg.line or boundary.line or None,
            )
