"""Expressive-range metrics of the junctions of any OpenDRIVE map (after the JunctionArt paper, with its defects fixed).

Everything is computed from the document the independent reader builds, so a generated map and a third-party map
(CARLA, esmini, RoadRunner...) are measured the same way.

Legs and their four points
--------------------------
A junction's *legs* are the ends of roads outside the junction that touch it: a road end whose ``predecessor`` /
``successor`` names the junction, plus any road end a connecting road (default junction) or a connection's
``linkedRoad`` (direct junction) names with its contact point. A leg is a (road, end) pair, so a road whose both ends
touch the same junction gives two legs.

For each leg the *incident point* ``p1`` is the middle of the drivable carriageway where the road touches the junction:
halfway (in plan view) between the outermost borders of its drivable lanes at that end (the lane-0 line if the road has
no drivable lane there). The *look-back point* ``p0`` is the same construction :data:`LOOKBACK` metres back along the
road (or the road's far end if it is shorter). The leg's *approach direction* ``u`` is ``p1 - p0`` normalised (the
reference-line tangent at the end if the two coincide). When leg ``i`` is compared with leg ``j``, the paper's ``p2``
and ``p3`` are leg ``j``'s ``p1`` and ``p0``: a vehicle leaving by leg ``j`` drives from ``p2`` towards ``p3``, in
direction ``w_j = -u_j``. The original's roads are straight between junctions, where this is exactly its definition
(``p0`` the far end).

Per-leg metrics (leg ``i`` against every other leg ``j`` whose incident point differs from ``p1``; angles in degrees)
--------------------------------------------------------------------------------------------------------------------
* ``fov = 2 max_j angle(u_i, p2 - p1)``: twice the widest sight angle off the approach direction, in [0, 360].
* ``corner_deviation = max_j angle(p2 - p1, w_j)``: how far the exit turns away from the sight line, in [0, 180].
* ``max_curvature = max_j |wrap(heading(w_j) - heading(u_i))| / |p2 - p1|`` in degrees per metre, the heading change
  wrapped to [-180, 180] degrees (the original did not wrap it).
* ``complexity = 0.5 nc + 0.25 nf + 0.25 nd`` with ``nc = max_curvature / 36`` (36 deg/m = 2 pi / 10 rad/m),
  ``nf = fov / 198`` (1.1 pi), ``nd = corner_deviation / 90`` (pi / 2), each clipped to [0, 1]. The paper says "min-max
  normalised" but its code divides by these fixed scales; fixed scales keep values comparable across runs and maps.

A leg with no other leg at a distinct point (a one-leg junction, or a direct junction whose roads meet at one point)
has no leg metrics (``None``).

Per-junction metrics
--------------------
* ``legs``: the number of legs.
* ``n_connection_lanes``: drivable lanes of the junction's connecting roads (per road, the most any of its lane
  sections has), U-turns included; ``n_u_turn_lanes`` of those on U-turn roads (both ends on the same outside road).
  A direct junction has no connecting roads: its count is the number of lane links.
* ``area``: area (m^2) of the union of the connection-lane polygons, U-turn lanes excluded as in the paper. Each
  polygon is a lane piece (one lane of one lane section) bounded by its exact inner and outer borders, sampled under the
  chord tolerance (:attr:`Tolerances.chord`), not 11 points per lane: its footprint in the lane mesh the overlap rules
  use (:mod:`xodrcheck.mesh.footprint`, which also computes the union and the overlaps).
* ``conflict_area``: area of the union of the pairwise intersections of those lane pieces, over pairs on different
  connecting roads whose intersection is at least :attr:`Tolerances.overlap_area` (smaller ones are lanes touching
  side by side, whose sampled borders cross by the chord error).
* ``conflict_ratio = conflict_area / area`` (``None`` when the area is 0).
* Direct junctions have no interior: their roads meet along one cross-section, so the "sight line" between two incident
  points is a sideways offset, not a view across a junction. Their legs are counted and located, but the leg metrics,
  area, conflict area and ratio are ``None``.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np
import shapely

from xodrcheck.config import Tolerances
from xodrcheck.geometry.lanes import RoadGeometry, geometry_of
from xodrcheck.mesh.footprint import area_and_conflict, overlap_index
from xodrcheck.model import (
    ContactPoint,
    Document,
    ElementType,
    Junction,
    JunctionType,
    LaneKey,
    Road,
)

__all__ = [
    "CURVATURE_SCALE",
    "DEVIATION_SCALE",
    "FOV_SCALE",
    "LOOKBACK",
    "WEIGHTS",
    "JunctionMetrics",
    "Leg",
    "LegMetrics",
    "complexity",
    "connecting_roads",
    "is_u_turn",
    "junction_legs",
    "junction_metrics",
    "leg_ends",
    "leg_metrics",
    "make_leg",
    "map_metrics",
    "smallest_leg_angle",
]


#: Distance (m) back along a leg at which its look-back point p0 is taken.
LOOKBACK = 50.0
#: The fixed normalisation scales of complexity: curvature (deg/m), FOV (deg), corner deviation (deg).
CURVATURE_SCALE = math.degrees(2 * math.pi / 10)
FOV_SCALE = math.degrees(1.1 * math.pi)
DEVIATION_SCALE = 90.0
#: Weights of complexity: curvature, FOV, corner deviation.
WEIGHTS = (0.5, 0.25, 0.25)


@dataclass(frozen=True, slots=True)
class Leg:
    """A road end touching a junction, with its incident point ``p1`` and look-back point ``p0`` (x, y)."""

    road: str
    end: ContactPoint
    p0: tuple[float, float]
    p1: tuple[float, float]


@dataclass(frozen=True, slots=True)
class LegMetrics:
    """The metrics of one leg of a junction: its road end, incident point and field of view."""

    road: str
    end: ContactPoint
    x: float  # incident point
    y: float
    fov: float | None  # degrees
    max_curvature: float | None  # degrees per metre
    corner_deviation: float | None  # degrees
    complexity: float | None


@dataclass(frozen=True, slots=True)
class JunctionMetrics:
    """The expressive-range metrics of one junction (the paper's FOV, maxCurvature, cornerDeviation, complexity,
    area, conflicts)."""

    junction: str
    name: str | None
    type: JunctionType
    legs: int
    n_connection_lanes: int
    n_u_turn_lanes: int
    area: float | None  # m^2
    conflict_area: float | None
    conflict_ratio: float | None
    leg_metrics: tuple[LegMetrics, ...]


# --------------------------------------------------------------------------------------------------------------------
# Legs
# --------------------------------------------------------------------------------------------------------------------
def _road_ends_at_junctions(document: Document) -> dict[str, list[tuple[str, ContactPoint]]]:
    """Junction id -> the road ends (of roads not inside that junction) whose links name the junction."""
    out: dict[str, list[tuple[str, ContactPoint]]] = {}
    for road in document.roads:
        for link, end in ((road.predecessor, ContactPoint.START), (road.successor, ContactPoint.END)):
            if link is not None and link.element_type is ElementType.JUNCTION and road.junction != link.element_id:
                out.setdefault(link.element_id, []).append((road.id, end))
    return out


def leg_ends(
    document: Document, junction: Junction, linked: Mapping[str, list] | None = None
) -> list[tuple[str, ContactPoint]]:
    """The (road, end) pairs of a junction's legs, in order of first mention (see the module docstring)."""
    roads = document.road_by_id
    found: dict[tuple[str, ContactPoint], None] = {}
    listed = (linked if linked is not None else _road_ends_at_junctions(document)).get(junction.id, ())
    for key in listed:
        found.setdefault(key, None)
    for c in junction.connections:
        if junction.type is JunctionType.DIRECT:
            if c.linked_road in roads and c.contact_point is not None:
                found.setdefault((c.linked_road, c.contact_point), None)
            continue
        connecting = roads.get(c.connecting_road) if c.connecting_road is not None else None
        if connecting is None:
            continue
        for link in (connecting.predecessor, connecting.successor):
            if link is None or link.element_type is not ElementType.ROAD or link.contact_point is None:
                continue
            other = roads.get(link.element_id)
            if other is not None and other.junction != junction.id:
                found.setdefault((other.id, link.contact_point), None)
    return list(found)


def _carriageway_middle(geometry: RoadGeometry, s: float) -> tuple[float, float]:
    """Plan-view middle of the drivable lanes' span at ``s`` (the lane-0 line when there is no drivable lane)."""
    at = np.array([s])
    road = geometry.road
    if not road.lane_sections:
        pose = geometry.reference(at)
        return float(pose.x[0]), float(pose.y[0])
    index = int(geometry.section_index(at)[0])
    left, right = geometry.side_lanes(index)
    drivable = [lane.id for lane in (*left.lanes, *right.lanes) if lane.drivable]
    if not drivable:
        p = geometry.lane_points(index, 0, at)
        return float(p.x[0]), float(p.y[0])
    extremes: list[tuple[float, int, str]] = []
    for lane_id in drivable:
        inner, outer = geometry.inner_outer(index, lane_id, at)
        extremes += [(float(inner[0]), lane_id, "inner"), (float(outer[0]), lane_id, "outer")]
    lo, hi = min(extremes), max(extremes)
    a = geometry.lane_points(index, lo[1], at, where=lo[2])
    b = geometry.lane_points(index, hi[1], at, where=hi[2])
    return float(a.x[0] + b.x[0]) / 2, float(a.y[0] + b.y[0]) / 2


def make_leg(geometry: RoadGeometry, end: ContactPoint, lookback: float = LOOKBACK) -> Leg:
    road = geometry.road
    length = max(road.length, 0.0)
    back = min(lookback, length)
    s1, s0 = (length, length - back) if end is ContactPoint.END else (0.0, back)
    p1 = _carriageway_middle(geometry, s1)
    p0 = _carriageway_middle(geometry, s0)
    if math.dist(p0, p1) <= Tolerances().position:  # a zero-length road: step back along the tangent instead
        hdg = float(geometry.reference(np.array([s1])).hdg[0]) + (0.0 if end is ContactPoint.END else math.pi)
        p0 = (p1[0] - math.cos(hdg), p1[1] - math.sin(hdg))
    return Leg(road.id, end, p0, p1)


def junction_legs(document: Document, junction: Junction, lookback: float = LOOKBACK) -> list[Leg]:
    """The legs of ``junction`` with their incident and look-back points (roads without geometry left out)."""
    geometries = geometry_of(document)
    return [make_leg(geometries[r], e, lookback) for r, e in leg_ends(document, junction) if r in geometries]


def smallest_leg_angle(legs: list[Leg] | tuple[Leg, ...]) -> float | None:
    """Smallest angle (degrees) between two neighbouring legs' directions out of the junction (``p1 -> p0``), the
    gaps taken around the circle; ``None`` for fewer than two legs."""
    if len(legs) < 2:
        return None
    out = np.array([leg.p0 for leg in legs], dtype=float) - np.array([leg.p1 for leg in legs], dtype=float)
    headings = np.sort(np.degrees(np.arctan2(out[:, 1], out[:, 0])) % 360.0)
    gaps = np.diff(np.append(headings, headings[0] + 360.0))
    return float(gaps.min())


# --------------------------------------------------------------------------------------------------------------------
# Per-leg metrics: functions of the four points only
# --------------------------------------------------------------------------------------------------------------------
def _angle_between(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Unsigned angle (rad, [0, pi]) between vectors in the last axis."""
    cross = a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0]
    dot = (a * b).sum(axis=-1)
    return np.abs(np.arctan2(cross, dot))


def complexity(fov: float, max_curvature: float, corner_deviation: float) -> float:
    """The paper's weighted sum with the fixed normalisation scales (module docstring)."""
    parts = (max_curvature / CURVATURE_SCALE, fov / FOV_SCALE, corner_deviation / DEVIATION_SCALE)
    return float(sum(w * min(max(p, 0.0), 1.0) for w, p in zip(WEIGHTS, parts)))


def leg_metrics(legs: list[Leg] | tuple[Leg, ...], tolerance: float | None = None) -> tuple[LegMetrics, ...]:
    """FOV, maxCurvature, cornerDeviation and complexity of every leg against the others (module docstring)."""
    tol = Tolerances().position if tolerance is None else tolerance
    n = len(legs)
    p0 = np.array([leg.p0 for leg in legs], dtype=float).reshape(n, 2)
    p1 = np.array([leg.p1 for leg in legs], dtype=float).reshape(n, 2)
    u = p1 - p0
    u /= np.linalg.norm(u, axis=1, keepdims=True)
    sight = p1[None, :, :] - p1[:, None, :]  # [i, j] = p2(j) - p1(i)
    distance = np.linalg.norm(sight, axis=2)
    valid = (distance > tol) & ~np.eye(n, dtype=bool)
    sight_angle = _angle_between(u[:, None, :], sight)
    w = -u
    deviation = _angle_between(sight, np.broadcast_to(w[None, :, :], sight.shape))
    turn = np.arctan2(w[:, 1], w[:, 0])[None, :] - np.arctan2(u[:, 1], u[:, 0])[:, None]
    turn = np.abs((turn + np.pi) % (2 * np.pi) - np.pi)
    with np.errstate(divide="ignore", invalid="ignore"):
        curvature = np.degrees(turn) / distance
    out = []
    for i, leg in enumerate(legs):
        row = valid[i]
        if not row.any():
            out.append(LegMetrics(leg.road, leg.end, leg.p1[0], leg.p1[1], None, None, None, None))
            continue
        fov = float(np.degrees(2 * sight_angle[i, row].max()))
        dev = float(np.degrees(deviation[i, row].max()))
        curv = float(curvature[i, row].max())
        out.append(LegMetrics(leg.road, leg.end, leg.p1[0], leg.p1[1], fov, curv, dev, complexity(fov, curv, dev)))
    return tuple(out)


# --------------------------------------------------------------------------------------------------------------------
# Connection lanes: counts and polygons
# --------------------------------------------------------------------------------------------------------------------
def connecting_roads(document: Document, junction: Junction) -> list[Road]:
    """The junction's connecting roads: those its connections name and those declaring themselves inside it."""
    roads = document.road_by_id
    ids: dict[str, None] = {}
    for c in junction.connections:
        if c.connecting_road in roads:
            ids.setdefault(c.connecting_road, None)
    for road in document.roads:
        if road.junction == junction.id:
            ids.setdefault(road.id, None)
    return [roads[i] for i in ids]


def is_u_turn(road: Road) -> bool:
    """Both ends of the connecting road on the same outside road."""
    a, b = road.predecessor, road.successor
    return (
        a is not None
        and b is not None
        and a.element_type is ElementType.ROAD
        and b.element_type is ElementType.ROAD
        and a.element_id == b.element_id
    )


def _drivable_lane_count(road: Road) -> int:
    return max(
        (sum(1 for lane in sec.lanes if lane.id != 0 and lane.drivable) for sec in road.lane_sections), default=0
    )


def _junction_footprints(document: Document, roads: list[Road], chord: float) -> tuple[list, list[str]]:
    """Plan-view footprints of the drivable lane pieces (lane x lane section) of ``roads``, U-turns left out, from the
    shared lane mesh (:mod:`xodrcheck.mesh.footprint`), with the road id of each."""
    index = overlap_index(document, chord)
    strip_of = index.strip_of
    polygons = index.footprints.polygons
    chosen: list = []
    owners: list[str] = []
    for road in roads:
        if is_u_turn(road):
            continue
        for section in road.lane_sections:
            for lane in section.lanes:
                if lane.id == 0 or not lane.drivable:
                    continue
                strip = strip_of.get(LaneKey(road.id, section.s, lane.id))
                if strip is not None and shapely.area(polygons[strip]) > 0:
                    chosen.append(polygons[strip])
                    owners.append(road.id)
    return chosen, owners


# --------------------------------------------------------------------------------------------------------------------
# Whole junctions and maps
# --------------------------------------------------------------------------------------------------------------------
def junction_metrics(
    document: Document,
    junction: Junction,
    tolerances: Tolerances | None = None,
    lookback: float = LOOKBACK,
    _linked: Mapping[str, list] | None = None,
) -> JunctionMetrics:
    tol = tolerances or Tolerances()
    geometries = geometry_of(document)
    ends = [(r, e) for r, e in leg_ends(document, junction, _linked) if r in geometries]
    legs = [make_leg(geometries[r], e, lookback) for r, e in ends]
    if junction.type is JunctionType.DIRECT:
        per_leg = tuple(LegMetrics(g.road, g.end, g.p1[0], g.p1[1], None, None, None, None) for g in legs)
        lanes = sum(len(c.lane_links) for c in junction.connections)
        return JunctionMetrics(
            junction.id, junction.name, junction.type, len(legs), lanes, 0, None, None, None, per_leg
        )
    per_leg = leg_metrics(legs, tol.position)
    roads = connecting_roads(document, junction)
    n_lanes = sum(_drivable_lane_count(r) for r in roads)
    n_u_turn = sum(_drivable_lane_count(r) for r in roads if is_u_turn(r))
    area, conflict = area_and_conflict(*_junction_footprints(document, roads, tol.chord), tol.overlap_area)
    ratio = conflict / area if area > 0 else None
    return JunctionMetrics(
        junction.id, junction.name, junction.type, len(legs), n_lanes, n_u_turn, area, conflict, ratio, per_leg
    )


def map_metrics(
    document: Document, tolerances: Tolerances | None = None, lookback: float = LOOKBACK
) -> tuple[JunctionMetrics, ...]:
    """Metrics of every junction of the document, in file order."""
    linked = _road_ends_at_junctions(document)
    return tuple(junction_metrics(document, j, tolerances, lookback, linked) for j in document.junctions)
