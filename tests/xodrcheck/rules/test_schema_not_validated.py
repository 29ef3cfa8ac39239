"""Rule schema-not-validated: its pass fixtures give no finding, its fail fixtures one where the defect is."""

from tests.xodrcheck.rules.helpers import assert_passes, findings, fixture, line_of
from xodrcheck.findings import Severity

RULE = "schema-not-validated"


def test_pass_fixtures_give_no_finding():
    assert_passes(RULE)


def test_unknown_version_gives_one_finding_at_the_header():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.line == line_of(path, "<header")
    assert f.severity is Severity.INFO and "1.9" in f.message
