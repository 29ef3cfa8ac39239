"""Rule centre-lane-invalid: its pass fixtures give no finding, its fail fixtures one where the defect is."""

from tests.xodrcheck.rules.helpers import assert_passes, findings, fixture, line_of

RULE = "centre-lane-invalid"


def test_pass_fixtures_give_no_finding():
    assert_passes(RULE)


def test_non_zero_lane_in_the_centre():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.lane) == ("1", 5)
    assert f.line == line_of(path, '<lane id="5"')
