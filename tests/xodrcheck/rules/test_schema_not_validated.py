"""Rule schema-not-validated: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of
from xodrcheck.findings import Severity

RULE = "schema-not-validated"


def test_unknown_version_gives_one_finding_at_the_header():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.line == line_of(path, "<header")
    assert f.severity is Severity.INFO and "1.10" in f.message
