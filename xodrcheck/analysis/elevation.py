"""Elevation summary of a map for ``xodrcheck info``: height range, steepest grade and the largest step in z where
two roads link (10.5: a road's ``<elevation>`` records, cubic in s; a road without records lies at z = 0).

Exact, not sampled: each record's extremes of z and of the grade lie at its ends or where its derivative vanishes.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from xodrcheck.model import ContactPoint, Document, ElementType, Profile, Road


@dataclass(frozen=True)
class ElevationInfo:
    """The heights of a map: lowest and highest reference-line point, steepest grade, largest step at a link."""

    min_z: float  #: m, lowest point of any reference line
    max_z: float
    max_grade: float  #: largest |dz/ds| of any reference line (a fraction: 0.08 is 8 %)
    max_link_step: float  #: m, largest |z difference| between the linked ends of two roads
    links: int  #: road-to-road links measured


def _records(road: Road) -> list[tuple[float, float, float, float, float, float]]:
    """(s, end, a, b, c, d) of each record over its stretch of the road."""
    recs = sorted(road.elevation, key=lambda c: c.s)
    ends = [c.s for c in recs[1:]] + [road.length]
    return [(c.s, max(end, c.s), c.a, c.b, c.c, c.d) for c, end in zip(recs, ends)]


def _roots(a: float, b: float, c: float, upper: float) -> list[float]:
    """Real roots of a + b u + c u^2 inside (0, upper)."""
    cands = [r.real for r in np.roots([c, b, a]) if abs(r.imag) < 1e-12] if c != 0.0 else [-a / b] if b != 0.0 else []
    return [u for u in cands if 0.0 < u < upper]


def z_at(profile: Profile, s: float) -> float:
    recs = [c for c in sorted(profile, key=lambda c: c.s) if c.s <= s + 1e-9] or list(profile[:1])
    if not recs:
        return 0.0
    c = recs[-1]
    u = s - c.s
    return c.a + u * (c.b + u * (c.c + u * c.d))


def _road_extremes(road: Road) -> tuple[float, float, float]:
    """(min z, max z, max |grade|) of one road."""
    zs, grades = [0.0] if not road.elevation else [], [0.0]
    for _s, end, a, b, c, d in _records(road):
        span = end - _s
        for u in [0.0, span, *_roots(b, 2 * c, 3 * d, span)]:
            zs.append(a + u * (b + u * (c + u * d)))
        for u in [0.0, span, *_roots(2 * c, 6 * d, 0.0, span)]:
            grades.append(abs(b + u * (2 * c + 3 * d * u)))
    return min(zs), max(zs), max(grades)


def _end_z(road: Road, contact: ContactPoint | None) -> float | None:
    if contact is None:
        return None
    return z_at(road.elevation, 0.0 if contact is ContactPoint.START else road.length)


def elevation_info(doc: Document) -> ElevationInfo | None:
    """The summary, or None for a map without roads."""
    if not doc.roads:
        return None
    roads = {r.id: r for r in doc.roads}
    lo, hi, grade = math.inf, -math.inf, 0.0
    for road in doc.roads:
        a, b, g = _road_extremes(road)
        lo, hi, grade = min(lo, a), max(hi, b), max(grade, g)
    step, links = 0.0, 0
    for road in doc.roads:
        for link, own in ((road.predecessor, ContactPoint.START), (road.successor, ContactPoint.END)):
            if link is None or link.element_type is not ElementType.ROAD or link.element_id not in roads:
                continue
            theirs = _end_z(roads[link.element_id], link.contact_point)
            mine = _end_z(road, own)  # (never None: own is an end)
            if theirs is None or mine is None:
                continue
            step, links = max(step, abs(mine - theirs)), links + 1
    return ElevationInfo(lo, hi, grade, step, links)
