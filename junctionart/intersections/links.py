"""Lane links of one intersection: which incoming lane feeds which outgoing lane.

For each incoming leg the outgoing lanes of the other legs are enumerated from the sharpest turn towards the kerb side
(right in RHT, left in LHT) to the sharpest turn the other way, each leg's lanes from the kerb to the centre; incoming
lanes are enumerated the same way and paired in order. Extra outgoing lanes are fed by the lane nearest the centre
(split-first) or the kerb (split-last). Every outgoing lane gets exactly one lane of each incoming leg, so no two lanes
of one road merge, every incoming lane reaches an outgoing lane, and one road's connection lanes keep their order.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..curves import wrap
from ..params import Params, SplitStrategy, TrafficRule
from .legs import Leg

#: Turns sharper than this (a near U-turn between two legs at a small angle) are only used when nothing else exists.
SHARPEST_TURN = math.radians(150.0)


@dataclass(frozen=True)
class LinkPlan:
    """Which incoming lane of which leg connects to which outgoing lane, and the lanes that reach the junction."""

    n_in_end: tuple[int, ...]  #: per leg: incoming lanes reaching the junction (after merges / turn lanes)
    n_out_end: tuple[int, ...]  #: per leg: outgoing lanes leaving the junction (unfed ones taper out)
    links: tuple[tuple[int, int, int, int], ...]  #: (leg in, lane k in, leg out, lane m out), k and m from 1


def turn(legs: list[Leg], i: int, j: int) -> float:
    """Signed heading change driving in on leg i and out on leg j (positive: left)."""
    return wrap(legs[j].angle - (legs[i].angle + math.pi))


def _same_road(legs: list[Leg], i: int, j: int) -> bool:
    """Legs i and j are the two ends of one road looping back to the junction."""
    return legs[i].road == legs[j].road != -1


def _targets(legs: list[Leg], rule: TrafficRule) -> list[list[int]]:
    """Per incoming leg, the legs it feeds, in enumeration order. Turns sharper than SHARPEST_TURN are left out, unless
    a leg would then have no exit at all, or only its own road's other end (a road looping back to the junction: its
    traffic would go round the loop for ever), or an outgoing leg no feeder, or only its own road's other end (traffic
    from elsewhere could never enter that direction of the loop): it is then fed by the least sharp turn from
    another road."""
    n = len(legs)
    out: list[list[int]] = []
    for i in range(n):
        others = [j for j in range(n) if j != i and legs[j].n_out > 0] if legs[i].n_in else []
        gentle = [j for j in others if abs(turn(legs, i, j)) <= SHARPEST_TURN]
        loop = all(_same_road(legs, i, j) for j in gentle)
        out.append(others if loop else gentle)
    for j in range(n):
        if not legs[j].n_out:
            continue
        fed_by = [i for i in range(n) if j in out[i]]
        if fed_by and not all(_same_road(legs, i, j) for i in fed_by):
            continue
        feeders = [i for i in range(n) if i != j and legs[i].n_in and not _same_road(legs, i, j)]
        if not feeders and not fed_by:
            feeders = [i for i in range(n) if i != j and legs[i].n_in]
        if feeders:
            out[min(feeders, key=lambda i: abs(turn(legs, i, j)))].append(j)
    sign = 1.0 if rule is TrafficRule.RHT else -1.0

    def by_turn(i: int, targets: list[int]) -> list[int]:
        return sorted(targets, key=lambda j: sign * turn(legs, i, j))

    return [by_turn(i, t) for i, t in enumerate(out)]


def plan(
    legs: list[Leg], params: Params, rng: np.random.Generator, drawn: dict[tuple[int, int], tuple[bool, bool]]
) -> LinkPlan:
    """Lane links for one junction. ``drawn`` remembers per leg what was drawn for it (a turn lane? split first?),
    so a leg keeps its choices while repairs elsewhere make the junction be planned again."""
    n = len(legs)
    n_in_end = [0] * n
    fed: list[set[int]] = [set() for _ in range(n)]
    links: list[tuple[int, int, int, int]] = []
    feeds = _targets(legs, params.traffic_rule)
    for i, leg in enumerate(legs):
        if leg.n_in == 0:
            continue
        targets = [(j, m) for j in feeds[i] for m in range(legs[j].n_out, 0, -1)]
        if not targets:
            continue
        count = min(leg.n_in, len(targets))
        if leg.key not in drawn:
            drawn[leg.key] = (bool(rng.random() < params.turn_lane_probability), bool(rng.random() < 0.5))
        turn_lane, first = drawn[leg.key]
        if turn_lane and count == leg.n_in and leg.n_in < 3 and len(targets) > count:
            count += 1  # a turn lane appears before the junction on the kerb side
        n_in_end[i] = count
        strategy = params.split_strategy
        if strategy is SplitStrategy.RANDOM:
            strategy = SplitStrategy.SPLIT_FIRST if first else SplitStrategy.SPLIT_LAST
        extra = len(targets) - count
        # incoming lanes from the kerb (k = count) to the centre (k = 1), each taking a block of targets
        pos = 0
        for rank, k in enumerate(range(count, 0, -1)):
            take = 1
            if strategy is SplitStrategy.SPLIT_LAST and rank == 0:
                take += extra
            if strategy is SplitStrategy.SPLIT_FIRST and k == 1:
                take += extra
            for j, m in targets[pos : pos + take]:
                links.append((i, k, j, m))
                fed[j].add(m)
            pos += take
    # outgoing lanes nobody feeds taper out before the junction; fed ones are a contiguous set 1..max
    n_out_end = [max(f) if f else 0 for f in fed]
    return LinkPlan(tuple(n_in_end), tuple(n_out_end), tuple(links))
