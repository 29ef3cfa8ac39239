import itertools
import math

import numpy as np
import pytest
from shapely import LineString, STRtree

from junctionart import controllines, network
from junctionart.params import Params


def _net(params: Params, seed: int, lines=None) -> network.Network:
    rng = np.random.default_rng(seed)
    cl = lines if lines is not None else controllines.automatic(params, rng)
    return network.build(cl, params, rng)


def _components(net: network.Network) -> int:
    parent = list(range(len(net.nodes)))

    def find(i):
        while parent[i] != i:
            i = parent[i]
        return i

    for e in net.edges:
        parent[find(e.u)] = find(e.v)
    return len({find(i) for i in range(len(net.nodes))})


CASES = [(Params(), s) for s in range(6)] + [(Params(width=1000, height=1000, curved_roads=True), s) for s in range(3)]


@pytest.mark.parametrize("params, seed", CASES)
def test_connected_planar_and_spread(params, seed):
    net = _net(params, seed)
    assert _components(net) == 1
    geoms = [LineString([net.nodes[e.u], net.nodes[e.v]]) for e in net.edges]
    left, _ = STRtree(geoms).query(geoms, predicate="crosses")
    assert len(left) == 0, "two roads cross without a junction"
    pts = np.asarray(net.nodes)
    d = np.hypot(pts[:, None, 0] - pts[None, :, 0], pts[:, None, 1] - pts[None, :, 1])
    np.fill_diagonal(d, np.inf)
    assert d.min() >= network.MERGE_DISTANCE
    assert all(e.u != e.v for e in net.edges)
    assert len({(min(e.u, e.v), max(e.u, e.v)) for e in net.edges}) == len(net.edges)


def test_same_seed_same_graph_other_seed_other_graph():
    p = Params(width=1000, height=1000)
    assert _net(p, 5) == _net(p, 5)
    assert _net(p, 5) != _net(p, 6)


def _two_lines(length=1000.0, gap=150.0):
    return controllines.parse(
        {"lines": [{"id": "a", "points": [[0, 0], [length, 0]]}, {"id": "b", "points": [[0, gap], [length, gap]]}]}
    )


def _table(**rows):
    t = {k: dict(v) for k, v in Params().transition_table().items()}
    t.update(rows)
    return t


def test_orthogonal_then_parallel_gives_rungs():
    t = _table(start={"orthogonal": 1.0}, orthogonal={"parallel": 1.0}, parallel={"parallel": 1.0})
    p = Params.create(transitions=t)
    net = _net(p, 3, _two_lines())
    rungs = [e for e in net.edges if e.line == -1]
    assert len(rungs) >= 4
    for e in rungs:
        (x0, y0), (x1, y1) = net.nodes[e.u], net.nodes[e.v]
        assert abs(x1 - x0) < 1e-9 and abs(abs(y1 - y0) - 150.0) < 1e-9


def test_common_end_makes_triangles():
    t = _table(
        start={"orthogonal": 1.0},
        orthogonal={"commonEnd": 1.0},
        commonEnd={"orthogonal": 0.5, "random": 0.5},
        random={"commonEnd": 1.0},
    )
    p = Params.create(transitions=t, snap_distance=10.0)
    net = _net(p, 1, _two_lines(2000.0))
    rungs = [e for e in net.edges if e.line == -1]
    shared = sum(1 for a, b in itertools.pairwise(rungs) if {a.u, a.v} & {b.u, b.v})
    assert shared >= 1


def test_snap_distance_and_gap_bounds_on_a_line():
    p = Params(snap_distance=60.0, min_distance=100.0, max_distance=150.0, gap_scale=(1.0, 1.0))
    net = _net(p, 2, _two_lines(3000.0))
    for y in (0.0, 150.0):
        xs = sorted(x for x, yy in net.nodes if abs(yy - y) < 1e-9)
        gaps = np.diff(xs)
        # consecutive control points are never closer than the snap distance (line ends excepted)
        assert gaps[1:-1].min() >= 60.0 - 1e-9
        # and the MDP's steps stay within what min/max distance allow (random steps reach 1.5 x max)
        assert gaps[1:-1].max() <= 1.5 * 150.0 + 60.0


def test_groups_are_joined():
    data = {
        "lines": [
            {"id": "a", "points": [[0, 0], [400, 0]], "group": 0},
            {"id": "b", "points": [[0, 200], [400, 200]], "group": 0},
            {"id": "c", "points": [[700, 0], [1100, 0]], "group": 1},
            {"id": "d", "points": [[700, 200], [1100, 200]], "group": 1},
        ]
    }
    net = _net(Params(), 0, controllines.parse(data))
    assert _components(net) == 1
    joins = [
        e
        for e in net.edges
        if e.line == -1
        and max(net.nodes[e.u][0], net.nodes[e.v][0]) >= 700
        and min(net.nodes[e.u][0], net.nodes[e.v][0]) <= 400
    ]
    assert len(joins) == 1


def test_curved_roads_add_bends():
    flat = _net(Params(width=1000, height=1000), 4)
    bent = _net(Params(width=1000, height=1000, curved_roads=True, curve_probability=1.0), 4)

    def deg2(n):
        return sum(1 for d in n.degree() if d == 2)

    assert deg2(bent) > deg2(flat)
    assert math.isfinite(sum(x for x, _ in bent.nodes))
