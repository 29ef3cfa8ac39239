"""Stage 2: lane configuration of every road (a chain of edges between junctions or dead ends).

Counts are per travel direction along the chain: ``forward`` lanes travel from its first node to its last,
``backward`` lanes the other way; 0 to 3 each, never 0 both. A median lane is added to some two-way roads. One-way
roads that would leave part of the network without a way in or out get a lane back (:func:`both_ways_where_needed`).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .controllines import ControlLines
from .errors import GenerationError
from .graph import Chain, chains
from .network import Network
from .params import Params


@dataclass(frozen=True)
class LaneConfig:
    """The lanes of a road: forward and backward counts, and whether a median separates them."""

    forward: int
    backward: int
    median: bool = False

    def reversed(self) -> LaneConfig:
        return LaneConfig(self.backward, self.forward, self.median)


@dataclass(frozen=True)
class LanedNetwork:
    """The road network with a lane configuration for each edge."""

    network: Network
    lanes: tuple[LaneConfig, ...]  #: per edge, oriented from edge.u to edge.v


def _draw(rng: np.random.Generator, dist: tuple[float, ...]) -> tuple[int, int]:
    for _ in range(50):
        a, b = (int(x) for x in rng.choice(4, size=2, p=np.asarray(dist) / sum(dist)))
        if a or b:
            return a, b
    return 1, 1


def _reached(arcs: list[tuple[int, int]], root: int) -> set[int]:
    """The nodes reachable from ``root`` along the directed ``arcs``."""
    out: dict[int, list[int]] = {}
    for a, b in arcs:
        out.setdefault(a, []).append(b)
    seen, stack = {root}, [root]
    while stack:
        for b in out.get(stack.pop(), ()):
            if b not in seen:
                seen.add(b)
                stack.append(b)
    return seen


def both_ways_where_needed(drawn: list[tuple[Chain, LaneConfig]], deg: list[int]) -> list[tuple[Chain, LaneConfig]]:
    """The drawn configurations, with one-way roads made two-way (one lane back, no median) until every node can
    reach every other one through the roads' directions, the map's open ends (nodes of degree 1, where traffic enters
    and leaves) joined through the outside: random one-way roads may otherwise lead traffic into a part it never
    leaves (a one-way loop fed by a one-way road). Roads are repaired in order, each one touching a node that cannot
    be reached or cannot get out; a map that is connected already keeps every draw."""
    configs = [cfg for _, cfg in drawn]
    nodes = sorted({n for ch, _ in drawn for n in (ch.start, ch.end)})
    outside = -1
    open_ends = [n for n in nodes if deg[n] == 1]
    root = outside if open_ends else (nodes[0] if nodes else outside)
    while True:
        arcs = [(outside, n) for n in open_ends] + [(n, outside) for n in open_ends]
        for (ch, _), cfg in zip(drawn, configs):
            if cfg.forward:
                arcs.append((ch.start, ch.end))
            if cfg.backward:
                arcs.append((ch.end, ch.start))
        there = _reached(arcs, root)
        back = _reached([(b, a) for a, b in arcs], root)
        stuck = {n for n in nodes if n not in there or n not in back}
        if not stuck:
            return [(ch, cfg) for (ch, _), cfg in zip(drawn, configs)]
        k = next(
            (
                k
                for k, ((ch, _), cfg) in enumerate(zip(drawn, configs))
                if not (cfg.forward and cfg.backward) and (ch.start in stuck or ch.end in stuck)
            ),
            None,
        )
        if k is None:  # every road is two-way already: the network itself is in pieces (never for a generated map)
            return [(ch, cfg) for (ch, _), cfg in zip(drawn, configs)]
        cfg = configs[k]
        configs[k] = LaneConfig(max(cfg.forward, 1), max(cfg.backward, 1), False)


def assign(net: Network, lines: ControlLines, params: Params, rng: np.random.Generator) -> LanedNetwork:
    """Draw one configuration per chain and give it to every edge of the chain."""
    deg = net.degree()
    lanes: list[LaneConfig | None] = [None] * len(net.edges)
    drawn: list[tuple[Chain, LaneConfig]] = []
    for ch in chains(len(net.nodes), [(e.u, e.v) for e in net.edges]):
        fixed = [
            (e, fw)
            for e, fw in zip(ch.edges, ch.forward)
            if net.edges[e].line >= 0 and lines.lines[net.edges[e].line].lanes is not None
        ]
        on_line = any(net.edges[e].line >= 0 for e in ch.edges)
        if not params.randomize_lanes:
            fwd, bwd = 1, 1
        elif fixed:
            e, fw = fixed[0]
            line = lines.lines[net.edges[e].line]
            if line.lanes is None:  # never: fixed holds the edges of lines with given lane counts
                raise GenerationError(f"control line {net.edges[e].line} has no lane counts; please report the seed")
            fwd, bwd = line.lanes
            # the line's direction is along its points; the chain may run the other way over this edge
            edge = net.edges[e]
            a, b = (edge.u, edge.v) if fw else (edge.v, edge.u)
            ta, tb = line.project(net.nodes[a]), line.project(net.nodes[b])
            if tb < ta:
                fwd, bwd = bwd, fwd
        else:
            fwd, bwd = _draw(rng, params.lane_distribution_control_lines if on_line else params.lane_distribution_side)
        if deg[ch.start] == 1 or deg[ch.end] == 1:  # a dead end must let traffic turn back out
            fwd, bwd = max(fwd, 1), max(bwd, 1)
        median = bool(fwd and bwd and rng.random() < params.median_probability)
        drawn.append((ch, LaneConfig(fwd, bwd, median)))
    for ch, cfg in both_ways_where_needed(drawn, deg):
        for e, fw in zip(ch.edges, ch.forward):
            lanes[e] = cfg if fw else cfg.reversed()
    configs = tuple(c for c in lanes if c is not None)
    if len(configs) != len(lanes):  # never: the chains cover every edge
        raise GenerationError("an edge of the network is in no chain; please report the seed")
    return LanedNetwork(net, configs)
