"""Rule lane-unreachable: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of
from xodrcheck.findings import Severity

RULE = "lane-unreachable"


def test_a_lane_opening_behind_a_solid_line_is_reached_by_no_route():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.lane, f.section_s, f.s) == ("1", -2, 50.0, 50.0)
    assert f.severity is Severity.WARNING
    assert f.line == line_of(path, '<lane id="-2"')
    assert "no lane links into it" in f.message


def test_the_same_lane_behind_a_broken_line_is_reached():
    assert findings(fixture(RULE, "pass.xodr"), RULE) == []
