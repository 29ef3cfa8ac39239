"""Rule plan-view-s-jump: its pass fixtures give no finding, its fail fixtures one where the defect is."""

from tests.xodrcheck.rules.helpers import assert_passes, findings, fixture

RULE = "plan-view-s-jump"


def test_pass_fixtures_give_no_finding():
    assert_passes(RULE)


def test_s_jumps_by_two_metres():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.s) == ("1", 52.0)
    assert "should start at s=50" in f.message and "gap of 2 m" in f.message
