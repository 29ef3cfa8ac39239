"""Rule junction-lane-link-direction: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "junction-lane-link-direction"


def test_lane_link_into_a_lane_running_back():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.lane) == ("1", -1)
    assert f.line == line_of(path, '<laneLink from="-1" to="1"/>')
