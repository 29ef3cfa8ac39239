"""The lane lines and reference line at a road's ends, evaluated once per file for the rules that join roads.

:func:`road_end` gives every lane line of a usable road (:meth:`.context.Context.usable_geometry`) at its start or end
(:class:`RoadEnd` of :class:`EndPoint`), :func:`reference_end` the reference line there; both are cached with the
check's context and dropped by :func:`.sampled.release_lines`. An end is evaluated just before it (:func:`end_s`,
:func:`left_of`).
"""

from __future__ import annotations

import math
import weakref
from dataclasses import dataclass

import numpy as np

from xodrcheck.geometry.batch import BATCH_SAMPLES, Evaluation
from xodrcheck.geometry.lanes import RoadGeometry
from xodrcheck.geometry.lines import LanePoints
from xodrcheck.model import ContactPoint, Road
from xodrcheck.rules.shared.context import Context
from xodrcheck.support.arrays import batches


def left_of(s: float) -> float:
    """``s`` moved back by a negligible amount (1e-9 relative): evaluating a section at its own end then uses the
    records in force before that ``s``, not those (laneOffset, plan view) that start exactly there."""
    return s - 1e-9 * max(1.0, abs(s))


def end_s(road: Road, end: ContactPoint) -> float:
    """``s`` of a road's start, or just before its end (see :func:`left_of`)."""
    return 0.0 if end is ContactPoint.START else left_of(float(road.length))


@dataclass(frozen=True, slots=True)
class EndPoint:
    """A point of a lane line at a road end (x, y, z), with the heading pointing out of the road there."""

    x: float
    y: float
    z: float
    outward: float


@dataclass(frozen=True, slots=True)
class RoadEnd:
    """Every lane line at one end of a road: ``outer[lane]`` is the lane's outer border (lane 0: the lane-0 line),
    ``inner[lane]`` the id of the lane whose outer border is its inner border. ``raised[(lane, where)]`` is the inner
    or outer edge of a lane with ``<height>`` records, lifted by its height (other lanes' edges are the borders)."""

    outer: dict[int, EndPoint]
    inner: dict[int, int]
    raised: dict[tuple[int, str], EndPoint]

    def border(self, lane_id: int, where: str) -> EndPoint | None:
        """A lane's ``"inner"`` or ``"outer"`` border (lane 0: its line); ``None`` when the lane is not there."""
        if lane_id not in self.outer:
            return None
        return self.outer.get(lane_id if where == "outer" or lane_id == 0 else self.inner[lane_id])

    def edge(self, lane_id: int, where: str) -> EndPoint | None:
        """A lane's own ``"inner"`` or ``"outer"`` edge in 3D: its border raised by the lane's height (ASAM OpenDRIVE
        Annex D.1.1's touching point); ``None`` when the lane is not there."""
        found = self.raised.get((lane_id, where))
        return found if found is not None else self.border(lane_id, where)


ENDS: weakref.WeakKeyDictionary[Context, dict[tuple[str, ContactPoint], RoadEnd]] = weakref.WeakKeyDictionary()


def end_samples(road: Road, end: ContactPoint) -> tuple[int, tuple[ContactPoint, ...], np.ndarray]:
    """Where :func:`road_end` evaluates a road's lines for ``end``: (lane section, the ends evaluated, their ``s``);
    a road with one lane section is evaluated at both ends in one call."""
    last = len(road.lane_sections) - 1
    ends = (ContactPoint.START, ContactPoint.END) if last == 0 else (end,)
    return 0 if end is ContactPoint.START else last, ends, np.array([end_s(road, e) for e in ends])


END_CURVES: weakref.WeakKeyDictionary[Context, dict[tuple[str, int], dict[int, LanePoints]]] = (
    weakref.WeakKeyDictionary()
)


def end_curves(ctx: Context) -> dict[tuple[str, int], dict[int, LanePoints]]:
    """The border curves :func:`road_end` needs (:meth:`RoadGeometry.border_curves` at :func:`end_samples`) of every
    usable road's end sections, evaluated together in batches (the same numbers, with a fraction of the numpy calls),
    keyed by (road id, section index)."""
    found = END_CURVES.get(ctx)
    if found is not None:
        return found
    entries: list[tuple[RoadGeometry, int]] = []
    keys: list[tuple[str, int]] = []
    grids: list[np.ndarray] = []
    for road in ctx.document.roads:
        geometry = ctx.usable_geometry(road)
        if geometry is None:
            continue
        for end in (ContactPoint.START, ContactPoint.END) if len(road.lane_sections) > 1 else (ContactPoint.START,):
            index, _, s = end_samples(road, end)
            entries.append((geometry, index))
            keys.append((road.id, index))
            grids.append(s)
    found = {}
    for lo, hi in batches([len(s) for s in grids], BATCH_SAMPLES):
        evaluation = Evaluation([geometry.rows(index) for geometry, index in entries[lo:hi]], grids[lo:hi])
        found.update(zip(keys[lo:hi], evaluation.border_points()))
    END_CURVES[ctx] = found
    return found


def road_end(ctx: Context, road: Road, end: ContactPoint) -> RoadEnd:
    """The lane lines of a usable road at its start or end (cached for the file; a road with one lane section is
    evaluated at both ends in one call; the border curves of all roads' ends in one pass, :func:`end_curves`)."""
    cache = ENDS.setdefault(ctx, {})
    found = cache.get((road.id, end))
    if found is None:
        geometry = ctx.geometry(road.id)
        assert geometry is not None, "road_end is asked for usable roads only"
        index, ends, s = end_samples(road, end)
        # taken out: each (road, section) is asked for once (both ends of a one-section road in one call), and the
        # curves of a big map's ends are large
        curves = end_curves(ctx).pop((road.id, index), None)
        if curves is None:
            curves = geometry.border_curves(index, s)
        inner: dict[int, int] = {}
        for side in geometry.side_lanes(index):
            previous = 0
            for lane in side.lanes:
                inner[lane.id] = previous
                previous = lane.id
        raised = {
            (lane_id, where): geometry.lane_points(index, lane_id, s, where, raised=True)
            for lane_id in inner
            if geometry.has_height(index, lane_id)
            for where in ("inner", "outer")
        }
        for k, e in enumerate(ends):
            outer = {lane_id: p for lane_id, points in curves.items() if (p := _end_point(points, k, e)) is not None}
            lifted = {key: p for key, points in raised.items() if (p := _end_point(points, k, e)) is not None}
            cache[(road.id, e)] = RoadEnd(outer, inner, lifted)
        found = cache[(road.id, end)]
    return found


REFERENCE: weakref.WeakKeyDictionary[Context, dict[tuple[str, ContactPoint], EndPoint | None]] = (
    weakref.WeakKeyDictionary()
)


def reference_end(ctx: Context, road: Road, end: ContactPoint) -> EndPoint | None:
    """The reference line of a usable road at its start or end (z: the elevation there), cached for the file;
    ``None`` where it does not evaluate to finite numbers."""
    cache = REFERENCE.setdefault(ctx, {})
    key = (road.id, end)
    if key not in cache:
        geometry = ctx.geometry(road.id)
        if geometry is None:
            cache[key] = None
        else:
            s = np.array([end_s(road, end)])
            pose = geometry.reference(s)
            points = LanePoints(pose.x, pose.y, geometry.elevation(s), pose.hdg, pose.curvature, np.ones(1))
            cache[key] = _end_point(points, 0, end)
    return cache[key]


def _end_point(points: LanePoints, k: int, end: ContactPoint) -> EndPoint | None:
    """Point ``k`` of a lane line as an :class:`EndPoint` at ``end`` (``None`` unless finite; z may be NaN only
    where x, y are not)."""
    x, y, z, hdg = float(points.x[k]), float(points.y[k]), float(points.z[k]), float(points.hdg[k])
    if not (math.isfinite(x) and math.isfinite(y) and math.isfinite(hdg)):
        return None
    return EndPoint(x, y, z, hdg if end is ContactPoint.END else hdg + math.pi)
