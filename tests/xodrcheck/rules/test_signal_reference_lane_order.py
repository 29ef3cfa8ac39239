"""Rule signal-reference-lane-order (T011): the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "signal-reference-lane-order"


def test_from_lane_above_to_lane():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.line == line_of(path, '<validity fromLane="1" toLane="-1"/>')
