"""Road-body overlap measured from a written file through xodrcheck's reader and lane geometry.

Two bodies may touch only where the map says they meet: a road and the connecting roads of a junction it links to,
or connecting roads of one junction among themselves. Anything else overlapping by more than ``min_area`` is reported.
"""

from __future__ import annotations

import numpy as np
import shapely
from shapely import STRtree

from xodrcheck.geometry.lanes import geometry_of
from xodrcheck.reader import read


def bodies(path):
    doc = read(path).document
    geos = geometry_of(doc)
    out = []
    for road in doc.roads:
        geo = geos[road.id]
        parts = []
        for idx, sec in enumerate(road.lane_sections):
            s0, s1 = sec.s, road.section_end(idx)
            s = np.linspace(s0, s1, max(3, int((s1 - s0) / 1.0) + 2))
            for lane in (*sec.left, *sec.right):
                a = geo.lane_points(idx, lane.id, s, where="inner")
                b = geo.lane_points(idx, lane.id, s, where="outer")
                ring = np.column_stack([np.r_[a.x, b.x[::-1]], np.r_[a.y, b.y[::-1]]])
                poly = shapely.make_valid(shapely.Polygon(ring))
                if poly.area > 1e-6:
                    parts.append(poly)
        out.append((road, shapely.union_all(parts) if parts else shapely.Polygon()))
    return doc, out


def overlaps(path, min_area: float = 0.5):
    """(road a, road b, area) for road bodies overlapping where the map does not connect them."""
    _, items = bodies(path)
    junction_of = {}
    touches: dict[str, set[str]] = {}
    for road, _ in items:
        if road.junction is not None:
            junction_of[road.id] = road.junction
    for road, _ in items:
        links = set()
        for link in (road.predecessor, road.successor):
            if link is not None:
                links.add(link.element_id)
        touches[road.id] = links
    polys = [p for _, p in items]
    tree = STRtree(polys)
    left, right = tree.query(polys, predicate="intersects")
    found = []
    for i, j in zip(left, right):
        if i >= j:
            continue
        a, b = items[i][0], items[j][0]
        ja, jb = junction_of.get(a.id), junction_of.get(b.id)
        if ja is not None and ja == jb:
            continue
        if (ja is not None and (jb == ja or b.id in touches[a.id])) or (jb is not None and a.id in touches[b.id]):
            continue
        area = polys[i].intersection(polys[j]).area
        if area > min_area:
            found.append((a.id, b.id, area))
    return found
