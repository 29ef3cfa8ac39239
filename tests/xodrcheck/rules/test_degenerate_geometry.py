"""Rule degenerate-geometry: its pass fixtures give no finding, its fail fixtures one where the defect is."""

from tests.xodrcheck.rules.helpers import assert_passes, findings, fixture, line_of
from xodrcheck.findings import Severity

RULE = "degenerate-geometry"


def test_pass_fixtures_give_no_finding():
    assert_passes(RULE)


def test_zero_length_element_is_an_error():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.severity is Severity.ERROR and f.s == 50.0
    assert f.line == line_of(path, 'length="0"')
