"""Elevation (issue 16): ``terrain="rolling"`` or ``"hilly"`` lays the map on smooth ground.

The ground is a sum of three plane waves (wavelengths and directions drawn from the map's own random stream) of
amplitude :data:`AMPLITUDE`. Every node of the network (junction or dead end) takes the ground's height there, then
the heights are pulled together until each road between two nodes fits the road-design limits of its terrain
(:data:`LIMITS`): a road of length L rises by at most ``min(G L / 1.5, L^2 / (6 R))`` for maximum grade G and
smallest vertical-curve radius R. A road's profile is the cubic from its start node's height to its end node's with
zero grade at both ends (``z = z0 + dz (3 u^2 - 2 u^3)``, ``u = s / L``): its steepest grade is 1.5 dz / L at
mid-road, its sharpest vertical curve 6 dz / L^2 at the ends, so both limits hold. Junctions are planar: each is flat
at its node's height, so z and the grade (zero) are continuous at every link. Flat terrain writes the paper's profile.
"""

from __future__ import annotations

import dataclasses
import itertools
import math

import numpy as np

from ..curves import end_pose
from ..intersections.model import Layout
from ..opendrive import Bridge, Cubic, Document, Road
from ..params import Params, Terrain
from .ids import Ids
from .overpass import RAMP_LIMITS, RISE, Crossing, crossing, half_width

#: (maximum grade, smallest vertical-curve radius in m) per terrain: 5 % and 1500 m rolling, 8 % and 600 m hilly,
#: the order of the limits for 50 km/h streets in common road-design guides (steeper only in mountains).
LIMITS = {Terrain.ROLLING: (0.05, 1500.0), Terrain.HILLY: (0.08, 600.0)}
#: Half the range (m) of the ground before the limits pull it flatter.
AMPLITUDE = {Terrain.ROLLING: 6.0, Terrain.HILLY: 20.0}
#: Range (m) of the ground waves' wavelengths.
WAVELENGTHS = (300.0, 900.0)
ITERATIONS = 200


def rise_bound(length: float, terrain: Terrain) -> float:
    """Largest height difference (m) between the ends of a road of ``length`` under ``terrain``'s limits (on flat
    terrain the overpass ramps' limits, :data:`junctionart.scenario.overpass.RAMP_LIMITS`)."""
    grade, radius = LIMITS.get(terrain, RAMP_LIMITS)
    return min(grade * length / 1.5, length * length / (6.0 * radius))


def profile(z0: float, z1: float, length: float) -> tuple[Cubic, ...]:
    """The elevation record from ``z0`` at s = 0 to ``z1`` at s = ``length``, level at both ends."""
    dz = z1 - z0
    if length <= 0.0 or dz == 0.0:
        return (Cubic(0.0, z0),)
    return (Cubic(0.0, z0, 0.0, 3.0 * dz / length**2, -2.0 * dz / length**3),)


def ground(rng: np.random.Generator, terrain: Terrain):
    """The ground height function z(x, y) of one map."""
    lam = rng.uniform(*WAVELENGTHS, 3)
    theta = rng.uniform(0.0, 2.0 * math.pi, 3)
    phase = rng.uniform(0.0, 2.0 * math.pi, 3)
    weight = rng.uniform(0.5, 1.0, 3)
    amp = AMPLITUDE.get(terrain, 0.0) / weight.sum()

    def z(x: float, y: float) -> float:
        arg = 2.0 * math.pi * (x * np.cos(theta) + y * np.sin(theta)) / lam + phase
        return float(amp * np.sum(weight * np.sin(arg)))

    return z


#: A stretch of a road at one height variable: (variable, offset added to it, s where it starts, s where it ends).
#: Road ends are stretches of length 0 at their node; an overpass's crossing is a level stretch of both roads, the
#: upper one :data:`RISE` above the lower one.
Stretch = tuple[int, float, float, float]


def _crossings(layout: Layout, params: Params) -> list[tuple[int, int, Crossing]]:
    """(upper road index, lower road index, where they cross) of each overpass."""
    out = []
    for up, low in layout.overpasses:
        c = crossing(layout.roads[up].geometry, layout.roads[low].geometry)
        if c is not None:  # stage 3 kept only crossings it measured
            out.append((up, low, c))
    return out


def _stretches(layout: Layout, params: Params) -> dict[int, list[Stretch]]:
    """Each road's stretches in order of s: its start node, its overpass crossings, its end node."""
    out: dict[int, list[Stretch]] = {rp.index: [(rp.start_node, 0.0, 0.0, 0.0)] for rp in layout.roads}
    for k, (up, low, c) in enumerate(_crossings(layout, params)):
        ru, rl = layout.roads[up], layout.roads[low]
        h_up, h_low = c.level(_half(ru, params), _half(rl, params))
        out[up].append((-1 - k, RISE, c.s_a - h_up, c.s_a + h_up))
        out[low].append((-1 - k, 0.0, c.s_b - h_low, c.s_b + h_low))
    for rp in layout.roads:
        out[rp.index] = [*sorted(out[rp.index], key=lambda st: st[2]), (rp.end_node, 0.0, rp.length, rp.length)]
    return out


def _half(rp, params: Params) -> float:
    counts = (rp.lanes.forward, rp.lanes.backward, rp.fwd_start, rp.bwd_start, rp.fwd_end, rp.bwd_end)
    return half_width(counts, rp.lanes.median, params)


def node_heights(layout: Layout, params: Params, seed: int, stretches: dict[int, list[Stretch]] | None = None):
    """Height of every node that a road meets (and of every overpass crossing's lower road, keyed -1, -2, ...),
    within the limits on every road piece."""
    z_of = ground(np.random.default_rng([seed, 17]), params.terrain) if params.terrain is not Terrain.FLAT else _level
    z: dict[int, float] = {}
    for rp in layout.roads:
        start, end = rp.geometry[0], end_pose(rp.geometry[-1])
        z.setdefault(rp.start_node, z_of(start.x, start.y))
        z.setdefault(rp.end_node, z_of(end.x, end.y))
    if stretches is None:
        stretches = {
            rp.index: [(rp.start_node, 0.0, 0.0, 0.0), (rp.end_node, 0.0, rp.length, rp.length)] for rp in layout.roads
        }
    pieces: list[tuple[int, float, int, float, float]] = []  # (a, offset a, b, offset b, bound)
    for rp in layout.roads:
        st = stretches[rp.index]
        for (a, oa, _, s0), (b, ob, s1, _) in itertools.pairwise(st):
            if b < 0 and b not in z:  # a crossing starts where the ground is, on its lower road
                z[b] = z[rp.start_node] + (z[rp.end_node] - z[rp.start_node]) * s1 / rp.length
            pieces.append((a, oa, b, ob, rise_bound(s1 - s0, params.terrain)))
    crossings = any(n < 0 for n in z)
    for _ in range(ITERATIONS):
        moved = False
        for a, oa, b, ob, bound in pieces:
            d = (z[b] + ob) - (z[a] + oa)
            if abs(d) > bound:
                half = math.copysign((abs(d) - bound) / 2.0, d)
                z[a] += half
                z[b] -= half
                moved = True
        if not moved:
            return z
    if crossings:
        return _scaled(z, pieces)
    # what the iterations left (a tight cycle of short roads): scale every height toward the mean until all fit
    ratio = min((bound / abs(z[b] - z[a]) for a, _, b, _, bound in pieces if z[b] != z[a]), default=1.0)
    if ratio < 1.0:
        mean = sum(z.values()) / len(z)
        z = {n: mean + (h - mean) * ratio * (1.0 - 1e-9) for n, h in z.items()}
    return z


def _scaled(z: dict[int, float], pieces: list[tuple[int, float, int, float, float]]) -> dict[int, float]:
    """What the iterations left with overpasses: every height scaled toward the mean by the largest ratio r that fits
    every piece. A piece's rise at r is ``r (z_b - z_a) + (o_b - o_a)``: at r = 0 only the offsets are left, which stage
    3 made fit (a ramp climbs RISE in time), so each piece fits on an interval of r from 0 up."""
    ratio = 1.0
    for a, oa, b, ob, bound in pieces:
        d, o = z[b] - z[a], ob - oa
        if d != 0.0:
            ratio = min(ratio, max(0.0, (math.copysign(bound, d) - o) / d))
    mean = sum(z.values()) / len(z)
    return {n: mean + (h - mean) * ratio * (1.0 - 1e-9) for n, h in z.items()}


def _level(x: float, y: float) -> float:
    """The ground of flat terrain (overpasses only)."""
    return 0.0


def _road_profile(stretches: list[Stretch], z: dict[int, float], length: float) -> tuple[Cubic, ...]:
    """Cubic pieces between the stretches, level along each crossing."""
    if len(stretches) == 2:
        (a, _, _, _), (b, _, _, _) = stretches
        return profile(z[a], z[b], length)
    out: list[Cubic] = []
    for (a, oa, _, s0), (b, ob, s1, _) in itertools.pairwise(stretches):
        (piece,) = profile(z[a] + oa, z[b] + ob, s1 - s0)
        out.append(dataclasses.replace(piece, s=s0))
        if b < 0:
            out.append(Cubic(s1, z[b] + ob))
    return tuple(out)


def _bridges(stretches: dict[int, list[Stretch]], ids: Ids | None) -> dict[int, tuple[Bridge, ...]]:
    """A ``<bridge>`` along each overpass deck (the upper road's level stretch), named after the road below."""
    lower = {v: road for road, st in stretches.items() for v, off, _, _ in st if v < 0 and off == 0.0}
    out: dict[int, tuple[Bridge, ...]] = {}
    for road, st in stretches.items():
        decks = [(v, s0, s1) for v, off, s0, s1 in st if v < 0 and off > 0.0]
        out[road] = tuple(
            Bridge(ids.next() if ids else f"bridge{-v}", s0, s1 - s0, f"overpass over road {lower[v] + 1}")
            for v, s0, s1 in decks
        )
    return out


def add_terrain(doc: Document, layout: Layout, params: Params, seed: int, ids: Ids | None = None) -> Document:
    """``doc`` with elevation profiles: roads between their nodes' heights (over or under their overpasses, a
    ``<bridge>`` along each deck), junction roads flat at theirs."""
    stretches = _stretches(layout, params)
    bridges = _bridges(stretches, ids) if layout.overpasses else {}
    z = node_heights(layout, params, seed, stretches)
    by_id = {str(rp.index + 1): rp for rp in layout.roads}
    junction_z = {j.id: z[jp.node] for j, jp in zip(doc.junctions, layout.junctions)}
    roads: list[Road] = []
    for road in doc.roads:
        rp = by_id.get(road.id) if road.junction == "-1" else None
        if rp is not None:
            elevation = _road_profile(stretches[rp.index], z, road.length)
            if bridges.get(rp.index):
                road = dataclasses.replace(road, bridges=bridges[rp.index])
        else:
            elevation = (Cubic(0.0, junction_z[road.junction]),)
        roads.append(dataclasses.replace(road, elevation=elevation))
    return dataclasses.replace(doc, roads=tuple(roads))
