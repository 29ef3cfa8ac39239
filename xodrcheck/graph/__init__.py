"""Where a car can go: the lane graph of a document, routes through it and what it can and cannot reach.

* :func:`lane_graph` (:mod:`.build`): nodes are lanes of lane sections driven one way, edges the links between them
  (inside roads, across road links and through default and direct junctions, :mod:`.topology`) and, optionally, lane
  changes where road marks allow them (:mod:`.marks`); driving directions follow the traffic rule and the 1.8 lane
  ``direction`` (:mod:`.direction`).
* :func:`route` (:mod:`.routes`): the shortest route between two lanes, its length and polyline on the lane centres
  (:mod:`.lengths`).
* :func:`reachability` (:mod:`.reach`): strongly connected parts, entries and exits at the map's open edges, the
  lanes no route reaches and the parts no route leaves.

The graph is computed with :mod:`scipy.sparse.csgraph` (scipy is already the checker's dependency; it is vectorised,
so a map of tens of thousands of lanes costs milliseconds). It reads only the typed document.
"""

from __future__ import annotations

from xodrcheck.graph.build import LANE_CHANGE, LINK, LaneGraph, Node, Stop, lane_graph

__all__ = ["LANE_CHANGE", "LINK", "LaneGraph", "Node", "Stop", "lane_graph"]
