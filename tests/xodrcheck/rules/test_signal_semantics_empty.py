"""Rule signal-semantics-empty (T005): the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "signal-semantics-empty"


def test_empty_semantics():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.line == line_of(path, "<semantics/>") and f.road == "1"
