"""Rule width-and-border-mixed: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "width-and-border-mixed"


def test_border_lane_beside_a_width_lane():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.lane) == ("1", -2)
    assert f.rule_uid.endswith("road.lane.border.exclusive_width_border")
    assert f.line == line_of(path, "<border ")
    assert "lane -1 has <width>" in f.message
