"""The lane graph as the page carries it: routes between two clicked lanes are found in the browser, and the lanes no
route reaches are shaded (``static/route.js``).

``{"nodes": [road, section index, lane id, travel, ...], "edges": [from, to, kind, ...], "unreached": [node, ...]}``:
``road`` indexes the map data's ``roads``, ``travel`` is +1 along s and -1 against it, ``kind`` 0 a link and 1 a lane
change (:mod:`xodrcheck.graph`); ``unreached`` are the lanes no route reaches (:func:`xodrcheck.graph.reach.unreached`).
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from xodrcheck.graph.build import lane_graph
from xodrcheck.graph.reach import unreached
from xodrcheck.model import Document


def graph_data(document: Document, roads: Sequence[tuple]) -> dict:
    """The payload for a map whose ``roads`` (id first) the page draws; nodes on roads it does not draw are left out,
    with their edges."""
    graph = lane_graph(document)
    index: dict[str, int] = {}
    for k, road in enumerate(roads):
        index.setdefault(road[0], k)
    keep = np.array([n.road in index for n in graph.nodes], dtype=bool)
    renumber = np.cumsum(keep) - 1
    nodes = [v for n in graph.nodes if n.road in index for v in (index[n.road], n.index, n.lane, n.travel)]
    ok = keep[graph.source] & keep[graph.target]
    edges = np.stack([renumber[graph.source[ok]], renumber[graph.target[ok]], graph.kind[ok]], axis=1)
    shaded = unreached(graph)
    return {
        "nodes": nodes,
        "edges": edges.ravel().tolist(),
        "unreached": renumber[np.flatnonzero(shaded & keep)].tolist(),
    }
