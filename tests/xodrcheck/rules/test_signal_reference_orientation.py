"""Rule signal-reference-orientation (T012): the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "signal-reference-orientation"


def test_reference_without_orientation():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.line == line_of(path, "<signalReference") and "has no orientation" in f.message
