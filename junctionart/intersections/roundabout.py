"""Roundabouts (issue 28): a one-way ring of one or two lanes round a central island, one junction per arm.

Layout: ring roads between arm junctions, the way CARLA's Town03 and most OpenDRIVE maps lay a roundabout out, and the
structure SUMO's ``netconvert`` recognises as a roundabout (a closed loop of one-way roads through nodes with three
or more attachments). One big junction holding every path round the ring would hide the ring from such readers (it
is one node to them), and its connecting roads would run the whole way round. Each arm's junction holds the ring's
lanes passing it (arcs of the ring's own circles), the entry from the arm into the ring and the exit from the ring
into the arm; between two arm junctions a ring road (an arc of the island's circle, its lanes outward of it) carries
the circulating lanes. Traffic circulates counter-clockwise in right-hand traffic, clockwise in left-hand traffic.

Geometry (the ring's centre ``C``, outer radius ``R``, ``n`` lanes of width ``w``; the island's radius ``R - n w`` is
the ring roads' reference line): an entry lane's inner border runs along the arm and turns onto the outer ring
lane's inner border circle along a right turn (left in left-hand traffic) of radius ``rho``, tangent to both: the
circle of the turn has its centre at distance ``r + rho`` from ``C`` and ``y + rho`` from the arm's axis (``y``: the
lane border's lateral offset), so it meets the ring at the angle ``atan2(y + rho, sqrt((r + rho)^2 - (y + rho)^2))``
from the arm, where the arm's junction ends. The exit mirrors it upstream. The connection lanes themselves are the
generator's Hermite cubics between those poses, checked against the radius bound like any other connection lane; the
entry radius ``rho`` is tried from large to small, and the ring is grown when its arms leave no ring road between
their junctions (:data:`MIN_RING`). Entries have as many lanes as the ring (at most the arm's), the kerb lane joining
the outer ring lane; exits leave from the outer ring lane into one lane (more open up behind the junction). A
two-way arm ends in a splitter island: a median lane widening to :func:`splitter_width` over the arm's last metres.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..curves import HermiteFit, connection_geometry, fit_connections, local_target
from ..lanegeom import border_point, inner_offset, lane_id
from ..opendrive import Arc, Geometry
from ..params import Params, TrafficRule
from ..scenario.roadside import roadside_width
from .crossing import LinkFit, crossing
from .fitting import SCALES
from .roundabout_choice import RoundaboutSpec

#: Shortest ring road (m, along the island's edge) between two arm junctions.
MIN_RING = 3.0
#: Straight lead (m) of an arm beyond the start of its entry and exit turns.
LEAD = 2.0
#: Angle (rad) an arm's body keeps inside its junction's sector of the ring.
SECTOR_MARGIN = math.radians(1.0)
#: Growth of the ring's radius per step when its arms do not fit (up to :attr:`RoundaboutSpec.largest`).
GROWTH = 1.15
#: Entry and exit turn radii tried: fractions of the ring's outer radius, then fixed radii (m) for a large ring whose
#: arms are close together (never under what the lanes allow).
TURN_FRACTIONS = (1.0, 0.75, 0.55, 0.4)
TURN_RADII = (16.0, 12.0)
#: Length (m) of the splitter island's full-width part at the end of a two-way arm.
SPLITTER_LENGTH = 10.0


def splitter_width(radius: float) -> float:
    """Width (m) of a splitter island on a roundabout of outer radius ``radius``: 1 m at a mini roundabout (often
    only painted) to 3 m at a large one."""
    return float(min(max(0.1 * radius, 1.0), 3.0))


def splitter_spans(width: float, median: float, params: Params) -> list[tuple[float, tuple[float, float]]]:
    """The lane sections of a splitter island ``width`` wide at the end of an arm whose median is ``median`` wide (0:
    none), from the arm's middle toward its end: (length, median width at both ends) of the widening, as long as a
    lane taper (:func:`junctionart.lanegeom.taper_length`), and of the full-width part, :data:`SPLITTER_LENGTH`;
    empty when the arm has no splitter or its median is as wide already."""
    if width <= median:
        return []
    widen = max(params.taper_length, math.sqrt(24.0 * (width - median) * params.min_turn_radius))
    return [(widen, (median, width)), (SPLITTER_LENGTH, (width, width))]


def smallest_radius(lanes: int, params: Params) -> float:
    """Smallest outer radius whose island edge and lanes keep the radius bound."""
    return lanes * params.lane_width + params.min_turn_radius + 0.5


@dataclass(frozen=True)
class ArmLeg:
    """A leg of the junction that becomes a roundabout, as the design sees it."""

    leg: int  #: index among the junction's legs
    angle: float  #: heading of the arm leaving the centre
    n_in: int  #: lanes towards the roundabout
    n_out: int
    median: bool
    at_start: bool  #: whether the arm's road starts at the roundabout


#: A road of a roundabout's junctions, by role: ("arm", leg index) or ("ring", ring road index).
RoadRole = tuple[str, int]


@dataclass(frozen=True)
class RingLink:
    """A connection lane of an arm junction, its roads named by role."""

    kind: str  #: "entry", "exit" or "through"
    road_in: RoadRole
    lane_in: int  #: lane id on the incoming road
    road_out: RoadRole
    lane_out: int
    geometry: Geometry  #: the lane's inner border
    min_radius: float


@dataclass(frozen=True)
class Arm:
    """One arm's junction: where its road ends, its lanes there and its connection lanes."""

    leg: int
    reach: float  #: distance of the arm road's end from the centre
    n_in: int  #: entry lanes at the junction
    n_out: int  #: exit lanes at the junction
    splitter: float  #: width of the splitter island at the arm's end (0: none)
    enter: float  #: ring angle (rad) where the junction ends downstream (the next ring road starts)
    leave: float  #: ring angle where the junction starts upstream (the previous ring road ends)
    links: tuple[RingLink, ...]
    position: tuple[float, float]  #: middle of the ring at the arm


@dataclass(frozen=True)
class Design:
    """A roundabout that fits its arms: ring, arm junctions (in driving order) and ring roads."""

    centre: tuple[float, float]
    radius: float  #: outer radius of the circulating carriageway (m)
    lanes: int
    island: float  #: radius of the island's edge: the ring roads' reference line
    sense: int  #: +1 counter-clockwise, -1 clockwise
    arms: tuple[Arm, ...]
    ring: tuple[Arc, ...]  #: ring road k runs from arms[k] to arms[k + 1]

    def lane_borders(self) -> list[Geometry]:
        """The inner border of every lane of the ring roads and of every connection lane (for overlap tests)."""
        out: list[Geometry] = [link.geometry for arm in self.arms for link in arm.links]
        w = (self.radius - self.island) / self.lanes
        for g in self.ring:
            a0 = math.atan2(g.y - self.centre[1], g.x - self.centre[0])
            for j in range(self.lanes):
                out.append(ring_arc(self.centre, self.island + j * w, a0, g.length / self.island, self.sense))
        return out


def ring_arc(centre: tuple[float, float], r: float, a0: float, span: float, sense: int) -> Arc:
    """The arc of radius ``r`` round ``centre`` from angle ``a0`` over ``span`` radians in the driving sense."""
    x, y = centre[0] + r * math.cos(a0), centre[1] + r * math.sin(a0)
    return Arc(0.0, x, y, a0 + sense * math.pi / 2, r * span, sense / r)


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


def _turn(offset: float, r: float, rho: float) -> tuple[float, float] | None:
    """(distance along the arm from the centre, angle from the arm) where a turn of radius ``rho`` from a line
    ``offset`` beside the arm's axis meets the circle ``r`` tangentially; None when the line lies outside it."""
    if offset + rho >= r + rho - 1e-9:
        return None
    along = math.sqrt((r + rho) ** 2 - (offset + rho) ** 2)
    return along, math.atan2(offset + rho, along)


def design(centre: tuple[float, float], legs: list[ArmLeg], spec: RoundaboutSpec, params: Params) -> Design | None:
    """The roundabout of ``spec`` round ``centre`` with ``legs`` as its arms, grown where its arms need room; None
    when even the largest ring tried does not fit them. Each gap between neighbouring arms takes the largest turn
    radius, up to a cap, that leaves a ring road between their junctions; caps are tried from large to small."""
    sense = 1 if params.traffic_rule is TrafficRule.RHT else -1
    radius = max(spec.radius, smallest_radius(spec.lanes, params))
    floor = params.min_turn_radius + 0.5 + params.lane_width + 1.0
    order = sorted(legs, key=lambda g: (sense * g.angle) % (2 * math.pi))
    while True:
        turns = {max(floor, min(t, radius)) for t in (*(f * radius for f in TURN_FRACTIONS), *TURN_RADII, floor)}
        candidates = sorted(turns, reverse=True)
        for cap in candidates:
            found = _attempt(centre, order, radius, spec.lanes, [t for t in candidates if t <= cap], params, sense)
            if found is not None:
                return found
        if radius >= spec.largest:
            return None
        radius = min(round(radius * GROWTH, 3), spec.largest)


Turn = tuple[float, float]  #: (distance along the arm from the centre, angle from the arm) where a turn meets the ring


def _gap_turns(
    shapes: list[_ArmShape], gaps: list[float], outer: float, island: float, radii: list[float]
) -> list[tuple[Turn, Turn]] | None:
    """Per arm, its entry and exit turns: each gap's two turns (the entry of the arm before it, the exit of the arm
    after it) with the largest of ``radii`` that leaves :data:`MIN_RING` of ring road between them; None when no
    radius does for some gap."""
    n = len(shapes)
    entry: list[Turn | None] = [None] * n
    leave: list[Turn | None] = [None] * n
    for k in range(n):
        a, b = shapes[k], shapes[(k + 1) % n]
        for rho in radii:
            e = _turn(a.entries[-1][1] if a.entries else 0.0, outer, rho)
            x = _turn(b.exit[1] if b.exit else 0.0, outer, rho)
            if e is not None and x is not None and (gaps[k] - e[1] - x[1]) * island >= MIN_RING:
                entry[k], leave[(k + 1) % n] = e, x
                break
        else:
            return None
    return [(e, x) for e, x in zip(entry, leave) if e is not None and x is not None]


def _attempt(
    centre: tuple[float, float],
    order: list[ArmLeg],
    radius: float,
    lanes: int,
    radii: list[float],
    params: Params,
    sense: int,
) -> Design | None:
    w = params.lane_width
    island = radius - lanes * w
    outer = island + (lanes - 1) * w  # inner border of the outer ring lane
    shapes = [_arm_shape(g, radius, lanes, params, sense) for g in order]
    n = len(order)
    gaps = [((sense * (order[(k + 1) % n].angle - order[k].angle)) % (2 * math.pi)) for k in range(n)]
    turns = _gap_turns(shapes, gaps, outer, island, radii)
    if turns is None or len(turns) != n:
        return None
    spans = [gaps[k] - turns[k][0][1] - turns[(k + 1) % n][1][1] for k in range(n)]
    ends = [_reach(s, t, radius, params) for s, t in zip(shapes, turns)]
    reach = [r for r in ends if r is not None]
    if len(reach) != n:
        return None
    for k in range(n):  # neighbouring arm roads apart (the W / sin(d) rule of ordinary junctions)
        a, b, d = shapes[k], shapes[(k + 1) % n], gaps[k]
        if d < math.pi / 2:
            need = (a.reach_entry + b.reach_exit + 1.0) / max(math.sin(d), 1e-3)
            reach[k], reach[(k + 1) % n] = max(reach[k], need), max(reach[(k + 1) % n], need)
    arms = _arms(centre, shapes, turns, reach, island, lanes, params, sense)
    if arms is None:
        return None
    ring = tuple(ring_arc(centre, island, order[k].angle + sense * turns[k][0][1], spans[k], sense) for k in range(n))
    return Design(centre, radius, lanes, island, sense, tuple(arms), ring)


def _reach(
    s: _ArmShape, turn: tuple[tuple[float, float], tuple[float, float]], radius: float, params: Params
) -> float | None:
    """The arm road's end: past both turns, outside the ring's roadside, and far enough that the arm's body lies in
    its own junction's sector of the ring."""
    (along_in, beta_in), (along_out, beta_out) = turn
    reach = max(along_in, along_out, radius + roadside_width(params) + 1.0) + LEAD
    for extent, beta in ((s.reach_entry, beta_in), (s.reach_exit, beta_out)):
        if beta <= SECTOR_MARGIN:
            return None
        reach = max(reach, extent / math.tan(beta - SECTOR_MARGIN))
    return reach


def _arms(centre, shapes, turns, reach, island, lanes, params, sense) -> list[Arm] | None:
    """Every arm junction's connection lanes, or None when one misses the radius bound or two lanes from one road
    cross."""
    w, rule = params.lane_width, params.traffic_rule
    n = len(shapes)
    ring_lane = [lane_id(True, j, False, rule) for j in range(1, lanes + 1)]
    radii = [island + j * w for j in range(lanes)]
    targets, rows = [], []  # Hermite targets and (arm, kind, lane in, lane out, start pose)
    for k, (s, t) in enumerate(zip(shapes, turns)):
        g = s.g
        phi, hdg = g.angle, g.angle if g.at_start else g.angle + math.pi
        ax, ay = centre[0] + reach[k] * math.cos(phi), centre[1] + reach[k] * math.sin(phi)
        enter, leave = phi + sense * t[0][1], phi - sense * t[1][1]
        for m, (lid, _) in enumerate(s.entries):
            j = lanes - (len(s.entries) - 1 - m)  # the kerb lane joins the outer ring lane
            x0, y0 = border_point(ax, ay, hdg, inner_offset(lid, s.splitter > 0, w, s.splitter))
            x1, y1 = centre[0] + radii[j - 1] * math.cos(enter), centre[1] + radii[j - 1] * math.sin(enter)
            h0, h1 = phi + math.pi, enter + sense * math.pi / 2
            targets.append(local_target(x0, y0, h0, x1, y1, h1))
            rows.append((k, "entry", lid, ring_lane[j - 1], (x0, y0, h0)))
        if s.exit is not None:
            lid = s.exit[0]
            x1, y1 = border_point(ax, ay, hdg, inner_offset(lid, s.splitter > 0, w, s.splitter))
            x0, y0 = centre[0] + radii[-1] * math.cos(leave), centre[1] + radii[-1] * math.sin(leave)
            h0 = leave + sense * math.pi / 2
            targets.append(local_target(x0, y0, h0, x1, y1, phi))
            rows.append((k, "exit", ring_lane[-1], lid, (x0, y0, h0)))
    side = -1.0 if rule is TrafficRule.RHT else 1.0
    offsets = (side * w / 2, side * w)
    fits = fit_connections(np.array(targets).reshape(-1, 3), offsets, params.min_turn_radius + 0.5, SCALES)
    if any(f is None for f in fits) or _entries_cross(rows, fits):
        return None
    arms = []
    for k, (s, t) in enumerate(zip(shapes, turns)):
        phi = s.g.angle
        enter, leave = phi + sense * t[0][1], phi - sense * t[1][1]
        before, after = ("ring", (k - 1) % n), ("ring", k)
        links: list[RingLink] = []
        for j in range(lanes):
            arc = ring_arc(centre, radii[j], leave, t[0][1] + t[1][1], sense)
            links.append(RingLink("through", before, ring_lane[j], after, ring_lane[j], arc, radii[j]))
        for (arm, kind, lid_in, lid_out, (x0, y0, h0)), fit in zip(rows, fits):
            if arm != k or fit is None:
                continue
            geometry = connection_geometry(x0, y0, h0, fit)
            road_in, road_out = (("arm", s.g.leg), after) if kind == "entry" else (before, ("arm", s.g.leg))
            links.append(RingLink(kind, road_in, lid_in, road_out, lid_out, geometry, fit.min_radius))
        middle = island + lanes * w / 2
        position = (centre[0] + middle * math.cos(phi), centre[1] + middle * math.sin(phi))
        arms.append(Arm(s.g.leg, reach[k], s.n_in, s.n_out, s.splitter, enter, leave, tuple(links), position))
    return arms


def _entries_cross(rows: list, fits: list[HermiteFit | None]) -> bool:
    """Whether two entry lanes of one arm cross (xodrcheck's J101: lanes from one road must not)."""
    linked = [
        LinkFit(arm, lid_in, 0, lid_out, lid_in, lid_out, (x0, y0), h0, fit)
        for (arm, kind, lid_in, lid_out, (x0, y0, h0)), fit in zip(rows, fits)
        if kind == "entry"
    ]
    return bool(crossing(linked, set())) if len({r.leg_in for r in linked}) < len(linked) else False
