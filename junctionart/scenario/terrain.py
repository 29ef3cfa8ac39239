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
import math

import numpy as np

from ..curves import end_pose
from ..intersections.model import Layout
from ..opendrive import Cubic, Document, Road
from ..params import Params, Terrain

#: (maximum grade, smallest vertical-curve radius in m) per terrain: 5 % and 1500 m rolling, 8 % and 600 m hilly,
#: the order of the limits for 50 km/h streets in common road-design guides (steeper only in mountains).
LIMITS = {Terrain.ROLLING: (0.05, 1500.0), Terrain.HILLY: (0.08, 600.0)}
#: Half the range (m) of the ground before the limits pull it flatter.
AMPLITUDE = {Terrain.ROLLING: 6.0, Terrain.HILLY: 20.0}
#: Range (m) of the ground waves' wavelengths.
WAVELENGTHS = (300.0, 900.0)
ITERATIONS = 200


def rise_bound(length: float, terrain: Terrain) -> float:
    """Largest height difference (m) between the ends of a road of ``length`` under ``terrain``'s limits."""
    grade, radius = LIMITS[terrain]
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
    amp = AMPLITUDE[terrain] / weight.sum()

    def z(x: float, y: float) -> float:
        arg = 2.0 * math.pi * (x * np.cos(theta) + y * np.sin(theta)) / lam + phase
        return float(amp * np.sum(weight * np.sin(arg)))

    return z


def node_heights(layout: Layout, params: Params, seed: int) -> dict[int, float]:
    """Height of every node that a road meets, within the limits on every road."""
    z_of = ground(np.random.default_rng([seed, 17]), params.terrain)
    z: dict[int, float] = {}
    for rp in layout.roads:
        start, end = rp.geometry[0], end_pose(rp.geometry[-1])
        z.setdefault(rp.start_node, z_of(start.x, start.y))
        z.setdefault(rp.end_node, z_of(end.x, end.y))
    roads = [(rp.start_node, rp.end_node, rise_bound(rp.length, params.terrain)) for rp in layout.roads]
    for _ in range(ITERATIONS):
        moved = False
        for a, b, bound in roads:
            d = z[b] - z[a]
            if abs(d) > bound:
                half = math.copysign((abs(d) - bound) / 2.0, d)
                z[a] += half
                z[b] -= half
                moved = True
        if not moved:
            break
    # what the iterations left (a tight cycle of short roads): scale every height toward the mean until all fit
    ratio = min((bound / abs(z[b] - z[a]) for a, b, bound in roads if z[b] != z[a]), default=1.0)
    if ratio < 1.0:
        mean = sum(z.values()) / len(z)
        z = {n: mean + (h - mean) * ratio * (1.0 - 1e-9) for n, h in z.items()}
    return z


def add_terrain(doc: Document, layout: Layout, params: Params, seed: int) -> Document:
    """``doc`` with elevation profiles: roads between their nodes' heights, junction roads flat at theirs."""
    z = node_heights(layout, params, seed)
    by_id = {str(rp.index + 1): rp for rp in layout.roads}
    junction_z = {j.id: z[jp.node] for j, jp in zip(doc.junctions, layout.junctions)}
    roads: list[Road] = []
    for road in doc.roads:
        rp = by_id.get(road.id) if road.junction == "-1" else None
        if rp is not None:
            elevation = profile(z[rp.start_node], z[rp.end_node], road.length)
        else:
            elevation = (Cubic(0.0, junction_z[road.junction]),)
        roads.append(dataclasses.replace(road, elevation=elevation))
    return dataclasses.replace(doc, roads=tuple(roads))
