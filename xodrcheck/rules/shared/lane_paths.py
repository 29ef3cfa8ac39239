"""A lane's path through a road as the junction rules follow it: from a contact point along the lane's centre,
across lane sections by its lane links (:func:`centre_path`); where two such paths part (:func:`parted`) and where
they meet (:func:`crossing`)."""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from xodrcheck.model import ContactPoint, Road
from xodrcheck.rules.shared.context import Context
from xodrcheck.rules.shared.sampled import section_samples

if TYPE_CHECKING:
    import shapely


#: Centre lines evaluated ahead, by (road id, section index, lane id): plan-view points (n, 2) at the section samples.
Known = dict[tuple[str, int, int], np.ndarray]


def walk(ctx: Context, road: Road, lane_id: int, contact: ContactPoint) -> list[tuple[int, int]]:
    """(section index, lane id) of the lane from ``contact`` through the road, following its lane links across
    sections while each is placed."""
    geometry = ctx.road_geometry(road)
    sections = road.lane_sections
    order = range(len(sections)) if contact is ContactPoint.START else range(len(sections) - 1, -1, -1)
    steps = []
    current: int | None = lane_id
    for index in order:
        lane = sections[index].lane(current) if current is not None else None
        if lane is None or current is None or current not in geometry.placed_lane_ids(index):
            break
        steps.append((index, current))
        links = lane.successors if contact is ContactPoint.START else lane.predecessors
        current = links[0] if len(links) == 1 else None
    return steps


def centre_path(
    ctx: Context, road: Road, lane_id: int, contact: ContactPoint, known: Known | None = None
) -> np.ndarray | None:
    """The lane's centre from ``contact`` through the road, following its lane links across sections (the lines in
    ``known`` are taken from there)."""
    geometry = ctx.road_geometry(road)
    pieces = []
    for index, current in walk(ctx, road, lane_id, contact):
        xy = known.get((road.id, index, current)) if known is not None else None
        if xy is None:
            points = geometry.lane_points(index, current, section_samples(ctx, road, index), "centre")
            xy = np.column_stack((points.x, points.y))
        pieces.append(xy if contact is ContactPoint.START else xy[::-1])
    if not pieces:
        return None
    xy = np.concatenate(pieces)
    xy = xy[np.all(np.isfinite(xy), axis=1)]
    return xy if len(xy) >= 2 else None


def parted(a: np.ndarray, b: shapely.LineString, tol: float) -> np.ndarray | None:
    """The part of polyline ``a`` from its first vertex further than ``tol`` from ``b`` on (``None``: never)."""
    import shapely

    distance = shapely.distance(shapely.points(a), b)
    far = np.nonzero(distance > tol)[0]
    if not len(far) or len(a) - far[0] < 2:
        return None
    return a[far[0] :]


def crossing(a: np.ndarray, b: np.ndarray, one_lane: bool, tol: float) -> np.ndarray | None:
    """A point where two paths from one road end meet other than at their start (``None`` when they do not); paths
    from ``one_lane`` are compared from where they part (:func:`parted`), as vehicles of one lane follow each other
    until then."""
    import shapely  # here: shapely loads only for junctions with paths to compare

    if one_lane:
        part_a, part_b = parted(a, shapely.LineString(b), tol), parted(b, shapely.LineString(a), tol)
        if part_a is None or part_b is None:
            return None
        a, b = part_a, part_b
    meet = shapely.intersection(shapely.LineString(a), shapely.LineString(b))
    if meet.is_empty:
        return None
    return shapely.get_coordinates(meet)[0]
