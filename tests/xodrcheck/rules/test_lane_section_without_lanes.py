"""Rule lane-section-without-lanes: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of
from xodrcheck.findings import Severity

RULE = "lane-section-without-lanes"


def test_permanent_section_with_only_its_centre_lane():
    """Not drivable (lane_section_drivable, a "should"); it still has lane 0, so layer_mandatory_permanent (at least
    one lane of the permanent layer at each s) is not what it breaks."""
    from xodrcheck.rules.shared import lane_uids as U

    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.section_s, f.severity, f.rule_uid) == ("1", 0.0, Severity.WARNING, U.LANE_SECTION_DRIVABLE)
    assert f.line == line_of(path, '<laneSection s="0"')


def test_no_lane_valid_for_the_whole_section_is_a_warning():
    (f,) = findings(fixture(RULE, "fail_drivable.xodr"), RULE)
    assert f.severity is Severity.WARNING and "sOffset 0" in f.message
