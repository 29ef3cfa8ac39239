"""Rule road-junction-missing: its pass fixtures give no finding, its fail fixtures one where the defect is."""

from tests.xodrcheck.rules.helpers import assert_passes, findings, fixture, line_of

RULE = "road-junction-missing"


def test_pass_fixtures_give_no_finding():
    assert_passes(RULE)


def test_road_naming_a_missing_junction():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.road == "2" and f.line == line_of(path, 'junction="300"')
