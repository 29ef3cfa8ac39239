from pathlib import Path

import numpy as np
import pytest

from junctionart import controllines, lanes, network
from junctionart.graph import chains
from junctionart.params import Params

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def _laned(params, seed, lines=None):
    rng = np.random.default_rng(seed)
    cl = lines if lines is not None else controllines.automatic(params, rng)
    net = network.build(cl, params, rng)
    return cl, lanes.assign(net, cl, params, rng)


@pytest.mark.parametrize("seed", range(8))
def test_random_lane_counts(seed):
    _, ln = _laned(Params(width=1000, height=1000, randomize_lanes=True), seed)
    net = ln.network
    deg = net.degree()
    for cfg in ln.lanes:
        assert 0 <= cfg.forward <= 3 and 0 <= cfg.backward <= 3
        assert cfg.forward + cfg.backward > 0
        assert not cfg.median or (cfg.forward and cfg.backward)
    for ch in chains(len(net.nodes), [(e.u, e.v) for e in net.edges]):
        cfgs = {(ln.lanes[e] if fw else ln.lanes[e].reversed()) for e, fw in zip(ch.edges, ch.forward)}
        assert len(cfgs) == 1, "one configuration per road"
        if deg[ch.start] == 1 or deg[ch.end] == 1:
            (cfg,) = cfgs
            assert cfg.forward and cfg.backward, "dead ends are two-way"


def test_fixed_lanes_without_randomize():
    _, ln = _laned(Params(randomize_lanes=False, median_probability=0.0), 3)
    assert {(c.forward, c.backward, c.median) for c in ln.lanes} == {(1, 1, False)}


def test_random_lanes_show_every_count_and_one_way_roads():
    seen, one_way = set(), 0
    for seed in range(10):
        _, ln = _laned(Params(width=1000, height=1000, randomize_lanes=True), seed)
        for c in ln.lanes:
            seen.update((c.forward, c.backward))
            one_way += (c.forward == 0) or (c.backward == 0)
    assert seen == {0, 1, 2, 3}
    assert one_way > 0


def test_control_line_lane_configuration_is_used():
    cl = controllines.load(EXAMPLES / "grid.json")
    _, ln = _laned(Params(randomize_lanes=True), 1, cl)
    on_lines = [c for e, c in zip(ln.network.edges, ln.lanes) if e.line >= 0]
    assert on_lines and all((c.forward, c.backward) == (2, 2) for c in on_lines)


def test_control_line_lane_configurations_for_automatic_lines():
    params = Params(randomize_lanes=True, control_line_lanes=((3, 0), (2, 2)))
    cl, ln = _laned(params, 5)
    assert cl.lines[0].lanes == (3, 0) and cl.lines[1].lanes == (2, 2)
    along = {e.line: c for e, c in zip(ln.network.edges, ln.lanes) if e.line in (0, 1)}
    for line, c in along.items():
        want = sorted(cl.lines[line].lanes)
        # a road ending in a dead end is opened both ways (0 lanes -> 1)
        assert sorted((c.forward, c.backward)) in (want, sorted(max(n, 1) for n in want))
    assert sorted((along[1].forward, along[1].backward)) == [2, 2]
