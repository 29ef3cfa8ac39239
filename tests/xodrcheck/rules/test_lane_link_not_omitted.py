"""Rule lane-link-not-omitted: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "lane-link-not-omitted"


def test_lane_successor_where_the_road_ends_in_a_junction():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.lane, f.s) == ("1", -1, 100.0)
    assert f.line == line_of(path, '<lane id="-1"')
    assert "junction 100" in f.message


def test_empty_link():
    path = fixture(RULE, "fail_empty.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.lane, f.line) == ("1", -1, line_of(path, "<link> </link>"))
