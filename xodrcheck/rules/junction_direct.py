"""Whether traffic crosses inside a direct junction (``J031``, 12.6).

A direct junction joins one road on one side to several on the other at one joint, where the incoming road ends and
the linked roads begin (their lanes may overlap to split or merge, 12.6.2). Each ``<laneLink>`` is a path through
the joint: a lane on one side continues in a lane on the other. Two paths cross when their lateral order differs on
the two sides: the first lies left of the second on one side and right of it on the other.

Lateral order is decided exactly from the lane ids where both lanes are on one road (a larger id lies further left;
a road that runs the other way at the joint, i.e. touches it at the same end as the frame road on the other side or
at the other end on the same side, is turned round), and from the plan view where they are on two roads: each lane's
interval across the frame road (its inner and outer border at its end, projected onto the frame road's normal at
the joint) lies wholly to one side of the other's, within ``gap``. Two lanes of two roads that overlap across (the
overlapping lanes of 12.6.2, which share the space until their roads part) take the order of their roads: the
middles of the roads' whole widths at the joint, the side each road leaves to. Two links leaving one lane (a split)
or entering one lane (a merge) have no order on that side, so they never cross; lanes whose roads cannot be evaluated
have no order across roads either, so no crossing is claimed for them.
"""

from __future__ import annotations

import math
from collections.abc import Iterator
from dataclasses import dataclass

from xodrcheck.findings import Category, Finding, Severity
from xodrcheck.model import Connection, ContactPoint, Junction, JunctionType, Road
from xodrcheck.rules.registry import rule
from xodrcheck.rules.shared import junction_uids as U
from xodrcheck.rules.shared.context import Context
from xodrcheck.rules.shared.road_ends import reference_end, road_end


@dataclass(frozen=True, slots=True)
class _End:
    """One end of a lane link: ``lane`` of ``road``, which touches the joint at ``end``; ``side`` 0 is the frame
    road's side of the joint, 1 the other."""

    road: Road
    end: ContactPoint
    lane: int
    side: int


@dataclass(frozen=True, slots=True)
class _Path:
    """A ``<laneLink>`` through the joint: ``a`` on the frame road's side, ``b`` on the other (``flip``: ``a`` is the
    linked road's lane, the link's ``to``)."""

    connection: Connection
    a: _End
    b: _End
    line: int
    flip: bool = False


@dataclass(frozen=True, slots=True)
class _Frame:
    """The frame road at the joint: its end there, and the joint's point and left normal (``None``: no plan view)."""

    road: Road
    end: ContactPoint
    origin: tuple[float, float] | None
    normal: tuple[float, float] | None


def _shared_road(junction: Junction) -> str | None:
    """The road in every connection of a direct junction (J020's one road on one side), ``None`` when none is."""
    pairs = [
        {c.incoming_road, c.linked_road}
        for c in junction.connections
        if c.incoming_road is not None and c.linked_road is not None and c.incoming_road != c.linked_road
    ]
    if not pairs:
        return None
    shared = set.intersection(*pairs)
    return min(shared) if len(shared) == 1 else None


def _paths(ctx: Context, junction: Junction) -> tuple[_Frame, list[_Path]] | None:
    """The junction's lane links as paths, each with its end on the frame road's side first. The frame road is the
    shared road (J020); without one (several roads on both sides, which J020 reports), the first connection's
    incoming road, with the incoming roads on its side and the linked roads on the other."""
    shared = _shared_road(junction)
    frame: _Frame | None = None
    paths: list[_Path] = []
    for c in junction.connections:
        incoming, linked = ctx.road(c.incoming_road), ctx.road(c.linked_road)
        into = ctx.incoming_contact(junction, c) if incoming is not None else None
        if incoming is None or linked is None or into is None or c.contact_point is None or incoming is linked:
            continue
        flip = shared is not None and linked.id == shared
        near, far = (linked, incoming) if flip else (incoming, linked)
        near_end, far_end = (c.contact_point, into) if flip else (into, c.contact_point)
        if frame is None:
            frame = _frame(ctx, near, near_end)
        for ll in c.lane_links:
            a_lane, b_lane = (ll.to_lane, ll.from_lane) if flip else (ll.from_lane, ll.to_lane)
            a, b = _End(near, near_end, a_lane, 0), _End(far, far_end, b_lane, 1)
            paths.append(_Path(c, a, b, ll.line or c.line, flip))
    return (frame, paths) if frame is not None else None


def _frame(ctx: Context, road: Road, end: ContactPoint) -> _Frame:
    point = reference_end(ctx, road, end) if ctx.usable_geometry(road) is not None else None
    if point is None:
        return _Frame(road, end, None, None)
    along = point.outward if end is ContactPoint.END else point.outward + math.pi
    return _Frame(road, end, (point.x, point.y), (-math.sin(along), math.cos(along)))


def _aligned(frame: _Frame, end: _End) -> int:
    """+1 when ``end``'s road runs the frame road's way at the joint (its left is the frame's left), else -1."""
    same_end = end.end is frame.end
    return 1 if same_end == (end.side == 0) else -1


def _across(ctx: Context, frame: _Frame, end: _End) -> tuple[float, float] | None:
    """(right, left) ``t`` of a lane's borders at its end, across the frame road at the joint."""
    if frame.origin is None or frame.normal is None or ctx.usable_geometry(end.road) is None:
        return None
    lines = road_end(ctx, end.road, end.end)
    inner, outer = lines.border(end.lane, "inner"), lines.border(end.lane, "outer")
    if inner is None or outer is None:
        return None
    (ox, oy), (nx, ny) = frame.origin, frame.normal
    t = sorted(((p.x - ox) * nx + (p.y - oy) * ny) for p in (inner, outer))
    return t[0], t[1]


def _order(ctx: Context, frame: _Frame, p: _End, q: _End) -> int:
    """+1 when lane ``p`` lies left of lane ``q`` across the joint, -1 right of it, 0 when neither is known."""
    if ctx.lane_at(p.road, p.end, p.lane) is None or ctx.lane_at(q.road, q.end, q.lane) is None:
        return 0  # a lane that is not there (the reference rules report it)
    if p.road.id == q.road.id:
        return 0 if p.lane == q.lane else _aligned(frame, p) * (1 if p.lane > q.lane else -1)
    tp, tq = _across(ctx, frame, p), _across(ctx, frame, q)
    if tp is None or tq is None:
        return 0
    gap = ctx.tolerances.gap
    left, right = tp[0] >= tq[1] - gap, tp[1] <= tq[0] + gap
    if left != right:
        return 1 if left else -1
    if tp[0] < tq[1] - gap and tq[0] < tp[1] - gap:  # the lanes overlap: their roads part to the sides they lie on
        cp, cq = _road_middle(ctx, frame, p), _road_middle(ctx, frame, q)
        if cp is not None and cq is not None and abs(cp - cq) > gap:
            return 1 if cp > cq else -1
    return 0


def _road_middle(ctx: Context, frame: _Frame, end: _End) -> float | None:
    """``t`` of the middle of a road's whole width at its end, across the frame road at the joint."""
    if frame.origin is None or frame.normal is None:
        return None
    (ox, oy), (nx, ny) = frame.origin, frame.normal
    t = [(p.x - ox) * nx + (p.y - oy) * ny for p in road_end(ctx, end.road, end.end).outer.values()]
    return 0.5 * (min(t) + max(t)) if t else None


def _crossings(ctx: Context, frame: _Frame, paths: list[_Path]) -> list[tuple[_Path, _Path, int]]:
    """Pairs of paths whose order on the frame road's side (+1: the first left) is reversed on the other side."""
    out = []
    for i, p in enumerate(paths):
        for q in paths[i + 1 :]:
            before = _order(ctx, frame, p.a, q.a)
            if before and before * _order(ctx, frame, p.b, q.b) < 0:
                out.append((p, q, before))
    return out


def _describe(path: _Path) -> str:
    """The link as the file writes it: from the incoming road's lane to the linked road's."""
    src, dst = (path.b, path.a) if path.flip else (path.a, path.b)
    return (
        f"connection {path.connection.id} (lane {src.lane} of road {src.road.id} to lane {dst.lane} of road "
        f"{dst.road.id}, line {path.line})"
    )


@rule("J031", "direct-junction-crossing-traffic", Category.JUNCTION, Severity.ERROR, uids=(U.DIRECT_SPLIT_OR_MERGE,))
def direct_junction_crossing_traffic(ctx: Context) -> Iterator[Finding]:
    """Two lane links of a direct junction cross: traffic crosses inside it.

    Direct junctions only split or merge roads without crossing traffic (``junctions.direct.split_or_merge``, 12.6;
    Figure 92 is the spec's crossing case). Each ``<laneLink>`` is a path through the joint where the one road meets
    the others; two paths cross when their lanes' lateral order on the one road's side is reversed on the other side:
    an inner lane continuing outside an outer lane's continuation, one lane split onto targets on both sides of
    another lane's target, or lanes of both driving directions swapped. Order on one road comes from the lane ids
    (exact), across two roads from the lanes' borders at the joint, within ``gap`` (overlapping lanes: from the
    sides their roads leave to). Links that leave or enter one lane (a split or a merge) never cross. One finding per
    junction, at the joint, naming the first crossing pair by line and how many more pairs cross. Links on a 1.9
    temporary lane layer are not considered.

    Passes (road 1's lanes -1 and -2 continue on road 2 and on road 3, which starts right of road 2)::

        <connection id="0" incomingRoad="1" linkedRoad="2" contactPoint="start"><laneLink from="-1" to="-1"/>
        <connection id="1" incomingRoad="1" linkedRoad="3" contactPoint="start"><laneLink from="-2" to="-1"/>

    Fails (lane -1 continues on road 3, right of road 2, where lane -2, right of lane -1, continues)::

        <connection id="0" incomingRoad="1" linkedRoad="2" contactPoint="start"><laneLink from="-2" to="-1"/>
        <connection id="1" incomingRoad="1" linkedRoad="3" contactPoint="start"><laneLink from="-1" to="-1"/>
    """
    for junction in ctx.document.junctions:
        if junction.type is not JunctionType.DIRECT:
            continue
        found = _paths(ctx, junction)
        if found is None:
            continue
        frame, paths = found
        crossing = _crossings(ctx, frame, paths)
        if not crossing:
            continue
        p, q, before = min(crossing, key=lambda pair: (max(pair[0].line, pair[1].line), pair[0].line))
        where = "left" if before > 0 else "right"
        there = "right" if before > 0 else "left"
        more = f"; {len(crossing) - 1} more pair(s) of links cross" if len(crossing) > 1 else ""
        yield direct_junction_crossing_traffic.finding(
            f"direct junction {junction.id}: {_describe(p)} and {_describe(q)} cross: lane {p.a.lane} of road "
            f"{p.a.road.id} lies {where} of lane {q.a.lane} of road {q.a.road.id}, but its continuation (lane "
            f"{p.b.lane} of road {p.b.road.id}) lies {there} of the other's (lane {q.b.lane} of road {q.b.road.id}) at "
            f"the joint{more}; a direct junction only splits or merges roads without crossing "
            "traffic (12.6): fix the lane links or model the crossing with a common junction and connecting roads",
            road=frame.road.id,
            s=0.0 if frame.end is ContactPoint.START else float(frame.road.length),
            line=max(p.line, q.line) or junction.line or None,
        )
