"""Rule degenerate-geometry: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of
from xodrcheck.findings import Severity

RULE = "degenerate-geometry"


def test_zero_length_element_is_an_error():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE, "generator")
    assert f.severity is Severity.ERROR and f.s == 50.0
    (f,) = findings(path, RULE)  # the 1.7 schema's length > 0 is S001's; here plausibility, a warning
    assert f.severity is Severity.WARNING and f.basis == "plausibility"
    assert f.line == line_of(path, 'length="0"')
