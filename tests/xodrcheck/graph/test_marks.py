"""Where road marks let traffic change lanes: laneChange first, else the mark's type."""

from __future__ import annotations

import pytest

from xodrcheck.graph.marks import crossable, line_owner
from xodrcheck.model import Lane, LaneSection, LaneType, RoadMark


def _section(owner: int, *marks: RoadMark) -> LaneSection:
    lanes = {i: Lane(i, LaneType.DRIVING) for i in (2, 1, -1, -2)}
    lanes[owner] = Lane(owner, LaneType.DRIVING, road_marks=marks)
    centre = (Lane(0, LaneType.NONE, road_marks=marks if owner == 0 else ()),)
    return LaneSection(0.0, left=(lanes[1], lanes[2]), center=centre, right=(lanes[-1], lanes[-2]))


def test_the_line_between_two_lanes_is_the_inner_ones_or_lane_0s():
    assert (line_owner(-1, -2), line_owner(-2, -1), line_owner(2, 1), line_owner(1, -1)) == (-1, -1, 1, 0)


@pytest.mark.parametrize(
    ("kind", "down", "up"),  # down: from -1 into -2 (lower id); up: from -2 into -1
    [
        ("broken", True, True),
        ("none", True, True),
        ("botts dots", True, True),
        ("broken broken", True, True),
        ("solid", False, False),
        ("solid solid", False, False),
        ("curb", False, False),
        ("grass", False, False),
        ("edge", False, False),
        ("custom", False, False),
        ("zigzag", False, False),
        ("solid broken", False, True),  # solid beside lane -1 (inside), broken beside -2: -2 may cross
        ("broken solid", True, False),
    ],
)
def test_types_without_lane_change(kind, down, up):
    section = _section(-1, RoadMark(0.0, kind))
    assert bool(crossable(section, 100.0, -1, -2)) is down
    assert bool(crossable(section, 100.0, -2, -1)) is up


def test_solid_broken_on_the_left_and_in_the_centre():
    left = _section(1, RoadMark(0.0, "solid broken"))  # solid beside lane 1, broken beside 2: 2 may cross into 1
    assert (bool(crossable(left, 10.0, 2, 1)), bool(crossable(left, 10.0, 1, 2))) == (True, False)
    centre = _section(0, RoadMark(0.0, "solid broken"))  # solid on the left (lane 1), broken on the right (-1)
    assert (bool(crossable(centre, 10.0, -1, 1)), bool(crossable(centre, 10.0, 1, -1))) == (True, False)


@pytest.mark.parametrize(
    ("change", "down", "up"),
    [("both", True, True), ("none", False, False), ("increase", False, True), ("decrease", True, False)],
)
def test_lane_change_attribute_wins_over_the_type(change, down, up):
    section = _section(-1, RoadMark(0.0, "solid", lane_change=change))
    assert (bool(crossable(section, 50.0, -1, -2)), bool(crossable(section, 50.0, -2, -1))) == (down, up)


def test_stretches_follow_the_records():
    section = _section(-1, RoadMark(10.0, "solid"), RoadMark(30.0, "broken"), RoadMark(80.0, "solid"))
    # no line before the first record (0-10), a broken one from 30 to 80
    assert crossable(section, 100.0, -1, -2) == [(0.0, 10.0), (30.0, 80.0)]
    assert crossable(_section(-1), 100.0, -1, -2) == [(0.0, 100.0)]
