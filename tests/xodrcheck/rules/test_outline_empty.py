"""Rule outline-empty: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "outline-empty"


def test_outline_without_corners_or_curves():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.line) == ("1", line_of(path, '<outline id="0"'))
    assert "object 1" in f.message
