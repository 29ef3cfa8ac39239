"""Road bodies and junction areas that overlap where the map does not connect them (found before writing)."""

from __future__ import annotations

import numpy as np
import shapely

from ..curves import end_pose, sample
from ..graph import Chain
from ..lanegeom import border_point, side_width
from ..lanes import LaneConfig
from ..opendrive import Geometry
from ..params import Params, TrafficRule


def _pose(g: tuple[Geometry, ...], at_start: bool) -> tuple[float, float, float]:
    if at_start:
        return g[0].x, g[0].y, g[0].hdg
    e = end_pose(g[-1])
    return e.x, e.y, e.hdg


def overlaps(chs: list[Chain], roads: list[tuple[tuple[Geometry, ...], LaneConfig]],
             junctions: dict[int, list[tuple[tuple[Geometry, ...], LaneConfig, bool]]],
             connections: dict[int, list[Geometry]], p: Params) -> list[list[int]]:
    """For each overlap, the chains (roads) whose removal would end it, in order of preference.

    Roads are their reference lines buffered by their wider side; a junction is the convex hull of its legs' end
    cross-sections together with the body of each of its connection lanes (``connections``: their reference lines,
    the lane lying on the traffic side), since a wide turn can leave the hull. Roads sharing an end node, and a
    junction with its own legs, may touch.
    """
    w, mw = p.lane_width, p.median_width
    shapes, owners = [], []
    for c, (g, cfg) in enumerate(roads):
        half = max(side_width(cfg.forward, cfg.median, w, mw), side_width(cfg.backward, cfg.median, w, mw))
        pts = np.concatenate([sample(e, max(2, int(e.length / 5.0) + 2)) for e in g])
        shapes.append(shapely.LineString(pts).buffer(half, cap_style="flat"))
        owners.append(("road", c))
    rht = p.traffic_rule is TrafficRule.RHT
    for node, legs in junctions.items():
        corners = []
        for g, cfg, at_start in legs:
            pose = _pose(g, at_start)
            left = side_width(cfg.backward if rht else cfg.forward, cfg.median, w, mw)
            right = side_width(cfg.forward if rht else cfg.backward, False, w, mw)
            corners.append(border_point(*pose, left))
            corners.append(border_point(*pose, -right))
        side = -w if rht else w  # connection lanes are -1 (RHT) or 1 (LHT): right or left of their reference line
        bodies = [shapely.MultiPoint(corners).convex_hull]
        for g in connections.get(node, ()):
            pts = sample(g, max(2, int(g.length / 2.0) + 2))
            bodies.append(shapely.buffer(shapely.LineString(pts), side, single_sided=True, cap_style="flat"))
        shapes.append(shapely.union_all(bodies).buffer(-0.5))
        owners.append(("junction", node))
    tree = shapely.STRtree(shapes)
    left_i, right_i = tree.query(shapes, predicate="intersects")
    found = []
    for i, j in sorted(zip(left_i.tolist(), right_i.tolist())):
        if i >= j:
            continue
        (ka, a), (kb, b) = owners[i], owners[j]
        if ka == "road" and kb == "road":
            if {chs[a].start, chs[a].end} & {chs[b].start, chs[b].end}:
                continue
            cands = [a, b]
        elif ka == "junction" and kb == "junction":
            cands = [c for c, ch in enumerate(chs) if {ch.start, ch.end} & {a, b}]
        else:
            road, node = (a, b) if ka == "road" else (b, a)
            if node in (chs[road].start, chs[road].end):
                continue
            cands = [road]
        if shapes[i].intersection(shapes[j]).area >= 0.01:
            found.append(cands)
    return found
