"""Rule road-link-target-missing: its pass fixtures give no finding, its fail fixtures one where the defect is."""

from tests.xodrcheck.rules.helpers import assert_passes, findings, fixture, line_of

RULE = "road-link-target-missing"


def test_pass_fixtures_give_no_finding():
    assert_passes(RULE)


def test_successor_to_a_missing_road():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.road == "1" and f.line == line_of(path, 'elementId="7"')
    assert "'7'" in f.message


def test_junction_link_naming_a_road_id_gets_a_hint():
    path = fixture(RULE, "fail_junction.xodr")
    (f,) = findings(path, RULE)
    assert f.road == "1" and f.line == line_of(path, 'elementType="junction" elementId="2"')
    assert "should elementType be road" in f.message
