"""Stage 4: lane sections with tapers where lane counts change, lane markings, and the final document.

A road whose lane count differs between its middle and one end (a merge before a junction, a turn lane, an exit lane
nobody feeds) gets a taper section at that end: the extra lanes, always the outermost of their side, go from full width
to zero (or from zero to full) with a smooth cubic, and link only to lanes that exist on the other side of the
section boundary. Markings: solid yellow centre line (solid white on one-way roads), broken white between lanes of one
direction and solid within :data:`SOLID_NEAR_JUNCTION` of a junction (but broken beside a taper, which traffic
crosses to enter or leave the lane that opens or closes), solid white road edges, none inside junctions.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from .intersections.model import Layout, RoadPlan
from .lanegeom import forward_side, lane_id, taper_length
from .opendrive import (
    Arc,
    Connection,
    Cubic,
    Document,
    Geometry,
    Header,
    Junction,
    Lane,
    LaneLink,
    LaneSection,
    Line,
    Link,
    Road,
    RoadMark,
)
from .params import Params, Roadside, TrafficRule
from .scenario.roadside import side_lanes

SOLID_NEAR_JUNCTION = 30.0
ROAD_SPEED = 50.0
JUNCTION_SPEED = 30.0


def _taper(a: float, b: float, length: float) -> Cubic:
    if a == b:
        return Cubic(0.0, a)
    d = b - a
    return Cubic(0.0, a, 0.0, 3 * d / length**2, -2 * d / length**3)


@dataclass(frozen=True)
class _Span:
    """A stretch of a road from ``s0`` to ``s1``, its (forward, backward) lane counts at both ends and the width of
    its median lane at both ends (None: no median lane)."""

    s0: float
    s1: float
    start: tuple[int, int]  # (forward, backward) lanes at s0
    end: tuple[int, int]
    median: tuple[float, float] | None = None


def _spans(rp: RoadPlan, params: Params) -> list[_Span]:
    """The road's lane sections: the middle, a taper at each end whose lane counts differ, and at a roundabout's end
    the splitter island (a median widening to its width, then keeping it to the end)."""
    mid = (rp.lanes.forward, rp.lanes.backward)
    first, last = (rp.fwd_start, rp.bwd_start), (rp.fwd_end, rp.bwd_end)
    base = (params.median_width, params.median_width) if rp.lanes.median else None
    head = _splitter(rp.splitter_start, base, params)
    tail = _splitter(rp.splitter_end, base, params)
    a, b = sum(length for length, _ in head), rp.length - sum(length for length, _ in tail)
    s1 = a + taper_length(params, first, mid)
    s2 = b - taper_length(params, last, mid)
    spans = []
    s = 0.0
    for length, widths in reversed(head):  # from the road's start: full width, then narrowing
        spans.append(_Span(s, s + length, first, first, (widths[1], widths[0])))
        s += length
    if s1 > a:
        spans.append(_Span(a, s1, first, mid, base))
    spans.append(_Span(s1, s2, mid, mid, base))
    if s2 < b:
        spans.append(_Span(s2, b, mid, last, base))
    s = b
    for length, widths in tail:
        spans.append(_Span(s, s + length, last, last, widths))
        s += length
    return spans


def _splitter(
    width: float, base: tuple[float, float] | None, params: Params
) -> list[tuple[float, tuple[float, float]]]:
    """A splitter island at one end of a road (:func:`junctionart.intersections.roundabout.splitter_spans`)."""
    if width <= 0.0:
        return []
    from .intersections.roundabout import splitter_spans

    return splitter_spans(width, base[0] if base is not None else 0.0, params)


def _marks(kind: str, color: str, s0: float, s1: float, rp: RoadPlan, taper: bool = False) -> tuple[RoadMark, ...]:
    """Marks of one border over [s0, s1): ``kind`` in the open, solid within reach of a junction, except beside a
    lane that opens or closes there (``taper``): its traffic crosses that line to enter or leave it; broken all round
    a roundabout's ring, whose lanes are changed between its junctions."""
    if kind == "solid":
        return (RoadMark(0.0, "solid", color, lane_change="none"),)
    if taper or rp.ring:
        return (RoadMark(0.0, kind, color, lane_change="both"),)
    cuts: list[tuple[float, str]] = []
    near0 = SOLID_NEAR_JUNCTION if rp.start_junction is not None else 0.0
    near1 = rp.length - SOLID_NEAR_JUNCTION if rp.end_junction is not None else rp.length
    pieces = [(0.0, near0, "solid"), (near0, near1, kind), (near1, rp.length, "solid")]
    for a, b, k in pieces:
        a, b = max(a, s0), min(b, s1)
        if b - a > 1e-9 and (not cuts or cuts[-1][1] != k):
            cuts.append((a - s0, k))
    if not cuts:
        cuts = [(0.0, "solid")]
    return tuple(RoadMark(s, k, color, lane_change="none" if k == "solid" else "both") for s, k in cuts)


def _section(rp: RoadPlan, span: _Span, params: Params, prev: _Span | None, nxt: _Span | None) -> LaneSection:
    w, rule = params.lane_width, params.traffic_rule
    median = span.median is not None
    prev_median = prev is not None and prev.median is not None
    next_median = nxt is not None and nxt.median is not None
    L = span.s1 - span.s0
    lanes_by_side: dict[int, list[Lane]] = {1: [], -1: []}
    for forward, idx in ((True, 0), (False, 1)):
        a, b = span.start[idx], span.end[idx]
        n = max(a, b)
        changing = {k for k in range(1, n + 1) if (k <= a) != (k <= b)}  # lanes that open or close in this span
        for k in range(1, n + 1):
            lid = lane_id(forward, k, median, rule)
            wa, wb = (w if k <= a else 0.0), (w if k <= b else 0.0)
            pred = _linked(prev, idx, k, wa, forward, prev_median, rule)
            succ = _linked(nxt, idx, k, wb, forward, next_median, rule)
            outer = k == n
            kind = "solid" if outer else "broken"
            marks = _marks(kind, "standard", span.s0, span.s1, rp, taper=k + 1 in changing)
            lanes_by_side[1 if lid > 0 else -1].append(Lane(lid, "driving", (_taper(wa, wb, L),), marks, pred, succ))
    if span.median is not None:
        m0, m1 = span.median
        lanes_by_side[1].append(
            Lane(
                1,
                "median",
                (_taper(m0, m1, L),),
                (RoadMark(0.0, "solid", "yellow"),),
                1 if prev_median else None,
                1 if next_median else None,
            )
        )
    if params.roadside is not Roadside.NONE:
        for side in (1, -1):
            lanes_by_side[side].extend(
                side_lanes(
                    params,
                    side,
                    _inner(rp, span, side, params),
                    _inner(rp, prev, side, params) if prev is not None else None,
                    _inner(rp, nxt, side, params) if nxt is not None else None,
                )
            )
    two_way = rp.lanes.forward > 0 and rp.lanes.backward > 0
    centre = Lane(0, "none", (), (RoadMark(0.0, "solid", "yellow" if two_way else "standard", lane_change="none"),))
    left = tuple(sorted(lanes_by_side[1], key=lambda lane: lane.id))
    right = tuple(sorted(lanes_by_side[-1], key=lambda lane: -lane.id))
    return LaneSection(span.s0, left, centre, right)


def _linked(
    other: _Span | None, idx: int, k: int, width: float, forward: bool, median: bool, rule: TrafficRule
) -> int | None:
    """The id of driving lane ``k`` in the neighbouring section ``other`` (None when it has no such lane or this lane
    has no width at their boundary)."""
    if other is None or k > max(other.start[idx], other.end[idx]) or width <= 0:
        return None
    return lane_id(forward, k, median, rule)


def _inner(rp: RoadPlan, span: _Span, side: int, params: Params) -> int:
    """Lanes of one side (+1 left, -1 right) of ``span`` inside its roadside: driving lanes, and the median on the
    left."""
    forward = forward_side(params.traffic_rule) == side
    idx = 0 if forward else 1
    n = max(span.start[idx], span.end[idx])
    return n + (1 if side > 0 and span.median is not None else 0)


def _road(rp: RoadPlan, rid: str, junction_ids: list[str], params: Params) -> Road:
    spans = _spans(rp, params)
    sections = tuple(
        _section(rp, sp, params, spans[i - 1] if i > 0 else None, spans[i + 1] if i + 1 < len(spans) else None)
        for i, sp in enumerate(spans)
    )
    pred = Link("junction", junction_ids[rp.start_junction]) if rp.start_junction is not None else None
    succ = Link("junction", junction_ids[rp.end_junction]) if rp.end_junction is not None else None
    return Road(
        rid,
        rp.length,
        "-1",
        rp.geometry,
        sections,
        params.traffic_rule.value,
        pred,
        succ,
        name=f"road {rid}" if not rp.ring else f"roundabout ring road {rid}",
        speed_kmh=ROAD_SPEED if not rp.ring else JUNCTION_SPEED,
    )


def _three_points(g: Geometry) -> tuple[tuple[float, float], ...]:
    """Start, middle and end of one element for the header's bounds (scalar arithmetic: a numpy call per element
    cost more than the sums; the same operations in the same order as :func:`junctionart.curves.sample`)."""
    if isinstance(g, Line):
        c, s = math.cos(g.hdg), math.sin(g.hdg)
        return tuple((g.x + d * c, g.y + d * s) for d in (0.0, 0.5 * g.length, g.length))
    if isinstance(g, Arc):
        k, s0, c0 = g.curvature, math.sin(g.hdg), math.cos(g.hdg)
        return tuple(
            (g.x + (math.sin(g.hdg + k * d) - s0) / k, g.y - (math.cos(g.hdg + k * d) - c0) / k)
            for d in (0.0, 0.5 * g.length, g.length)
        )
    c, s = math.cos(g.hdg), math.sin(g.hdg)
    out = []
    for t in (0.0, 0.5, 1.0):
        u = g.au + t * (g.bu + t * (g.cu + t * g.du))
        v = g.av + t * (g.bv + t * (g.cv + t * g.dv))
        out.append((g.x + c * u - s * v, g.y + s * u + c * v))
    return tuple(out)


def document(layout: Layout, params: Params, name: str = "junctionart") -> Document:
    """The OpenDRIVE document of a finished layout."""
    n_roads = len(layout.roads)
    n_conn = sum(len(j.connections) for j in layout.junctions)
    road_ids = [str(i + 1) for i in range(n_roads)]
    junction_ids = [str(n_roads + n_conn + 1 + i) for i in range(len(layout.junctions))]
    roads = [_road(rp, road_ids[rp.index], junction_ids, params) for rp in layout.roads]
    conn_lane = -1 if params.traffic_rule is TrafficRule.RHT else 1
    next_id = n_roads + 1
    junctions = []
    for jn, jp in enumerate(layout.junctions):
        conns = []
        for cn, cp in enumerate(jp.connections):
            rid = str(next_id)
            next_id += 1
            lane = Lane(
                conn_lane,
                "driving",
                (Cubic(0.0, params.lane_width),),
                (RoadMark(0.0, "none", "standard"),),
                cp.in_lane,
                cp.out_lane,
            )
            centre = Lane(0, "none", (), (RoadMark(0.0, "none", "standard"),))
            sec = LaneSection(0.0, (lane,) if conn_lane > 0 else (), centre, (lane,) if conn_lane < 0 else ())
            roads.append(
                Road(
                    rid,
                    cp.geometry.length,
                    junction_ids[jn],
                    (cp.geometry,),
                    (sec,),
                    params.traffic_rule.value,
                    Link("road", road_ids[cp.in_road], cp.in_contact),
                    Link("road", road_ids[cp.out_road], cp.out_contact),
                    name=f"junction {junction_ids[jn]} connection {cn + 1}",
                    speed_kmh=JUNCTION_SPEED,
                )
            )
            conns.append(
                Connection(str(cn + 1), road_ids[cp.in_road], rid, "start", (LaneLink(cp.in_lane, conn_lane),))
            )
        junctions.append(Junction(junction_ids[jn], f"junction {junction_ids[jn]} ({jp.legs} legs)", tuple(conns)))
    points = [xy for r in roads for g in r.geometry for xy in _three_points(g)]
    xs, ys = [x for x, _ in points], [y for _, y in points]
    header = Header(
        name=name,
        north=max(ys, default=0.0),
        south=min(ys, default=0.0),
        east=max(xs, default=0.0),
        west=min(xs, default=0.0),
    )
    return Document(header, tuple(roads), tuple(junctions))
