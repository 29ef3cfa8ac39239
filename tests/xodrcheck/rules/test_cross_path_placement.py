"""Rule cross-path-placement: the findings each fail fixture gives."""

import pytest

from tests.xodrcheck.rules.helpers import findings, fixture, line_of
from xodrcheck.rules.shared import junction_uids as U

RULE = "cross-path-placement"


def test_start_link_away_from_the_crossing_road():
    path = fixture(RULE, "fail_linkage.xodr")
    (f,) = findings(path, RULE)
    assert (f.rule_uid, f.road, f.lane, f.s) == (U.CROSS_PATH_LANE_LINKAGE, "75", -1, 0.0)
    assert (f.x, f.y) == pytest.approx((59.0, 4.5))  # the centre of road 75's lane -1 at its start
    assert f.line == line_of(path, "<startLaneLink")


def test_crossing_road_wider_than_the_linked_lanes_reach():
    path = fixture(RULE, "fail_contained.xodr")
    by_uid: dict[str, list] = {}
    for f in findings(path, RULE):
        by_uid.setdefault(f.rule_uid, []).append(f)
    start, end = by_uid[U.CROSS_PATH_CONTAINED]
    assert (start.x, start.y, start.line) == (pytest.approx(49.0), pytest.approx(4.5), line_of(path, "<startLaneLink"))
    assert (end.x, end.y, end.line) == (pytest.approx(49.0), pytest.approx(-4.5), line_of(path, "<endLaneLink"))
    assert "1 m outside lane -2 of road 11" in start.message
    (outside,) = by_uid[U.CROSS_PATH_WITHIN_JUNCTION]  # x=49 is outside the junction's roads too
    assert outside.x == pytest.approx(49.0)


def test_crossing_road_past_the_virtual_junctions_end():
    path = fixture(RULE, "fail_virtual_extent.xodr")
    found = findings(path, RULE)
    assert {f.rule_uid for f in found} == {U.VIRTUAL_CROSS_PATH_S_T, U.CROSS_PATH_WITHIN_JUNCTION}
    for f in found:
        assert (f.road, f.x, f.line) == ("5", pytest.approx(97.0), line_of(path, '<crossPath id="0"'))
        assert "between sStart=92 and sEnd=96" in f.message
