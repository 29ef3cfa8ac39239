"""Rule connecting-road-outside-junction: its pass fixtures give no finding, its fail fixtures one where the defect is."""

from tests.xodrcheck.rules.helpers import assert_passes, findings, fixture, line_of

RULE = "connecting-road-outside-junction"


def test_pass_fixtures_give_no_finding():
    assert_passes(RULE)


def test_connecting_road_not_in_the_junction():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.road == "11"
    assert f.line == line_of(path, 'connectingRoad="11"')
