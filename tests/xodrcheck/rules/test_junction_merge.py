"""Rule junction-merge: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "junction-merge"


def test_two_incoming_lanes_into_one_connecting_lane():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.lane) == ("10", -1)
    assert f.line == line_of(path, '<laneLink from="-2" to="-1"/>')
    assert "2 lanes" in f.message
