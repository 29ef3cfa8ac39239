"""Rule signal-reference-not-signal (T013): the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "signal-reference-not-signal"


def test_reference_to_an_object():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.line == line_of(path, "<signalReference")
    assert f"names an object (line {line_of(path, '<object ')})" in f.message
