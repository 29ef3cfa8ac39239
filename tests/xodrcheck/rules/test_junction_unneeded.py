"""Rule junction-unneeded: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of
from xodrcheck.findings import Severity
from xodrcheck.rules.shared import junction_uids as U

RULE = "junction-unneeded"


def test_two_roads_joined_by_a_junction():
    path = fixture(RULE, "fail_two_roads.xodr")
    (f,) = findings(path, RULE)
    assert (f.rule_uid, f.severity, f.line) == (U.COMMON_WHEN_TO_USE, Severity.ERROR, line_of(path, "<junction"))
    assert "(1-2)" in f.message


def test_two_roads_in_a_1_9_file_are_one_finding():
    """Two roads that could be linked directly: the error of when_to_use says it all; not_only_two's warning (1.9)
    is not given beside it (one defect, one finding)."""
    found = findings(fixture(RULE, "fail_two_roads_1_9.xodr"), RULE)
    assert [(f.rule_uid, f.severity) for f in found] == [(U.COMMON_WHEN_TO_USE, Severity.ERROR)]


def test_two_roads_where_one_may_turn_back_are_only_two():
    """Road 1 may go on to road 2 or turn back onto itself: a junction resolves that, but only two roads meet in it,
    which 1.9 advises against (a warning)."""
    found = findings(fixture(RULE, "fail_two_roads_u_turn_1_9.xodr"), RULE)
    assert [(f.rule_uid, f.severity) for f in found] == [(U.COMMON_NOT_ONLY_TWO, Severity.WARNING)]


def test_a_road_meeting_the_junction_with_both_ends_is_two_legs():
    """Road 2 starts and ends at the junction and road 1 ends there: three legs, road 1 has two ways on (road 2's
    start and its end). Was: J019 counted roads, not road ends, and called the junction unneeded (fuzz, seed 690)."""
    assert findings(fixture(RULE, "pass_loop.xodr"), RULE) == []
