"""Rule centre-lane-invalid: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "centre-lane-invalid"


def test_non_zero_lane_in_the_centre():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.lane) == ("1", 5)
    assert f.line == line_of(path, '<lane id="5"')
