"""Rule centre-lane-width: its pass fixtures give no finding, its fail fixtures one where the defect is."""

from tests.xodrcheck.rules.helpers import assert_passes, findings, fixture, line_of

RULE = "centre-lane-width"


def test_pass_fixtures_give_no_finding():
    assert_passes(RULE)


def test_centre_lane_with_a_width_record():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.lane) == ("1", 0)
    assert f.line == line_of(path, 'a="0.2"')
