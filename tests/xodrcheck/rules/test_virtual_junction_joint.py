"""Rule virtual-junction-joint: the findings each fail fixture gives."""

import pytest

from tests.xodrcheck.rules.helpers import findings, fixture, line_of
from xodrcheck.findings import Severity
from xodrcheck.rules.shared import junction_uids as U

RULE = "virtual-junction-joint"


def test_branch_leaving_at_an_angle():
    path = fixture(RULE, "fail_heading.xodr")
    found = {f.rule_uid: f for f in findings(path, RULE)}
    f = found[U.VIRTUAL_HEADING]
    assert (f.road, f.s, f.x, f.y) == ("2", 0.0, 50.0, 0.0)
    assert f.line == line_of(path, 'elementId="1" elementS="50"')
    assert "2.86 deg off" in f.message
    # turned 0.05 rad about its start, the lane's outer border (3.5 m out) moves 3.5 * 0.05 m
    assert "0.175 m apart" in found[U.VIRTUAL_SMOOTH].message


def test_branch_beside_its_lane():
    path = fixture(RULE, "fail_lane_gap.xodr")
    (f,) = findings(path, RULE)
    assert (f.rule_uid, f.severity, f.road, f.lane) == (U.VIRTUAL_SMOOTH, Severity.ERROR, "2", -1)
    assert (f.x, f.y) == pytest.approx((50.0, -5.0))  # the branch's outer border, 1.5 m right of the lane's
    assert "1.5 m apart" in f.message


def test_main_road_joined_at_the_wrong_s_is_off_its_lane_too():
    (f,) = findings(fixture("virtual-junction-branches", "fail_start_end.xodr"), RULE)
    assert f.rule_uid == U.VIRTUAL_SMOOTH and "5 m apart" in f.message
