"""Rule connecting-road-outside-junction: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "connecting-road-outside-junction"


def test_connecting_road_not_in_the_junction():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.road == "11"
    assert f.line == line_of(path, 'connectingRoad="11"')
