"""Rule lane-sections-from-start: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "lane-sections-from-start"


def test_first_section_at_five_metres():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.section_s, f.s) == ("1", 5.0, 0.0)
    assert f.line == line_of(path, '<laneSection s="5"')
