"""Rule lane-link-direction: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture

RULE = "lane-link-direction"


def test_right_lane_continuing_a_left_lane_end_to_start():
    path = fixture(RULE, "fail.xodr")
    found = findings(path, RULE)
    assert sorted((f.road, f.lane) for f in found) == [("1", -1), ("1", 1)]
    assert all("an end meets a start" in f.message for f in found)


def test_same_side_lanes_linked_where_two_ends_meet():
    path = fixture(RULE, "fail_opposite.xodr")
    found = findings(path, RULE)
    assert sorted((f.road, f.lane) for f in found) == [("1", -1), ("1", 1)]
    assert all("two ends meet" in f.message for f in found)
