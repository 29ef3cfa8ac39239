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

from xodrcheck.model import Arc, Line

if TYPE_CHECKING:
    from xodrcheck.findings import Finding
    from xodrcheck.lanes import RoadGeometry
    from xodrcheck.rules.context import Context

#: (road id, s, lane, section_s): a place as a finding names it.
Key = tuple[str, float, int | None, float | None]
#: Inertial (x, y, z) of a place (z NaN where not finite), or ``None`` where it is not finite.
Point = tuple[float, float, float] | None


def lane_placed(geometry: RoadGeometry, s: float, lane: int | None, section_s: float | None) -> tuple[int, int] | None:
    """(lane section index, lane) whose centre is the place; ``None``: the reference line."""
    from xodrcheck.rules.context import placed_lane_ids

    sections = geometry.road.lane_sections
    if not lane or not sections:
        return None
    starts = [i for i, section in enumerate(sections) if section.s == section_s]
    index = starts[0] if starts else int(geometry.section_index(np.array([float(s)]))[0])
    return (index, lane) if lane in placed_lane_ids(geometry, index) else None


def points_at(geometry: RoadGeometry, at: np.ndarray, placed: tuple[int, int] | None) -> list[Point]:
    """The points at ``at`` (finite ``s`` on a road with a plan view) of a lane's centre or of the reference line."""
    with np.errstate(all="ignore"):
        if placed is not None:
            p = geometry.lane_points(placed[0], placed[1], at, "centre", raised=True)
            xs, ys, zs = p.x, p.y, p.z
        else:
            pose = geometry.reference(at)
            xs, ys, zs = pose.x, pose.y, geometry.elevation(at)
    out: list[Point] = []
    for x, y, z in zip(xs.tolist(), ys.tolist(), zs.tolist()):
        out.append((x, y, z if math.isfinite(z) else float("nan")) if math.isfinite(x) and math.isfinite(y) else None)
    return out


def _pointwise(geometry: RoadGeometry) -> bool:
    """Whether the road's plan view evaluates every point on its own (lines and arcs: a point's numbers do not depend
    on the other points evaluated with it; spirals, poly3 and paramPoly3 choose series and iterations per call)."""
    return all(type(element) in (Line, Arc) for element in geometry.reference_line.elements)


def locate_all(ctx: Context, findings: list[Finding]) -> list[Finding]:
    """:meth:`Context.locate` of every finding, with the places on one lane of one section (or on one road's reference
    line) evaluated in one call where the road's plan view is pointwise: the same numbers as one by one."""
    groups: dict[tuple[str, tuple[int, int] | None], dict[Key, float]] = {}
    for f in findings:
        if f.x is not None or f.road is None or f.s is None or not math.isfinite(f.s):
            continue
        key: Key = (f.road, f.s, f.lane, f.section_s)
        geometry = ctx.geometry(f.road)
        if ctx.known_position(key) or geometry is None or not geometry.road.plan_view or not _pointwise(geometry):
            continue
        groups.setdefault((f.road, lane_placed(geometry, f.s, f.lane, f.section_s)), {})[key] = float(f.s)
    for (road_id, placed), places in groups.items():
        if len(places) > 1:
            geometry = ctx.geometry(road_id)
            assert geometry is not None
            found = points_at(geometry, np.array(list(places.values())), placed)
            for key, point in zip(places, found):
                ctx.remember_position(key, point)
    return [ctx.locate(f) for f in findings]
