"""Chains of a road graph: maximal paths through nodes of degree 2 (each chain becomes one road)."""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass


@dataclass(frozen=True)
class Chain:
    """A path through the network graph between two nodes that are not plain pass-throughs: one road."""

    nodes: tuple[int, ...]  #: the path, end nodes included
    edges: tuple[int, ...]  #: edge indexes along the path
    forward: tuple[bool, ...]  #: True where the path runs the edge from u to v

    @property
    def start(self) -> int:
        return self.nodes[0]

    @property
    def end(self) -> int:
        return self.nodes[-1]


def chains(n_nodes: int, edges: Sequence[tuple[int, int]]) -> list[Chain]:
    """Chains in a deterministic order; a cycle of degree-2 nodes starts at its lowest node."""
    adj: list[list[int]] = [[] for _ in range(n_nodes)]
    for k, (u, v) in enumerate(edges):
        adj[u].append(k)
        adj[v].append(k)
    seen = [False] * len(edges)
    out: list[Chain] = []

    def walk(start: int, first: int) -> Chain:
        nodes, es, fw = [start], [], []
        at, e = start, first
        while True:
            seen[e] = True
            u, v = edges[e]
            nxt = v if u == at else u
            es.append(e)
            fw.append(u == at)
            nodes.append(nxt)
            at = nxt
            if len(adj[at]) != 2 or at == start:
                break
            e = adj[at][0] if adj[at][0] != e else adj[at][1]
            if seen[e]:
                break
        return Chain(tuple(nodes), tuple(es), tuple(fw))

    for n in range(n_nodes):
        if len(adj[n]) != 2:
            for e in sorted(adj[n]):
                if not seen[e]:
                    out.append(walk(n, e))
    for e in range(len(edges)):  # pure cycles
        if not seen[e]:
            out.append(walk(min(edges[e]), e))
    return out
