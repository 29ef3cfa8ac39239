"""Rule outline-outer-count: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of
from xodrcheck.check import check

RULE = "outline-outer-count"


def test_outlines_without_outer_are_outer_in_1_9():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.line == line_of(path, "<outlines>") and "has 2 outer outlines" in f.message


def test_no_outer_outline():
    (f,) = findings(fixture(RULE, "fail_none.xodr"), RULE)
    assert "has no outer outline" in f.message


def test_before_1_9_outer_has_no_default_and_the_rule_does_not_apply():
    text = fixture(RULE, "fail.xodr").read_text(encoding="utf-8").replace('revMinor="9"', 'revMinor="8"')
    assert [f for f in check(text.encode(), select=("B017",)).findings if f.code == "B017"] == []
