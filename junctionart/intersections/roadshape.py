"""The geometry of one road between its two incident points, or why it cannot have one.

A road is its chain's polyline trimmed at both ends by the incident distances, with a fillet arc at each interior
vertex. The arcs must keep every lane centre above the turn-radius bound (lane tapers on the curve included) and the
road must stay long enough for its tapers, so a shape is only returned when it is drivable; otherwise the misfit says
which repair applies (:mod:`.roads` makes it): a bend that is too sharp is cut open or straightened, a road that is too
short is merged away or removed. :class:`Contact` is where a finished road meets its junction: the connection lanes
start and end there.
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass
from enum import Enum
from typing import NamedTuple

import numpy as np
import shapely

from ..curves import end_pose, fillet_chain, sample, unit_tangents, wrap
from ..lanegeom import border_point, inner_offset, lane_id, min_curve_radius, side_width
from ..lanes import LaneConfig
from ..opendrive import Geometry
from ..params import Params
from ..scenario.roadside import roadside_width

#: Total turning (rad) of a road's bends beyond which its borders are tested for crossing themselves.
SELF_OVERLAP_TURN = 0.9 * math.pi
SHARPEST_VERTEX = math.radians(170)  #: a vertex turning more than this is never filleted
PREFERRED_RADIUS = 60.0  #: bends are this round where the road has room (never tighter than the lanes allow)


class EndLanes(NamedTuple):
    """Lane counts at one end of a road, along its direction (tapers lead there from the middle's counts)."""

    forward: int
    backward: int


@dataclass(frozen=True)
class RoadSpec:
    """What the road of one chain must carry: its lanes in the middle and at both ends, and its shortest length."""

    chain: int
    lanes: LaneConfig
    start: EndLanes
    end: EndLanes
    need: float  #: shortest length that holds both tapers and a minimal straight piece
    splitter_start: float = 0.0  #: width of a roundabout's splitter island at the road's start (0: none)
    splitter_end: float = 0.0


class Misfit(Enum):
    """Why a road has no geometry."""

    SHARP_BEND = "a bend too sharp for the road's lanes"
    TOO_SHORT = "too short for its incident points and lane tapers"


class RoadShape(NamedTuple):
    """The road's lines and arcs, or (geometry empty) its misfit; ``bend`` is the chain index of the vertex to repair
    for a sharp bend."""

    geometry: tuple[Geometry, ...]
    misfit: Misfit | None = None
    bend: int = 0


class Contact(NamedTuple):
    """Where a road meets its junction: the reference line's pose there, and whether that is the road's start."""

    x: float
    y: float
    hdg: float
    at_start: bool

    @property
    def inward(self) -> float:
        """Heading of traffic driving into the junction here."""
        return self.hdg + (math.pi if self.at_start else 0.0)

    @property
    def outward(self) -> float:
        """Heading of traffic driving out of the junction here."""
        return self.hdg + (0.0 if self.at_start else math.pi)

    def entering(self, k: int, median: bool, params: Params) -> tuple[int, tuple[float, float]]:
        """Lane id of incoming lane ``k`` (1 = next to the centre) and where its inner border meets the junction."""
        return self._lane(lane_id(not self.at_start, k, median, params.traffic_rule), median, params)

    def leaving(self, m: int, median: bool, params: Params) -> tuple[int, tuple[float, float]]:
        """Lane id of outgoing lane ``m`` (1 = next to the centre) and where its inner border meets the junction."""
        return self._lane(lane_id(self.at_start, m, median, params.traffic_rule), median, params)

    def _lane(self, lid: int, median: bool, params: Params) -> tuple[int, tuple[float, float]]:
        offset = inner_offset(lid, median, params.lane_width, params.median_width)
        return lid, border_point(self.x, self.y, self.hdg, offset)


def contact(geometry: tuple[Geometry, ...], at_start: bool) -> Contact:
    """The pose of a road's reference line at its start or end."""
    if at_start:
        return Contact(geometry[0].x, geometry[0].y, geometry[0].hdg, True)
    e = end_pose(geometry[-1])
    return Contact(e.x, e.y, e.hdg, False)


_TOO_SHORT = RoadShape((), Misfit.TOO_SHORT)


class _Segment(NamedTuple):
    ux: float  #: unit direction
    uy: float
    length: float


def _segment(a: tuple[float, float], b: tuple[float, float]) -> _Segment:
    dx, dy = b[0] - a[0], b[1] - a[1]
    L = math.hypot(dx, dy)
    return _Segment(dx / L, dy / L, L)


class _Corners(NamedTuple):
    """Per interior vertex: fillet radius and tangent length (both 0 where the polyline runs straight on) and the
    turn, which starts with a 0 for the start so that its index is the vertex's. ``sharp``: the first vertex that
    cannot be filleted, where there is one (the lists then stop before it)."""

    radii: list[float]
    tangents: list[float]
    turns: list[float]
    sharp: int | None


def _corners(segs: list[_Segment], avail: list[float], r_min: float, r_pref: float) -> _Corners:
    """Fillet each interior vertex with the preferred radius where the segments' room allows it (an inner segment
    shares its room between its two ends), never under ``r_min``."""
    n = len(segs)
    out = _Corners([], [], [0.0], None)
    for i in range(1, n):
        theta = abs(wrap(math.atan2(segs[i].uy, segs[i].ux) - math.atan2(segs[i - 1].uy, segs[i - 1].ux)))
        out.turns.append(theta)
        share_l = avail[i - 1] / (2 if i - 1 > 0 else 1)
        share_r = avail[i] / (2 if i < n - 1 else 1)
        t_max = min(share_l, share_r) - 0.5
        if theta < 1e-9:  # collinear: no vertex, one line runs through
            out.radii.append(0.0)
            out.tangents.append(0.0)
            continue
        if t_max <= 0 or theta > SHARPEST_VERTEX:
            return out._replace(sharp=i)
        R = min(r_pref, t_max / math.tan(theta / 2))
        if r_min > R:
            return out._replace(sharp=i)
        out.radii.append(R)
        out.tangents.append(R * math.tan(theta / 2))
    return out


def shape_road(P: list[tuple[float, float]], r0: float, r1: float, spec: RoadSpec, params: Params) -> RoadShape:
    """The road through chain points ``P`` from ``r0`` after its first point to ``r1`` before its last."""
    segs = [_segment(a, b) for a, b in itertools.pairwise(P)]
    if any(s.length < 1e-6 for s in segs):
        return _TOO_SHORT
    avail = [s.length for s in segs]
    avail[0] -= r0
    avail[-1] -= r1
    cfg, ends = spec.lanes, (spec.start, spec.end)
    mid = (cfg.forward, cfg.backward)
    widest = max(side_width(n, cfg.median, params.lane_width, params.median_width) for n in (*mid, *ends[0], *ends[1]))
    splitter = max(spec.splitter_start, spec.splitter_end)
    if splitter > 0.0:  # a roundabout's arm: its splitter island widens one side
        widest = max(widest, max(*mid, *ends[0], *ends[1]) * params.lane_width + splitter)
    # lane centres on the inside keep 3/4 of the curvature budget; a lane taper on the curve may use the rest
    r_min = min_curve_radius(params, widest, ends, mid)
    corners = _corners(segs, avail, r_min, max(r_min, PREFERRED_RADIUS))
    if corners.sharp is not None:
        return RoadShape((), Misfit.SHARP_BEND, corners.sharp)
    if any(a <= 0 for a in avail) and len(segs) == 1:
        return _TOO_SHORT
    if sum(avail) - 2 * sum(corners.tangents) < 0:
        return _TOO_SHORT
    start = (P[0][0] + r0 * segs[0].ux, P[0][1] + r0 * segs[0].uy)
    end = (P[-1][0] - r1 * segs[-1].ux, P[-1][1] - r1 * segs[-1].uy)
    rounded = [(v, r) for v, r in zip(P[1:-1], corners.radii) if r > 0]
    geom = fillet_chain(start, [v for v, _ in rounded], end, [r for _, r in rounded])
    if geom[-1].s + geom[-1].length < spec.need:
        return _TOO_SHORT
    if sum(corners.turns) > SELF_OVERLAP_TURN and _folds(geom, widest + roadside_width(params)):
        return RoadShape((), Misfit.SHARP_BEND, int(np.argmax(corners.turns)))
    return RoadShape(geom)


def _folds(geom: tuple[Geometry, ...], offset: float) -> bool:
    """Whether a border ``offset`` to either side of the chain ``geom`` crosses itself: bends turning the road back
    on itself (two tight bends, 200 deg in all) put a lane over its own surface."""
    pts = np.concatenate([sample(e, max(4, int(e.length / 2.0) + 2))[:-1] for e in geom] + [sample(geom[-1], 2)[-1:]])
    tangent = unit_tangents(pts)
    normal = np.column_stack([-tangent[:, 1], tangent[:, 0]])
    borders = shapely.linestrings(np.stack([pts + offset * normal, pts - offset * normal]))
    return not bool(shapely.is_simple(borders).all())
