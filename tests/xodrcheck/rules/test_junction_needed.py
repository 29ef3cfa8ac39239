"""Rule junction-needed: its pass fixtures give no finding, its fail fixtures one where the defect is."""

from tests.xodrcheck.rules.helpers import assert_passes, findings, fixture, line_of

RULE = "junction-needed"


def test_pass_fixtures_give_no_finding():
    assert_passes(RULE)


def test_two_roads_ending_at_one_road_start():
    path = fixture(RULE, "fail.xodr")
    found = findings(path, RULE)
    assert sorted(f.road for f in found) == ["1", "3"]
    assert {f.line for f in found} == {
        line_of(path, '<successor elementType="road" elementId="2"'),
        line_of(path, '<successor elementType="road" elementId="2"', occurrence=2),
    }
