"""Rule junction-lane-link-direction: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "junction-lane-link-direction"


def test_lane_link_into_a_lane_running_back():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.lane) == ("1", -1)
    assert f.line == line_of(path, '<laneLink from="-1" to="1"/>')


def test_lanes_without_one_direction_have_none_to_contradict():
    """A sidewalk (CARLA's towns) and a lane with direction="both" (ASAM's Ex_Bidirectional_Junction) continue as a
    right lane of a connecting road whose reference line runs along their outer edge: no traffic reverses there."""
    assert findings(fixture(RULE, "pass_sidewalk.xodr"), RULE) == []
    assert findings(fixture(RULE, "pass_direction_both.xodr"), RULE) == []
