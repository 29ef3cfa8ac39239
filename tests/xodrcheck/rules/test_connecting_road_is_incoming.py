"""Rule connecting-road-is-incoming: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "connecting-road-is-incoming"


def test_connecting_road_used_as_incoming_road():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.road == "10"
    assert f.line == line_of(path, 'incomingRoad="10"')
