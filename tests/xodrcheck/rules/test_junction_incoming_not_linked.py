"""Rule junction-incoming-not-linked: its pass fixtures give no finding, its fail fixtures one where the defect is."""

from tests.xodrcheck.rules.helpers import assert_passes, findings, fixture, line_of

RULE = "junction-incoming-not-linked"


def test_pass_fixtures_give_no_finding():
    assert_passes(RULE)


def test_incoming_road_linking_the_connecting_road_instead_of_the_junction():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.road == "1"
    assert f.line == line_of(path, '<connection id="0"')
