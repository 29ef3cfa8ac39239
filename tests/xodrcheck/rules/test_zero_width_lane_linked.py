"""Rule zero-width-lane-linked: its pass fixtures give no finding, its fail fixtures one where the defect is."""

from tests.xodrcheck.rules.helpers import assert_passes, findings, fixture
from xodrcheck.findings import Severity

RULE = "zero-width-lane-linked"


def test_pass_fixtures_give_no_finding():
    assert_passes(RULE)


def test_linking_the_opening_lane_is_an_error_in_17():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.lane) == ("2", -1)
    assert f.severity is Severity.ERROR
    assert "lane -2" in f.message and "opens" in f.message


def test_before_17_it_is_a_warning():
    path = fixture(RULE, "fail_14.xodr")
    (f,) = findings(path, RULE)
    assert f.severity is Severity.WARNING
