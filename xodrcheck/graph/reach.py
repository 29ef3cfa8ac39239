"""What the lane graph can reach, with :mod:`scipy.sparse.csgraph`.

* *Entries* are the nodes whose traffic comes in at an open edge of the map (a road end without a link), *exits* the
  nodes whose traffic leaves the map there.
* A *circuit* is a strongly connected part where traffic can go round: a link runs inside it (lanes joined only by
  lane changes are not one); the *main part* is the largest strongly connected part (ties: the first). The lanes a
  route *reaches* are those reachable from an entry or a circuit: only a lane nothing leads into, and what only it
  leads to, is not. The lanes a route *leaves* are those from which an exit or a circuit is reachable.
* A *trap* is a strongly connected part with a cycle that traffic enters from outside and never leaves: no edge leads
  out of it and it holds no exit (on a closed map the main part is the map, not a trap).
"""

from __future__ import annotations

import weakref
from collections.abc import Iterable, Sequence

import numpy as np
from scipy.sparse import csgraph, csr_matrix

from xodrcheck.classcache import dataclass
from xodrcheck.graph.build import LaneGraph
from xodrcheck.model import Document

__all__ = ["Reachability", "best_partial", "reachability", "reached", "shortest_from", "unwind"]


def matrix(graph: LaneGraph, weights: np.ndarray | None = None, reverse: bool = False) -> csr_matrix:
    """The graph as a sparse matrix: one entry per (source, target), the least weight of the edges joining them
    (1 without ``weights``); transposed with ``reverse``."""
    n = len(graph.nodes)
    w = np.ones(len(graph.source)) if weights is None else np.asarray(weights, dtype=float)
    src, dst = (graph.target, graph.source) if reverse else (graph.source, graph.target)
    order = np.lexsort((w, dst, src))
    src, dst, w = src[order], dst[order], w[order]
    first = np.ones(len(src), dtype=bool)
    first[1:] = (src[1:] != src[:-1]) | (dst[1:] != dst[:-1])
    return csr_matrix((w[first], (src[first], dst[first])), shape=(n, n))


def reached(graph: LaneGraph, sources: Iterable[int], reverse: bool = False) -> np.ndarray:
    """Which nodes a route from any of ``sources`` reaches (with ``reverse``: from which nodes one of them is
    reached), the sources included."""
    n = len(graph.nodes)
    out = np.zeros(n, dtype=bool)
    starts = np.fromiter(sources, dtype=np.int64)
    if not starts.size:
        return out
    src, dst = (graph.target, graph.source) if reverse else (graph.source, graph.target)
    # one search from an extra node joined to every source
    rows = np.concatenate([src, np.full(starts.size, n)])
    cols = np.concatenate([dst, starts])
    m = csr_matrix((np.ones(rows.size), (rows, cols)), shape=(n + 1, n + 1))
    order = csgraph.breadth_first_order(m, n, directed=True, return_predecessors=False)
    out[order[order < n]] = True
    return out


def shortest_from(graph: LaneGraph, weights: np.ndarray, start: int) -> tuple[np.ndarray, np.ndarray]:
    """Distances from ``start`` to every node (inf where none) and the predecessors of the shortest paths."""
    dist, pred = csgraph.dijkstra(matrix(graph, weights), directed=True, indices=start, return_predecessors=True)
    return dist, pred


def unwind(pred: np.ndarray, start: int, goal: int) -> list[int]:
    """The nodes of the shortest path from ``start`` to ``goal`` (which ``pred`` reaches)."""
    path = [goal]
    while path[-1] != start:
        path.append(int(pred[path[-1]]))
    return path[::-1]


@dataclass(frozen=True, eq=False)
class Reachability:
    """Strongly connected parts (``labels``, ``count``; ``main`` the label of the largest), entries, exits, which
    nodes a route reaches and leaves (boolean per node), and the traps (labels)."""

    labels: np.ndarray
    count: int
    main: int
    entries: tuple[int, ...]
    exits: tuple[int, ...]
    reached: np.ndarray
    leaves: np.ndarray
    traps: tuple[int, ...]

    def members(self, label: int) -> np.ndarray:
        return np.flatnonzero(self.labels == label)


_CACHE: weakref.WeakKeyDictionary[LaneGraph, Reachability] = weakref.WeakKeyDictionary()


def reachability(graph: LaneGraph) -> Reachability:
    """The reachability of ``graph`` (cached while the graph lives)."""
    found = _CACHE.get(graph)
    if found is None:
        found = _CACHE[graph] = _reachability(graph)
    return found


def _reachability(graph: LaneGraph) -> Reachability:
    n = len(graph.nodes)
    if n == 0:
        empty = np.zeros(0, dtype=bool)
        return Reachability(np.zeros(0, dtype=np.int64), 0, -1, (), (), empty, empty, ())
    count, labels = csgraph.connected_components(matrix(graph), directed=True, connection="strong")
    sizes = np.bincount(labels, minlength=count)
    main = int(np.argmax(sizes))
    entries = tuple(sorted(graph.starts_open))
    exits = tuple(i for i in range(n) if graph.ends_open(i))
    circuits = _circuits(graph, labels, count)
    core = np.flatnonzero(circuits[labels]).tolist()
    reached_ = reached(graph, [*entries, *core])
    leaves = reached(graph, [*exits, *core], reverse=True)
    traps = tuple(k for k in _traps(graph, labels, circuits, exits) if exits or k != main)
    return Reachability(labels, count, main, entries, exits, reached_, leaves, traps)


def _circuits(graph: LaneGraph, labels: np.ndarray, count: int) -> np.ndarray:
    """Which strongly connected parts are circuits: those a link edge runs inside (every edge inside such a part lies
    on a cycle). Lanes joined only by lane changes, back and forth beside each other, go round nothing."""
    a, b = labels[graph.source], labels[graph.target]
    out = np.zeros(count, dtype=bool)
    out[a[(a == b) & (graph.kind == 0)]] = True
    return out


def _traps(graph: LaneGraph, labels: np.ndarray, cyclic: np.ndarray, exits: Sequence[int]) -> tuple[int, ...]:
    count = len(cyclic)
    a, b = labels[graph.source], labels[graph.target]
    leaving = np.zeros(count, dtype=bool)
    leaving[a[a != b]] = True
    entered = np.zeros(count, dtype=bool)
    entered[b[a != b]] = True
    with_exit = np.zeros(count, dtype=bool)
    with_exit[labels[list(exits)]] = True
    return tuple(int(k) for k in np.flatnonzero(cyclic & entered & ~leaving & ~with_exit))


def best_partial(document: Document, graph: LaneGraph, start: int, goals: Sequence[int]) -> tuple[list[int], str]:
    """When no route leads from ``start`` to any of ``goals``: the path to the reachable node nearest the first
    goal (in plan view, lane centre to lane centre) and why the route stops there, in words."""
    from xodrcheck.graph.lengths import centre_line, node_lengths  # geometry only for the command line's answer

    weights = node_lengths(document, graph) + 1e-9
    dist, pred = shortest_from(graph, weights[graph.source], start)
    candidates = np.flatnonzero(np.isfinite(dist))
    goal = graph.nodes[goals[0]]
    target = centre_line(document, goal.road, goal.index, goal.lane)
    gap = np.full(len(candidates), np.inf)
    if len(target.x):
        for k, i in enumerate(candidates.tolist()):
            node = graph.nodes[i]
            line = centre_line(document, node.road, node.index, node.lane)
            if len(line.x):
                gap[k] = np.min(np.hypot(line.x[:, None] - target.x[None, :], line.y[:, None] - target.y[None, :]))
    best = int(candidates[int(np.argmin(gap))]) if np.isfinite(gap).any() else start
    path = unwind(pred, start, best)
    near = f", {float(np.min(gap)):.1f} m from the destination" if np.isfinite(gap).any() else ""
    return path, _why(graph, best, goals, len(candidates), near)


def _why(graph: LaneGraph, best: int, goals: Sequence[int], from_start: int, near: str) -> str:
    node = graph.nodes[best]
    stop = graph.stops.get(best)
    if stop is not None and not graph.out_edges(best).size:
        return f"the route gets nearest at {node.describe()}{near}, and stops there: {stop.why}"
    into = reached(graph, goals, reverse=True)
    goal = graph.nodes[goals[0]]
    if int(into.sum()) == len(set(goals)):
        return f"no lane leads into {goal.describe()}; the nearest the route gets is {node.describe()}{near}"
    return (
        f"the {from_start} lanes a route from the start reaches and the {int(into.sum())} lanes that lead to the "
        f"destination do not meet; the nearest the route gets is {node.describe()}{near}"
    )
