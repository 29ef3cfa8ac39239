"""Rule border-with-lane-offset: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "border-with-lane-offset"


def test_border_and_lane_offset_are_both_reported():
    path = fixture(RULE, "fail.xodr")
    found = {f.rule_uid.rsplit(":", 1)[-1]: f for f in findings(path, RULE)}
    assert set(found) == {
        "road.lane.border.exclusive_offset_border",
        "road.lanes.lane_offset.no_offset_if_border_defined",
    }
    border = found["road.lane.border.exclusive_offset_border"]
    assert (border.road, border.lane, border.line) == ("1", -1, line_of(path, "<border "))
    offset = found["road.lanes.lane_offset.no_offset_if_border_defined"]
    assert (offset.road, offset.lane, offset.s, offset.line) == ("1", None, 0.0, line_of(path, "<laneOffset "))
