"""Rule cross-path-roads: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of
from xodrcheck.findings import Severity
from xodrcheck.rules.shared import junction_uids as U

RULE = "cross-path-roads"


def test_crossing_road_outside_the_junction():
    path = fixture(RULE, "fail_junction_id.xodr")
    (f,) = findings(path, RULE)
    assert (f.rule_uid, f.road, f.line) == (U.CROSS_PATH_JUNCTION_ID, "75", line_of(path, "<crossPath"))


def test_cross_path_into_a_driving_lane():
    path = fixture(RULE, "fail_lane_type.xodr")
    (f,) = findings(path, RULE)
    assert (f.rule_uid, f.road, f.lane, f.line) == (U.CROSS_PATH_LANE_TYPES, "10", -1, line_of(path, "<endLaneLink"))


def test_elevation_of_the_crossing_road_is_an_info():
    path = fixture(RULE, "fail_elevation.xodr")
    (f,) = findings(path, RULE)
    assert (f.rule_uid, f.severity, f.road) == (U.CROSS_PATH_ELEVATION, Severity.INFO, "75")
