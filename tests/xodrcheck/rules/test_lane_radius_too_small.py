"""Rule lane-radius-too-small: its pass fixtures give no finding, its fail fixtures one where the defect is."""

from tests.xodrcheck.rules.helpers import assert_passes, findings, fixture

RULE = "lane-radius-too-small"


def test_pass_fixtures_give_no_finding():
    assert_passes(RULE)


def test_lane_centres_inside_a_four_metre_arc():
    path = fixture(RULE, "fail.xodr")
    found = findings(path, RULE)
    assert {f.lane for f in found} == {1}  # lane 1 centre at radius 2.25 m; lane -1 at 5.75 m is fine
    assert "radius of 2.25 m" in found[0].message
