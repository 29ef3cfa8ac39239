"""Overlap rules (``O0xx``): lane surfaces that occupy the same place, from the plan-view footprints of the lane
meshes (:mod:`xodrcheck.mesh.footprint`, sampled under ``Tolerances.chord``).

Two roads may overlap when they are *related* (:class:`xodrcheck.mesh.footprint.Relations`): consecutive roads (a road
link either way: ASAM OpenDRIVE 10.3 tolerates an overlap where properly linked roads meet; such roads are not
compared anywhere, so an overlap away from their joint goes unreported: ``O001``'s partial note), members of one
junction (only roads with the same junction id may overlap, Annex F ``road.overlap_inside_junction``; their connection
lanes cross by design, :func:`xodrcheck.mesh.footprint.conflict_areas`), and the roads of one direct junction. Other
pairs overlap when their footprints share more than ``Tolerances.overlap_area`` square metres where their surfaces are
closer in height than ``Tolerances.clearance`` (a bridge with clearance is no overlap). Heights are compared at a
point inside each shared piece and at up to 24 points of its outline; a piece counts in proportion to its points
within the clearance. Borders that merely touch share no area. A road overlapping itself is ``O002`` (a lane folds) or
``O005`` (two of its lanes).

An overlap involving a drivable lane is an error (``O001`` between roads outside junctions, ``O003`` when one of the
roads is a junction's connecting road); overlaps between roadside lanes only (sidewalks, shoulders, borders, lanes of
type none...) are ``O004`` warnings, except between roads that share a junction (two of its legs, a leg and a
connecting road), whose sidewalks commonly meet at the junction's corners.
"""

from __future__ import annotations

from collections import defaultdict
from collections.abc import Iterator
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np

from xodrcheck.findings import Basis, Category, Severity
from xodrcheck.rules.registry import rule
from xodrcheck.rules.shared import junction_uids as JU
from xodrcheck.rules.shared import road_uids as U
from xodrcheck.rules.shared.context import Context
from xodrcheck.support import memory
from xodrcheck.support.quantities import metres

if TYPE_CHECKING:
    from xodrcheck.mesh.footprint import Overlap, OverlapIndex


#: Height (m) between two overlapping surfaces from which the message treats the upper one as a bridge lacking
#: clearance rather than two roads meeting at one height.
BRIDGE_HEIGHT = 1.0


def _overlap_index(ctx: Context) -> OverlapIndex:
    """The file's :class:`~xodrcheck.mesh.footprint.OverlapIndex` (shapely loads here, when an overlap rule runs)."""
    from xodrcheck.mesh.footprint import overlap_index

    return overlap_index(ctx.document, ctx.tolerances.chord, ctx.out_of_time, ctx.tolerances.max_turns)


def _swapped(o: Overlap) -> Overlap:
    return type(o)(o.lane_b, o.lane_a, o.area, o.x, o.y, o.dz, o.s_b, o.s_a)


@dataclass
class _Pair:
    """What overlaps between two roads: the total area, the largest overlap and the lane pairs."""

    area: float = 0.0
    largest: Overlap | None = None
    lanes: set[tuple[int, int]] = field(default_factory=set)


def _pairs(ctx: Context, drivable: bool) -> dict[tuple[str, str], _Pair]:
    """Unrelated road pairs and their shared area within the clearance, counting lane pairs with a drivable lane
    (``drivable``) or lane pairs of roadside lanes only (``not drivable``). Cached on the context."""
    cache = ctx.__dict__.setdefault("_overlap_pairs", {})  # per file: O001, O003 and O004 share one pass
    if drivable in cache:
        return cache[drivable]
    from xodrcheck.mesh.footprint import DRIVABLE_TYPE_NAMES

    tol = ctx.tolerances
    index = _overlap_index(ctx)
    surfaces = index.surfaces
    both: dict[bool, dict[tuple[str, str], _Pair]] = {True: defaultdict(_Pair), False: defaultdict(_Pair)}
    # a pair is named in file order, not id order, so that renaming roads changes nothing but the names
    order = {road.id: n for n, road in reversed(list(enumerate(ctx.document.roads)))}
    for o in index.overlaps(tol.overlap_area, tol.clearance, ctx.out_of_time):
        a, b = surfaces.lanes[o.lane_a], surfaces.lanes[o.lane_b]
        types = surfaces.lane_types
        kind = types[o.lane_a] in DRIVABLE_TYPE_NAMES or types[o.lane_b] in DRIVABLE_TYPE_NAMES
        if not kind and index.relations.shared_junction(a.road, b.road) is not None:
            continue  # sidewalks of a junction's roads meeting at its corners
        if (order.get(a.road, -1), a.lane) > (order.get(b.road, -1), b.lane):
            o = _swapped(o)
            a, b = b, a
        pair = both[kind][(a.road, b.road)]
        pair.area += o.area
        pair.lanes.add((a.lane, b.lane))
        if pair.largest is None or o.area > pair.largest.area:
            pair.largest = o
    cache.update({k: {p: v for p, v in d.items() if v.area > tol.overlap_area} for k, d in both.items()})
    return cache[drivable]


def _message(
    ctx: Context, roads: tuple[str, str], area: float, lanes: list[tuple[int, int]], o: Overlap, what: str
) -> str:
    shown = ", ".join(f"{a}/{b}" for a, b in lanes[:4]) + (" ..." if len(lanes) > 4 else "")
    junction = _overlap_index(ctx).relations.shared_junction(*roads)
    if junction is None:
        why = "they are neither linked nor in one junction"
    else:
        members = [r for r in roads if (road := ctx.road(r)) is not None and road.junction == junction]
        why = (
            f"road {members[0]} belongs to junction {junction} and road {(set(roads) - set(members)).pop()} is one "
            f"of its legs, not linked to it"
            if len(members) == 1
            else f"both are legs of junction {junction}, not linked to each other: only roads of one junction may "
            "overlap"
        )
    clearance = ctx.tolerances.clearance
    # a road passing over the other (more than a step apart): say how much height the bridge lacks
    short = f": {clearance - o.dz:.2f} m short of it as a bridge" if o.dz >= BRIDGE_HEIGHT else ""
    return (
        f"{what}road {roads[0]} and road {roads[1]} overlap by {area:.1f} m2 in plan view (lanes {shown}) with "
        f"{o.dz:.2f} m between their surfaces (clearance {metres(clearance)} m{short}), around ({o.x:.2f}, {o.y:.2f}); "
        f"{why}"
    )


#: Lane sections from which a file's first overlap rule drops the roads' cached geometry and collects garbage before
#: meshing (:func:`xodrcheck.support.memory.give_back`): worth it on a big map, whose caches are large; a small map's
#: mesh reuses the geometry, and a collection costs with every object of the process (many small checks in one
#: process would pay it for nothing).
GIVE_BACK_SECTIONS = 5000


def _sections(ctx: Context) -> int:
    return sum(len(road.lane_sections) for road in ctx.document.roads)


def _in_junction(ctx: Context, road_id: str) -> bool:
    road = ctx.road(road_id)
    return road is not None and road.junction is not None


def _findings(ctx: Context, check, drivable: bool, junction: bool | None, what: str) -> Iterator:
    from xodrcheck.rules.shared.sampled import release_lines

    release_lines(ctx)  # the rules after these read no section lines or road ends: room for the lane meshes
    if "_overlap_pairs" not in ctx.__dict__ and _sections(ctx) >= GIVE_BACK_SECTIONS:
        ctx.release_geometry()  # a big map: the mesh evaluates its roads run by run, not with every road's geometry
        memory.give_back()  # what they held, before the largest allocation of a big map's check (its lane meshes)
    surfaces = _overlap_index(ctx).surfaces
    roadside = _pairs(ctx, False) if drivable else {}
    for roads, pair in sorted(_pairs(ctx, drivable).items()):
        members = [_in_junction(ctx, r) for r in roads]
        if junction is not None and any(members) is not junction:
            continue
        if not drivable and roads in _pairs(ctx, True):
            continue  # one overlap of two roads, one finding: O001's or O003's, which says so
        o, lanes = pair.largest, sorted(pair.lanes)
        if o is None:  # every pair holds at least one overlap (_pairs)
            continue
        also = roadside.get(roads)
        if junction and not members[0]:  # name the connecting road first
            roads = (roads[1], roads[0])
            o = _swapped(o)
            lanes = sorted((b, a) for a, b in lanes)
        key = surfaces.lanes[o.lane_a]
        road = ctx.road(key.road)
        where: dict[str, Any] = {
            "road": key.road,
            "lane": key.lane,
            "section_s": key.section_s,
            "s": o.s_a,
            "x": o.x,
            "y": o.y,
        }
        message = _message(ctx, roads, pair.area, lanes, o, what)
        if also is not None:
            message += f"; their roadside lanes (no drivable lane) overlap too, by {also.area:.1f} m2"
        line = road.line if road is not None else None
        if check is not connection_overlap:
            yield check.finding(message, line=line, **where)
            continue
        yield check.finding(message, uid=U.OVERLAP_INSIDE_JUNCTION, line=line, **where)
        owners = [r.junction if (r := ctx.road(road_id)) is not None else None for road_id in roads]
        if None not in owners and owners[0] != owners[1]:  # two junctions overlap (junctions.no_overlap, 12.1)
            yield check.finding(
                f"junction {owners[0]} and junction {owners[1]} overlap: {message}; junctions shall not overlap",
                uid=JU.NO_OVERLAP,
                line=line,
                **where,
            )


_NOT_ROADSIDE = (
    "not checked: two roads linked to each other (a road predecessor or successor, either way), anywhere along them. "
    "10.3 tolerates an overlap where properly linked roads meet ('overlaps or leaps should be avoided but are not "
    "prohibited if the road reference lines are connected properly'); that tolerance is for their joint, but the "
    "overlap index does not tell an overlap at the joint from one elsewhere, so a linked road that overlaps its "
    "neighbour away from their joint (a road curling back over the next one) is not reported. Overlaps of roadside "
    "lanes only (sidewalks, shoulders, borders, lanes of type none: no drivable lane) are O004's warnings, and are not "
    "reported between roads that share a junction, whose sidewalks commonly meet at its corners"
)


@rule(
    "O001",
    "road-overlap",
    Category.OVERLAP,
    Severity.ERROR,
    partial={U.NO_OVERLAP_OUTSIDE_JUNCTION: _NOT_ROADSIDE},
    every_version=True,
)
def road_overlap(ctx: Context):
    """Two roads outside junctions that are not linked overlap in plan view at the same height.

    The lane surfaces of the two roads (a drivable lane on at least one side) share more than
    ``Tolerances.overlap_area`` m2 where they are closer in height than ``Tolerances.clearance``: a car could drive
    from one road onto the other where no link says so. Roads crossing need a junction; a bridge needs clearance (a
    surface :data:`BRIDGE_HEIGHT` m or more above the other counts as a bridge, and the message says how much height
    it lacks). Two legs of one junction are compared too. Annex F ``road.no_overlap_outside_junction``.

    Passes (road 2 crosses road 1 six metres above it)::

        <road id="1" junction="-1"> ... <geometry x="-50" y="0" hdg="0" length="100"><line/></geometry> ...
        <road id="2" junction="-1"> ... <geometry x="0" y="-50" hdg="1.5708" length="100"><line/></geometry> ...
          <elevationProfile><elevation s="0" a="6" b="0" c="0" d="0"/></elevationProfile>

    Fails (road 2 a bridge only 3 m above road 1: "1.50 m short of it as a bridge")::

        <road id="2" junction="-1"> ... <elevationProfile><elevation s="0" a="3" b="0" c="0" d="0"/></elevationProfile>

    Fails (the same roads at one height, no junction)::

        <road id="1" junction="-1"> ... <geometry x="-50" y="0" hdg="0" length="100"><line/></geometry> ...
        <road id="2" junction="-1"> ... <geometry x="0" y="-50" hdg="1.5708" length="100"><line/></geometry> ...
    """
    yield from _findings(ctx, road_overlap, True, False, "")


@rule("O002", "lane-fold", Category.OVERLAP, Severity.ERROR, uids=(U.NO_OVERLAP_SELF,), every_version=True)
def lane_fold(ctx: Context):
    """A lane's surface folds over itself in plan view.

    The lane's triangles cover some area more than once by more than ``Tolerances.overlap_area`` m2: its outer border
    runs backwards where the lane is wider than the radius of its inner side's curve (width times curvature past 1),
    or the lane crosses itself. Reported once per lane and lane section, at the first place it folds. A road shall not
    overlap with itself (Annex F ``road.no_overlap_self``; two lanes of one road overlapping: ``road-self-overlap``).
    A lane that covers itself while turning through more than ``Tolerances.max_turns`` full circles winds round
    itself (a curvature or length far too large, e.g. a 3 km arc of radius 0.5 m): the finding says so, and its
    overlaps are not computed.

    Passes (a 3.5 m lane on a 20 m radius)::

        <geometry ... length="30"><arc curvature="-0.05"/></geometry> ... <lane id="-1"><width a="3.5" .../>

    Fails (a 3.5 m lane on the inside of a 2 m radius)::

        <geometry ... length="6"><arc curvature="-0.5"/></geometry> ... <lane id="-1"><width a="3.5" .../>

    Fails (winds round a 0.5 m circle 35 times)::

        <geometry ... length="112"><arc curvature="2.0"/></geometry>
    """
    index = _overlap_index(ctx)
    surfaces, footprints = index.surfaces, index.footprints
    for lane in map(int, footprints.invalid):
        if ctx.out_of_time():
            return
        turns = footprints.winding.get(lane)
        area = 0.0 if turns is not None else footprints.self_overlap(lane)
        if turns is None and area <= ctx.tolerances.overlap_area:
            continue
        key = surfaces.lanes[lane]
        first, stop = surfaces.lane_faces[lane], surfaces.lane_faces[lane + 1]
        flipped = np.flatnonzero(surfaces.plan_areas[first:stop] < 0)
        face = first + int(flipped[0]) if len(flipped) else first
        corner = surfaces.vertices[surfaces.faces[face, 0]]
        road = ctx.road(key.road)
        where = f"lane {key.lane} of road {key.road} (lane section at s={metres(key.section_s)})"
        if turns is not None:
            end = float(surfaces.face_s[stop - 1])
            message = (
                f"{where} winds round itself: between s={metres(key.section_s)} and s={metres(end)} it turns through "
                f"{turns:,.0f} full circles and covers the same ground over and over (more than "
                f"{ctx.tolerances.max_turns:g} turns, tolerance max_turns); correct the curvature or length of the "
                "plan view there. Its overlaps were not computed"
            )
        else:
            message = f"{where} covers {area:.1f} m2 of plan view twice: its surface folds over itself" + (
                f" from s={surfaces.face_s[face]:.2f}" if len(flipped) else ""
            )
        yield lane_fold.finding(
            message,
            road=key.road,
            lane=key.lane,
            section_s=key.section_s,
            s=float(surfaces.face_s[face]),
            x=float(corner[0]),
            y=float(corner[1]),
            line=road.line if road is not None else None,
        )


@rule(
    "O003",
    "connection-overlap",
    Category.OVERLAP,
    Severity.ERROR,
    uids=(JU.NO_OVERLAP,),
    partial={U.OVERLAP_INSIDE_JUNCTION: _NOT_ROADSIDE},
    every_version=True,
)
def connection_overlap(ctx: Context):
    """A junction's connecting road overlaps a road that belongs neither to its junction nor to its legs.

    Connection lanes of one junction overlap each other on purpose (conflict areas); they must not overlap, at the
    same height and by more than ``Tolerances.overlap_area`` m2 with a drivable lane involved, a road that is not in
    the junction and not linked to them: another junction's connecting road, an unrelated road, or a leg of the
    junction they do not join (Annex F ``road.overlap_inside_junction``: only roads with the same junction id may
    overlap on the same level). Where the other road is a connecting road of another junction, the two junctions
    overlap, and a second finding names ``junctions.no_overlap`` (12.1: no junctions of any type overlap).

    Passes: a four-leg junction whose left turns cross the straight connections (all in junction 100).

    Fails (road 50, linked to nothing, lies across connecting road 10 of junction 100)::

        <road id="10" junction="100"> ... <geometry x="-10" y="0" hdg="0" length="20"><line/></geometry> ...
        <road id="50" junction="-1"> ... <geometry x="-7" y="-3" hdg="0" length="6"><line/></geometry> ...
    """
    yield from _findings(ctx, connection_overlap, True, True, "connecting ")


@rule("O004", "roadside-overlap", Category.OVERLAP, Severity.WARNING, basis=Basis.PLAUSIBILITY)
def roadside_overlap(ctx: Context):
    """Roadside lanes (no drivable lane on either side) of two unrelated roads overlap at the same height.

    Sidewalks, shoulders, borders or lanes of type none of two roads that are neither linked nor share a junction
    cover the same ground (more than ``Tolerances.overlap_area`` m2 within ``Tolerances.clearance``): usually two
    sidewalks drawn across each other at a corner, or a road of roadside lanes laid over another. Two roads whose
    drivable lanes overlap too are ``road-overlap``'s or ``connection-overlap``'s, whose one finding says so.

    Plausibility: roadside lanes drawn across each other are common and not what
    ``road.no_overlap_outside_junction`` is written for; a warning whatever the profile.

    Passes (two sidewalk roads side by side, 1 m apart).

    Fails (two sidewalk-only roads crossing at one height)::

        <road id="1"> ... <lane id="-1" type="sidewalk"> ... <geometry x="-20" y="0" hdg="0" length="40"> ...
        <road id="2"> ... <lane id="-1" type="sidewalk"> ... <geometry x="0" y="-20" hdg="1.5708" length="40"> ...
    """
    yield from _findings(ctx, roadside_overlap, False, None, "roadside lanes of ")


@rule("O005", "road-self-overlap", Category.OVERLAP, Severity.ERROR, uids=(U.NO_OVERLAP_SELF,))
def road_self_overlap(ctx: Context):
    """Two lanes of one road overlap in plan view at the same height: the road overlaps itself.

    A road shall not overlap with itself (Annex F ``road.no_overlap_self``): lanes of one road that are not
    neighbours share more than ``Tolerances.overlap_area`` m2 where their surfaces are closer in height than
    ``Tolerances.clearance`` (a road that loops over itself on a ramp passes). Usually a reference line that curls back
    over the road, or a lane drawn over its neighbour. Lanes that fold over themselves are ``lane-fold``'s.

    Passes (a 3/4 circle of radius 20 m: the road comes back beside its start, not onto it).

    Fails (a full circle and a bit: the road's end runs over its start)::

        <geometry s="0" x="0" y="0" hdg="0" length="140"><arc curvature="0.05"/></geometry>
    """
    index = _overlap_index(ctx)
    surfaces = index.surfaces
    tol = ctx.tolerances
    per_road: dict[str, _Pair] = defaultdict(_Pair)
    for o in index.overlaps(tol.overlap_area, tol.clearance, ctx.out_of_time, pairs=index.self_pairs):
        a, b = surfaces.lanes[o.lane_a], surfaces.lanes[o.lane_b]
        if (a.section_s, a.lane) > (b.section_s, b.lane):
            o, a, b = _swapped(o), b, a
        pair = per_road[a.road]
        pair.area += o.area
        pair.lanes.add((a.lane, b.lane))
        if pair.largest is None or o.area > pair.largest.area:
            pair.largest = o
    for road_id, pair in per_road.items():
        largest = pair.largest
        if pair.area <= tol.overlap_area or largest is None:
            continue
        o = largest
        a, b = surfaces.lanes[o.lane_a], surfaces.lanes[o.lane_b]
        road = ctx.road(road_id)
        yield road_self_overlap.finding(
            f"road {road_id} overlaps itself by {pair.area:.1f} m2 in plan view: lane {a.lane} at s={o.s_a:.2f} (lane "
            f"section s={metres(a.section_s)}) and lane {b.lane} at s={o.s_b:.2f} (lane section "
            f"s={metres(b.section_s)}) cover the same ground around ({o.x:.2f}, {o.y:.2f}), {o.dz:.2f} m apart in "
            f"height (clearance {metres(tol.clearance)} m)",
            road=road_id,
            lane=a.lane,
            section_s=a.section_s,
            s=o.s_a,
            x=o.x,
            y=o.y,
            line=road.line if road is not None else None,
        )
