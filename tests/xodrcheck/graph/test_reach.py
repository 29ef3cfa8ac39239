"""Reachability: the breadth-first search against scipy's, and the parts a route cannot reach or leave."""

from __future__ import annotations

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.sparse import csgraph

from tests.xodrcheck.graph.maps import FIXTURES, LOOP, T_JUNCTION, TRAP, document
from xodrcheck.graph import lane_graph
from xodrcheck.graph.build import LaneGraph, Node, matrix
from xodrcheck.graph.reach import components, goes_on, reachability, reached, traps, unentered
from xodrcheck.model import LaneKey


def _graph(n: int, edges: list[tuple[int, int]]) -> LaneGraph:
    nodes = tuple(Node(LaneKey(str(i), 0.0, -1), 0, 1, "driving", None) for i in range(n))
    src = np.array([a for a, _ in edges], dtype=np.int64)
    dst = np.array([b for _, b in edges], dtype=np.int64)
    kinds, at = np.zeros(len(edges), dtype=np.int8), np.ones(len(edges))
    return LaneGraph(nodes, src, dst, kinds, at, {}, frozenset(), True, {})


@st.composite
def graphs(draw):
    n = draw(st.integers(1, 30))
    edges = draw(st.lists(st.tuples(st.integers(0, n - 1), st.integers(0, n - 1)), max_size=80))
    return _graph(n, edges), draw(st.lists(st.integers(0, n - 1), max_size=4))


@settings(max_examples=200, deadline=None)
@given(graphs(), st.booleans())
def test_reached_is_scipys_breadth_first_search(case, reverse):
    graph, sources = case
    m = matrix(graph)
    m = m.T.tocsr() if reverse else m
    expected = np.zeros(len(graph.nodes), dtype=bool)
    for s in sources:
        expected[csgraph.breadth_first_order(m, s, directed=True, return_predecessors=False)] = True
    assert np.array_equal(reached(graph, sources, reverse=reverse), expected)


def test_t_junction_is_open_and_every_lane_is_entered_and_goes_on():
    graph = lane_graph(document(T_JUNCTION))
    found = reachability(graph)
    assert (len(found.entries), len(found.exits), found.components, found.largest) == (3, 3, 12, 1)
    assert not unentered(graph).any() and goes_on(graph).all() and traps(graph) == []


def test_the_loop_is_a_trap_only_without_its_way_out():
    assert traps(lane_graph(document(LOOP))) == []
    (trap,) = traps(lane_graph(document(TRAP)))
    graph = lane_graph(document(TRAP))
    assert sorted(graph.nodes[i].road for i in trap) == ["11", "2"]


def test_lanes_nothing_enters_and_dead_ends():
    opening = lane_graph(document(FIXTURES / "lane-unreachable" / "fail.xodr"))
    assert [opening.nodes[i].describe() for i in np.flatnonzero(unentered(opening))] == [
        "road 1 lane -2 (lane section s=50)"
    ]
    closing = lane_graph(document(FIXTURES / "lane-dead-end" / "fail.xodr"))
    assert [closing.nodes[i].describe() for i in np.flatnonzero(~goes_on(closing))] == [
        "road 1 lane -2 (lane section s=0)"
    ]


def test_components_of_a_closed_circuit():
    count, labels = components(_graph(4, [(0, 1), (1, 2), (2, 0), (2, 3)]))
    assert count == 2 and labels[0] == labels[1] == labels[2] != labels[3]
