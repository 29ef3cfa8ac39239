"""Rule junction-priority-pair: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of
from xodrcheck.rules.shared import junction_uids as U

RULE = "junction-priority-pair"


def test_priority_naming_one_road_twice():
    path = fixture(RULE, "fail_same_road.xodr")
    (f,) = findings(path, RULE)
    assert (f.rule_uid, f.road, f.line) == (U.PRIORITY_HIGH_AND_LOW, "2", line_of(path, "<priority"))


def test_crossing_with_two_prioritised_roads():
    path = fixture(RULE, "fail_two_high.xodr")
    (f,) = findings(path, RULE)
    assert f.rule_uid == U.CROSSING_ONE_HIGH
    assert f.line == line_of(path, '<priority high="1"')
    assert "roads 1, 2" in f.message
