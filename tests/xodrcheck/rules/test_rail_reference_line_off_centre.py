"""Rule rail-reference-line-off-centre (W002): the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "rail-reference-line-off-centre"


def test_rail_lane_beside_the_reference_line():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.road == "1" and f.lane == -1 and f.line == line_of(path, 'type="rail"')
    assert "is at t=-1.250 m" in f.message
