"""Fitting a roundabout's junctions round its ring (:mod:`.roundabout` says what is built and why).

For one outer radius and a list of entry/exit turn radii: each gap between neighbouring arms (in driving order) takes
the largest turn radius that leaves :data:`MIN_RING` of ring road between the entry of the arm before it and the exit of
the arm after it. Two arms whose gap leaves no ring road at any turn radius share one junction: the first arm's entry
then runs to where that junction ends (past the second arm's), the second arm's exit starts where it begins (before the
first arm's). A junction holds at most two arms and takes at most :data:`MAX_SPAN` of the ring, and the ring has at
least :data:`MIN_JUNCTIONS` junctions (what SUMO's ``netconvert`` needs to call the loop a roundabout). The connection
lanes are Hermite cubics checked against the radius bound, lanes from one road must not cross (xodrcheck's J101), and a
shared junction's long entry and exit never run further from the centre than their arm's end, so they pass inside the
other arm's road end.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..curves import HermiteFit, connection_geometry, fit_connections, local_target
from ..lanegeom import border_point, inner_offset, lane_id
from ..params import Params, TrafficRule
from ..scenario.roadside import roadside_width
from .crossing import LinkFit, crossing
from .fitting import SCALES
from .roundabout import Arm, ArmLeg, Design, RingJunction, RingLink, ring_arc, splitter_width

#: Shortest ring road (m, along the island's edge) between two junctions.
MIN_RING = 3.0
#: Fewest junctions round a ring.
MIN_JUNCTIONS = 3
#: Widest sector (rad) of the ring one junction may take: the ring turns by that much inside it, and SUMO's
#: ``netconvert`` takes a turn of 90 degrees or more between two edges for a corner, not a roundabout.
MAX_SPAN = math.radians(80.0)
#: Straight lead (m) of an arm beyond the start of its entry and exit turns.
LEAD = 2.0
#: Angle (rad) an arm's body keeps inside its junction's sector of the ring.
SECTOR_MARGIN = math.radians(1.0)
#: How far (m) a shared junction's long entry or exit may step away from (toward) the centre between two samples.
REACH_SLACK = 1e-6

#: (distance along the arm from the centre, angle from the arm) where a turn meets the ring.
Turn = tuple[float, float]


def _unit(a: float) -> tuple[float, float]:
    return math.cos(a), math.sin(a)


@dataclass(frozen=True)
class _ArmShape:
    """An arm's lane borders at its end, measured across the arm (positive toward its entry side)."""

    g: ArmLeg
    splitter: float
    n_in: int
    n_out: int
    entries: tuple[tuple[int, float], ...]  #: (lane id, lateral offset of the inner border), from the centre out
    exit: tuple[int, float] | None  #: (lane id, lateral offset toward the exit side) of the exit lane
    reach_entry: float  #: the arm's extent across on its entry side (lanes and roadside)
    reach_exit: float


def _arm_shape(g: ArmLeg, radius: float, lanes: int, params: Params, sense: int) -> _ArmShape:
    w, rule = params.lane_width, params.traffic_rule
    split = (
        round(max(splitter_width(radius), params.median_width if g.median else 0.0), 3) if g.n_in and g.n_out else 0.0
    )
    hdg = g.angle if g.at_start else g.angle + math.pi
    ex, ey = _unit(g.angle + sense * math.pi / 2)

    def lateral(lid: int) -> float:
        px, py = border_point(0.0, 0.0, hdg, inner_offset(lid, split > 0, w, split))
        return px * ex + py * ey

    n_in = min(g.n_in, lanes)
    n_out = 1 if g.n_out else 0
    entries = tuple(
        (lid, lateral(lid)) for lid in (lane_id(not g.at_start, k, split > 0, rule) for k in range(1, n_in + 1))
    )
    out = None
    if n_out:
        lid = lane_id(g.at_start, 1, split > 0, rule)
        out = (lid, -lateral(lid))
    rs = roadside_width(params)
    far_in = lateral(lane_id(not g.at_start, g.n_in, split > 0, rule)) + w if g.n_in else 0.0
    far_out = -lateral(lane_id(g.at_start, g.n_out, split > 0, rule)) + w if g.n_out else 0.0
    return _ArmShape(g, split, n_in, n_out, entries, out, max(far_in, 0.0) + rs, max(far_out, 0.0) + rs)


def _turn(offset: float, r: float, rho: float) -> Turn | None:
    """Where a turn of radius ``rho`` from a line ``offset`` beside the arm's axis meets the circle ``r``
    tangentially; None when the line lies outside it."""
    if offset + rho >= r + rho - 1e-9:
        return None
    along = math.sqrt((r + rho) ** 2 - (offset + rho) ** 2)
    return along, math.atan2(offset + rho, along)


def _entry_turn(s: _ArmShape, outer: float, rho: float) -> Turn | None:
    return _turn(s.entries[-1][1] if s.entries else 0.0, outer, rho)


def _exit_turn(s: _ArmShape, outer: float, rho: float) -> Turn | None:
    return _turn(s.exit[1] if s.exit else 0.0, outer, rho)


@dataclass(frozen=True)
class _Plan:
    """How the arms share the ring: per arm its entry and exit turns, and the arms of each junction (driving order,
    the first junction's first arm the first arm of ``order``)."""

    order: list[_ArmShape]
    entry: list[Turn]
    leave: list[Turn]
    groups: list[list[int]]
    gaps: list[float]


def _plan(shapes: list[_ArmShape], gaps: list[float], outer: float, island: float, radii: list[float]) -> _Plan | None:
    """Each gap's turns with the largest of ``radii`` that leaves a ring road; a gap none does joins its two arms in
    one junction. None when a junction would hold more than two arms or the ring fewer than :data:`MIN_JUNCTIONS`."""
    n = len(shapes)
    entry: list[Turn | None] = [None] * n
    leave: list[Turn | None] = [None] * n
    shared = [False] * n
    for k in range(n):
        a, b = shapes[k], shapes[(k + 1) % n]
        for rho in radii:
            e, x = _entry_turn(a, outer, rho), _exit_turn(b, outer, rho)
            if e is not None and x is not None and (gaps[k] - e[1] - x[1]) * island >= MIN_RING:
                entry[k], leave[(k + 1) % n] = e, x
                break
        else:
            shared[k] = True
    if n - sum(shared) < MIN_JUNCTIONS or any(shared[k] and shared[k - 1] for k in range(n)):
        return None
    for k in range(n):  # an arm's side facing a shared gap: its turn at the floor radius (its road's end only)
        if shared[k]:
            entry[k] = _entry_turn(shapes[k], outer, radii[-1])
            leave[(k + 1) % n] = _exit_turn(shapes[(k + 1) % n], outer, radii[-1])
    if any(t is None for t in (*entry, *leave)):
        return None
    first = next(k for k in range(n) if not shared[k - 1])  # a junction starts here
    rot = [(first + i) % n for i in range(n)]
    groups: list[list[int]] = []
    for i in range(n):
        if i and shared[rot[i - 1]]:
            groups[-1].append(i)
        else:
            groups.append([i])
    return _Plan(
        [shapes[k] for k in rot],
        [t for k in rot if (t := entry[k]) is not None],
        [t for k in rot if (t := leave[k]) is not None],
        groups,
        [gaps[k] for k in rot],
    )


def attempt(
    centre: tuple[float, float],
    order: list[ArmLeg],
    radius: float,
    lanes: int,
    radii: list[float],
    params: Params,
    sense: int,
) -> Design | None:
    """The roundabout of outer ``radius`` with entry/exit turn radii from ``radii`` (largest first), or None."""
    w = params.lane_width
    island = radius - lanes * w
    outer = island + (lanes - 1) * w  # inner border of the outer ring lane
    shapes = [_arm_shape(g, radius, lanes, params, sense) for g in order]
    n = len(order)
    gaps = [((sense * (order[(k + 1) % n].angle - order[k].angle)) % (2 * math.pi)) for k in range(n)]
    plan = _plan(shapes, gaps, outer, island, radii)
    if plan is None:
        return None
    reach = _reaches(plan, radius, params)
    if reach is None:
        return None
    junctions = _junctions(centre, plan, reach, island, lanes, params, sense)
    if junctions is None:
        return None
    m = len(junctions)
    ring = tuple(
        ring_arc(centre, island, a.enter, (sense * (b.leave - a.enter)) % (2 * math.pi), sense)
        for a, b in zip(junctions, junctions[1:] + junctions[:1])
    )
    if min(g.length for g in ring) < MIN_RING - 1e-6 or m < MIN_JUNCTIONS:
        return None
    return Design(centre, radius, lanes, island, sense, tuple(junctions), ring)


def _reaches(plan: _Plan, radius: float, params: Params) -> list[float] | None:
    """Each arm road's end: past both its turns, outside the ring's roadside, far enough that its body lies in its
    junction's sector of the ring and apart from its neighbours' (the W / sin(d) rule of ordinary junctions); the two
    arms of a shared junction end equally far out."""
    out = []
    for s, e, x in zip(plan.order, plan.entry, plan.leave):
        reach = max(e[0], x[0], radius + roadside_width(params) + 1.0) + LEAD
        for extent, beta in ((s.reach_entry, e[1]), (s.reach_exit, x[1])):
            if beta <= SECTOR_MARGIN:
                return None
            reach = max(reach, extent / math.tan(beta - SECTOR_MARGIN))
        out.append(reach)
    n = len(out)
    for k in range(n):
        a, b, d = plan.order[k], plan.order[(k + 1) % n], plan.gaps[k]
        if d < math.pi / 2:
            need = (a.reach_entry + b.reach_exit + 1.0) / max(math.sin(d), 1e-3)
            out[k], out[(k + 1) % n] = max(out[k], need), max(out[(k + 1) % n], need)
    for group in plan.groups:
        far = max(out[i] for i in group)
        for i in group:
            out[i] = far
    return out


@dataclass(frozen=True)
class _Ring:
    """What every junction of one ring shares: centre, island, lanes (ids and inner-border radii), driving sense."""

    centre: tuple[float, float]
    island: float
    width: float
    sense: int
    ids: tuple[int, ...]  #: lane id of ring lane 1 (next to the island) .. n
    radii: tuple[float, ...]  #: inner border of ring lane 1 .. n

    def point(self, j: int, angle: float) -> tuple[float, float]:
        """Where ring lane ``j`` (from 1) has its inner border at ``angle``."""
        return self.centre[0] + self.radii[j - 1] * math.cos(angle), self.centre[1] + self.radii[j - 1] * math.sin(
            angle
        )


def _bounds(plan: _Plan, sense: int) -> list[tuple[float, float]] | None:
    """(enter, leave) angles of each junction; None when one would take more than :data:`MAX_SPAN` of the ring."""
    out = []
    for group in plan.groups:
        first, last = plan.order[group[0]], plan.order[group[-1]]
        enter = last.g.angle + sense * plan.entry[group[-1]][1]
        leave = first.g.angle - sense * plan.leave[group[0]][1]
        if (sense * (enter - leave)) % (2 * math.pi) > MAX_SPAN:
            return None
        out.append((enter, leave))
    return out


def _rows(ring: _Ring, plan: _Plan, reach: list[float], bounds: list[tuple[float, float]]) -> tuple[list, list]:
    """Every entry and exit to fit: its Hermite target, and (junction, arm, kind, lane in, lane out, start pose, long:
    whether it crosses a shared junction)."""
    w, lanes = ring.width, len(ring.ids)
    targets, rows = [], []
    for jn, group in enumerate(plan.groups):
        enter, leave = bounds[jn]
        for i in group:
            s = plan.order[i]
            phi, hdg = s.g.angle, s.g.angle if s.g.at_start else s.g.angle + math.pi
            ax, ay = ring.centre[0] + reach[i] * math.cos(phi), ring.centre[1] + reach[i] * math.sin(phi)
            for m, (lid, _) in enumerate(s.entries):
                j = lanes - (len(s.entries) - 1 - m)  # the kerb lane joins the outer ring lane
                x0, y0 = border_point(ax, ay, hdg, inner_offset(lid, s.splitter > 0, w, s.splitter))
                x1, y1 = ring.point(j, enter)
                targets.append(local_target(x0, y0, phi + math.pi, x1, y1, enter + ring.sense * math.pi / 2))
                rows.append((jn, i, "entry", lid, ring.ids[j - 1], (x0, y0, phi + math.pi), i != group[-1]))
            if s.exit is not None:
                lid = s.exit[0]
                x1, y1 = border_point(ax, ay, hdg, inner_offset(lid, s.splitter > 0, w, s.splitter))
                x0, y0 = ring.point(lanes, leave)
                h0 = leave + ring.sense * math.pi / 2
                targets.append(local_target(x0, y0, h0, x1, y1, phi))
                rows.append((jn, i, "exit", ring.ids[-1], lid, (x0, y0, h0), i != group[0]))
    return targets, rows


def _junctions(
    centre: tuple[float, float], plan: _Plan, reach: list[float], island: float, lanes: int, params: Params, sense: int
) -> list[RingJunction] | None:
    """Every junction with its connection lanes, or None when one takes too much of the ring, misses the radius
    bound, has two lanes from one road crossing, or a long entry or exit of a shared junction strays outward."""
    w, rule = params.lane_width, params.traffic_rule
    ring = _Ring(
        centre,
        island,
        w,
        sense,
        tuple(lane_id(True, j, False, rule) for j in range(1, lanes + 1)),
        tuple(island + j * w for j in range(lanes)),
    )
    bounds = _bounds(plan, sense)
    if bounds is None:
        return None
    targets, rows = _rows(ring, plan, reach, bounds)
    side = -1.0 if rule is TrafficRule.RHT else 1.0
    fits = fit_connections(
        np.array(targets).reshape(-1, 3), (side * w / 2, side * w), params.min_turn_radius + 0.5, SCALES
    )
    if any(f is None for f in fits) or _cross(rows, fits) or _strays(centre, rows, fits):
        return None
    return [_junction(ring, plan, reach, jn, bounds[jn], rows, fits) for jn in range(len(plan.groups))]


def _junction(
    ring: _Ring,
    plan: _Plan,
    reach: list[float],
    jn: int,
    bound: tuple[float, float],
    rows: list,
    fits: list[HermiteFit | None],
) -> RingJunction:
    """Junction ``jn``: the ring's lanes through it (arcs), its arms' entries and exits, its arms."""
    enter, leave = bound
    n = len(plan.groups)
    before, after = ("ring", (jn - 1) % n), ("ring", jn)
    span = (ring.sense * (enter - leave)) % (2 * math.pi)
    links = [
        RingLink("through", before, lid, after, lid, ring_arc(ring.centre, r, leave, span, ring.sense), r)
        for lid, r in zip(ring.ids, ring.radii)
    ]
    for (junction, i, kind, lid_in, lid_out, (x0, y0, h0), _), fit in zip(rows, fits):
        if junction != jn or fit is None:
            continue
        arm = ("arm", plan.order[i].g.leg)
        road_in, road_out = (arm, after) if kind == "entry" else (before, arm)
        geometry = connection_geometry(x0, y0, h0, fit)
        links.append(RingLink(kind, road_in, lid_in, road_out, lid_out, geometry, fit.min_radius))
    shapes = [(plan.order[i], reach[i]) for i in plan.groups[jn]]
    arms = tuple(Arm(s.g.leg, r, s.n_in, s.n_out, s.splitter) for s, r in shapes)
    middle = ring.island + len(ring.ids) * ring.width / 2
    mid = leave + ring.sense * span / 2
    position = (ring.centre[0] + middle * math.cos(mid), ring.centre[1] + middle * math.sin(mid))
    return RingJunction(arms, enter, leave, tuple(links), position)


def _cross(rows: list, fits: list[HermiteFit | None]) -> bool:
    """Whether two lanes from one road cross (xodrcheck's J101): entries of one arm, or the exits of one junction
    (both leave the outer ring lane of the ring road coming in)."""
    linked = []
    for (junction, arm, kind, lid_in, lid_out, (x0, y0, h0), _), fit in zip(rows, fits):
        road = arm if kind == "entry" else -1 - junction  # the incoming road: the arm, or the junction's ring road
        linked.append(LinkFit(road, lid_in, 0, lid_out, lid_in, lid_out, (x0, y0), h0, fit))
    if len({r.leg_in for r in linked}) == len(linked):
        return False
    return bool(crossing(linked, set()))


def _strays(centre: tuple[float, float], rows: list, fits: list[HermiteFit | None]) -> bool:
    """Whether a shared junction's long entry (exit) ever turns away from (toward) the centre: it must pass inside
    the other arm's road end."""
    p = np.linspace(0.0, 1.0, 65)
    for (_, _, kind, _, _, (x0, y0, h0), long), fit in zip(rows, fits):
        if not long or fit is None:
            continue
        c = fit.coef
        u = c[0] + p * (c[1] + p * (c[2] + p * c[3]))
        v = c[4] + p * (c[5] + p * (c[6] + p * c[7]))
        r = np.hypot(
            x0 + math.cos(h0) * u - math.sin(h0) * v - centre[0], y0 + math.sin(h0) * u + math.cos(h0) * v - centre[1]
        )
        steps = np.diff(r) if kind == "exit" else -np.diff(r)
        if (steps < -REACH_SLACK).any():
            return True
    return False
