"""Rule degenerate-geometry: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of
from xodrcheck.findings import Severity

RULE = "degenerate-geometry"


def test_zero_length_element_is_an_error():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.severity is Severity.ERROR and f.s == 50.0
    assert f.line == line_of(path, 'length="0"')
