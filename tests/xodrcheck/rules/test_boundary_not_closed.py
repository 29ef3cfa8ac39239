"""Rule boundary-not-closed: the finding each fail fixture gives."""

import pytest

from tests.xodrcheck.rules.helpers import findings, fixture, line_of
from xodrcheck.rules.shared import junction_uids as U

RULE = "boundary-not-closed"


def test_lane_segment_stopping_short_of_the_next_joint():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (f.rule_uid, f.road) == (U.BOUNDARY_CLOSED, "10")
    assert f.line == line_of(path, 'roadId="10" boundaryLane="-1"')
    assert (f.x, f.y) == pytest.approx((65.0, -3.5), abs=1e-6)  # s=15 of road 10, lane -1's outer border
    assert "5 m from where the joint segment of road 2" in f.message


def test_a_missing_joint_leaves_a_gap_too():
    (f,) = findings(fixture("boundary-roads", "fail_missing_road.xodr"), RULE)
    assert (f.road, f.x, f.y) == ("16", pytest.approx(63.5), pytest.approx(10.0))
