"""Rule elevation-beyond-road: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "elevation-beyond-road"


def test_elevation_record_past_the_road_end():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.s) == ("1", 160.0) and f.line == line_of(path, '<elevation s="160"')
    assert "length 100" in f.message
