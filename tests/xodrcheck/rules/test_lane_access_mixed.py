"""Rule lane-access-mixed: its pass fixtures give no finding, its fail fixtures one where the defect is."""

from tests.xodrcheck.rules.helpers import assert_passes, findings, fixture, line_of

RULE = "lane-access-mixed"


def test_pass_fixtures_give_no_finding():
    assert_passes(RULE)


def test_allow_and_deny_at_one_offset():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.lane) == ("1", -1)
    assert f.line == line_of(path, 'rule="deny"')
