"""Rule incoming-lane-unconnected: its pass fixtures give no finding, its fail fixtures one where the defect is."""

from tests.xodrcheck.rules.helpers import assert_passes, findings, fixture, line_of

RULE = "incoming-lane-unconnected"


def test_pass_fixtures_give_no_finding():
    assert_passes(RULE)


def test_incoming_lane_without_a_lane_link():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.lane, f.s) == ("2", 1, 0.0)
    assert f.line == line_of(path, '<lane id="1"', occurrence=2)
