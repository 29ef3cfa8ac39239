"""The lane graph's nodes and edges on small maps whose topology is known."""

from __future__ import annotations

import dataclasses

import numpy as np

from tests.xodrcheck.graph.maps import FIXTURES, T_JUNCTION, document
from xodrcheck.graph import LANE_CHANGE, LINK, lane_graph
from xodrcheck.graph.build import KINDS
from xodrcheck.model import LaneDirection, LaneType


def _edges(graph, kind=None):
    return {
        ((graph.nodes[a].road, graph.nodes[a].lane), (graph.nodes[b].road, graph.nodes[b].lane))
        for a, b, k in zip(graph.source.tolist(), graph.target.tolist(), graph.kind.tolist())
        if kind is None or KINDS[k] == kind
    }


def test_t_junction_links():
    """West (1), east (2) and south (3) roads, one lane each way; connecting roads 101 (straight), 102 and 103 (turns),
    each driven both ways by its lanes -1 and 1."""
    graph = lane_graph(document(T_JUNCTION))
    assert len(graph.nodes) == 12
    assert _edges(graph) == {
        (("1", -1), ("101", -1)), (("101", -1), ("2", -1)),  # west to east
        (("2", 1), ("101", 1)), (("101", 1), ("1", 1)),  # east to west
        (("1", -1), ("102", -1)), (("102", -1), ("3", 1)),  # west to south
        (("3", -1), ("102", 1)), (("102", 1), ("1", 1)),  # south to west
        (("2", 1), ("103", 1)), (("103", 1), ("3", 1)),  # east to south
        (("3", -1), ("103", -1)), (("103", -1), ("2", -1)),  # south to east
    }  # fmt: skip
    # every road's outer end is open: traffic enters on one lane and leaves on the other
    assert {graph.nodes[i].describe() for i in graph.starts_open} == {
        "road 1 lane -1 (lane section s=0)",
        "road 2 lane 1 (lane section s=0)",
        "road 3 lane -1 (lane section s=0)",
    }
    assert sorted(graph.nodes[i].road for i in range(len(graph.nodes)) if graph.ends_open(i)) == ["1", "2", "3"]


def test_lane_changes_where_the_mark_allows():
    """The lane-dead-end fixtures: lanes -1 and -2 side by side over the first 50 m, the line between them broken
    (pass) or solid (fail)."""
    broken = lane_graph(document(FIXTURES / "lane-dead-end" / "pass.xodr"))
    assert _edges(broken, LANE_CHANGE) == {(("1", -2), ("1", -1)), (("1", -1), ("1", -2))}
    assert np.all(broken.at[broken.kind == 1] == 0.0)
    solid = lane_graph(document(FIXTURES / "lane-dead-end" / "fail.xodr"))
    assert _edges(solid, LANE_CHANGE) == set()
    links_only = lane_graph(document(FIXTURES / "lane-dead-end" / "pass.xodr"), lane_changes=False)
    assert _edges(links_only, LANE_CHANGE) == set()
    (stop,) = [s for i, s in solid.stops.items() if solid.nodes[i].lane == -2]
    assert stop.kind == "section" and "names no successor in the lane section at s=50" in stop.why


def test_a_lane_driven_both_ways_is_two_nodes():
    doc = document(T_JUNCTION)
    road = doc.road_by_id["1"]
    section = road.lane_sections[0]
    both = dataclasses.replace(section.lane(-1), direction=LaneDirection.BOTH)
    road = dataclasses.replace(road, lane_sections=(dataclasses.replace(section, right=(both,)),))
    doc = dataclasses.replace(doc, roads=tuple(road if r.id == "1" else r for r in doc.roads))
    graph = lane_graph(doc)
    assert sorted(n.travel for n in graph.nodes if (n.road, n.lane) == ("1", -1)) == [-1, 1]
    # driven west, it leaves the map at road 1's open start; driven east it enters the junction as before
    assert (("1", -1), ("101", -1)) in _edges(graph, LINK)


def test_lane_types_outside_the_graph_are_no_nodes():
    doc = document(FIXTURES / "lane-dead-end" / "pass.xodr")
    assert {n.lane for n in lane_graph(doc, lane_types=[LaneType.SIDEWALK]).nodes} == set()
    assert len(lane_graph(doc).nodes) == 5  # lanes 1, -1, -2 of the first section, 1 and -1 of the second
