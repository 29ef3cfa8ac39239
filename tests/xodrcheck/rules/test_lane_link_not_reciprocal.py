"""Rule lane-link-not-reciprocal: its pass fixtures give no finding, its fail fixtures one where the defect is."""

from tests.xodrcheck.rules.helpers import assert_passes, findings, fixture, line_of

RULE = "lane-link-not-reciprocal"


def test_pass_fixtures_give_no_finding():
    assert_passes(RULE)


def test_successor_lane_without_the_predecessor_link():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.lane) == ("2", -1)
    assert f.line == line_of(path, '<lane id="-1"', occurrence=2)
