"""Rule lane-level-changes: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture

RULE = "lane-level-changes"


def test_level_changes_between_linked_lanes_of_two_sections():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.lane, f.section_s) == ("2", -1, 0.0)
    assert "level=false" in f.message and "level=true" in f.message
