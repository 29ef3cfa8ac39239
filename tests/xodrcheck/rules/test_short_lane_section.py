"""Rule short-lane-section: its pass fixtures give no finding, its fail fixtures one where the defect is."""

from tests.xodrcheck.rules.helpers import assert_passes, findings, fixture

RULE = "short-lane-section"


def test_pass_fixtures_give_no_finding():
    assert_passes(RULE)


def test_five_millimetre_section():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.section_s) == ("1", 0.0)
    assert "0.005 m long" in f.message
