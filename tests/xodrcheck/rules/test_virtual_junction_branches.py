"""Rule virtual-junction-branches: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of
from xodrcheck.rules.shared import junction_uids as U

RULE = "virtual-junction-branches"


def test_branch_leaving_between_start_and_end():
    path = fixture(RULE, "fail_start_end.xodr")
    (f,) = findings(path, RULE)
    assert (f.rule_uid, f.road, f.line) == (U.VIRTUAL_START_END, "2", line_of(path, 'elementS="55"'))


def test_connecting_road_that_does_not_touch_the_main_road():
    path = fixture(RULE, "fail_main_road.xodr")
    (f,) = findings(path, RULE)
    assert (f.rule_uid, f.road, f.line) == (U.VIRTUAL_MAIN_ROAD_ONLY, "4", line_of(path, 'connectingRoad="4"'))
