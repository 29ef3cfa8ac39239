"""Rule redundant-record: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of
from xodrcheck.findings import Severity

RULE = "redundant-record"


def test_width_record_repeating_the_previous_one():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.lane, f.s) == ("1", -1, 50.0)
    assert f.severity is Severity.INFO
    assert f.line == line_of(path, 'sOffset="50"')
