"""Values stage 3 hands to stage 4: roads with their end lane counts, junctions with their connection lanes."""

from __future__ import annotations

from dataclasses import dataclass

from ..lanes import LaneConfig
from ..opendrive import Geometry


@dataclass(frozen=True)
class RoadPlan:
    """A road of the layout between two nodes: geometry, length, lanes and the lane counts at its ends."""

    index: int
    start_node: int
    end_node: int
    start_junction: int | None  #: index into Layout.junctions, None for a dead end
    end_junction: int | None
    geometry: tuple[Geometry, ...]
    length: float
    lanes: LaneConfig  #: counts along the middle of the road
    fwd_start: int
    bwd_start: int
    fwd_end: int
    bwd_end: int
    splitter_start: float = 0.0  #: width of a roundabout's splitter island at the road's start (0: none)
    splitter_end: float = 0.0
    ring: bool = False  #: a roundabout's ring road (one-way round the island, lanes outward of its reference line)


@dataclass(frozen=True)
class ConnectionPlan:
    """A connecting road of a junction: from an incoming lane to an outgoing lane, its geometry and radius."""

    in_road: int
    in_contact: str  #: "start" / "end" of the incoming road
    in_lane: int  #: lane id on the incoming road
    out_road: int
    out_contact: str
    out_lane: int
    geometry: Geometry  #: the lane's inner border: a paramPoly3, or a U-turn's half circle
    min_radius: float  #: smallest radius of the reference line, lane centre and outer border


def contact_point(at_start: bool) -> str:
    """How OpenDRIVE names the end of a road: ``contactPoint`` "start" or "end"."""
    return "start" if at_start else "end"


@dataclass(frozen=True)
class JunctionPlan:
    """A junction of the layout: its node, position, legs and connections."""

    node: int
    position: tuple[float, float]
    legs: int
    connections: tuple[ConnectionPlan, ...]


@dataclass(frozen=True)
class RoundaboutPlan:
    """A roundabout of the layout: its ring, its arm junctions and ring roads in driving order, and its arms."""

    node: int
    centre: tuple[float, float]
    radius: float  #: outer radius of the circulating carriageway (m)
    lanes: int  #: circulating lanes
    junctions: tuple[int, ...]  #: indexes into Layout.junctions, in driving order (one per arm, or two arms' shared)
    ring_roads: tuple[int, ...]  #: indexes into Layout.roads: ring road k runs from junctions[k] to junctions[k + 1]
    #: each arm in driving order: (road index, contact point, index into Layout.junctions of its junction)
    arms: tuple[tuple[int, str, int], ...]


@dataclass(frozen=True)
class Layout:
    """The intersection stage's result: roads, junctions and the repairs made."""

    roads: tuple[RoadPlan, ...]
    junctions: tuple[JunctionPlan, ...]
    repairs: tuple[str, ...]  #: what was changed to make every intersection fit (no map is ever discarded)
    overpasses: tuple[tuple[int, int], ...] = ()  #: (upper, lower) indexes into ``roads`` of each overpass
    roundabouts: tuple[RoundaboutPlan, ...] = ()
