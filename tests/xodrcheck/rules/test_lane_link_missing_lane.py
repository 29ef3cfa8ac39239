"""Rule lane-link-missing-lane: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of
from xodrcheck.findings import Severity

RULE = "lane-link-missing-lane"


def test_successor_lane_missing_on_the_next_road():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.lane, f.section_s) == ("1", -1, 0.0)
    assert f.severity is Severity.ERROR
    assert f.line == line_of(path, '<lane id="-1"')
    assert "lane -2" in f.message and "road 2" in f.message


def test_lane_link_where_the_road_has_no_link_breaks_no_link():
    """Annex F road.lane.link.no_link: a lane with no link there has no <link> entry for it (an error)."""
    path = fixture(RULE, "fail_dangling.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.lane) == ("2", -1)
    assert f.severity is Severity.ERROR
    assert f.rule_uid == "asam.net:xodr:1.4.0:road.lane.link.no_link"
    assert f.line == line_of(path, '<lane id="-1"', occurrence=2)
