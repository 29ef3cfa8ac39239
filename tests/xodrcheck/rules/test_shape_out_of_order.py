"""Rule shape-out-of-order: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "shape-out-of-order"


def test_t_descending_at_one_s():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.s) == ("1", 0.0) and f.line == line_of(path, '<shape s="0" t="-5"')
    assert "t at s=0 descends" in f.message


def test_s_descending():
    path = fixture(RULE, "fail_s.xodr")
    (f,) = findings(path, RULE)
    assert f.line == line_of(path, '<shape s="0" t="-5"') and ": s descends" in f.message
