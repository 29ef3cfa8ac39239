"""Rule lane-access-mixed: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "lane-access-mixed"


def test_allow_and_deny_at_one_offset():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.lane) == ("1", -1)
    assert f.line == line_of(path, 'rule="deny"')
