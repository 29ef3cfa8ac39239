"""Rule plan-view-kink: its pass fixtures give no finding, its fail fixtures one where the defect is."""

from tests.xodrcheck.rules.helpers import assert_passes, findings, fixture

RULE = "plan-view-kink"


def test_pass_fixtures_give_no_finding():
    assert_passes(RULE)


def test_kink_without_gap():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.s) == ("1", 50.0)
    assert "5.73 deg" in f.message
