"""Rule connection-duplicate: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "connection-duplicate"


def test_two_connections_for_one_incoming_and_connecting_road():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.road == "10"
    assert f.line == line_of(path, '<connection id="2"')
