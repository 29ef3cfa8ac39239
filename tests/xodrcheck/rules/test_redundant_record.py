"""Rule redundant-record: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of
from xodrcheck.check import check
from xodrcheck.findings import Severity
from xodrcheck.rules.shared import road_uids as U

RULE = "redundant-record"


def test_width_record_repeating_the_previous_one():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.lane, f.s) == ("1", -1, 50.0)
    assert f.severity is Severity.INFO
    assert f.line == line_of(path, 'sOffset="50"')


def test_lane_section_repeating_the_previous_one():
    """Same lanes, types, identity links, widths that continue (3 + 0.01 s reaches 3.6 at s=60), same marks."""
    path = fixture(RULE, "fail_lane_section.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.section_s, f.s) == ("1", 60.0, 60.0)
    assert f.line == line_of(path, '<laneSection s="60"')
    assert f.rule_uid == U.AVOID_REDUNDANT_INFO


def test_road_type_repeating_the_previous_one():
    path = fixture(RULE, "fail_type.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.s) == ("1", 50.0) and f.line == line_of(path, '<type s="50"')


def test_a_lane_section_with_records_not_compared_is_not_called_redundant():
    """An <access> record (not read into the model) may be what the second section changes."""
    text = fixture(RULE, "fail_lane_section.xodr").read_text(encoding="utf-8")
    marked = text.replace(
        '<link><predecessor id="-1"/></link>',
        '<link><predecessor id="-1"/></link>\n            <access sOffset="0" rule="deny" restriction="truck"/>',
    )
    assert marked != text
    report = check(marked.encode(), select=("G901",))
    assert [f for f in report.findings if f.code == "G901"] == []
