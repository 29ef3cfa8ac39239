"""Rule lane-section-beyond-road: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "lane-section-beyond-road"


def test_temporary_section_ends_past_the_road():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.section_s) == ("1", 80.0)
    assert f.line == line_of(path, '<laneSection s="80" length="30"')
    assert "ends at s=110, 10 m past" in f.message
