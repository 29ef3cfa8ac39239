"""Stage 1: control points by the Markov decision process, connections, a connected planar graph.

The result is a plain value: nodes are control points (positions), edges are future roads. All randomness comes from
the one ``numpy.random.Generator`` passed in, consumed in a fixed order, so a seed reproduces the graph exactly.
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass

import numpy as np
from shapely import LineString, STRtree

from .controllines import ControlLine, ControlLines, RoundaboutRequest
from .grade_separation import GradeSeparation
from .params import Params

MERGE_DISTANCE = 5.0  #: control points of different lines closer than this become one node


@dataclass(frozen=True)
class Edge:
    """An edge of the road network: from node u to node v, along a control line or joining two."""

    u: int
    v: int
    line: int = -1  #: index of the control line the edge runs along, -1 for a connection between lines


@dataclass(frozen=True)
class Network:
    """The road network as a graph: node positions and edges."""

    nodes: tuple[tuple[float, float], ...]
    edges: tuple[Edge, ...]
    #: (upper, lower) edge indexes of each crossing kept as an overpass (:mod:`junctionart.grade_separation`)
    overpasses: tuple[tuple[int, int], ...] = ()
    #: roundabouts the control-line file asks for (stage 3 gives each to the junction nearest to it)
    roundabouts: tuple[RoundaboutRequest, ...] = ()

    def degree(self) -> list[int]:
        deg = [0] * len(self.nodes)
        for e in self.edges:
            deg[e.u] += 1
            deg[e.v] += 1
        return deg


class _Builder:
    """Mutable helper while stage 1 runs; frozen into a :class:`Network` at the end."""

    def __init__(self) -> None:
        self.nodes: list[tuple[float, float]] = []
        self.edges: dict[tuple[int, int], int] = {}  # (min, max) -> line

    def node(self, xy: tuple[float, float]) -> int:
        self.nodes.append((float(xy[0]), float(xy[1])))
        return len(self.nodes) - 1

    def edge(self, a: int, b: int, line: int = -1) -> None:
        if a == b:
            return
        key = (min(a, b), max(a, b))
        if key not in self.edges or self.edges[key] == -1:
            self.edges[key] = line if key not in self.edges else max(line, self.edges[key])


class _LinePoints:
    """Control points on one control line, by arc length, with snapping."""

    def __init__(self, line: ControlLine, builder: _Builder, shared: dict[tuple[float, float], int]) -> None:
        self.line = line
        self.b = builder
        self.points: list[tuple[float, int]] = []
        for a, xy in zip(line.cumulative(), line.points):
            key = (round(xy[0], 6), round(xy[1], 6))
            if key not in shared:
                shared[key] = builder.node(xy)
            self.points.append((float(a), shared[key]))

    def at(self, a: float, snap: float) -> tuple[float, int]:
        """The control point at arc length ``a``: an existing one within ``snap``, else a new one."""
        best = min(self.points, key=lambda p: abs(p[0] - a))
        if abs(best[0] - a) < snap:
            return best
        p = (a, self.b.node(self.line.point_at(a)))
        self.points.append(p)
        return p


def _choose(rng: np.random.Generator, row: tuple[tuple[str, float], ...]) -> str:
    names = [n for n, _ in row]
    probs = np.array([p for _, p in row])
    return names[int(rng.choice(len(names), p=probs / probs.sum()))]


def _mdp_pair(A: _LinePoints, B: _LinePoints, params: Params, rng: np.random.Generator, builder: _Builder) -> None:
    """Connections between the lines of one pair, the next section's shape chosen by the MDP."""
    table = dict(params.transitions)
    la, lb = A.line.length, B.line.length
    da = np.subtract(A.line.points[-1], A.line.points[0])
    db = np.subtract(B.line.points[-1], B.line.points[0])
    flip = float(np.dot(da, db)) < 0  # walk B in the direction of A

    def b_at(b: float) -> float:
        return lb - b if flip else b

    def proj(a: float) -> float:
        return b_at(B.line.project(A.line.point_at(a)))

    state = "start"
    last: tuple[float, float] | None = None  # where the previous connection meets A and B
    snap = params.snap_distance
    for _ in range(10_000):
        gap = rng.uniform(params.min_distance, params.max_distance) * rng.uniform(*params.gap_scale)
        state = _choose(rng, table[state])
        if last is None:
            a = rng.uniform(0.0, 0.5 * gap)
            b = proj(a) if state == "orthogonal" else rng.uniform(0.0, 0.5 * gap)
        else:
            a_last, b_last = last
            if state == "orthogonal":
                a = a_last + gap
                b = proj(a)
            elif state == "parallel":
                a, b = a_last + gap, b_last + gap
            elif state == "random":
                a, b = a_last + gap * rng.uniform(0.5, 1.5), b_last + gap * rng.uniform(0.5, 1.5)
            elif rng.random() < 0.5:  # commonEnd: a triangle, one line reuses its last point
                a, b = a_last + gap, b_last
            else:
                a, b = a_last, b_last + gap
        if a > la + snap / 2 or b > lb + snap / 2:
            break
        pa = A.at(min(a, la), snap)
        pb = B.at(b_at(min(b, lb)), snap)
        ba = b_at(pb[0])
        if last is not None and (pa[0] < last[0] or ba < last[1]):
            continue  # snapping would cross the previous connection
        if pa[1] != pb[1]:
            builder.edge(pa[1], pb[1])
        last = (pa[0], ba)


def _merge_close(nodes: list[tuple[float, float]], edges: dict[tuple[int, int], int]) -> dict[tuple[int, int], int]:
    """Merge nodes closer than MERGE_DISTANCE (union into the lowest index)."""
    pts = np.asarray(nodes)
    order = np.lexsort((pts[:, 1], pts[:, 0]))
    parent = list(range(len(nodes)))

    def find(i: int) -> int:
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i

    xs = pts[order, 0]
    for k, i in enumerate(order):
        j = k + 1
        while j < len(order) and xs[j] - xs[k] < MERGE_DISTANCE:
            o = order[j]
            if math.hypot(*(pts[i] - pts[o])) < MERGE_DISTANCE:
                ri, ro = find(int(i)), find(int(o))
                if ri != ro:
                    parent[max(ri, ro)] = min(ri, ro)
            j += 1
    out: dict[tuple[int, int], int] = {}
    for (a, b), line in edges.items():
        ra, rb = find(a), find(b)
        if ra != rb:
            key = (min(ra, rb), max(ra, rb))
            out[key] = max(out.get(key, -1), line)
    return out


def _planarize(
    nodes: list[tuple[float, float]], edges: dict[tuple[int, int], int], grade: GradeSeparation | None = None
) -> dict[tuple[int, int], int]:
    """Split crossing edges at their crossing point (a new node), until no two edges cross, except where ``grade``
    keeps the crossing as an overpass."""
    for _ in range(50):
        keys = sorted(edges)
        geoms = [LineString([nodes[a], nodes[b]]) for a, b in keys]
        tree = STRtree(geoms)
        left, right = tree.query(geoms, predicate="crosses")
        pairs = sorted({(int(i), int(j)) for i, j in zip(left, right) if i < j})
        if grade is not None and grade.probability > 0.0:
            pairs = [(i, j) for i, j in pairs if not _overpass(grade, geoms[i], geoms[j])]
        if not pairs:
            return edges
        used: set[int] = set()
        for i, j in pairs:
            if i in used or j in used:
                continue
            inter = geoms[i].intersection(geoms[j])
            if inter.geom_type != "Point":
                continue
            used.update((i, j))
            n = len(nodes)
            nodes.append((float(inter.x), float(inter.y)))
            for k in (i, j):
                a, b = keys[k]
                line = edges.pop((a, b))
                edges[(min(a, n), max(a, n))] = line
                edges[(min(b, n), max(b, n))] = line
        edges = _merge_close(nodes, edges)
    return edges


def _overpass(grade: GradeSeparation, a: LineString, b: LineString) -> bool:
    """Whether the crossing of ``a`` and ``b`` is (or now becomes) an overpass."""
    inter = a.intersection(b)
    return inter.geom_type == "Point" and (grade.is_kept(inter) or grade.keep(a, b, inter))


def _split_at_nodes(nodes: list[tuple[float, float]], edges: dict[tuple[int, int], int]) -> dict[tuple[int, int], int]:
    """A node lying on (or within MERGE_DISTANCE of) another edge's interior splits that edge: overlapping and
    touching roads become roads meeting at a junction."""
    from shapely import points as shp_points

    for _ in range(50):
        keys = sorted(edges)
        geoms = [LineString([nodes[a], nodes[b]]) for a, b in keys]
        tree = STRtree(geoms)
        used = sorted({n for k in keys for n in k})
        pts = shp_points(np.asarray([nodes[n] for n in used]))
        pi, ei = tree.query(pts, predicate="dwithin", distance=MERGE_DISTANCE)
        hits = sorted({(keys[int(e)], used[int(p)]) for p, e in zip(pi, ei) if used[int(p)] not in keys[int(e)]})
        if not hits:
            return edges
        done: set[tuple[int, int]] = set()
        for (a, b), n in hits:
            if (a, b) in done or (a, b) not in edges:
                continue
            done.add((a, b))
            line = edges.pop((a, b))
            for x in (a, b):
                key = (min(x, n), max(x, n))
                edges[key] = max(line, edges.get(key, -1))
    return edges


def _components(n: int, edges: dict[tuple[int, int], int]) -> list[list[int]]:
    adj: dict[int, list[int]] = {}
    for a, b in edges:
        adj.setdefault(a, []).append(b)
        adj.setdefault(b, []).append(a)
    seen: set[int] = set()
    comps = []
    for start in sorted(adj):
        if start in seen:
            continue
        stack, comp = [start], []
        seen.add(start)
        while stack:
            x = stack.pop()
            comp.append(x)
            for y in adj[x]:
                if y not in seen:
                    seen.add(y)
                    stack.append(y)
        comps.append(sorted(comp))
    comps.sort(key=lambda c: (-len(c), c[0]))
    return comps


def _connect(nodes: list[tuple[float, float]], edges: dict[tuple[int, int], int], ends: set[int]) -> None:
    """Join components: the nearest pair of line-end nodes (or any nodes) between the main part and the rest."""
    while True:
        comps = _components(len(nodes), edges)
        if len(comps) <= 1:
            return
        main = set(comps[0])
        best = None
        for comp in comps[1:]:
            cand_a = [i for i in comp if i in ends] or comp
            cand_b = [i for i in main if i in ends] or sorted(main)
            pa = np.asarray([nodes[i] for i in cand_a])
            pb = np.asarray([nodes[i] for i in cand_b])
            d = np.hypot(pa[:, None, 0] - pb[None, :, 0], pa[:, None, 1] - pb[None, :, 1])
            k = np.unravel_index(int(np.argmin(d)), d.shape)
            if best is None or d[k] < best[0]:
                best = (float(d[k]), cand_a[k[0]], cand_b[k[1]])
        assert best is not None
        a, b = best[1], best[2]
        edges[(min(a, b), max(a, b))] = -1


def _bend(
    nodes: list[tuple[float, float]], edges: dict[tuple[int, int], int], params: Params, rng: np.random.Generator
) -> dict[tuple[int, int], int]:
    """Curved roads: long connections get an extra vertex moved sideways (a fillet arc later)."""
    out: dict[tuple[int, int], int] = {}
    for a, b in sorted(edges):
        line = edges[(a, b)]
        (x0, y0), (x1, y1) = nodes[a], nodes[b]
        L = math.hypot(x1 - x0, y1 - y0)
        if line == -1 and L > 150.0 and rng.random() < params.curve_probability:
            off = rng.uniform(-0.12, 0.12) * L
            nx, ny = -(y1 - y0) / L, (x1 - x0) / L
            m = len(nodes)
            nodes.append(((x0 + x1) / 2 + off * nx, (y0 + y1) / 2 + off * ny))
            out[(a, m)] = line
            out[(b, m)] = line
        else:
            out[(a, b)] = line
    return out


def build(lines: ControlLines, params: Params, rng: np.random.Generator) -> Network:
    """Stage 1: control points and connections for every pair, roads along every line, groups joined."""
    builder = _Builder()
    shared: dict[tuple[float, float], int] = {}
    on_line = [_LinePoints(ln, builder, shared) for ln in lines.lines]
    for i, j in lines.pairs:
        _mdp_pair(on_line[i], on_line[j], params, rng, builder)
    for k, lp in enumerate(on_line):
        pts = sorted(lp.points)
        for (_, a), (_, b) in itertools.pairwise(pts):
            builder.edge(a, b, k)
    nodes = builder.nodes
    ends = {lp.points[0][1] for lp in on_line} | {lp.points[len(lp.line.points) - 1][1] for lp in on_line}
    edges = _merge_close(nodes, builder.edges)
    if params.curved_roads:
        edges = _bend(nodes, edges, params, rng)
    grade = GradeSeparation(params)
    edges = _split_at_nodes(nodes, _planarize(nodes, edges, grade))
    _connect(nodes, edges, ends)
    edges = _split_at_nodes(nodes, _planarize(nodes, edges, grade))
    while grade.kept and grade.settle(nodes, sorted(edges)):  # an overpass edge was split: refuse it, split it
        edges = _split_at_nodes(nodes, _planarize(nodes, edges, grade))
    # Renumber: only nodes that carry an edge, in first-use order of the sorted edge list.
    used: dict[int, int] = {}
    for a, b in sorted(edges):
        for x in (a, b):
            if x not in used:
                used[x] = len(used)
    new_nodes = tuple(nodes[old] for old in used)  # used numbers the nodes in insertion order
    out_edges = tuple(Edge(used[a], used[b], edges[(a, b)]) for a, b in sorted(edges))
    overpasses = grade.pairs(nodes, sorted(edges)) if grade.kept else ()
    return Network(new_nodes, out_edges, overpasses, lines.roundabouts)
