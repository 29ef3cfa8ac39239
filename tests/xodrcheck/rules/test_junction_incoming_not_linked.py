"""Rule junction-incoming-not-linked: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "junction-incoming-not-linked"


def test_incoming_road_linking_the_connecting_road_instead_of_the_junction():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.road == "1"
    assert f.line == line_of(path, '<connection id="0"')
