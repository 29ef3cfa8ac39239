"""Rule duplicate-lane-id: its pass fixtures give no finding, its fail fixtures one where the defect is."""

from tests.xodrcheck.rules.helpers import assert_passes, findings, fixture, line_of

RULE = "duplicate-lane-id"


def test_pass_fixtures_give_no_finding():
    assert_passes(RULE)


def test_second_lane_with_the_id_is_reported_with_its_road_and_section():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.lane, f.section_s) == ("2", -1, 0.0)
    assert f.line == line_of(path, '<lane id="-1" type="sidewalk"')
