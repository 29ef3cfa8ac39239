"""Rule junction-lane-link-outbound: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of
from xodrcheck.findings import Severity

RULE = "junction-lane-link-outbound"


def test_lane_link_from_an_outgoing_lane_is_a_warning_in_17():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.lane) == ("1", 1)
    assert f.severity is Severity.WARNING
    assert f.line == line_of(path, '<laneLink from="1" to="1"/>')


def test_before_17_it_is_an_info():
    (f,) = findings(fixture(RULE, "fail_14.xodr"), RULE)
    assert f.severity is Severity.INFO


def test_an_outbound_lane_link_is_an_error_from_1_8():
    from xodrcheck.rules.shared import junction_uids as U

    path = fixture(RULE, "fail_1_8.xodr")
    (f,) = findings(path, RULE)
    assert (f.severity, f.rule_uid, f.road, f.lane) == (Severity.ERROR, U.CONNECTION_ONE_LINK, "1", 1)
    assert f.line == line_of(path, '<laneLink from="1" to="-1"/>')


def test_direct_junctions_are_not_checked():
    """12.6.1 links lane 1 of the road that ends at a direct junction (its traffic leaves it)."""
    assert findings(fixture("direct-junction-shape", "pass.xodr"), RULE) == []


def test_lanes_driven_both_ways_lead_into_the_junction_too():
    """11.3.1: direction="both" allows both driving directions, so each of its links leads into the junction."""
    assert findings(fixture(RULE, "pass_direction_both.xodr"), RULE) == []
    assert findings(fixture("junction-lane-link-direction", "pass_sidewalk.xodr"), RULE) == []


def test_a_reversed_lane_leaves_the_junction_at_its_road_end():
    path = fixture(RULE, "fail_direction_reversed.xodr")
    found = findings(path, RULE)
    assert [(f.road, f.lane, f.severity) for f in found] == [("1", -1, Severity.ERROR)] * 2
    assert all('direction="reversed"' in f.message for f in found)
