"""Geometry the geometric rules share, computed once per file.

Each lane section is sampled and evaluated once (:func:`section_lines`) and kept with the check's
:class:`~xodrcheck.rules.context.Context`, so the link, curvature and junction rules share one evaluation. A road without a plan view or
without lane sections has no geometry here (``None``): the reader reports those.
"""

from __future__ import annotations

import math
import weakref
from dataclasses import dataclass

import numpy as np

from xodrcheck.config import Tolerances
from xodrcheck.lanes import LanePoints, RoadGeometry
from xodrcheck.model import ContactPoint, Road
from xodrcheck.rules.context import Context
from xodrcheck.sampling import knots, step_counts


def usable(ctx: Context, road: Road) -> RoadGeometry | None:
    """The road's geometry when it can be evaluated: a plan view, lane sections and a positive length."""
    if not road.plan_view or not road.lane_sections or not road.length > 0 or not math.isfinite(road.length):
        return None
    if ctx.document.road_by_id.get(road.id) is not road:
        return None  # a duplicated id: only the first road of that id can be looked up (R001 reports it)
    return ctx.geometry(road.id)


def section_samples(ctx: Context, road: Road, section_index: int) -> np.ndarray:
    """Sorted ``s`` covering lane section ``section_index``, cached for the file.

    Every knot of the section (:func:`xodrcheck.sampling.knots`: record starts, plan-view joints, section ends) and
    even steps between them no longer than ``sqrt(8 * chord * min_radius)`` (and ``max_step``): a polyline through
    them strays at most ``chord`` from any line curving no tighter than the ``min_radius`` bound (tighter curves are
    reported by the curvature rules). The section's end is taken just before it (:func:`left_of`).
    """
    return section_lines(ctx, road, section_index).s


@dataclass(frozen=True)
class SectionLines:
    """A lane section evaluated once at its samples: ``t`` of every lane's outer border (lane 0: the lane-0 line),
    the reference line's curvature, and the border lines in plan view."""

    s: np.ndarray
    t: dict[int, np.ndarray]
    curvature: np.ndarray
    borders: dict[int, LanePoints]


_LINES: weakref.WeakKeyDictionary[Context, dict[tuple[str, int], SectionLines]] = weakref.WeakKeyDictionary()


def grid_step(tol: Tolerances) -> float:
    """The longest step of :func:`section_samples` (within the sample budget)."""
    return min(tol.max_step, math.sqrt(8.0 * tol.chord * max(tol.min_radius, tol.chord)))


def _grid(ctx: Context, geometry: RoadGeometry, section_index: int) -> np.ndarray:
    start, end = geometry.section_range(section_index)
    if not end > start:
        return np.array([start], dtype=float)
    tol = ctx.tolerances
    step = grid_step(tol)
    cuts = knots(geometry, section_index)
    lengths = np.diff(cuts)
    counts = step_counts(lengths, step, tol.max_samples_per_section)
    owner = np.repeat(np.arange(len(lengths)), counts)
    offset = np.arange(owner.size) - np.repeat(np.cumsum(counts) - counts, counts)
    s = np.append(cuts[owner] + lengths[owner] * offset / counts[owner], left_of(end))
    return np.maximum.accumulate(s)


def section_lines(ctx: Context, road: Road, section_index: int) -> SectionLines:
    """The lane section's lines at its samples (one evaluation per section for all the geometric rules)."""
    cache = _LINES.setdefault(ctx, {})
    key = (road.id, section_index)
    found = cache.get(key)
    if found is None:
        geometry = ctx.geometry(road.id)
        s = _grid(ctx, geometry, section_index)
        found = SectionLines(
            s,
            geometry.borders(section_index, s),
            geometry.reference(s).curvature,
            geometry.border_curves(section_index, s),
        )
        cache[key] = found
    return found


def left_of(s: float) -> float:
    """``s`` moved back by a negligible amount (1e-9 relative): evaluating a section at its own end then uses the
    records in force before that ``s``, not those (laneOffset, plan view) that start exactly there."""
    return s - 1e-9 * max(1.0, abs(s))


def end_s(road: Road, end: ContactPoint) -> float:
    """``s`` of a road's start, or just before its end (see :func:`left_of`)."""
    return 0.0 if end is ContactPoint.START else left_of(float(road.length))


@dataclass(frozen=True, slots=True)
class EndPoint:
    """A point of a lane line at a road end, with the heading pointing out of the road there."""

    x: float
    y: float
    outward: float


@dataclass(frozen=True, slots=True)
class RoadEnd:
    """Every lane line at one end of a road: ``outer[lane]`` is the lane's outer border (lane 0: the lane-0 line),
    ``inner[lane]`` the id of the lane whose outer border is its inner border."""

    outer: dict[int, EndPoint]
    inner: dict[int, int]

    def border(self, lane_id: int, where: str) -> EndPoint | None:
        """A lane's ``"inner"`` or ``"outer"`` border (lane 0: its line); ``None`` when the lane is not there."""
        if lane_id not in self.outer:
            return None
        return self.outer.get(lane_id if where == "outer" or lane_id == 0 else self.inner[lane_id])


_ENDS: weakref.WeakKeyDictionary[Context, dict[tuple[str, ContactPoint], RoadEnd]] = weakref.WeakKeyDictionary()


def road_end(ctx: Context, road: Road, end: ContactPoint) -> RoadEnd:
    """The lane lines of a usable road at its start or end (cached for the file; a road with one lane section is
    evaluated at both ends in one call)."""
    cache = _ENDS.setdefault(ctx, {})
    found = cache.get((road.id, end))
    if found is None:
        geometry = ctx.geometry(road.id)
        last = len(road.lane_sections) - 1
        ends = (ContactPoint.START, ContactPoint.END) if last == 0 else (end,)
        index = 0 if end is ContactPoint.START else last
        s = np.array([end_s(road, e) for e in ends])
        curves = geometry.border_curves(index, s)
        inner: dict[int, int] = {}
        for side in geometry.side_lanes(index):
            previous = 0
            for lane in side.lanes:
                inner[lane.id] = previous
                previous = lane.id
        for k, e in enumerate(ends):
            outer: dict[int, EndPoint] = {}
            for lane_id, points in curves.items():
                x, y, hdg = float(points.x[k]), float(points.y[k]), float(points.hdg[k])
                if math.isfinite(x) and math.isfinite(y) and math.isfinite(hdg):
                    outer[lane_id] = EndPoint(x, y, hdg if e is ContactPoint.END else hdg + math.pi)
            cache[(road.id, e)] = RoadEnd(outer, inner)
        found = cache[(road.id, end)]
    return found


def angle_between(a: float, b: float) -> float:
    """Absolute difference of two angles, wrapped to [0, pi]."""
    return abs(math.remainder(a - b, 2.0 * math.pi))
