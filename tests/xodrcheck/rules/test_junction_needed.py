"""Rule junction-needed: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "junction-needed"


def test_two_roads_ending_at_one_road_start():
    path = fixture(RULE, "fail.xodr")
    found = findings(path, RULE)
    assert sorted(f.road for f in found) == ["1", "3"]
    assert {f.line for f in found} == {
        line_of(path, '<successor elementType="road" elementId="2"'),
        line_of(path, '<successor elementType="road" elementId="2"', occurrence=2),
    }
