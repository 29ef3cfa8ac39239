"""Rule junction-lane-links-crossed: its pass fixtures give no finding, its fail fixtures one where the defect is."""

from tests.xodrcheck.rules.helpers import assert_passes, findings, fixture

RULE = "junction-lane-links-crossed"


def test_pass_fixtures_give_no_finding():
    assert_passes(RULE)


def test_swapped_lane_links():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.road == "1"
    assert "lanes -1 and -2 of road 1" in f.message and "swapped order" in f.message
