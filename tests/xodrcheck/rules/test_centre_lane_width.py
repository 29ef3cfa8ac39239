"""Rule centre-lane-width: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "centre-lane-width"


def test_centre_lane_with_a_width_record():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.lane) == ("1", 0)
    assert f.line == line_of(path, 'a="0.2"')
