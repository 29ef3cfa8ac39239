"""Rule repeat-beyond-road: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "repeat-beyond-road"


def test_repeat_past_the_road_end():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.line == line_of(path, "<repeat ") and "runs from s=50 to 130, past the end of road 1 at s=100" in f.message
