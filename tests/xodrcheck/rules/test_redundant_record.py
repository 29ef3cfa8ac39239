"""Rule redundant-record: its pass fixtures give no finding, its fail fixtures one where the defect is."""

from tests.xodrcheck.rules.helpers import assert_passes, findings, fixture, line_of
from xodrcheck.findings import Severity

RULE = "redundant-record"


def test_pass_fixtures_give_no_finding():
    assert_passes(RULE)


def test_width_record_repeating_the_previous_one():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.lane, f.s) == ("1", -1, 50.0)
    assert f.severity is Severity.INFO
    assert f.line == line_of(path, 'sOffset="50"')
