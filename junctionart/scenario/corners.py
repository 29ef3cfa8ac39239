"""Roadside lanes round junction corners: one connecting road per corner, carrying the legs' roadside lanes from one
leg's kerb to the next (:mod:`.roadside` says where each corner runs).

A corner of its own (no kerb-side connection lane to follow) must not cover a connection lane of its junction: where
its body would, it is left out and the two legs' roadside lanes end at the junction.
"""

from __future__ import annotations

import dataclasses

import shapely

from ..intersections.model import ConnectionPlan, Layout, RoadPlan
from ..intersections.overlap import _lane_bodies
from ..opendrive import Connection, Cubic, Document, Junction, Lane, LaneHeight, LaneLink, LaneSection, Link, Road
from ..params import Params, TrafficRule
from .ids import Ids
from .roadside import LANES, Corner, LegEnd, corner, corner_pairs, kerb_side, leg_end

#: Largest area (m^2) a corner of its own may share with a connection lane of its junction.
CORNER_OVERLAP = 0.05


def add_corners(doc: Document, layout: Layout, params: Params, ids: Ids) -> Document:
    """``doc`` with a roadside corner road at each corner of every junction."""
    roads = {r.id: r for r in doc.roads}
    extra: list[Road] = []
    junctions = []
    for jp, junction in zip(layout.junctions, doc.junctions):
        legs = [_leg(roads, rp, jn_end, jp.position) for rp, jn_end in _legs_of(layout, junction, doc)]
        new_roads, new_conns = _junction_corners(junction, legs, jp.connections, doc, params, ids)
        extra.extend(new_roads)
        junctions.append(dataclasses.replace(junction, connections=junction.connections + tuple(new_conns)))
    return dataclasses.replace(doc, roads=doc.roads + tuple(extra), junctions=tuple(junctions))


def _legs_of(layout: Layout, junction: Junction, doc: Document) -> list[tuple[RoadPlan, str]]:
    """The road plans meeting ``junction`` and which end of each meets it (a road may meet it with both ends)."""
    index = [j.id for j in doc.junctions].index(junction.id)
    out = []
    for rp in layout.roads:
        if rp.start_junction == index:
            out.append((rp, "start"))
        if rp.end_junction == index:
            out.append((rp, "end"))
    return out


def _leg(roads: dict[str, Road], rp: RoadPlan, contact: str, at: tuple[float, float]) -> LegEnd:
    road = roads[str(rp.index + 1)]
    section = road.sections[0] if contact == "start" else road.sections[-1]
    nxt = road.sections[1].s if len(road.sections) > 1 else road.length
    length = (nxt if contact == "start" else road.length) - section.s
    return leg_end(road.id, contact, road.geometry, section, length, at)


def _junction_corners(
    junction: Junction,
    legs: list[LegEnd],
    plans: tuple[ConnectionPlan, ...],
    doc: Document,
    params: Params,
    ids: Ids,
) -> tuple[list[Road], list[Connection]]:
    roads_by_id = {r.id: r for r in doc.roads}
    connecting = [roads_by_id[c.connecting_road] for c in junction.connections]
    widths = tuple(r.width for r in LANES[params.roadside])
    side = kerb_side(params)
    lane_side = -1.0 if params.traffic_rule is TrafficRule.RHT else 1.0
    bodies = [b for b in _lane_bodies([r.geometry[0] for r in connecting], lane_side, params.lane_width) if b]
    roads: list[Road] = []
    conns: list[Connection] = []
    for a, b in corner_pairs(legs, params):
        turn = _kerb_turn(a, b, connecting, roads_by_id, side)
        c = corner(a, b, turn, params, widths)
        if c is None or (turn is None and _covers(c, bodies, side, sum(widths))):
            continue
        rid = ids.next()
        roads.append(_corner_road(c, rid, junction.id, params, side))
        links = tuple(LaneLink(a_id, side * (k + 1)) for k, a_id in enumerate(c.a_ids))
        conns.append(Connection(str(len(junction.connections) + len(conns) + 1), a.road, rid, "start", links))
    return roads, conns


def _kerb_turn(a: LegEnd, b: LegEnd, connecting: list[Road], roads: dict[str, Road], side: int):
    """The reference line of the connection lane from ``a``'s outermost entering lane to ``b``'s outermost leaving
    lane (the kerb-side turn round the corner), or None."""
    lane_a = _outermost(a, roads[a.road], True, side)
    lane_b = _outermost(b, roads[b.road], False, side)
    if lane_a is None or lane_b is None:
        return None
    for r in connecting:
        p, s = r.predecessor, r.successor
        lane = (r.sections[0].left + r.sections[0].right)[0]
        if (
            p is not None
            and s is not None
            and (p.element_id, p.contact_point, lane.predecessor) == (a.road, a.contact, lane_a)
            and (s.element_id, s.contact_point, lane.successor) == (b.road, b.contact, lane_b)
        ):
            return r.geometry[0]
    return None


def _outermost(leg: LegEnd, road: Road, entering: bool, side: int) -> int | None:
    """Id of the outermost driving lane of ``leg`` carrying traffic into (or out of) the junction, with its full
    width at the junction."""
    along_s = (leg.contact == "end") == entering
    lane_side = side if along_s else -side
    section = road.sections[0] if leg.contact == "start" else road.sections[-1]
    lanes = section.left if lane_side > 0 else section.right
    at_end = leg.contact == "end"
    length = road.length - section.s if at_end else 0.0
    full = [ln.id for ln in lanes if ln.type == "driving" and _width(ln.widths[0], length) > 1e-6]
    return max(full, key=abs) if full else None


def _width(w: Cubic, ds: float) -> float:
    return w.a + ds * (w.b + ds * (w.c + ds * w.d))


def _covers(c: Corner, bodies: list, side: int, width: float) -> bool:
    """Whether a corner of its own (reference line at its kerb) covers a connection lane's body."""
    mine = _lane_bodies([c.geometry], float(side), width)[0]
    if mine is None or not bodies:
        return mine is None
    return any(shapely.intersection(mine, b).area > CORNER_OVERLAP for b in bodies)


def _corner_road(c: Corner, rid: str, junction_id: str, params: Params, side: int) -> Road:
    lanes = []
    for k, r in enumerate(LANES[params.roadside]):
        heights = (LaneHeight(0.0, r.height, r.height),) if r.height else ()
        lanes.append(Lane(side * (k + 1), r.type, (Cubic(0.0, r.width),), (), c.a_ids[k], c.b_ids[k], heights))
    centre = Lane(0, "none")
    left, right = (tuple(lanes), ()) if side > 0 else ((), tuple(lanes))
    section = LaneSection(0.0, left, centre, right)
    offset = (Cubic(0.0, c.lane_offset),) if c.lane_offset != 0.0 else ()
    return Road(
        rid,
        c.geometry.length,
        junction_id,
        (dataclasses.replace(c.geometry, s=0.0),),
        (section,),
        params.traffic_rule.value,
        Link("road", c.a.road, c.a.contact),
        Link("road", c.b.road, c.b.contact),
        lane_offset=offset,
        name=f"junction {junction_id} corner {c.a.road}-{c.b.road}",
    )
