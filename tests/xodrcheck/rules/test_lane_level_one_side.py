"""Rule lane-level-one-side: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "lane-level-one-side"


def test_non_level_lane_outside_a_level_lane():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.lane) == ("1", -2)
    assert f.line == line_of(path, '<lane id="-2" type="sidewalk" level="false"')
