"""What the lane graph can reach.

* *Entries* are the nodes whose traffic comes in at an open edge of the map (a road end without a link), *exits* the
  nodes whose traffic leaves the map there.
* A lane is *entered* when it is an entry, a link leads into it, or traffic can change into it from a lane that is.
  A lane that is not is where a stretch no route reaches begins (:func:`unentered`); everything past it is reached
  only through it.
* A lane *goes on* when it is an exit, a link leads on from it, or traffic can change from it into a lane that does
  (:func:`goes_on`); one that does not is a dead end.
* A *trap* is a strongly connected part with a cycle of links that traffic enters from outside and never leaves: no
  edge leads out of it and it holds no exit (on a closed map, without entries or exits, the largest part is the map,
  not a trap).

A check runs these on every file, so the common answers need no graph library: :func:`reached` is a breadth-first
search over the edge arrays in numpy (loading :mod:`scipy.sparse.csgraph` costs a check about 0.3 s of CPU), and
:func:`traps` asks :mod:`scipy.sparse.csgraph` for strongly connected parts only when some lane cannot reach an exit
(or, on a closed map, the map is not strongly connected). :func:`components` and :mod:`.paths` use it directly.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass

import numpy as np

from xodrcheck.graph.build import LaneGraph, matrix
from xodrcheck.support.arrays import ranges

__all__ = [
    "Reachability",
    "components",
    "entries",
    "exits",
    "goes_on",
    "on_circuits",
    "reachability",
    "reached",
    "traps",
    "unentered",
    "unreached",
]


def entries(graph: LaneGraph) -> np.ndarray:
    return np.array(sorted(graph.starts_open), dtype=np.int64)


def exits(graph: LaneGraph) -> np.ndarray:
    return np.array(sorted(i for i in graph.stops if graph.ends_open(i)), dtype=np.int64)


def reached(graph: LaneGraph, sources: Iterable[int], reverse: bool = False) -> np.ndarray:
    """Which nodes a route from any of ``sources`` reaches, the sources included (with ``reverse``: from which nodes
    one of them is reached): a breadth-first search, a frontier of nodes at a time."""
    n = len(graph.nodes)
    src, dst = (graph.target, graph.source) if reverse else (graph.source, graph.target)
    order = np.argsort(src, kind="stable")
    heads = dst[order]
    first = np.searchsorted(src[order], np.arange(n + 1))
    seen = np.zeros(n, dtype=bool)
    frontier = np.unique(np.fromiter(sources, dtype=np.int64))
    seen[frontier] = True
    while frontier.size:
        following = heads[ranges(first[frontier], first[frontier + 1] - first[frontier])]
        frontier = np.unique(following[~seen[following]])
        seen[frontier] = True
    return seen


def _spread(graph: LaneGraph, marked: np.ndarray, reverse: bool) -> np.ndarray:
    """``marked`` spread along lane changes (backwards with ``reverse``) until nothing changes: a lane section has a
    handful of lanes, so a few passes."""
    changes = graph.kind == 1
    a, b = (graph.target[changes], graph.source[changes]) if reverse else (graph.source[changes], graph.target[changes])
    while True:
        more = marked.copy()
        more[b[marked[a]]] = True
        if np.array_equal(more, marked):
            return marked
        marked = more


def unentered(graph: LaneGraph) -> np.ndarray:
    """Per node: whether nothing enters it (see the module docstring)."""
    entered = np.zeros(len(graph.nodes), dtype=bool)
    entered[graph.target[graph.kind == 0]] = True
    entered[list(graph.starts_open)] = True
    return ~_spread(graph, entered, reverse=False)


def goes_on(graph: LaneGraph) -> np.ndarray:
    """Per node: whether its traffic goes on (see the module docstring)."""
    on = np.zeros(len(graph.nodes), dtype=bool)
    on[graph.source[graph.kind == 0]] = True
    on[exits(graph)] = True
    return _spread(graph, on, reverse=True)


def components(graph: LaneGraph) -> tuple[int, np.ndarray]:
    """The strongly connected parts: their number and each node's label."""
    from scipy.sparse import csgraph  # here: a check that needs no components loads no scipy

    count, labels = csgraph.connected_components(matrix(graph), directed=True, connection="strong")
    return int(count), labels


def on_circuits(graph: LaneGraph) -> np.ndarray:
    """Per node: whether it lies in a circuit (a strongly connected part a link runs inside)."""
    if not graph.nodes:
        return np.zeros(0, dtype=bool)
    count, labels = components(graph)
    a, b = labels[graph.source], labels[graph.target]
    circuit = np.zeros(count, dtype=bool)
    circuit[a[(a == b) & (graph.kind == 0)]] = True  # every edge inside a strongly connected part lies on a cycle
    return circuit[labels]


def unreached(graph: LaneGraph) -> np.ndarray:
    """Per node: whether no route reaches it, from an entry or a circuit: the lanes nothing enters (:func:`unentered`)
    and what only they lead to. Strongly connected parts are computed only when some lane is unentered."""
    if not unentered(graph).any():
        return np.zeros(len(graph.nodes), dtype=bool)
    sources = np.flatnonzero(on_circuits(graph)).tolist() + entries(graph).tolist()
    return ~reached(graph, sources)


def _needs_components(graph: LaneGraph, outs: np.ndarray, ins: np.ndarray) -> bool:
    """Whether the map may have a trap: some lane reaches no exit (or, on a closed map, the map is not strongly
    connected)."""
    n = len(graph.nodes)
    if not n:
        return False
    if outs.size:
        return not bool(reached(graph, outs, reverse=True).all())
    if ins.size:
        return True  # traffic comes in and never leaves the map
    return not (bool(reached(graph, [0]).all()) and bool(reached(graph, [0], reverse=True).all()))


def traps(graph: LaneGraph) -> list[np.ndarray]:
    """The traps (see the module docstring), each as its nodes."""
    outs, ins = exits(graph), entries(graph)
    if not _needs_components(graph, outs, ins):
        return []
    count, labels = components(graph)
    a, b = labels[graph.source], labels[graph.target]
    circuit = np.zeros(count, dtype=bool)
    circuit[a[(a == b) & (graph.kind == 0)]] = True  # as on_circuits, per part
    leaving = np.zeros(count, dtype=bool)
    leaving[a[a != b]] = True
    entered = np.zeros(count, dtype=bool)
    entered[b[a != b]] = True
    with_exit = np.zeros(count, dtype=bool)
    with_exit[labels[outs]] = True
    main = int(np.argmax(np.bincount(labels, minlength=count)))
    found = np.flatnonzero(circuit & entered & ~leaving & ~with_exit)
    return [np.flatnonzero(labels == k) for k in found.tolist() if ins.size or outs.size or k != main]


@dataclass(frozen=True, eq=False)
class Reachability:
    """A map's reachability in numbers: strongly connected parts, the largest one's size, entries, exits, lanes
    nothing enters, dead ends, traps."""

    components: int
    largest: int
    entries: np.ndarray
    exits: np.ndarray
    unentered: np.ndarray
    dead_ends: np.ndarray
    traps: list[np.ndarray]


def reachability(graph: LaneGraph) -> Reachability:
    count, labels = components(graph) if graph.nodes else (0, np.zeros(0, dtype=np.int64))
    largest = int(np.bincount(labels).max()) if count else 0
    return Reachability(
        count,
        largest,
        entries(graph),
        exits(graph),
        np.flatnonzero(unentered(graph)),
        np.flatnonzero(~goes_on(graph)),
        traps(graph),
    )
