"""Rule object-off-road: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "object-off-road"


def test_object_past_the_end_of_its_road():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.line, f.s) == ("1", line_of(path, '<object id="1"'), 100.0), "placed at the road's end"
    assert "stands at s=120, but road 1 runs from s=0 to 100" in f.message


def test_object_without_t():
    path = fixture(RULE, "fail_no_t.xodr")
    (f,) = findings(path, RULE)
    assert f.line == line_of(path, '<object id="1"') and "has no valid t" in f.message and f.s is None
