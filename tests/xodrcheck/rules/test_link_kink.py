"""Rule link-kink: its pass fixtures give no finding, its fail fixtures one where the defect is."""

from tests.xodrcheck.rules.helpers import assert_passes, findings, fixture
from xodrcheck.findings import Severity

RULE = "link-kink"


def test_pass_fixtures_give_no_finding():
    assert_passes(RULE)


def test_heading_kink_without_gap():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.road == "1" and f.severity is Severity.ERROR
    assert "(0.1 rad)" in f.message
