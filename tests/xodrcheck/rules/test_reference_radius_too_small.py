"""Rule reference-radius-too-small: its pass fixtures give no finding, its fail fixtures one where the defect is."""

from tests.xodrcheck.rules.helpers import assert_passes, findings, fixture

RULE = "reference-radius-too-small"


def test_pass_fixtures_give_no_finding():
    assert_passes(RULE)


def test_four_metre_arc_between_driving_lanes():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.road == "1" and f.lane is None
    assert "radius of 4 m" in f.message
