"""Overpasses (issue 16): where two roads cross without a junction, one passes over the other.

``overpass_probability`` turns a crossing of two control-line edges into an overpass instead of a junction (stage 1,
:mod:`junctionart.grade_separation`) when both roads are long enough: the upper road rises over ramps to a level deck
:data:`RISE` above the lower road's surface and comes down again; the lower road runs through at grade, level under
the deck. :data:`RISE` is the free height of 4.5 m (the minimum the issue asks for, and ``xodrcheck``'s
``Tolerances.clearance``) plus a 1.0 m deck (slab and surfacing of a short urban bridge). The ramps are the terrain's
cubic profiles, within its grade and vertical-curve limits (:data:`junctionart.scenario.terrain.LIMITS`); on flat
terrain within :data:`RAMP_LIMITS`.

This module holds the geometry both stage 3 (which removes an upper road too short for its ramps) and the terrain
step (which writes the profiles) measure: where two reference lines cross and how long the level stretches are.
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from dataclasses import dataclass

import numpy as np
import shapely

from ..curves import sample
from ..lanegeom import side_width
from ..opendrive import Geometry
from ..params import Params, Terrain
from .roadside import roadside_width

#: Height (m) of the upper road's surface above the lower road's: 4.5 m free height + 1.0 m deck.
RISE = 5.5
#: (maximum grade, smallest vertical-curve radius in m) of the ramps on flat terrain: 6 % and 1000 m, the order of
#: urban bridge approaches (the rolling and hilly terrains use their own, :data:`terrain.LIMITS`).
RAMP_LIMITS = (0.06, 1000.0)
#: Smallest angle (degrees) between two crossing roads that may become an overpass (a flatter crossing needs a long
#: deck); a flatter crossing stays a junction.
MIN_ANGLE = 40.0
#: Room (m) kept between a ramp's foot and the end of the control-line edge in stage 1: the junction at the edge's
#: end takes that much of the road (incident distance, lane tapers) before the road's own length starts.
JUNCTION_ROOM = 60.0
#: Extra length (m) of each level stretch beyond the other road's footprint.
MARGIN = 3.0
#: Smallest distance (m) between the lower road's level stretch and its ends (the junctions there).
LOWER_ROOM = 10.0
#: Widest road (m) one side of its reference line can be in stage 1 (3 lanes + median + roadside), used before the
#: lanes are known: the level stretch is at most this wide / sin(angle).
WIDEST_SIDE = 3 * 6.0 + 10.0 + 3.0


def limits(terrain: Terrain) -> tuple[float, float]:
    """(maximum grade, smallest vertical-curve radius) the ramps and every other road profile keep to."""
    from .terrain import LIMITS

    return LIMITS.get(terrain, RAMP_LIMITS)


def ramp_length(terrain: Terrain, rise: float = RISE) -> float:
    """Shortest ramp (m) climbing ``rise`` with the cubic profile within ``terrain``'s limits (its steepest grade
    1.5 rise / L, its sharpest curve 6 rise / L^2)."""
    grade, radius = limits(terrain)
    return max(1.5 * rise / grade, math.sqrt(6.0 * radius * rise))


def half_width(counts: Iterable[int], median: bool, params: Params) -> float:
    """The wider side (m) of a road with these lane counts on its sides, roadside and one turn lane included."""
    return side_width(max(counts) + 1, median, params.lane_width, params.median_width) + roadside_width(params)


@dataclass(frozen=True)
class Crossing:
    """Where two reference lines cross: s on each and the sine and cosine of the angle between them."""

    s_a: float
    s_b: float
    sin: float
    cos: float

    def level(self, half_a: float, half_b: float) -> tuple[float, float]:
        """Half-lengths of the level stretches on road a and road b that cover the other road's footprint."""
        sin, cot = max(self.sin, 1e-6), abs(self.cos) / max(self.sin, 1e-6)
        return half_b / sin + half_a * cot + MARGIN, half_a / sin + half_b * cot + MARGIN


def _polyline(geometry: tuple[Geometry, ...]) -> tuple[np.ndarray, np.ndarray]:
    """Points every <= 0.5 m along a reference line and their s."""
    pts, ss = [], []
    for g in geometry:
        n = max(2, int(g.length / 0.5) + 2)
        pts.append(sample(g, n))
        ss.append(g.s + np.linspace(0.0, g.length, n))
    return np.concatenate(pts), np.concatenate(ss)


def crossing(a: tuple[Geometry, ...], b: tuple[Geometry, ...]) -> Crossing | None:
    """The one point where reference lines ``a`` and ``b`` cross, or None (apart, touching or crossing twice)."""
    pa, sa = _polyline(a)
    pb, sb = _polyline(b)
    la, lb = shapely.LineString(pa), shapely.LineString(pb)
    hit = la.intersection(lb)
    if hit.geom_type != "Point":
        return None
    ta, tb = _tangent(pa, sa, la, hit), _tangent(pb, sb, lb, hit)
    cross = abs(ta[0] * tb[1] - ta[1] * tb[0])
    s_a = float(np.interp(la.project(hit), _chords(pa), sa))
    s_b = float(np.interp(lb.project(hit), _chords(pb), sb))
    return Crossing(s_a, s_b, float(cross), float(ta[0] * tb[0] + ta[1] * tb[1]))


def _chords(p: np.ndarray) -> np.ndarray:
    return np.concatenate([[0.0], np.cumsum(np.hypot(*np.diff(p, axis=0).T))])


def _tangent(p: np.ndarray, s: np.ndarray, line: shapely.LineString, at: shapely.Point) -> np.ndarray:
    k = int(np.clip(np.searchsorted(_chords(p), line.project(at)), 1, len(p) - 1))
    d = p[k] - p[k - 1]
    return d / max(float(np.hypot(*d)), 1e-12)


def fits(length_up: float, length_low: float, c: Crossing, half_up: float, half_low: float, params: Params) -> bool:
    """Whether the upper road (a of ``c``) has room for both ramps and the lower road (b) for its level stretch."""
    if c.sin < math.sin(math.radians(MIN_ANGLE)):
        return False
    h_up, h_low = c.level(half_up, half_low)
    ramp = ramp_length(params.terrain)
    return (
        c.s_a - h_up >= ramp
        and length_up - c.s_a - h_up >= ramp
        and c.s_b - h_low >= LOWER_ROOM
        and length_low - c.s_b - h_low >= LOWER_ROOM
    )
