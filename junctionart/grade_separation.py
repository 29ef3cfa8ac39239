"""Stage 1: crossings of two control-line edges kept as overpasses instead of split into a junction (issue 16).

A crossing is kept when the two edges meet at :data:`~junctionart.scenario.overpass.MIN_ANGLE` or more, one of them
(the upper road) reaches far enough on both sides of the crossing for a ramp, the junction at its end and half the
level deck, the other (the lower road) for its level stretch and the junction at its end, neither edge already
carries an overpass, and a draw is below ``overpass_probability``. The draw comes from a generator seeded with the
crossing point's coordinates, not from the map's random stream, so turning overpasses on changes no other choice and
a map without crossings (every automatic map) stays byte-identical. Before the lanes are drawn a road's width is
estimated (:data:`HALF_ESTIMATE`); stage 3 measures the laid roads again and turns an overpass whose ramps do not fit
back into a junction (:meth:`junctionart.intersections.state.NetworkState.at_grade`).
"""

from __future__ import annotations

import math

import numpy as np
from shapely import LineString, Point

from .params import Params
from .scenario.overpass import JUNCTION_ROOM, MIN_ANGLE, Crossing, ramp_length

#: A road's wider side (m) before its lanes are drawn: two lanes, kerb and sidewalk, a turn lane.
HALF_ESTIMATE = 12.0
#: Two points closer than this (m) are the same crossing.
SAME = 1e-6


def _direction(seg: LineString) -> np.ndarray:
    (x0, y0), (x1, y1) = seg.coords
    d = np.array([x1 - x0, y1 - y0])
    return d / max(float(np.hypot(*d)), 1e-12)


def _reach(seg: LineString, pt: Point) -> float:
    """Distance from ``pt`` to the nearer end of ``seg``."""
    (x0, y0), (x1, y1) = seg.coords
    return min(math.hypot(pt.x - x0, pt.y - y0), math.hypot(pt.x - x1, pt.y - y1))


class GradeSeparation:
    """The overpass decisions of one stage-1 run: crossing points kept (with the upper edge's direction) or
    refused."""

    def __init__(self, params: Params) -> None:
        self.probability = params.overpass_probability
        self.ramp = ramp_length(params.terrain)
        self.kept: list[tuple[float, float, np.ndarray]] = []
        self.refused: set[tuple[float, float]] = set()

    def is_kept(self, pt) -> bool:
        return pt.geom_type == "Point" and any(abs(pt.x - x) < SAME and abs(pt.y - y) < SAME for x, y, _ in self.kept)

    def _fits(self, upper: LineString, lower: LineString, pt: Point) -> bool:
        du, dl = _direction(upper), _direction(lower)
        sin = abs(float(du[0] * dl[1] - du[1] * dl[0]))
        if sin < math.sin(math.radians(MIN_ANGLE)):
            return False
        h_up, h_low = Crossing(0.0, 0.0, sin, float(du @ dl)).level(HALF_ESTIMATE, HALF_ESTIMATE)
        return _reach(upper, pt) >= self.ramp + JUNCTION_ROOM + h_up and _reach(lower, pt) >= JUNCTION_ROOM + h_low

    def _carries(self, seg: LineString) -> bool:
        return any(seg.distance(Point(x, y)) < SAME for x, y, _ in self.kept)

    def keep(self, a: LineString, b: LineString, pt: Point) -> bool:
        """Whether the crossing of edges ``a`` and ``b`` at ``pt`` becomes an overpass (decided once per point)."""
        if self.probability <= 0.0 or (pt.x, pt.y) in self.refused:
            return False
        upper = next(
            (u for u, v in sorted(((a, b), (b, a)), key=lambda p: -_reach(p[0], pt)) if self._fits(u, v, pt)), None
        )
        if upper is None or self._carries(a) or self._carries(b) or self._draw(pt) >= self.probability:
            self.refused.add((pt.x, pt.y))
            return False
        self.kept.append((pt.x, pt.y, _direction(upper)))
        return True

    @staticmethod
    def _draw(pt: Point) -> float:
        words = np.frombuffer(np.array([pt.x, pt.y], dtype=np.float64).tobytes(), dtype=np.uint32)
        return float(np.random.default_rng(words.tolist()).random())

    def _roles(self, k: int, geoms: list[LineString]) -> tuple[int, int] | None:
        """(upper, lower) indexes into ``geoms`` of the edges crossing at kept point ``k``."""
        x, y, d = self.kept[k]
        pt = Point(x, y)
        on = [i for i, g in enumerate(geoms) if g.distance(pt) < SAME]
        if len(on) != 2:
            return None
        dirs = [_direction(geoms[i]) for i in on]
        parallel = [abs(float(d[0] * e[1] - d[1] * e[0])) < 1e-9 for e in dirs]
        if parallel.count(True) != 1:
            return None
        return (on[0], on[1]) if parallel[0] else (on[1], on[0])

    def settle(self, nodes: list[tuple[float, float]], keys: list[tuple[int, int]]) -> bool:
        """Refuse every kept crossing that no longer fits the final edges ``keys`` (an edge split by another
        crossing); True when one was refused (stage 1 then planarizes again, splitting it)."""
        geoms = [LineString([nodes[a], nodes[b]]) for a, b in keys]
        changed = False
        for k in reversed(range(len(self.kept))):
            roles = self._roles(k, geoms)
            x, y, _ = self.kept[k]
            if roles is None or not self._fits(geoms[roles[0]], geoms[roles[1]], Point(x, y)):
                del self.kept[k]
                self.refused.add((x, y))
                changed = True
        return changed

    def pairs(self, nodes: list[tuple[float, float]], keys: list[tuple[int, int]]) -> tuple[tuple[int, int], ...]:
        """(upper, lower) indexes into ``keys`` of every overpass, in the order the crossings were kept."""
        geoms = [LineString([nodes[a], nodes[b]]) for a, b in keys]
        return tuple(r for k in range(len(self.kept)) if (r := self._roles(k, geoms)) is not None)
