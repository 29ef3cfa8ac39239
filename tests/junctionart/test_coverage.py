"""Breadth over many random-lane maps: the features the generator promises all occur (issue 5's acceptance list).

The full acceptance run is 100 maps of 2 km (``slow``); the quick variant checks the same features on 12 maps of 1 km,
where 6- and 7-leg intersections are too rare to require.
"""

from __future__ import annotations

from collections import Counter

import pytest

import junctionart as ja
from junctionart.params import Params, SplitStrategy


def _features(size: float, seeds: range) -> dict:
    legs: Counter = Counter()
    lane_counts: set[int] = set()
    one_way = splits = merges = turn_lanes = 0
    strategies = set()
    for seed in seeds:
        strategy = SplitStrategy.SPLIT_FIRST if seed % 2 else SplitStrategy.SPLIT_LAST
        params = Params(width=size, height=size, randomize_lanes=True, split_strategy=strategy)
        lay = ja.generate_layout(params, seed).layout
        legs.update(j.legs for j in lay.junctions)
        for rp in lay.roads:
            lane_counts.update((rp.lanes.forward, rp.lanes.backward))
            one_way += rp.lanes.forward == 0 or rp.lanes.backward == 0
            ends = [
                (rp.fwd_start, rp.lanes.forward),
                (rp.bwd_start, rp.lanes.backward),
                (rp.fwd_end, rp.lanes.forward),
                (rp.bwd_end, rp.lanes.backward),
            ]
            merges += sum(end < mid for end, mid in ends)
            splits += sum(end > mid for end, mid in ends)
            turn_lanes += (rp.end_junction is not None and rp.fwd_end > rp.lanes.forward) + (
                rp.start_junction is not None and rp.bwd_start > rp.lanes.backward
            )
        # which incoming lane feeds several outgoing lanes tells the strategy that ran
        per_lane: Counter = Counter()
        for j in lay.junctions:
            for c in j.connections:
                per_lane[(j.node, c.in_road, c.in_contact, abs(c.in_lane))] += 1
        for (node, road, contact, lane), n in per_lane.items():
            if n > 1:
                lanes = sorted(k[3] for k in per_lane if k[:3] == (node, road, contact))
                if len(lanes) > 1:
                    strategies.add("first" if lane == lanes[0] else "last" if lane == lanes[-1] else "?")
    return {
        "legs": legs,
        "lane_counts": lane_counts,
        "one_way": one_way,
        "splits": splits,
        "merges": merges,
        "turn_lanes": turn_lanes,
        "strategies": strategies,
    }


def _assert(f: dict, legs: set[int]) -> None:
    assert legs <= set(f["legs"]), f["legs"]
    assert max(f["legs"]) <= 7 and min(f["legs"]) >= 3
    assert f["lane_counts"] == {0, 1, 2, 3}
    assert f["one_way"] > 0
    assert f["splits"] > 0 and f["merges"] > 0 and f["turn_lanes"] > 0
    assert {"first", "last"} <= f["strategies"]


def test_features_on_1km_maps():
    _assert(_features(1000.0, range(12)), {3, 4, 5})


@pytest.mark.slow
def test_features_on_100_maps_of_2km():
    _assert(_features(2000.0, range(100)), {3, 4, 5, 6, 7})
