"""Values stage 3 hands to stage 4: roads with their end lane counts, junctions with their connection lanes."""

from __future__ import annotations

from dataclasses import dataclass

from ..lanes import LaneConfig
from ..opendrive import Geometry


@dataclass(frozen=True)
class RoadPlan:
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


@dataclass(frozen=True)
class ConnectionPlan:
    in_road: int
    in_contact: str  #: "start" / "end" of the incoming road
    in_lane: int  #: lane id on the incoming road
    out_road: int
    out_contact: str
    out_lane: int
    geometry: Geometry  #: a paramPoly3 (reference line on the lane's inner border), or a U-turn's arc
    min_radius: float  #: smallest radius of the reference line, lane centre and outer border
    lane_offset: float = 0.0  #: laneOffset of the connecting road (a U-turn's reference line is its lane centre)


@dataclass(frozen=True)
class JunctionPlan:
    node: int
    position: tuple[float, float]
    legs: int
    connections: tuple[ConnectionPlan, ...]


@dataclass(frozen=True)
class Layout:
    roads: tuple[RoadPlan, ...]
    junctions: tuple[JunctionPlan, ...]
    repairs: tuple[str, ...]  #: what was changed to make every intersection fit (no map is ever discarded)
