"""Rule skeleton-segment-degenerate: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of
from xodrcheck.findings import Severity

RULE = "skeleton-segment-degenerate"


def test_two_vertices_at_one_place():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.severity is Severity.INFO and f.line == line_of(path, 'id="2" intersectionPoint="true"')
    assert f"the one before it (line {f.line - 1})" in f.message
