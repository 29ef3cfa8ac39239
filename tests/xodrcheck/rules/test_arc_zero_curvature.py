"""Rule arc-zero-curvature: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of
from xodrcheck.findings import Severity

RULE = "arc-zero-curvature"


def test_arc_without_curvature():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.s, f.severity) == ("1", 0.0, Severity.WARNING)
    assert f.line == line_of(path, '<arc curvature="0"/>')
