"""Rule road-type-out-of-order: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "road-type-out-of-order"


def test_type_before_its_predecessor():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.s) == ("1", 0.0)
    assert f.line == line_of(path, '<type s="0"')
    assert "before the one at line" in f.message and "(s=50)" in f.message
