"""Lane centre lines of the graph's nodes: their points (from :mod:`xodrcheck.geometry.lanes`, sampled within the chord
tolerance as ``xodrcheck sample`` and the snapshots' lane length are) and their lengths in plan view."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from xodrcheck.config import Tolerances
from xodrcheck.geometry.lanes import geometry_of
from xodrcheck.graph.build import LaneGraph
from xodrcheck.model import Document, document_cache

__all__ = ["CentreLine", "centre_line", "node_lengths"]


@dataclass(frozen=True, eq=False)
class CentreLine:
    """A lane's centre line over its lane section, ordered by increasing ``s`` (empty arrays where it cannot be
    evaluated: a road without a plan view, say)."""

    s: np.ndarray
    x: np.ndarray
    y: np.ndarray
    z: np.ndarray

    def between(self, s0: float, s1: float) -> CentreLine:
        """The part from ``s0`` to ``s1`` (either order; points in that order), its ends interpolated."""
        lo, hi = min(s0, s1), max(s0, s1)
        if not len(self.s):
            return self
        inside = (self.s > lo) & (self.s < hi)
        s = np.concatenate([[lo], self.s[inside], [hi]])
        part = CentreLine(s, *(np.interp(s, self.s, v) for v in (self.x, self.y, self.z)))
        if s0 > s1:
            part = CentreLine(*(v[::-1] for v in (part.s, part.x, part.y, part.z)))
        return part

    @property
    def length(self) -> float:
        if len(self.s) < 2:
            return 0.0
        return float(np.sum(np.hypot(np.diff(self.x), np.diff(self.y))))


_EMPTY = CentreLine(np.zeros(0), np.zeros(0), np.zeros(0), np.zeros(0))


def centre_line(document: Document, road_id: str, index: int, lane: int) -> CentreLine:
    """The centre line of ``lane`` in lane section ``index`` of road ``road_id`` (cached with the document)."""
    cache = document_cache(document).setdefault("graph centre lines", {})
    key = (road_id, index)
    lines = cache.get(key)
    if lines is None:
        lines = cache[key] = _section_lines(document, road_id, index)
    return lines.get(lane, _EMPTY)


def _section_lines(document: Document, road_id: str, index: int) -> dict[int, CentreLine]:
    road = document.road_by_id[road_id]
    start, end = road.lane_sections[index].s, road.section_end(index)
    if not road.plan_view or not end >= start:
        return {}
    rg = geometry_of(document)[road_id]
    tol = Tolerances()
    s = rg.sample_s(index, chord=tol.chord, max_step=tol.max_step) if end > start else np.array([start])
    # The section's last point is evaluated just before its end: a profile record starting there (a laneOffset that
    # steps where the next section begins) is the next section's, not this one's.
    at = s.copy()
    if len(at) > 1:
        at[-1] = np.nextafter(at[-1], -np.inf)
    out = {}
    for side in rg.side_lanes(index):
        for lane in side.lanes:
            p = rg.lane_points(index, lane.id, at, "centre")
            z = np.broadcast_to(p.z, s.shape)
            if np.all(np.isfinite(p.x)) and np.all(np.isfinite(p.y)):
                out[lane.id] = CentreLine(s, np.asarray(p.x), np.asarray(p.y), np.array(z, dtype=float))
    return out


def node_lengths(document: Document, graph: LaneGraph) -> np.ndarray:
    """The length of each node's lane centre line over its lane section (m; 0 where it cannot be evaluated)."""
    return np.array([centre_line(document, n.road, n.index, n.lane).length for n in graph.nodes])
