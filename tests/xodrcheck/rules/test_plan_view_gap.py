"""Rule plan-view-gap: its pass fixtures give no finding, its fail fixtures one where the defect is."""

from tests.xodrcheck.rules.helpers import assert_passes, findings, fixture, line_of

RULE = "plan-view-gap"


def test_pass_fixtures_give_no_finding():
    assert_passes(RULE)


def test_five_millimetre_gap():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.s) == ("1", 50.0)
    assert "a gap of 0.005 m" in f.message
    assert f.line == line_of(path, 'x="50.005"')
