"""Rule connection-road-missing: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "connection-road-missing"


def test_missing_connecting_road():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.line == line_of(path, 'connectingRoad="99"')
    assert "connectingRoad '99'" in f.message


def test_missing_incoming_road():
    path = fixture(RULE, "fail_incoming.xodr")
    (f,) = findings(path, RULE)
    assert f.line == line_of(path, 'incomingRoad="98"')
    assert "incomingRoad '98'" in f.message
