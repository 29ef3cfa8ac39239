"""Forks and ramps in a generated map (``fork_probability``, ``ramp_probability``; control-line files' ``forks`` and
``ramps``): the last step of generation, after the scenario features.

Each road of the finished map with a stretch for it (:func:`.site.stretch`) gets a fork with chance
``fork_probability`` and else a ramp pair with chance ``ramp_probability``; the draws come from a generator seeded
with the map's seed and the road's id, not from the map's random stream, so turning them on changes no other choice
and with both 0 (the paper profile) this step does nothing. A fork's angle is drawn from 10 to 45 degrees, a ramp's
from 20 to 40. A structure is put in the middle of its stretch when it fits there and keeps clear of every other
road (its footprint: each road's reference line widened by its widest side); otherwise the road keeps its shape.
A control-line file asks for a structure at a distance along one of its lines: it goes on the road running along
the line there, centred as near that point as its stretch allows; one that does not fit is reported, not forced.
"""

from __future__ import annotations

import math
from collections.abc import Iterable

import numpy as np
import shapely

from ..controllines import Request
from ..curves import sample
from ..opendrive import Document, Road
from ..params import Params
from ..scenario.ids import Ids
from ..scenario.roadside import roadside_width
from .insert import lane_groups, place
from .site import Design, Stretch, design, loop_path, point_on, stretch

#: Angles (degrees) drawn for forks and ramps.
FORK_ANGLES = (10.0, 45.0)
RAMP_ANGLES = (20.0, 40.0)
#: Metres a branch keeps from every other road.
CLEAR = 1.0


def _polyline(geometry, step: float) -> shapely.LineString:
    """The reference line through points about ``step`` apart, without repeated points (elements share their ends;
    GEOS refuses to buffer a line that doubles back on a repeated point)."""
    pts = np.concatenate([sample(g, max(2, int(g.length / step) + 2)) for g in geometry])
    keep = np.concatenate([[True], np.hypot(*np.diff(pts, axis=0).T) > 1e-6])
    return shapely.LineString(pts[keep])


def _footprint(road: Road) -> shapely.Geometry:
    half = max(
        (
            sum(lane.widths[0].a if lane.widths else 0.0 for lane in side)
            for sec in road.sections
            for side in (sec.left, sec.right)
        ),
        default=0.0,
    )
    offset = max((abs(c.a) for c in road.lane_offset), default=0.0)
    return _polyline(road.geometry, 2.0).buffer(half + offset + CLEAR)


def _forward_lanes(road: Road, st: Stretch, fs: int) -> int:
    sec = road.sections[st.section]
    side = sec.left if fs > 0 else sec.right
    return sum(1 for lane in side if lane.type == "driving")


def _fits(d: Design, st: Stretch, centre: float) -> bool:
    return st.s0 <= centre - d.length / 2 and centre + d.length / 2 <= st.s1


def _branch_area(d: Design, st: Stretch, centre: float, doc_params: Params, road: Road, fs: int) -> shapely.Geometry:
    """The branch's footprint: its reference line widened on its lane side by its lanes and roadside."""
    x, y, hdg = point_on(st.line, centre - d.loop / 2)
    sec = road.sections[st.section]
    side = sec.left if fs > 0 else sec.right
    inner = sum(lane.widths[0].a for lane in side if lane.type in ("driving", "median"))
    if not d.added:
        inner -= d.far_lanes * doc_params.lane_width
    fx, fy = x - fs * inner * math.sin(hdg), y + fs * inner * math.cos(hdg)
    geo = loop_path(d, fx, fy, hdg, fs)
    width = d.far_lanes * doc_params.lane_width + roadside_width(doc_params)
    line = _polyline(geo, 1.0)
    return line.buffer(width + CLEAR, single_sided=True) if fs > 0 else line.buffer(-(width + CLEAR), single_sided=True)


def _draws(doc: Document, params: Params, seed: int) -> list[Request]:
    """The structures the map's roads draw (module docstring), each as a request on its road (``source``: its id)."""
    out = []
    for road in doc.roads:
        if road.junction != "-1" or not road.id.isdigit():
            continue
        rng = np.random.default_rng([seed, 28, int(road.id)])
        fork, ramp, share = rng.random(), rng.random(), rng.random()
        if fork < params.fork_probability:
            angle = FORK_ANGLES[0] + share * (FORK_ANGLES[1] - FORK_ANGLES[0])
            out.append(Request("fork", math.nan, math.nan, angle, road.id))
        elif ramp < params.ramp_probability:
            angle = RAMP_ANGLES[0] + share * (RAMP_ANGLES[1] - RAMP_ANGLES[0])
            out.append(Request("ramp", math.nan, math.nan, angle, road.id))
    return out


def add(doc: Document, params: Params, seed: int, requests: Iterable[Request] = ()) -> tuple[Document, list[str]]:
    """``doc`` with forks and ramps (module docstring), and a note for each request that did not fit."""
    fs = -1 if params.traffic_rule.value == "RHT" else 1
    ids = Ids(doc)
    kind = "direct" if params.direct_junctions else "default"
    areas = {r.id: _footprint(r) for r in doc.roads}
    notes: list[str] = []
    jobs = [(req, True) for req in requests] + [(req, False) for req in _draws(doc, params, seed)]
    for req, asked in jobs:
        why = _why_not(doc, req, asked, params, fs, areas)
        if isinstance(why, str):
            if asked:
                notes.append(f"{req.kind} asked on {req.source}: {why}")
            continue
        st, d, centre = why
        placed = place(doc, st, d, centre, params, ids, kind)
        if placed is None:
            if asked:
                notes.append(f"{req.kind} asked on {req.source}: road {st.road.id} has no lanes for it")
            continue
        changed = st.road.id
        doc = placed
        for road in doc.roads:  # the road's pieces, the branch and any connecting roads: their own footprints
            if road.id == changed or road.id not in areas:
                areas[road.id] = _footprint(road)
    return doc, notes


def _why_not(
    doc: Document, req: Request, asked: bool, params: Params, fs: int, areas: dict[str, shapely.Geometry]
) -> str | tuple[Stretch, Design, float]:
    """Where and how ``req`` goes (stretch, design, centre), or why it cannot."""
    road = _road_at(doc, req) if asked else _by_id(doc, req.source)
    if road is None:
        return f"no road runs within 5 m of ({req.x:.1f}, {req.y:.1f})"
    st = stretch(road)
    if st is None:
        return f"road {road.id} has no straight stretch away from its junctions and objects"
    lanes = _forward_lanes(road, st, fs)
    if lanes == 0:
        return f"road {road.id} has no lane driving along it"
    d = design(req.kind, lanes, req.angle if req.angle is not None else 30.0, params.lane_width, roadside_width(params))
    centre = _centre(st, d, req if asked else None)
    if centre is None or lane_groups(road.sections[st.section], 0.0, fs, d, params.lane_width) is None:
        return f"road {road.id}'s straight stretch is {st.s1 - st.s0:.0f} m long, the {req.kind} needs {d.length:.0f} m"
    area = _branch_area(d, st, centre, params, road, fs)
    if any(area.intersects(a) for rid, a in areas.items() if rid != road.id):
        return f"its branch beside road {road.id} would run into another road"
    return st, d, centre


def _by_id(doc: Document, rid: str) -> Road | None:
    return next((r for r in doc.roads if r.id == rid), None)


def _road_at(doc: Document, req: Request) -> Road | None:
    """The road outside junctions whose reference line passes nearest (x, y), within 5 m."""
    pt = shapely.Point(req.x, req.y)
    best, best_d = None, 5.0
    for road in doc.roads:
        if road.junction != "-1":
            continue
        dist = _polyline(road.geometry, 2.0).distance(pt)
        if dist < best_d:
            best, best_d = road, dist
    return best


def _centre(st: Stretch, d: Design, req: Request | None) -> float | None:
    """Road s of the structure's middle: the stretch's middle, or as near the requested point as it fits."""
    lo, hi = st.s0 + d.length / 2, st.s1 - d.length / 2
    if hi < lo:
        return None
    if req is None:
        return (lo + hi) / 2
    g = st.line
    along = (req.x - g.x) * math.cos(g.hdg) + (req.y - g.y) * math.sin(g.hdg) + g.s
    return min(max(along, lo), hi)
