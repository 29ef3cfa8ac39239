"""Rule lane-link-not-reciprocal: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "lane-link-not-reciprocal"


def test_successor_lane_without_the_predecessor_link():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.lane) == ("2", -1)
    assert f.line == line_of(path, '<lane id="-1"', occurrence=2)
