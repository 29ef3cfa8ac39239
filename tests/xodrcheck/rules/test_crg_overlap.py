"""Rule crg-overlap (U003): the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of
from xodrcheck.findings import Severity

RULE = "crg-overlap"


def test_two_elevation_files_overlapping_by_20_m():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.severity is Severity.WARNING and f.s == 40 and f.line == line_of(path, 'file="b.crg"')
    assert "from s=40 to 60 for purpose elevation" in f.message
