"""Rule duplicate-lane-id: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "duplicate-lane-id"


def test_second_lane_with_the_id_is_reported_with_its_road_and_section():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.lane, f.section_s) == ("2", -1, 0.0)
    assert f.line == line_of(path, '<lane id="-1" type="sidewalk"')
