"""Rule incoming-lane-unconnected: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "incoming-lane-unconnected"


def test_incoming_lane_without_a_lane_link():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.lane, f.s) == ("2", 1, 0.0)
    assert f.line == line_of(path, '<lane id="1"', occurrence=2)
