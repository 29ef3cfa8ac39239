"""Which way a lane is driven: side, traffic rule, the 1.8 direction and the bidirectional type."""

from __future__ import annotations

import pytest

from xodrcheck.graph.direction import entering, leaving, travels
from xodrcheck.model import ContactPoint, Lane, LaneDirection, LaneType, Road, TrafficRule


@pytest.mark.parametrize(
    ("rule", "lane_id", "direction", "expected"),
    [
        (TrafficRule.RHT, -1, LaneDirection.STANDARD, (1,)),
        (TrafficRule.RHT, 2, LaneDirection.STANDARD, (-1,)),
        (TrafficRule.LHT, -1, LaneDirection.STANDARD, (-1,)),
        (TrafficRule.LHT, 1, LaneDirection.STANDARD, (1,)),
        (TrafficRule.RHT, -1, LaneDirection.REVERSED, (-1,)),
        (TrafficRule.LHT, 1, LaneDirection.REVERSED, (-1,)),
        (TrafficRule.RHT, 1, LaneDirection.BOTH, (1, -1)),
        (TrafficRule.RHT, 0, LaneDirection.STANDARD, ()),
    ],
)
def test_travel_directions(rule, lane_id, direction, expected):
    road = Road("1", 10.0, rule=rule)
    assert travels(road, Lane(lane_id, LaneType.DRIVING, direction=direction)) == expected


def test_a_bidirectional_lane_is_driven_both_ways():
    assert travels(Road("1", 10.0), Lane(-1, LaneType.BIDIRECTIONAL)) == (1, -1)


def test_ends_left_and_entered():
    assert (leaving(1), leaving(-1)) == (ContactPoint.END, ContactPoint.START)
    assert (entering(ContactPoint.START), entering(ContactPoint.END)) == (1, -1)
