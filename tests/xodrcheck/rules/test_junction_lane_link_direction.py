"""Rule junction-lane-link-direction: its pass fixtures give no finding, its fail fixtures one where the defect is."""

from tests.xodrcheck.rules.helpers import assert_passes, findings, fixture, line_of

RULE = "junction-lane-link-direction"


def test_pass_fixtures_give_no_finding():
    assert_passes(RULE)


def test_lane_link_into_a_lane_running_back():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.lane) == ("1", -1)
    assert f.line == line_of(path, '<laneLink from="-1" to="1"/>')
