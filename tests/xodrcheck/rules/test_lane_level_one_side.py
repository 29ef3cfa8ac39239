"""Rule lane-level-one-side: its pass fixtures give no finding, its fail fixtures one where the defect is."""

from tests.xodrcheck.rules.helpers import assert_passes, findings, fixture, line_of

RULE = "lane-level-one-side"


def test_pass_fixtures_give_no_finding():
    assert_passes(RULE)


def test_non_level_lane_outside_a_level_lane():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.lane) == ("1", -2)
    assert f.line == line_of(path, '<lane id="-2" type="sidewalk" level="false"')
