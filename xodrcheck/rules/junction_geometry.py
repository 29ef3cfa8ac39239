"""Junction geometry (``J1xx``): the paths a junction offers from one incoming road do not cross.

A *connection lane* is a lane of a connecting road entered from a lane of an incoming road by a junction
``<laneLink>``; its path is the lane's centre line from the contact point through the connecting road (following the
lane's links across lane sections), sampled once per lane section (:mod:`.shared.sampled`). Only lanes whose
traffic enters the junction are followed (``junction-lane-link-outbound`` reports the others).

* The paths leaving one incoming road may share their start (several turns from one lane) but must not meet
  anywhere else: two turns that cross each other conflict inside the junction (``J101``). Paths from the same lane
  are compared from where they part, their centre lines ``junction_start`` (1 m) apart: until then they carry one
  queue of vehicles, so a slow weave of a few cm where two turns part is no crossing; paths from different lanes
  anywhere.
* Within one connection, the laneLinks keep the lanes' side-by-side order: the incoming lanes ordered across the
  road at the contact must enter connecting lanes in the same order (``J102``), or the lanes swap places at the
  contact point.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from xodrcheck.findings import Basis, Category, Severity
from xodrcheck.geometry.batch import centre_lines
from xodrcheck.model import Connection, ContactPoint, JunctionType, Road
from xodrcheck.rules.registry import rule
from xodrcheck.rules.shared.context import Context, travel_direction
from xodrcheck.rules.shared.lane_paths import Known, centre_path, crossing, walk
from xodrcheck.rules.shared.road_ends import end_s, road_end
from xodrcheck.rules.shared.sampled import BATCH_SAMPLES, section_samples

if TYPE_CHECKING:
    pass


@dataclass(frozen=True)
class _Connected:
    """A connection whose connecting road exists and can be evaluated, with that road and its contact point."""

    connection: Connection
    road: Road
    contact: ContactPoint


@dataclass(frozen=True)
class _Path:
    """One lane's path through a junction, sampled in plan view from the contact point on."""

    connection: Connection
    from_lane: int
    road: Road
    lane: int
    line: int | None
    xy: np.ndarray  # (n, 2) from the contact point on


def _enters(ctx: Context, incoming: Road, end: ContactPoint, lane_id: int) -> bool:
    """Whether traffic on the lane travels towards the road's ``end`` (into the junction); not for a lane without one
    direction of traffic (a sidewalk, a shoulder, ``direction="both"``...)."""
    lane = ctx.lane_at(incoming, end, lane_id)
    return lane is not None and travel_direction(incoming, lane) == (1 if end is ContactPoint.END else -1)


def _groups(ctx: Context):
    """(junction, incoming road, its end at the junction, connections from it) for every default junction."""
    for junction in ctx.document.junctions:
        if junction.type is JunctionType.DIRECT:
            continue
        for incoming_id in junction.incoming_roads:
            incoming = ctx.road(incoming_id)
            if incoming is None or ctx.usable_geometry(incoming) is None:
                continue
            connections = ctx.connections_by_incoming.get((junction.id, incoming_id), ())
            ends: dict[ContactPoint, list[_Connected]] = {}
            for c in connections:
                end = ctx.incoming_contact(junction, c)
                connecting = ctx.road(c.connecting_road)
                if (
                    end is None
                    or connecting is None
                    or c.contact_point is None
                    or ctx.usable_geometry(connecting) is None
                ):
                    continue
                ends.setdefault(end, []).append(_Connected(c, connecting, c.contact_point))
            for end, group in ends.items():
                yield junction, incoming, end, group


def _paths(
    ctx: Context, incoming: Road, end: ContactPoint, connections: list[_Connected], known: Known | None = None
) -> list[_Path]:
    out: list[_Path] = []
    seen: set[tuple[str, int]] = set()
    for c, connecting, contact in ((k.connection, k.road, k.contact) for k in connections):
        for link in c.lane_links:
            if not _enters(ctx, incoming, end, link.from_lane) or (connecting.id, link.to_lane) in seen:
                continue
            xy = centre_path(ctx, connecting, link.to_lane, contact, known)
            if xy is None:
                continue
            seen.add((connecting.id, link.to_lane))
            out.append(_Path(c, link.from_lane, connecting, link.to_lane, link.line or c.line, xy))
    return out


def _ahead(ctx: Context):
    """:func:`_groups`, each with the centre lines its paths follow (:data:`Known`), evaluated ahead for a run of
    groups at a time (:func:`_known`; at most about ``BATCH_SAMPLES`` points kept)."""
    run: list[tuple] = []
    wanted: dict[tuple[str, int], tuple[Road, list[int]]] = {}
    size = 0
    for group in _groups(ctx):
        _, incoming, end, connections = group
        for k in connections:
            for link in k.connection.lane_links:
                if not _enters(ctx, incoming, end, link.from_lane):
                    continue
                for index, lane_id in walk(ctx, k.road, link.to_lane, k.contact):
                    road, lanes = wanted.setdefault((k.road.id, index), (k.road, []))
                    if lane_id not in lanes:
                        lanes.append(lane_id)
                        size += len(section_samples(ctx, road, index))
        run.append(group)
        if size >= BATCH_SAMPLES:
            known = _known(ctx, wanted)
            yield from ((*g, known) for g in run)
            run, wanted, size = [], {}, 0
    if run:
        known = _known(ctx, wanted)
        yield from ((*g, known) for g in run)


def _known(ctx: Context, wanted: dict[tuple[str, int], tuple[Road, list[int]]]) -> Known:
    """The centre lines of ``wanted`` lanes ((road id, section index) -> road, lane ids), evaluated together
    (:func:`xodrcheck.geometry.batch.centre_lines`: the points of ``lane_points`` lane by lane)."""
    sections, keys, grids, lanes = [], [], [], []
    for (road_id, index), (road, ids) in wanted.items():
        sections.append(ctx.road_geometry(road).rows(index))
        keys.append((road_id, index))
        grids.append(section_samples(ctx, road, index))
        lanes.append(ids)
    out: Known = {}
    for lo, hi, found in centre_lines(sections, grids, lanes, BATCH_SAMPLES):
        x, y = found.xy()
        line = 0
        for k in range(lo, hi):
            for lane_id in lanes[k]:
                a, b = int(found.starts[line]), int(found.starts[line + 1])
                out[(keys[k][0], keys[k][1], lane_id)] = np.column_stack((x[a:b], y[a:b]))
                line += 1
    return out


def _describe(p: _Path) -> str:
    return f"lane {p.from_lane} -> road {p.road.id} lane {p.lane} (connection {p.connection.id})"


@rule("J101", "connection-lanes-cross", Category.JUNCTION, Severity.ERROR, basis=Basis.PLAUSIBILITY)
def connection_lanes_cross(ctx: Context):
    """Two connection lanes leaving one incoming road cross (or meet) inside the junction.

    The centre lines of the connecting-road lanes entered from one road's lanes must not intersect except where they
    start together (turns from the same lane part there). A left turn from the right lane crossing the straight-on
    path from the left lane, or two laneLinks in crossed order, make vehicles of one approach collide.

    Plausibility: the JunctionArt paper's rule for the connection lanes of one road, not the standard's; a warning
    under the default profile, an error under ``--profile generator`` (what junctionart guarantees) or ``strict``.

    Passes (lane -1 goes straight on, lane -2 turns right: the paths part and stay apart)::

        <connection incomingRoad="1" connectingRoad="10" contactPoint="start"><laneLink from="-1" to="-1"/>
        <connection incomingRoad="1" connectingRoad="11" contactPoint="start"><laneLink from="-2" to="-1"/>

    Fails (lane -2 turns left across the straight-on path of lane -1)::

        <connection incomingRoad="1" connectingRoad="10" contactPoint="start"><laneLink from="-1" to="-1"/>
        <connection incomingRoad="1" connectingRoad="12" contactPoint="start"><laneLink from="-2" to="-1"/>
    """
    tol = ctx.tolerances.junction_start
    for junction, incoming, end, group, known in _ahead(ctx):
        paths = _paths(ctx, incoming, end, group, known)
        for i, p in enumerate(paths):
            for q in paths[i + 1 :]:
                point = crossing(p.xy, q.xy, p.from_lane == q.from_lane, tol)
                if point is None:
                    continue
                yield connection_lanes_cross.finding(
                    f"junction {junction.id}: from road {incoming.id}, {_describe(p)} and {_describe(q)} meet at "
                    f"({point[0]:.3f}, {point[1]:.3f}): paths leaving one road must not cross; reorder the laneLinks "
                    f"or reshape the connecting roads",
                    road=incoming.id,
                    lane=p.from_lane,
                    s=end_s(incoming, end),
                    x=float(point[0]),
                    y=float(point[1]),
                    line=q.line or junction.line or None,
                )


def _order_pairs(ctx: Context, incoming: Road, end: ContactPoint, connected: _Connected):
    """(from lane, to lane, lateral position of each at the contact, line) for a connection's laneLinks."""
    c = connected.connection
    mine = road_end(ctx, incoming, end)
    theirs = road_end(ctx, connected.road, connected.contact)
    axis = mine.border(0, "outer")
    if axis is None:
        return []
    normal = np.array([-np.sin(axis.outward), np.cos(axis.outward)])
    out = []
    for link in c.lane_links:
        a0, a1 = (mine.border(link.from_lane, w) for w in ("inner", "outer"))
        b0, b1 = (theirs.border(link.to_lane, w) for w in ("inner", "outer"))
        if a0 is None or a1 is None or b0 is None or b1 is None:
            continue
        along_a = float(normal @ np.array([(a0.x + a1.x) / 2, (a0.y + a1.y) / 2]))
        along_b = float(normal @ np.array([(b0.x + b1.x) / 2, (b0.y + b1.y) / 2]))
        out.append((link.from_lane, link.to_lane, along_a, along_b, link.line or c.line))
    return out


@rule("J102", "junction-lane-links-crossed", Category.JUNCTION, Severity.ERROR, basis=Basis.PLAUSIBILITY)
def junction_lane_links_crossed(ctx: Context):
    """Two laneLinks of one connection swap the lanes' order: the left incoming lane enters the right lane.

    At the contact point, the incoming lanes' centres and the connecting lanes' centres are ordered across the road;
    the laneLinks of a connection must keep that order.

    Plausibility: the JunctionArt paper's rule (connection lanes of one road do not cross), not the standard's; a
    warning under the default profile, an error under ``--profile generator`` or ``strict``.

    Passes::

        <connection incomingRoad="1" connectingRoad="10" contactPoint="start">
          <laneLink from="-1" to="-1"/><laneLink from="-2" to="-2"/></connection>

    Fails::

        <connection incomingRoad="1" connectingRoad="10" contactPoint="start">
          <laneLink from="-1" to="-2"/><laneLink from="-2" to="-1"/></connection>
    """
    tol = ctx.tolerances.position
    for junction, incoming, end, group in _groups(ctx):
        for connected in group:
            c = connected.connection
            pairs = _order_pairs(ctx, incoming, end, connected)
            for i, (fa, ta, xa, ya, _) in enumerate(pairs):
                for fb, tb, xb, yb, line in pairs[i + 1 :]:
                    if fa == fb or ta == tb or (xa - xb) * (ya - yb) >= 0 or min(abs(xa - xb), abs(ya - yb)) <= tol:
                        continue
                    point = road_end(ctx, incoming, end).border(fb, "outer")
                    yield junction_lane_links_crossed.finding(
                        f"junction {junction.id}, connection {c.id}: lanes {fa} and {fb} of road {incoming.id} enter "
                        f"lanes {ta} and {tb} of road {c.connecting_road} in swapped order (the lane on one side "
                        f"continues on the other side); link each lane to the connecting lane beside it",
                        road=incoming.id,
                        lane=fb,
                        s=end_s(incoming, end),
                        x=point.x if point else None,
                        y=point.y if point else None,
                        line=line or c.line or None,
                    )
