"""Shortest paths on the lane graph with :mod:`scipy.sparse.csgraph`, and where a route that finds no way stops."""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from xodrcheck.graph.build import LaneGraph, matrix
from xodrcheck.graph.reach import reached
from xodrcheck.model import Document

__all__ = ["best_partial", "shortest_from", "unwind"]


def shortest_from(graph: LaneGraph, weights: np.ndarray, start: int) -> tuple[np.ndarray, np.ndarray]:
    """Distances from ``start`` to every node (inf where none) and the predecessors of the shortest paths; the
    weights must be positive."""
    from scipy.sparse import csgraph

    dist, pred = csgraph.dijkstra(matrix(graph, weights), directed=True, indices=start, return_predecessors=True)
    return dist, pred


def unwind(pred: np.ndarray, start: int, goal: int) -> list[int]:
    """The nodes of the shortest path from ``start`` to ``goal`` (which ``pred`` reaches)."""
    path = [goal]
    while path[-1] != start:
        path.append(int(pred[path[-1]]))
    return path[::-1]


def best_partial(document: Document, graph: LaneGraph, start: int, goals: Sequence[int]) -> tuple[list[int], str]:
    """When no route leads from ``start`` to any of ``goals``: the path to the reachable node nearest the first
    goal (in plan view, lane centre to lane centre) and why the route stops there, in words."""
    from xodrcheck.graph.lengths import centre_line, node_lengths

    weights = node_lengths(document, graph) + 1e-9
    dist, pred = shortest_from(graph, weights[graph.source], start)
    candidates = np.flatnonzero(np.isfinite(dist))
    goal = graph.nodes[goals[0]]
    target = centre_line(document, goal.road, goal.index, goal.lane)
    gap = np.full(len(candidates), np.inf)
    if len(target.x):
        for k, i in enumerate(candidates.tolist()):  # each line's ends and middle against the destination's line
            node = graph.nodes[i]
            line = centre_line(document, node.road, node.index, node.lane)
            if len(line.x):
                pick = [0, len(line.x) // 2, -1]
                dx, dy = line.x[pick][:, None] - target.x[None, :], line.y[pick][:, None] - target.y[None, :]
                gap[k] = np.min(np.hypot(dx, dy))
    best = int(candidates[int(np.argmin(gap))]) if np.isfinite(gap).any() else start
    near = f", {float(np.min(gap)):.1f} m from the destination" if np.isfinite(gap).any() else ""
    return unwind(pred, start, best), _why(graph, best, goals, len(candidates), near)


def _why(graph: LaneGraph, best: int, goals: Sequence[int], from_start: int, near: str) -> str:
    node = graph.nodes[best]
    stop = graph.stops.get(best)
    if stop is not None and not np.any(graph.source == best):
        return f"the route gets nearest at {node.describe()}{near}, and stops there: {stop.why}"
    into = reached(graph, goals, reverse=True)
    goal = graph.nodes[goals[0]]
    if int(into.sum()) == len(set(goals)):
        return f"no lane leads into {goal.describe()}; the nearest the route gets is {node.describe()}{near}"
    return (
        f"the {from_start} lanes a route from the start reaches and the {int(into.sum())} lanes that lead to the "
        f"destination do not meet; the nearest the route gets is {node.describe()}{near}"
    )
