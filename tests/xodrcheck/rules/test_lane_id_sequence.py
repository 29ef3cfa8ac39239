"""Rule lane-id-sequence: its pass fixtures give no finding, its fail fixtures one where the defect is."""

from tests.xodrcheck.rules.helpers import assert_passes, findings, fixture

RULE = "lane-id-sequence"


def test_pass_fixtures_give_no_finding():
    assert_passes(RULE)


def test_gap_in_right_lane_ids():
    path = fixture(RULE, "fail.xodr")
    found = findings(path, RULE)
    assert sorted(f.road for f in found) == ["1", "2"]
    assert all(f.lane == -2 and "skip id(s) -2" in f.message for f in found)
