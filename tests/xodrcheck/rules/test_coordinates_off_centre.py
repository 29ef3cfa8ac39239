"""Rule coordinates-off-centre: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of
from xodrcheck.findings import Severity

RULE = "coordinates-off-centre"


def test_utm_coordinates_without_offset():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.severity is Severity.WARNING and f.line == line_of(path, "<header")
    assert (f.x, f.y) == (500000.0, 5400000.0)
    assert "5423 km from (0, 0)" in f.message and "step by 0.5 m" in f.message
    assert "add (500000.0, 5400000.0) to the header's <offset>" in f.message
