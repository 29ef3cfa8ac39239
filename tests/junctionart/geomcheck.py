"""Geometric promises of a written map, measured through xodrcheck's reader and lane geometry (not the generator's).

``measure(path)`` returns the worst position gap (m) and heading gap (rad) over every lane link between a connecting
road and its incoming / outgoing road (both borders of the linked lanes), and the smallest lane-centre / reference-line
radius of the connecting roads.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from xodrcheck.geometry.lanes import geometry_of
from xodrcheck.reader import read


@dataclass(frozen=True)
class Measures:
    links: int
    max_gap: float
    max_heading: float
    min_radius: float
    read_errors: tuple[str, ...]
    min_lane_radius: float = math.inf  #: over every driving lane centre of every road (tapers and bends included)


def _wrap(a: float) -> float:
    return (a + math.pi) % (2 * math.pi) - math.pi


def _end_points(geo, road, lane_id: int, contact: str):
    idx = 0 if contact == "start" else len(road.lane_sections) - 1
    s = np.array([0.0 if contact == "start" else road.length])
    inner = geo.lane_points(idx, lane_id, s, where="inner")
    outer = geo.lane_points(idx, lane_id, s, where="outer")
    return inner, outer


def measure(path) -> Measures:
    res = read(path)
    errors = tuple(f"{f.code} {f.message}" for f in res.findings if f.severity.name == "ERROR")
    doc = res.document
    assert doc is not None
    geos = geometry_of(doc)
    roads = {r.id: r for r in doc.roads}
    gap = head = 0.0
    rmin = math.inf
    n = 0
    for road in doc.roads:
        if road.junction is None:
            continue
        geo = geos[road.id]
        (sec,) = road.lane_sections
        (lane,) = [*sec.left, *sec.right]
        s = np.linspace(0.0, road.length, 200)
        for where in ("centre",):
            k = np.abs(geo.lane_points(0, lane.id, s, where=where).curvature)
            rmin = min(rmin, 1.0 / max(float(k.max()), 1e-12))
        rmin = min(rmin, 1.0 / max(float(np.abs(geo.reference(s).curvature).max()), 1e-12))
        for link, my_contact, other_lane in (
            (road.predecessor, "start", lane.predecessors),
            (road.successor, "end", lane.successors),
        ):
            other = roads[link.element_id]
            ci, co = _end_points(geo, road, lane.id, my_contact)
            oi, oo = _end_points(geos[other.id], other, other_lane[0], link.contact_point.value)
            gap = max(
                gap,
                float(math.hypot(ci.x[0] - oi.x[0], ci.y[0] - oi.y[0])),
                float(math.hypot(co.x[0] - oo.x[0], co.y[0] - oo.y[0])),
            )
            # travel heading: along s for the connecting lane; the other lane's travel direction at its contact
            h_conn = float(ci.hdg[0])
            h_other = float(oi.hdg[0])
            flip = (my_contact == "start") == (link.contact_point.value == "start")
            head = max(head, abs(_wrap(h_conn - h_other - (math.pi if flip else 0.0))))
            n += 1
    lane_r = math.inf
    for road in doc.roads:
        geo = geos[road.id]
        for idx, sec in enumerate(road.lane_sections):
            s0, s1 = sec.s, road.section_end(idx)
            s = np.linspace(s0, s1, max(3, int((s1 - s0) / 0.5) + 2))
            for lane in (*sec.left, *sec.right):
                if lane.type.value == "driving":
                    k = float(np.abs(geo.lane_points(idx, lane.id, s).curvature).max())
                    lane_r = min(lane_r, 1.0 / max(k, 1e-12))
    return Measures(n, gap, head, rmin, errors, lane_r)
