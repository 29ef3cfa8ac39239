"""Rule junction-lane-link-missing-lane: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "junction-lane-link-missing-lane"


def test_to_lane_missing_on_the_connecting_road():
    path = fixture(RULE, "fail_to.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.lane) == ("10", -3)
    assert f.line == line_of(path, 'to="-3"')


def test_from_lane_missing_at_the_incoming_roads_junction_end():
    path = fixture(RULE, "fail_from.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.lane) == ("2", 5)
    assert f.line == line_of(path, 'from="5"')
    assert "at its start" in f.message
