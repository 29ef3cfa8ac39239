"""Rule boundary-roads: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of
from xodrcheck.rules.shared import junction_uids as U

RULE = "boundary-roads"


def test_no_segment_at_a_road_of_the_junction():
    path = fixture(RULE, "fail_missing_road.xodr")
    (f,) = findings(path, RULE)
    assert (f.rule_uid, f.road, f.s, f.line) == (U.BOUNDARY_EACH_ROAD, "3", 0.0, line_of(path, "<boundary>"))


def test_added_road_outside_the_junction():
    path = fixture(RULE, "fail_new_road.xodr")
    (f,) = findings(path, RULE)
    assert (f.rule_uid, f.road, f.line) == (U.BOUNDARY_CLOSE_GAP_WITH_NEW_ROADS, "100", line_of(path, 'roadId="100"'))
