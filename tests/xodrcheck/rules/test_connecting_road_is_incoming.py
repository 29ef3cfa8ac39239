"""Rule connecting-road-is-incoming: its pass fixtures give no finding, its fail fixtures one where the defect is."""

from tests.xodrcheck.rules.helpers import assert_passes, findings, fixture, line_of

RULE = "connecting-road-is-incoming"


def test_pass_fixtures_give_no_finding():
    assert_passes(RULE)


def test_connecting_road_used_as_incoming_road():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.road == "10"
    assert f.line == line_of(path, 'incomingRoad="10"')
