"""The network as one pass of stage 3 sees it: roads (chains of edges), node degrees and the legs of each junction.

Repairs change the network between passes, so chains and degrees are taken afresh at the start of each pass and stay
fixed during it (a repair marks the nodes it touched instead, see :class:`.state.NetworkState`). Lane configurations
are read from the state each time, because opening exits changes them within the pass.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ..graph import Chain, chains
from ..lanes import LaneConfig
from .legs import Leg, LegKey
from .state import NetworkState


@dataclass(frozen=True)
class Survey:
    """The network's roads (chains) and node degrees at the start of a pass."""

    state: NetworkState
    chains: list[Chain]  #: one per road, naming edges by their ids in ``state.edges``
    degree: list[int]  #: per node, at the start of the pass

    @classmethod
    def take(cls, st: NetworkState) -> Survey:
        """Chains and degrees of the current network, with every chain given one lane configuration."""
        ids = sorted(st.edges)
        found = chains(len(st.nodes), [st.edges[k][:2] for k in ids])
        view = cls(st, [Chain(c.nodes, tuple(ids[e] for e in c.edges), c.forward) for c in found], st.degree())
        view._normalise()
        return view

    def _normalise(self) -> None:
        """Give every chain its first edge's configuration (a road has one); break pure cycles, which have no
        junction to end at. A road with a dead end gets a lane each way (a one-way road could not be left), and a
        one-way road no median."""
        deg = self.degree
        for c, ch in enumerate(self.chains):
            if ch.start == ch.end and deg[ch.start] == 2:
                self.state.remove_edge(
                    ch.edges[0], f"removed a road forming a closed loop without junction at node {ch.start}"
                )
                continue
            cfg = self.lanes(c)
            if deg[ch.start] == 1 or deg[ch.end] == 1:
                cfg = LaneConfig(max(cfg.forward, 1), max(cfg.backward, 1), cfg.median)
            if not (cfg.forward and cfg.backward):
                cfg = LaneConfig(cfg.forward, cfg.backward, False)
            self.set_lanes(c, cfg)

    def lanes(self, c: int) -> LaneConfig:
        """The lane configuration of chain ``c``, oriented along the chain."""
        ch = self.chains[c]
        cfg = self.state.edges[ch.edges[0]][2]
        return cfg if ch.forward[0] else cfg.reversed()

    def set_lanes(self, c: int, cfg: LaneConfig) -> None:
        """Give every edge of chain ``c`` the configuration ``cfg`` (oriented along the chain)."""
        ch = self.chains[c]
        for e, fw in zip(ch.edges, ch.forward):
            u, v, _ = self.state.edges[e]
            self.state.edges[e] = (u, v, cfg if fw else cfg.reversed())

    def points(self, c: int) -> list[tuple[float, float]]:
        return [self.state.nodes[n] for n in self.chains[c].nodes]

    def is_junction(self, node: int) -> bool:
        return self.degree[node] >= 3

    def legs_at(self) -> dict[int, list[LegKey]]:
        """The legs of every junction (node of degree 3 or more), in chain order."""
        legs: dict[int, list[LegKey]] = {}
        for c, ch in enumerate(self.chains):
            if self.is_junction(ch.start):
                legs.setdefault(ch.start, []).append(LegKey(c, True))
            if self.is_junction(ch.end):
                legs.setdefault(ch.end, []).append(LegKey(c, False))
        return legs

    def leg_edge(self, key: LegKey) -> int:
        """The edge by which leg ``key`` meets its junction."""
        ch = self.chains[key.chain]
        return ch.edges[0] if key.at_start else ch.edges[-1]

    def leg(self, key: LegKey) -> Leg:
        """Heading and lane counts of a leg as seen from its junction."""
        ch, cfg = self.chains[key.chain], self.lanes(key.chain)
        nodes = self.state.nodes
        if key.at_start:
            node, a, b = ch.nodes[0], nodes[ch.nodes[0]], nodes[ch.nodes[1]]
            n_in, n_out = cfg.backward, cfg.forward
        else:
            node, a, b = ch.nodes[-1], nodes[ch.nodes[-1]], nodes[ch.nodes[-2]]
            n_in, n_out = cfg.forward, cfg.backward
        angle = math.atan2(b[1] - a[1], b[0] - a[0])
        return Leg((node, self.leg_edge(key)), angle, n_in, n_out, cfg.median, key.chain)

    def drop_leg(self, node: int, keys: list[LegKey], prefer: list[int], why: str) -> None:
        """Remove the edge of one leg at ``node``: the first of ``prefer`` (indexes into ``keys``) whose removal keeps
        the map connected, else the first (the map then loses what lies behind it; repairs never discard a map)."""
        edges = [e for e in (self.leg_edge(keys[i]) for i in prefer) if e in self.state.edges]
        if not edges:
            return
        for e in edges:
            if self.state.connected_without(e):
                self.state.remove_edge(e, why)
                return
        self.state.remove_edge(edges[0], why + " (the map loses the part behind it)")
