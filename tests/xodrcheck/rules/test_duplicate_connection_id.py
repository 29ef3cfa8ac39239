"""Rule duplicate-connection-id: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "duplicate-connection-id"


def test_second_connection_with_the_id_is_reported():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.line == line_of(path, '<connection id="0"', occurrence=2)
    assert "junction 100" in f.message
