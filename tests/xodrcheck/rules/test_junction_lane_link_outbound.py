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
