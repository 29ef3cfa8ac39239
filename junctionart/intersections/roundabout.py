"""Roundabouts (issue 28): a one-way ring of one or two lanes round a central island, a junction per arm.

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
entry radius ``rho`` is tried from large to small for each gap between neighbouring arms. Two arms too close for a
ring road between their junctions at any ``rho`` share one junction (as two arms close together do on real
roundabouts: the first's entry and the second's exit cross in it); the ring grows only when that does not fit either
(:mod:`.roundabout_fit`). Entries have as many lanes as the ring (at most the arm's), the kerb lane joining the outer
ring lane; exits leave from the outer ring lane into one lane (more open up behind the junction). A two-way arm ends
in a splitter island: a median lane widening to :func:`splitter_width` over the arm's last metres.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ..opendrive import Arc, Geometry
from ..params import Params, TrafficRule
from .roundabout_choice import RoundaboutSpec

#: Growth of the ring's radius per step when its arms do not fit (up to :attr:`RoundaboutSpec.largest`).
GROWTH = 1.15
#: Entry and exit turn radii tried: fractions of the ring's outer radius, then fixed radii (m) for a large ring whose
#: arms are close together (never under what the lanes allow).
TURN_FRACTIONS = (1.0, 0.75, 0.55, 0.4)
TURN_RADII = (16.0, 12.0)
#: Length (m) of the splitter island's full-width part at the end of a two-way arm.
SPLITTER_LENGTH = 10.0
#: Room (m) an arm road keeps clear of its splitter island: what the junction at its other end puts on it (a stop line
#: up to 6 m back behind a crosswalk, a traffic light) then lies in a lane section of its own, where simulators that
#: split roads at lane sections (SUMO) look for it.
SPLITTER_CLEAR = 10.0


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
    """One arm: where its road ends and its lanes there."""

    leg: int
    reach: float  #: distance of the arm road's end from the centre
    n_in: int  #: entry lanes at the junction
    n_out: int  #: exit lanes at the junction
    splitter: float  #: width of the splitter island at the arm's end (0: none)


@dataclass(frozen=True)
class RingJunction:
    """A junction of the ring: its arm (or two arms close together, in driving order) and its connection lanes."""

    arms: tuple[Arm, ...]
    enter: float  #: ring angle (rad) where the junction ends downstream (the next ring road starts)
    leave: float  #: ring angle where the junction starts upstream (the previous ring road ends)
    links: tuple[RingLink, ...]
    position: tuple[float, float]  #: middle of the ring at the junction


@dataclass(frozen=True)
class Design:
    """A roundabout that fits its arms: ring, its junctions (in driving order) and ring roads."""

    centre: tuple[float, float]
    radius: float  #: outer radius of the circulating carriageway (m)
    lanes: int
    island: float  #: radius of the island's edge: the ring roads' reference line
    sense: int  #: +1 counter-clockwise, -1 clockwise
    junctions: tuple[RingJunction, ...]
    ring: tuple[Arc, ...]  #: ring road k runs from junctions[k] to junctions[k + 1]

    @property
    def arms(self) -> tuple[Arm, ...]:
        """Every arm, in driving order."""
        return tuple(arm for j in self.junctions for arm in j.arms)

    def lane_borders(self) -> list[Geometry]:
        """The inner border of every lane of the ring roads and of every connection lane (for overlap tests)."""
        out: list[Geometry] = [link.geometry for j in self.junctions for link in j.links]
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


def design(centre: tuple[float, float], legs: list[ArmLeg], spec: RoundaboutSpec, params: Params) -> Design | None:
    """The roundabout of ``spec`` round ``centre`` with ``legs`` as its arms, grown where its arms need room; None
    when even the largest ring tried does not fit them. Each gap between neighbouring arms takes the largest turn
    radius, up to a cap, that leaves a ring road between their junctions (two arms too close for that share one
    junction); caps are tried from large to small (:mod:`.roundabout_fit`)."""
    from .roundabout_fit import attempt

    sense = 1 if params.traffic_rule is TrafficRule.RHT else -1
    radius = max(spec.radius, smallest_radius(spec.lanes, params))
    floor = params.min_turn_radius + 0.5 + params.lane_width + 1.0
    order = sorted(legs, key=lambda g: (sense * g.angle) % (2 * math.pi))
    while True:
        turns = {max(floor, min(t, radius)) for t in (*(f * radius for f in TURN_FRACTIONS), *TURN_RADII, floor)}
        candidates = sorted(turns, reverse=True)
        for cap in candidates:
            found = attempt(centre, order, radius, spec.lanes, [t for t in candidates if t <= cap], params, sense)
            if found is not None:
                return found
        if radius >= spec.largest:
            return None
        radius = min(round(radius * GROWTH, 3), spec.largest)
