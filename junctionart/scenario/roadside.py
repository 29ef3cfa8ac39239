"""Roadside lanes: what lies beyond the outermost driving lane of every road, and its continuation round junctions.

``roadside="urban"``: a kerb (lane type ``curb``, 0.2 m) and a sidewalk (2.0 m), both raised 0.15 m (``<height>``),
on both sides of every road: town streets have them whatever their class. ``roadside="rural"``: a paved shoulder
(1.5 m) and an unpaved border (0.5 m) at road level. The widths are those of common street design (a 2 m sidewalk is
the usual minimum for two people to pass; 1.5 m shoulders on two-lane rural roads).

Junctions continue the roadside round each corner: between two neighbouring legs a connecting road carries the
roadside lanes from one leg's kerb side to the other's. Where a connection lane makes the kerb-side turn between
those two legs from their outermost lanes, the corner road shares its reference line and sits exactly one lane
width beside it (``laneOffset``), so the sidewalk borders the turning lane without a gap or an overlap; elsewhere
the corner is a Hermite curve of its own from kerb to kerb.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..curves import HermiteFit, connection_geometry, fit_connections, local_target
from ..lanegeom import border_point
from ..opendrive import Cubic, Geometry, Lane, LaneHeight, LaneSection
from ..params import Params, Roadside, TrafficRule


@dataclass(frozen=True)
class RoadsideLane:
    """A lane beside the outer driving lanes (kerb, sidewalk, shoulder, border): type, width, height."""

    type: str
    width: float  #: m
    height: float  #: m above the road surface (``<height inner outer>``, both edges)


#: The roadside lanes of each kind, from the driving lanes outward.
LANES: dict[Roadside, tuple[RoadsideLane, ...]] = {
    Roadside.URBAN: (RoadsideLane("curb", 0.2, 0.15), RoadsideLane("sidewalk", 2.0, 0.15)),
    Roadside.RURAL: (RoadsideLane("shoulder", 1.5, 0.0), RoadsideLane("border", 0.5, 0.0)),
    Roadside.NONE: (),
}

#: Lane types the roadside adds.
ROADSIDE_TYPES = frozenset(r.type for lanes in LANES.values() for r in lanes)

#: Radius (m) every roadside lane border of a corner keeps at least (its borders must not fold).
CORNER_MIN_RADIUS = 1.0


def roadside_width(params: Params) -> float:
    """Total width (m) of the roadside lanes on one side of a road (0 without roadside)."""
    return sum(r.width for r in LANES[params.roadside])


def side_lanes(params: Params, side: int, inner: int, before: int | None, after: int | None) -> list[Lane]:
    """The roadside lanes of one side (+1 left, -1 right) of a lane section whose side has ``inner`` lanes (driving
    lanes and median); ``before`` and ``after``: that count in the previous and next lane section of the road (None
    where there is none), for the lane links."""
    out = []
    for k, r in enumerate(LANES[params.roadside], start=1):
        lane_id = side * (inner + k)
        pred = side * (before + k) if before is not None else None
        succ = side * (after + k) if after is not None else None
        heights = (LaneHeight(0.0, r.height, r.height),) if r.height else ()
        out.append(Lane(lane_id, r.type, (Cubic(0.0, r.width),), (), pred, succ, heights))
    return out


# ---------------------------------------------------------------------------------------------------------------------
# Corners
# ---------------------------------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class LegEnd:
    """One leg of a junction as a corner sees it."""

    road: str
    contact: str  #: "start" / "end" of the leg's road at the junction
    x: float
    y: float
    hdg: float  #: of the reference line there
    angle: float  #: direction from the junction's position to the contact point (orders the legs)
    left_edge: float  #: t of the outer border of the innermost-out lanes on the left (driving lanes and median)
    right_edge: float  #: the same on the right (negative)
    left_ids: tuple[int, ...]  #: roadside lane ids on the left, from the kerb outward
    right_ids: tuple[int, ...]

    @property
    def inward(self) -> float:
        return self.hdg + (math.pi if self.contact == "start" else 0.0)

    @property
    def outward(self) -> float:
        return self.hdg + (0.0 if self.contact == "start" else math.pi)

    def kerb(self, entering: bool, kerb_side: int) -> tuple[float, tuple[int, ...]]:
        """The t of the kerb and the roadside lane ids on the side that lies toward ``kerb_side`` (-1 right, +1 left)
        of traffic entering (or leaving) the junction here."""
        along_s = (self.contact == "end") == entering  # this traffic drives along s
        side = kerb_side if along_s else -kerb_side
        return (self.left_edge, self.left_ids) if side > 0 else (self.right_edge, self.right_ids)


def leg_end(
    road_id: str, contact: str, geometry: tuple[Geometry, ...], section: LaneSection, length: float, at: tuple
) -> LegEnd:
    """The leg of ``road_id`` meeting a junction at position ``at`` with its ``contact`` end, whose lane section there
    is ``section``, ``length`` long; widths are read at that end of the section."""
    from ..curves import end_pose

    if contact == "start":
        x, y, hdg = geometry[0].x, geometry[0].y, geometry[0].hdg
    else:
        e = end_pose(geometry[-1])
        x, y, hdg = e.x, e.y, e.hdg
    roadside = ROADSIDE_TYPES
    edges = {}
    ids = {}
    for side, lanes in ((1, section.left), (-1, section.right)):
        inner = [ln for ln in lanes if ln.type not in roadside]
        edges[side] = side * sum(_width_at(ln, length if contact == "end" else 0.0) for ln in inner)
        ids[side] = tuple(ln.id for ln in sorted(lanes, key=lambda ln: abs(ln.id)) if ln.type in roadside)
    angle = math.atan2(y - at[1], x - at[0])
    return LegEnd(road_id, contact, x, y, hdg, angle, edges[1], edges[-1], ids[1], ids[-1])


def _width_at(lane: Lane, length: float) -> float:
    """A lane's width ``length`` after the start of its section (the generator writes one cubic per lane and
    section)."""
    w = lane.widths[0]
    return w.a + length * (w.b + length * (w.c + length * w.d))


@dataclass(frozen=True)
class Corner:
    """A corner's connecting road: from the kerb of leg ``a`` (traffic entering) to that of leg ``b`` (leaving)."""

    a: LegEnd
    b: LegEnd
    geometry: Geometry
    lane_offset: float  #: t of the kerb from the reference line (0 when the reference line is the kerb)
    a_ids: tuple[int, ...]  #: roadside lane ids of leg a at the junction, from the kerb outward
    b_ids: tuple[int, ...]


def kerb_side(params: Params) -> int:
    """The side of the kerb relative to the direction of travel: right (-1) in right-hand traffic, else left."""
    return -1 if params.traffic_rule is TrafficRule.RHT else 1


def corner_pairs(legs: list[LegEnd], params: Params) -> list[tuple[LegEnd, LegEnd]]:
    """Each corner of a junction as (leg traffic enters by, leg it leaves by) of the kerb-side turn round it: the
    next leg counter-clockwise in right-hand traffic (a right turn), clockwise in left-hand traffic."""
    order = sorted(legs, key=lambda g: (g.angle, g.road, g.contact))
    if len(order) < 2:
        return []
    pairs = list(zip(order, order[1:] + order[:1]))
    if params.traffic_rule is TrafficRule.RHT:
        return pairs
    return [(b, a) for a, b in pairs]


def corner(a: LegEnd, b: LegEnd, turn: Geometry | None, params: Params, widths: tuple[float, ...]) -> Corner | None:
    """The corner from leg ``a`` to leg ``b``: along ``turn`` (the kerb-side connection lane between their outermost
    lanes, whose reference line is that lane's inner border) when there is one, else a curve of its own; None when no
    curve of its own keeps its borders unfolded."""
    side = kerb_side(params)
    ka, a_ids = a.kerb(True, side)
    kb, b_ids = b.kerb(False, side)
    if not a_ids or not b_ids:
        return None
    if turn is not None:
        return Corner(a, b, turn, side * params.lane_width, a_ids, b_ids)
    x0, y0 = border_point(a.x, a.y, a.hdg, ka)
    x1, y1 = border_point(b.x, b.y, b.hdg, kb)
    h0, h1 = a.inward, b.outward
    offsets = tuple(side * sum(widths[: k + 1]) for k in range(len(widths)))
    fits: list[HermiteFit | None] = fit_connections(
        np.array([local_target(x0, y0, h0, x1, y1, h1)]), offsets, CORNER_MIN_RADIUS, _SCALES
    )
    if fits[0] is None:
        return None
    return Corner(a, b, connection_geometry(x0, y0, h0, fits[0]), 0.0, a_ids, b_ids)


_SCALES = np.linspace(0.2, 1.4, 17)
