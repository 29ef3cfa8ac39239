"""The editable network of stage 3: nodes, edges with lane configurations, and the repairs applied to them.

Every edit records which nodes it touched (``dirty``) so that one pass can apply several independent repairs, and a
line in ``repairs`` saying what was changed and why.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
import shapely

from ..graph import Chain
from ..lanes import LaneConfig


@dataclass
class NetworkState:
    """The network while the intersection stage grows, repairs and redraws it."""

    nodes: list[tuple[float, float]]
    edges: dict[int, tuple[int, int, LaneConfig]]
    factor: dict[int, float] = field(default_factory=dict)  #: random factor of each node's incident distances
    scale: dict[int, float] = field(default_factory=dict)  #: growth of each node's incident distances
    growth: dict[int, int] = field(default_factory=dict)  #: growth steps taken per node
    drawn: dict[tuple[int, int], tuple[bool, bool]] = field(default_factory=dict)  #: per leg: turn lane, split first
    repairs: list[str] = field(default_factory=list)
    dirty: set[int] = field(default_factory=set)
    #: (upper, lower) edges crossing as an overpass (:mod:`junctionart.grade_separation`)
    overpasses: set[tuple[int, int]] = field(default_factory=set)

    def degree(self) -> list[int]:
        deg = [0] * len(self.nodes)
        for u, v, _ in self.edges.values():
            deg[u] += 1
            deg[v] += 1
        return deg

    def connected_without(self, eid: int | set[int]) -> bool:
        """Whether the ends of edge ``eid`` (or of a chain given as a set of edges, first and last node) stay
        connected without it."""
        drop = {eid} if isinstance(eid, int) else set(eid)
        if isinstance(eid, int):
            u, v, _ = self.edges[eid]
        else:
            ends = [n for e in drop for n in self.edges[e][:2]]
            odd = sorted({n for n in ends if ends.count(n) == 1})
            if len(odd) != 2:
                return True  # a closed chain: removing it cannot disconnect the rest
            u, v = odd
        adj: dict[int, list[int]] = {}
        for k, (a, b, _) in self.edges.items():
            if k not in drop:
                adj.setdefault(a, []).append(b)
                adj.setdefault(b, []).append(a)
        seen, stack = {u}, [u]
        while stack:
            x = stack.pop()
            if x == v:
                return True
            for y in adj.get(x, ()):
                if y not in seen:
                    seen.add(y)
                    stack.append(y)
        return False

    def touched(self, nodes) -> bool:
        return not self.dirty.isdisjoint(nodes)

    def remove_edge(self, eid: int, why: str) -> None:
        u, v, _ = self.edges.pop(eid)
        self.dirty.update((u, v))
        self.repairs.append(why)

    def contract(self, eid: int, why: str) -> None:
        u, v, _ = self.edges.pop(eid)
        self.dirty.update((u, v))
        for a, b, _ in self.edges.values():
            if {a, b} & {u, v}:
                self.dirty.update((a, b))
        (x0, y0), (x1, y1) = self.nodes[u], self.nodes[v]
        self.nodes[u] = ((x0 + x1) / 2, (y0 + y1) / 2)
        seen: set[tuple[int, int]] = set()
        for k in sorted(self.edges):
            a, b, cfg = self.edges[k]
            a, b = (u if a == v else a), (u if b == v else b)
            key = (min(a, b), max(a, b))
            if a == b or key in seen:
                del self.edges[k]
                continue
            seen.add(key)
            self.edges[k] = (a, b, cfg)
        self.scale.pop(u, None)
        self.growth.pop(u, None)
        for k in [k for k in sorted(self.edges) if u in self.edges[k][:2]]:
            a, b, cfg = self.edges.pop(k)
            self.insert_planar(a, b, cfg)
        self.repairs.append(why)

    def smooth(self, chain: Chain, i: int, why: str) -> None:
        """Repair a bend at interior vertex ``chain.nodes[i]``: cut it open when the map stays connected (one side
        becomes a dead end), otherwise replace its two edges by one straight edge (split where it crosses others)."""
        a, v, b = chain.nodes[i - 1], chain.nodes[i], chain.nodes[i + 1]
        e1, e2 = chain.edges[i - 1], chain.edges[i]
        self.dirty.update((a, v, b))
        for e in (e2, e1):
            if self.connected_without(e):
                self.remove_edge(e, why + " (cut open)")
                return
        cfg = self.edges[e1][2] if chain.forward[i - 1] else self.edges[e1][2].reversed()  # oriented a -> v
        del self.edges[e1], self.edges[e2]
        exists = any({x, y} == {a, b} for x, y, _ in self.edges.values())
        if a != b and not exists:
            self.insert_planar(a, b, cfg)
        self.repairs.append(why + " (straightened)")

    def at_grade(self, pair: tuple[int, int], why: str) -> None:
        """Turn an overpass back into a crossing at grade: the upper edge is laid again, split with the lower one
        where they cross (a new intersection)."""
        self.overpasses.discard(pair)
        a, b, cfg = self.edges.pop(pair[0])
        self.insert_planar(a, b, cfg)
        self.repairs.append(why)

    def insert_planar(self, a: int, b: int, cfg: LaneConfig) -> None:
        """Add edge a-b; where it crosses an existing edge both are split at a new node (a new intersection)."""
        pa, pb = self.nodes[a], self.nodes[b]
        self.dirty.update((a, b))
        new = shapely.LineString([pa, pb])
        keys = [k for k in sorted(self.edges) if a not in self.edges[k][:2] and b not in self.edges[k][:2]]
        cuts = []
        if keys:
            nodes = np.asarray(self.nodes)
            ends = np.array([self.edges[k][:2] for k in keys])
            segs = shapely.linestrings(np.stack([nodes[ends[:, 0]], nodes[ends[:, 1]]], axis=1))
            for i in np.flatnonzero(shapely.crosses(new, segs)):
                pt = new.intersection(segs[i])
                if pt.geom_type == "Point":
                    cuts.append((math.hypot(pt.x - pa[0], pt.y - pa[1]), keys[i], (pt.x, pt.y)))
        prev = a
        next_id = max(self.edges, default=-1) + 1
        for _, k, xy in sorted(cuts):
            u, v, c = self.edges.pop(k)
            n = len(self.nodes)
            self.dirty.update((u, v, n))
            self.nodes.append((float(xy[0]), float(xy[1])))
            self.edges[k] = (u, n, c)
            self.edges[next_id] = (n, v, c)
            self.edges[next_id + 1] = (prev, n, cfg)
            next_id += 2
            prev = n
        self.edges[next_id] = (prev, b, cfg)
