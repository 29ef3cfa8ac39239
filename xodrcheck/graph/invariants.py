"""Reachability invariants of a map, for its snapshot (:mod:`xodrcheck.analysis.snapshot`): the lane graph's strongly
connected parts, where traffic enters and leaves the map, and which (entry, exit) pairs no route joins.

An entry or exit is named ``ROAD:LANE:END``: the road, the lane id of its lane section there and the road's end
(``start`` or ``end``) where traffic comes in or goes out. The snapshot keeps the pairs *without* a route (few on a
well-connected map, where all of them would be many), so a route that vanishes is a pair that appears among them while
both its ends are still there.
"""

from __future__ import annotations

from collections.abc import Iterator, Mapping
from typing import Any

from xodrcheck.graph.build import LaneGraph, Node, lane_graph
from xodrcheck.graph.reach import components, entries, exits, reached
from xodrcheck.model import Document

__all__ = ["KEYS", "reach_differences", "reach_invariants"]

#: The snapshot's keys this module fills.
KEYS = ("strong_components", "entries", "exits", "unroutable")


def _name(node: Node, entering: bool) -> str:
    along = node.travel > 0
    end = ("start" if along else "end") if entering else ("end" if along else "start")
    return f"{node.road}:{node.lane}:{end}"


def reach_invariants(document: Document) -> dict[str, Any]:
    """``strong_components`` (a count), ``entries`` and ``exits`` (sorted names) and ``unroutable`` (sorted
    [entry, exit] pairs no route joins)."""
    graph: LaneGraph = lane_graph(document)
    count = components(graph)[0] if graph.nodes else 0
    ins, outs = entries(graph).tolist(), exits(graph).tolist()
    unroutable: set[tuple[str, str]] = set()
    for i in ins:
        hit = reached(graph, [i])
        unroutable.update((_name(graph.nodes[i], True), _name(graph.nodes[o], False)) for o in outs if not hit[o])
    return {
        "strong_components": count,
        "entries": tuple(sorted({_name(graph.nodes[i], True) for i in ins})),
        "exits": tuple(sorted({_name(graph.nodes[o], False) for o in outs})),
        "unroutable": tuple(sorted(unroutable)),
    }


def reach_differences(old: Mapping, new: Mapping) -> Iterator[str]:
    """Readable lines for what changed between two snapshots' invariants (nothing when ``old`` has none: a snapshot
    written before they were kept)."""
    if old.get("entries") is None or new.get("entries") is None:
        return
    if old["strong_components"] != new["strong_components"]:
        yield f"strongly connected parts of the lane graph: {old['strong_components']} -> {new['strong_components']}"
    for key, word in (("entries", "entry"), ("exits", "exit")):
        gone, came = sorted(set(old[key]) - set(new[key])), sorted(set(new[key]) - set(old[key]))
        yield from (f"{word} {name} is gone" for name in gone)
        yield from (f"new {word} {name}" for name in came)
    both = set(old["entries"]) & set(new["entries"]), set(old["exits"]) & set(new["exits"])
    before, after = set(map(tuple, old["unroutable"])), set(map(tuple, new["unroutable"]))
    for a, b in sorted(after - before):
        if a in both[0] and b in both[1]:
            yield f"route from {a} to {b} vanished"
    for a, b in sorted(before - after):
        if a in both[0] and b in both[1]:
            yield f"route from {a} to {b} appeared"
