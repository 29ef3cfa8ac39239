"""Rule permanent-section-length: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "permanent-section-length"


def test_length_on_a_permanent_section():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.section_s, f.line) == ("1", 0.0, line_of(path, '<laneSection s="0" length="100"'))


def test_length_leaving_the_road_without_permanent_lanes():
    """The permanent section at s=20 ends at s=40 and the next starts at s=50: one finding, under
    layer_mandatory_permanent (no permanent lane from s=40 to s=50), which also says the length is not allowed."""
    from xodrcheck.rules.shared import lane_uids as U

    path = fixture(RULE, "fail_gap.xodr")
    (f,) = findings(path, RULE)
    assert (f.rule_uid, f.line) == (U.LAYER_MANDATORY_PERMANENT, line_of(path, '<laneSection s="20" length="20"'))
    assert "no permanent lane from s=40 to s=50" in f.message and "only temporary lane sections" in f.message
    assert findings(path, "lane-section-without-lanes") == []
