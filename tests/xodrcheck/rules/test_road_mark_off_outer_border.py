"""Rule road-mark-off-outer-border: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of
from xodrcheck.rules.shared import lane_uids as U

RULE = "road-mark-off-outer-border"


def test_lines_on_the_inner_border_or_past_the_middle_of_the_lane():
    path = fixture(RULE, "fail.xodr")
    left, right = sorted(findings(path, RULE), key=lambda f: f.line)
    assert (left.road, left.lane, left.line) == ("1", 1, line_of(path, 'tOffset="-2.5"'))
    assert (right.road, right.lane, right.line) == ("1", -1, line_of(path, 'tOffset="3.5"'))
    assert {left.rule_uid, right.rule_uid} == {U.ROAD_MARK_ONLY_OUTER}
    assert "tOffset=3.5, 3.5 m from the lane's outer border toward its inside, in a lane 3.5 m wide" in right.message


def test_lines_straddling_or_near_the_outer_border_pass():
    """A double line straddling the outer border, a line 0.2 m in from it: both style the outer border."""
    assert findings(fixture(RULE, "pass.xodr"), RULE) == []
