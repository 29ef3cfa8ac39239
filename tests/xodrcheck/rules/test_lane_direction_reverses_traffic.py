"""Rule lane-direction-reverses-traffic: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "lane-direction-reverses-traffic"


def test_all_drivable_lanes_reversed():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.lane, f.line) == ("1", 1, line_of(path, '<lane id="1"'))
    assert "(1, -1)" in f.message and "RHT/LHT" in f.message


def test_a_contraflow_lane_is_fine():
    assert findings(fixture(RULE, "pass.xodr"), RULE) == []
