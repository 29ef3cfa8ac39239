"""Where roads and lanes end, for the fixes that must know whether ends meet before they link them: reference-line
end points, road widths at an end, the roads ending near an end, and the lanes of a road end that hold a point.

All from the exact lane geometry (:mod:`xodrcheck.geometry.lanes`), in plan view.
"""

from __future__ import annotations

import math

import numpy as np

from xodrcheck.fix.workspace import Workspace
from xodrcheck.model import ContactPoint, Road

__all__ = ["end_pose", "lane_centre", "lanes_holding", "roads_near_end", "side_at", "width_at"]


def _s(road: Road, end: ContactPoint) -> float:
    return 0.0 if end is ContactPoint.START else float(road.length)


def end_pose(ws: Workspace, road: Road, end: ContactPoint) -> tuple[float, float, float] | None:
    """x, y and heading of the road's reference line at ``end`` (``None`` when it cannot be evaluated)."""
    if not road.plan_view:
        return None
    pose = ws.geometry[road.id].reference(np.array([_s(road, end)]))
    x, y, hdg = float(pose.x[0]), float(pose.y[0]), float(pose.hdg[0])
    return (x, y, hdg) if all(map(math.isfinite, (x, y, hdg))) else None


def _section_index(road: Road, end: ContactPoint) -> int | None:
    if not road.lane_sections:
        return None
    return 0 if end is ContactPoint.START else len(road.lane_sections) - 1


def width_at(ws: Workspace, road: Road, end: ContactPoint) -> float:
    """The road's width across all its lanes at ``end`` (0 without lanes)."""
    index = _section_index(road, end)
    if index is None:
        return 0.0
    t = [float(v[0]) for v in ws.geometry[road.id].borders(index, np.array([_s(road, end)])).values()]
    t = [v for v in t if math.isfinite(v)]
    return max(t) - min(t) if t else 0.0


def roads_near_end(ws: Workspace, road: Road, end: ContactPoint, radius: float | None = None) -> list[str]:
    """Other roads with an end whose reference point lies within ``radius`` of this end's (default: this road's
    width there, and at least the ``gap`` tolerance)."""
    here = end_pose(ws, road, end)
    if here is None:
        return []
    reach = max(width_at(ws, road, end), ws.tolerances.gap) if radius is None else radius
    out = []
    for other in ws.document.roads:
        if other.id == road.id:
            continue
        for other_end in (ContactPoint.START, ContactPoint.END):
            there = end_pose(ws, other, other_end)
            if there is not None and math.hypot(there[0] - here[0], there[1] - here[1]) <= reach:
                out.append(other.id)
                break
    return out


def side_at(road: Road, end: ContactPoint) -> tuple[int, float] | None:
    """The lane section index and ``s`` at a road's ``end`` (``None`` without lane sections)."""
    index = _section_index(road, end)
    return None if index is None else (index, _s(road, end))


def lane_centre(ws: Workspace, road: Road, index: int, s: float, lane_id: int) -> tuple[float, float] | None:
    """The centre point of lane ``lane_id`` of lane section ``index`` at ``s`` (``None`` when it has no such lane)."""
    if not 0 <= index < len(road.lane_sections) or lane_id == 0 or road.lane_sections[index].lane(lane_id) is None:
        return None
    p = ws.geometry[road.id].lane_points(index, lane_id, np.array([s]))
    x, y = float(p.x[0]), float(p.y[0])
    return (x, y) if math.isfinite(x) and math.isfinite(y) else None


def lanes_holding(
    ws: Workspace, road: Road, index: int, s: float, point: tuple[float, float], reach: float
) -> list[int] | None:
    """The lanes (not lane 0, none zero wide) of lane section ``index`` at ``s`` whose span across the road holds
    ``point``; ``None`` when the point lies more than ``reach`` along the road from ``s`` (it is not there). A point
    within a millimetre of a border counts for neither lane beside it."""
    if not road.plan_view or not 0 <= index < len(road.lane_sections):
        return None
    pose = ws.geometry[road.id].reference(np.array([s]))
    x0, y0, hdg = float(pose.x[0]), float(pose.y[0]), float(pose.hdg[0])
    dx, dy = point[0] - x0, point[1] - y0
    along = math.cos(hdg) * dx + math.sin(hdg) * dy
    t = -math.sin(hdg) * dx + math.cos(hdg) * dy
    if not abs(along) <= reach:
        return None
    geometry, at = ws.geometry[road.id], np.array([s])
    out = []
    for lane in road.lane_sections[index].lanes:
        if lane.id == 0:
            continue
        inner, outer = (float(v[0]) for v in geometry.inner_outer(index, lane.id, at))
        low, high = min(inner, outer), max(inner, outer)
        if high - low > 2e-3 and low + 1e-3 < t < high - 1e-3:
            out.append(lane.id)
    return out
