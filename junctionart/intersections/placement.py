"""Where a junction's incident points go and the geometry of a road between two of them.

``incident_distances``: the distance of each leg's incident point from its control point. ``road_geometry``: a chain's
lines and fillet arcs between its two incident points, or why it does not fit (a bend too sharp, a road too short).
"""

from __future__ import annotations

import itertools
import math

import numpy as np
import shapely

from ..curves import fillet_chain, sample, unit_tangents, wrap
from ..lanegeom import min_curve_radius, side_width
from ..lanes import LaneConfig
from ..params import Params
from . import links as linkplan
from .legs import Leg, neighbour_gaps

MARGIN = 1.0  #: clearance between the stubs of neighbouring legs
#: Total turning (rad) of a road's bends beyond which its borders are tested for crossing themselves.
SELF_OVERLAP_TURN = 0.9 * math.pi


def _unit(a: tuple[float, float], b: tuple[float, float]) -> tuple[float, float, float]:
    dx, dy = b[0] - a[0], b[1] - a[1]
    L = math.hypot(dx, dy)
    return dx / L, dy / L, L


def incident_distances(L: list[Leg], plan: linkplan.LinkPlan, params: Params, scale: float) -> list[float]:
    """Distance of each leg's incident point from the control point: the paper's W / sin(d) rule with the legs'
    actual widths, room for a turn between neighbouring legs that ``plan`` links, times ``scale`` (the node's
    random factor and growth). Neighbours at a sharp angle that no lane links need only keep their stubs apart."""
    # lanes at the junction: a turn lane added before it widens the incoming side
    half = [
        max(
            side_width(max(l.n_in, plan.n_in_end[i]), l.median, params.lane_width, params.median_width),
            side_width(l.n_out, l.median, params.lane_width, params.median_width),
        )
        for i, l in enumerate(L)
    ]
    r = [h + params.min_turn_radius + 2.0 for h in half]
    turn_r = params.min_turn_radius + 1.0 + params.lane_width / 2
    linked = {frozenset((i, j)) for i, _, j, _ in plan.links}
    for d, a, b in neighbour_gaps(L):
        W = half[a] + half[b] + MARGIN
        need = W / max(math.sin(d), 1e-3) if d < math.pi / 2 else W
        if d < math.pi and frozenset((a, b)) in linked:
            # a kerb-side turn through the wedge: tangent points of a circle of radius turn_r fitted between
            # the two legs' outer lanes lie (offset + radius) / tan(d / 2) from the control point
            need = max(need, (max(half[a], half[b]) + turn_r) / max(math.tan(d / 2), 1e-3))
        r[a], r[b] = max(r[a], need), max(r[b], need)
    return [x * scale for x in r]


def road_geometry(
    P: list[tuple[float, float]],
    r0: float,
    r1: float,
    need: float,
    cfg: LaneConfig,
    ends: tuple[tuple[int, int], tuple[int, int]],
    params: Params,
):
    """Geometry of a chain through points ``P`` trimmed by r0 / r1, or ("vertex", i) / ("short", None) when it does
    not fit.
    ``ends``: the (forward, backward) lane counts at its start and end (tapers from ``cfg``'s counts)."""
    segs = [_unit(a, b) for a, b in itertools.pairwise(P)]
    if any(s[2] < 1e-6 for s in segs):
        return "short", None
    n = len(segs)
    avail = [s[2] for s in segs]
    avail[0] -= r0
    avail[-1] -= r1
    mid = (cfg.forward, cfg.backward)
    widest = max(side_width(n, cfg.median, params.lane_width, params.median_width) for n in (*mid, *ends[0], *ends[1]))
    # lane centres on the inside keep 3/4 of the curvature budget; a lane taper on the curve may use the rest
    r_min = min_curve_radius(params, widest, ends, mid)
    r_pref = max(r_min, 60.0)
    radii = []
    tangents = []
    turns = [0.0]  # turn at each interior vertex (index i), for the self-overlap test below
    for i in range(1, n):
        theta = abs(wrap(math.atan2(segs[i][1], segs[i][0]) - math.atan2(segs[i - 1][1], segs[i - 1][0])))
        turns.append(theta)
        share_l = avail[i - 1] / (2 if i - 1 > 0 else 1)
        share_r = avail[i] / (2 if i < n - 1 else 1)
        t_max = min(share_l, share_r) - 0.5
        if theta < 1e-9:  # collinear: no vertex, one line runs through
            radii.append(0.0)
            tangents.append(0.0)
            continue
        if t_max <= 0 or theta > math.radians(170):
            return "vertex", i
        R = min(r_pref, t_max / math.tan(theta / 2))
        if r_min > R:
            return "vertex", i
        radii.append(R)
        tangents.append(R * math.tan(theta / 2))
    if any(a <= 0 for a in avail) and n == 1:
        return "short", None
    straight = sum(avail) - 2 * sum(tangents)
    if straight < 0:
        return "short", None
    start = (P[0][0] + r0 * segs[0][0], P[0][1] + r0 * segs[0][1])
    end = (P[-1][0] - r1 * segs[-1][0], P[-1][1] - r1 * segs[-1][1])
    corners = [(v, r) for v, r in zip(P[1:-1], radii) if r > 0]
    geom = fillet_chain(start, [v for v, _ in corners], end, [r for _, r in corners])
    length = geom[-1].s + geom[-1].length
    if length < need:
        return "short", None
    if sum(turns) > SELF_OVERLAP_TURN and _folds(geom, widest):
        return "vertex", int(np.argmax(turns))
    return "ok", geom


def _folds(geom, offset: float) -> bool:
    """Whether a border ``offset`` to either side of the chain ``geom`` crosses itself: bends turning the road back
    on itself (two tight bends, 200 deg in all) put a lane over its own surface."""
    pts = np.concatenate([sample(e, max(4, int(e.length / 2.0) + 2))[:-1] for e in geom] + [sample(geom[-1], 2)[-1:]])
    tangent = unit_tangents(pts)
    normal = np.column_stack([-tangent[:, 1], tangent[:, 0]])
    borders = shapely.linestrings(np.stack([pts + offset * normal, pts - offset * normal]))
    return not bool(shapely.is_simple(borders).all())
