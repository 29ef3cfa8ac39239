"""A junction's area in plan view: its boundary (12.10), its reference line (12.9) and its elevation grid (12.11).

:func:`boundary_pieces` evaluates the segments of a ``<boundary>`` as polylines, each from the segment's start to its
end, with the exact lane geometry (:class:`xodrcheck.geometry.lanes.RoadGeometry`): a ``lane`` segment runs along the
outer border of ``boundaryLane`` of its road from ``sStart`` to ``sEnd`` (lane 0: the lane-0 line, that is the reference
line moved by the laneOffset), at the road's section samples between them; a ``joint`` segment runs straight across
the road at its contact point, from the outer border of ``jointLaneStart`` to that of ``jointLaneEnd``. A joint
without lanes crosses all of them: from the outermost border on one side to the outermost on the other, in whichever
order follows on from the segment before it (the file does not say which).

:class:`ReferenceLine` is a junction reference line of one ``<line>``, with the (s, t) of points in its frame, and
:class:`GridArea` the part of the plane an elevation grid defines: the complete squares of its rows (12.11: rows at
``sStart + i * gridSpacing`` along the line, points ``gridSpacing`` apart across it).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from xodrcheck.geometry.lanes import RoadGeometry
from xodrcheck.model import ContactPoint, Road
from xodrcheck.rules.shared.context import Context
from xodrcheck.rules.shared.road_ends import left_of
from xodrcheck.rules.shared.sampled import section_lines

if TYPE_CHECKING:
    from xodrcheck.model import (
        Boundary,
        BoundarySegment,
        ElevationGrid,
        JointSegment,
        Junction,
        LaneSegment,
        RoadPlace,
    )


@dataclass(frozen=True)
class Piece:
    """One boundary segment in plan view: ``xy`` (n x 2) from its start to its end; ``free``: a joint across all
    lanes, which may run either way."""

    segment: BoundarySegment
    xy: np.ndarray
    free: bool = False

    @property
    def start(self) -> np.ndarray:
        return self.xy[0]

    @property
    def end(self) -> np.ndarray:
        return self.xy[-1]


def road_s(road: Road, place: RoadPlace | None) -> float | None:
    """``s`` of a segment's place on its road: ``start`` 0, ``end`` the length, a number itself (``None``: none or
    outside the road)."""
    if place is None:
        return None
    if isinstance(place, ContactPoint):
        return 0.0 if place is ContactPoint.START else float(road.length)
    value = float(place)
    return value if -1e-9 <= value <= road.length + 1e-6 else None


def _lane_piece(ctx: Context, seg: LaneSegment) -> np.ndarray | None:
    road = ctx.road(seg.road)
    if road is None or seg.lane is None or ctx.usable_geometry(road) is None:
        return None
    geometry = ctx.geometry(road.id)
    a, b = road_s(road, seg.s_start), road_s(road, seg.s_end)
    if a is None or b is None or geometry is None:
        return None
    lo, hi = min(a, b), max(a, b)
    hi = min(hi, left_of(float(road.length)))
    parts: list[np.ndarray] = []
    for index in range(len(road.lane_sections)):
        start, end = geometry.section_range(index)
        if end < lo or start > hi or (end == lo and index + 1 < len(road.lane_sections)):
            continue
        s = section_lines(ctx, road, index).s
        s = np.unique(np.concatenate(([max(lo, start)], s[(s > lo) & (s < hi)], [min(hi, left_of(end))])))
        try:
            points = geometry.lane_points(index, seg.lane, s, where="outer")
        except KeyError:
            return None  # no such lane in this section (R012-like; reported by the segment rule)
        parts.append(np.column_stack((points.x, points.y)))
    if not parts:
        return None
    xy = np.concatenate(parts)
    return xy if a <= b else xy[::-1]


def _outer(ctx: Context, road: Road, s: float, lane: int) -> np.ndarray | None:
    geometry = ctx.geometry(road.id)
    index = int(geometry.section_index(s)[0]) if geometry is not None else -1
    if geometry is None or index < 0:
        return None
    try:
        p = geometry.lane_points(index, lane, np.array([s]), where="outer")
    except KeyError:
        return None
    return np.array([p.x[0], p.y[0]])


def joint_lanes(geometry: RoadGeometry, index: int, seg: JointSegment) -> tuple[int, int]:
    """The lanes whose outer borders a joint runs between, in lane section ``index`` of its road: ``jointLaneStart``
    and ``jointLaneEnd``, a missing one the outermost lane (of the other side than the given one; both missing: from
    the outermost left lane to the outermost right one)."""
    left, right = geometry.side_lanes(index)
    outermost_left = left.lanes[-1].id if left.lanes else 0
    outermost_right = right.lanes[-1].id if right.lanes else 0
    first, last = seg.lane_start, seg.lane_end
    if first is None:
        first = outermost_left if (last is None or last <= 0) else outermost_right
    if last is None:
        last = outermost_right if first >= 0 else outermost_left
    return first, last


def _joint_piece(ctx: Context, seg: JointSegment) -> tuple[np.ndarray, bool] | None:
    road = ctx.road(seg.road)
    if road is None or ctx.usable_geometry(road) is None:
        return None
    s = road_s(road, seg.contact)
    geometry = ctx.geometry(road.id)
    if s is None or geometry is None:
        return None
    s = min(s, left_of(float(road.length)))
    index = int(geometry.section_index(s)[0])
    if index < 0:
        return None
    first, last = joint_lanes(geometry, index, seg)
    free = seg.lane_start is None and seg.lane_end is None
    a, b = _outer(ctx, road, s, first), _outer(ctx, road, s, last)
    if a is None or b is None:
        return None
    steps = np.linspace(0.0, 1.0, 9)[:, None]
    return a + steps * (b - a), free


def boundary_pieces(ctx: Context, boundary: Boundary) -> list[Piece] | None:
    """The boundary's segments in plan view, in file order; ``None`` when a segment cannot be placed (an unknown
    road or lane, a place off its road: the segment rules report those)."""
    from xodrcheck.model import LaneSegment

    pieces: list[Piece] = []
    for seg in boundary.segments:
        if isinstance(seg, LaneSegment):
            xy = _lane_piece(ctx, seg)
            if xy is None:
                return None
            pieces.append(Piece(seg, xy))
        else:
            found = _joint_piece(ctx, seg)
            if found is None:
                return None
            pieces.append(Piece(seg, found[0], found[1]))
    if not pieces:
        return None
    return _orient(pieces)


def _orient(pieces: list[Piece]) -> list[Piece]:
    """Free joints turned to follow on from the piece before them (or lead into the one after)."""
    out = list(pieces)
    n = len(out)
    for k, piece in enumerate(out):
        if not piece.free or n < 2:
            continue
        before, after = out[k - 1], out[(k + 1) % n]
        keep = _dist(before.end, piece.start) + _dist(piece.end, after.start)
        turn = _dist(before.end, piece.end) + _dist(piece.start, after.start)
        if turn < keep:
            out[k] = Piece(piece.segment, piece.xy[::-1], True)
    return out


def _dist(p: np.ndarray, q: np.ndarray) -> float:
    return float(math.hypot(p[0] - q[0], p[1] - q[1]))


def gaps(pieces: list[Piece]) -> list[tuple[Piece, Piece, float]]:
    """Each piece with the next one (cyclically) and the distance from its end to the next one's start."""
    n = len(pieces)
    return [(pieces[k], pieces[(k + 1) % n], _dist(pieces[k].end, pieces[(k + 1) % n].start)) for k in range(n)]


def ring(pieces: list[Piece]) -> np.ndarray:
    """The boundary's points in order (m x 2)."""
    return np.concatenate([p.xy for p in pieces])


def signed_area(xy: np.ndarray) -> float:
    """Shoelace area of a closed ring: positive when it runs counter-clockwise."""
    x, y = xy[:, 0], xy[:, 1]
    return 0.5 * float(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1)))


@dataclass(frozen=True)
class ReferenceLine:
    """A junction reference line of one straight ``<geometry>``."""

    x: float
    y: float
    hdg: float
    length: float
    line: int

    def frame(self, xy: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """(s, t) of points: along the line from its start, and to its left."""
        dx, dy = xy[:, 0] - self.x, xy[:, 1] - self.y
        c, s = math.cos(self.hdg), math.sin(self.hdg)
        return dx * c + dy * s, -dx * s + dy * c

    def point(self, s: float) -> tuple[float, float]:
        return self.x + s * math.cos(self.hdg), self.y + s * math.sin(self.hdg)


def reference_line(j: Junction) -> ReferenceLine | None:
    """The junction's reference line when it is one ``<geometry>`` of one ``<line>`` with every value set (the shape
    rule, J013, reports the others)."""
    view = j.plan_view
    if view is None or len(view.geometries) != 1:
        return None
    g = view.geometries[0]
    if g.shapes != ("line",) or g.x is None or g.y is None or g.hdg is None or g.length is None or not g.length > 0:
        return None
    return ReferenceLine(g.x, g.y, g.hdg, g.length, g.line)


@dataclass(frozen=True)
class GridArea:
    """Where an elevation grid defines heights: between rows ``i`` and ``i + 1`` (at ``s0 + i * spacing``), from
    ``-right[i] * spacing`` to ``left[i] * spacing`` across the line (the points both rows have)."""

    s0: float
    spacing: float
    left: np.ndarray  # points to the left, per pair of rows
    right: np.ndarray

    @property
    def s_end(self) -> float:
        return self.s0 + len(self.left) * self.spacing

    def outside(self, s: np.ndarray, t: np.ndarray, tol: float) -> np.ndarray:
        """Which (s, t) lie outside every complete square of the grid (by more than ``tol``)."""
        u = (s - self.s0) / self.spacing
        pair = np.clip(np.floor(u).astype(int), 0, max(len(self.left) - 1, 0))
        if len(self.left) == 0:
            return np.ones(len(s), dtype=bool)
        # a point on the line between two pairs of rows may use either pair
        other = np.clip(np.where(u - np.floor(u) < 1e-9, pair - 1, pair), 0, len(self.left) - 1)
        reach_left = np.maximum(self.left[pair], self.left[other]) * self.spacing
        reach_right = np.maximum(self.right[pair], self.right[other]) * self.spacing
        along = (s < self.s0 - tol) | (s > self.s_end + tol)
        across = (t > reach_left + tol) | (t < -reach_right - tol)
        return along | across


def grid_area(grid: ElevationGrid) -> GridArea | None:
    """The grid's area (``None`` without a positive spacing or with a row that does not parse)."""
    if grid.spacing is None or not grid.spacing > 0 or grid.s_start is None:
        return None
    if any(row.left is None or row.right is None or row.center is None for row in grid.rows):
        return None
    # a row without a centre point breaks the squares through the line (-1: not even the line is covered)
    left = np.array([len(row.left or ()) if row.center else -1 for row in grid.rows], dtype=float)
    right = np.array([len(row.right or ()) if row.center else -1 for row in grid.rows], dtype=float)
    return GridArea(grid.s_start, grid.spacing, np.minimum(left[:-1], left[1:]), np.minimum(right[:-1], right[1:]))


# ------------------------------------------------------------------------------------------------------ lane strips
def strip(ctx: Context, road: Road, lane: int | None, lo: float, hi: float):
    """The plan-view area of one lane of a usable road (``lane=None``: of the whole road, outermost border to
    outermost border) between ``lo`` and ``hi`` along it, as a shapely geometry (``None``: nothing there)."""
    import shapely

    geometry = ctx.geometry(road.id)
    if geometry is None or ctx.usable_geometry(road) is None:
        return None
    lo, hi = max(lo, 0.0), min(hi, left_of(float(road.length)))
    pieces = []
    for index in range(len(road.lane_sections)):
        start, end = geometry.section_range(index)
        if end < lo or start > hi:
            continue
        s = section_lines(ctx, road, index).s
        s = np.unique(np.concatenate(([max(lo, start)], s[(s > lo) & (s < hi)], [min(hi, left_of(end))])))
        if lane is None:
            left, right = geometry.side_lanes(index)
            ids = (left.lanes[-1].id if left.lanes else 0, right.lanes[-1].id if right.lanes else 0)
            sides = [geometry.lane_points(index, i, s, where="outer") for i in ids]
        else:
            try:
                sides = [geometry.lane_points(index, lane, s, where=w) for w in ("inner", "outer")]
            except KeyError:
                continue
        xy = np.concatenate(
            (np.column_stack((sides[0].x, sides[0].y)), np.column_stack((sides[1].x, sides[1].y))[::-1])
        )
        if len(xy) >= 3 and np.isfinite(xy).all():
            pieces.append(shapely.make_valid(shapely.Polygon(xy)))
    return shapely.union_all(pieces) if pieces else None


def road_points(ctx: Context, road: Road, s: float | None = None) -> np.ndarray | None:
    """Every lane border point of a usable road (``s``: only at that ``s``), n x 2; ``None`` without geometry."""
    geometry = ctx.geometry(road.id)
    if geometry is None or ctx.usable_geometry(road) is None:
        return None
    parts: list[np.ndarray] = []
    for index in range(len(road.lane_sections)):
        if s is None:
            lines = section_lines(ctx, road, index).borders
        else:
            if int(geometry.section_index(min(s, left_of(float(road.length))))[0]) != index:
                continue
            lines = geometry.border_curves(index, np.array([min(s, left_of(float(road.length)))]))
        parts.extend(np.column_stack((p.x, p.y)) for p in lines.values())
    xy = np.concatenate(parts) if parts else np.empty((0, 2))
    return xy[np.isfinite(xy).all(axis=1)]
