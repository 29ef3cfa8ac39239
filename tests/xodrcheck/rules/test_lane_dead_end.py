"""Rule lane-dead-end: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of
from xodrcheck.findings import Severity

RULE = "lane-dead-end"


def test_a_lane_closing_beside_a_solid_line_leads_nowhere():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.lane, f.section_s, f.s) == ("1", -2, 0.0, 50.0)
    assert f.severity is Severity.WARNING and f.rule_uid is None
    assert f.line == line_of(path, '<lane id="-2"')
    assert "names no successor" in f.message and "no road mark" in f.message


def test_the_same_lane_beside_a_broken_line_is_no_dead_end():
    assert findings(fixture(RULE, "pass.xodr"), RULE) == []
