"""Where a finding is: the inertial point of a place named by road, ``s`` and lane (:meth:`Context.position`), and
the places of many findings evaluated together (:func:`locate_all`).

A place on a lane is the lane's centre (raised by its height) in the lane section starting at the finding's
``section_s`` (default: the section containing ``s``); without a lane, for lane 0, or for a lane the section does not
place, it is the reference line (z: the elevation).
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:
    from xodrcheck.findings import Finding
    from xodrcheck.geometry.lanes import RoadGeometry
    from xodrcheck.model import Geometry, Road
    from xodrcheck.rules.shared.context import Context

#: (road id, s, lane, section_s): a place as a finding names it.
Key = tuple[str, float, int | None, float | None]
#: Inertial (x, y, z) of a place (z NaN where not finite), or ``None`` where it is not finite.
Point = tuple[float, float, float] | None


def finite(*values: float) -> bool:
    """Whether every value is a finite number (a record's attributes before placing it)."""
    return all(math.isfinite(v) for v in values)


def element_place(road: Road, element: Geometry) -> dict:
    """Where a finding about plan-view element ``element`` of ``road`` points: its start s, x, y and line."""
    return {"road": road.id, "s": element.s, "x": element.x, "y": element.y, "line": element.line or road.line or None}


def lane_placed(geometry: RoadGeometry, s: float, lane: int | None, section_s: float | None) -> tuple[int, int] | None:
    """(lane section index, lane) whose centre is the place; ``None``: the reference line."""
    sections = geometry.road.lane_sections
    if not lane or not sections:
        return None
    starts = [i for i, section in enumerate(sections) if section.s == section_s]
    index = starts[0] if starts else int(geometry.section_index(np.array([float(s)]))[0])
    return (index, lane) if lane in geometry.placed_lane_ids(index) else None


def points_at(geometry: RoadGeometry, at: np.ndarray, placed: tuple[int, int] | None) -> list[Point]:
    """The points at ``at`` (finite ``s`` on a road with a plan view) of a lane's centre or of the reference line."""
    with np.errstate(all="ignore"):
        if placed is not None:
            p = geometry.lane_points(placed[0], placed[1], at, "centre", raised=True)
            xs, ys, zs = p.x, p.y, p.z
        else:
            pose = geometry.reference(at)
            xs, ys, zs = pose.x, pose.y, geometry.elevation(at)
    return _points(xs, ys, zs)


def _points(xs: np.ndarray, ys: np.ndarray, zs: np.ndarray) -> list[Point]:
    out: list[Point] = []
    for x, y, z in zip(xs.tolist(), ys.tolist(), zs.tolist()):
        out.append((x, y, z if math.isfinite(z) else float("nan")) if math.isfinite(x) and math.isfinite(y) else None)
    return out


#: Places evaluated together: it bounds a batch's temporaries (each place a block of one sample: a few hundred
#: bytes each).
PLACES_TOGETHER = 1 << 12


def locate_all(ctx: Context, findings: list[Finding]) -> list[Finding]:
    """:meth:`Context.locate` of every finding, with the places not known yet evaluated together, each as a block of
    its own (:class:`~xodrcheck.geometry.batch.Evaluation`, :func:`~xodrcheck.geometry.planview.poses`): the same
    numbers as one by one."""
    on_lanes: dict[Key, tuple[RoadGeometry, tuple[int, int]]] = {}
    on_lines: dict[Key, RoadGeometry] = {}
    for f in findings:
        if f.x is not None or f.road is None or f.s is None or not math.isfinite(f.s):
            continue
        key: Key = (f.road, f.s, f.lane, f.section_s)
        geometry = ctx.geometry(f.road)
        if ctx.known_position(key) or key in on_lanes or key in on_lines or geometry is None:
            continue
        if geometry.road.plan_view:
            placed = lane_placed(geometry, f.s, f.lane, f.section_s)
            if placed is None:
                on_lines[key] = geometry
            else:
                on_lanes[key] = (geometry, placed)
    keys = list(on_lanes)
    for lo in range(0, len(keys), PLACES_TOGETHER):
        _lane_places(ctx, {key: on_lanes[key] for key in keys[lo : lo + PLACES_TOGETHER]})
    _line_places(ctx, on_lines)
    return [ctx.locate(f) for f in findings]


def _lane_places(ctx: Context, places: dict[Key, tuple[RoadGeometry, tuple[int, int]]]) -> None:
    """Remember the lane centres (raised by the lane's height) at ``places``, evaluated together."""
    from xodrcheck.geometry.batch import Evaluation

    if not places:
        return
    with np.errstate(all="ignore"):
        evaluation = Evaluation(
            [geometry.rows(index) for geometry, (index, _) in places.values()],
            [np.array([float(key[1])]) for key in places],
        )
        wanted = [(k, lane, "centre", True) for k, (_, (_, lane)) in enumerate(places.values())]
        p = evaluation.lines(wanted).points()
    for key, point in zip(places, _points(p.x, p.y, p.z)):
        ctx.remember_position(key, point)


def _line_places(ctx: Context, places: dict[Key, RoadGeometry]) -> None:
    """Remember the reference-line points (z: the elevation) at ``places``, evaluated together."""
    from xodrcheck.geometry.planview import poses

    if not places:
        return
    s = np.array([key[1] for key in places], dtype=float)
    geometries = list(places.values())
    z = np.empty(len(s))
    with np.errstate(all="ignore"):
        pose = poses([geometry.reference_line for geometry in geometries], s, np.arange(len(s) + 1))
        by_road: dict[int, list[int]] = {}
        for k, geometry in enumerate(geometries):
            by_road.setdefault(id(geometry), []).append(k)
        for ks in by_road.values():  # the elevation is evaluated point by point
            z[ks] = geometries[ks[0]].elevation(s[ks])
    for key, point in zip(places, _points(pose.x, pose.y, z)):
        ctx.remember_position(key, point)
