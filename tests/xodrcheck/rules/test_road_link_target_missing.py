"""Rule road-link-target-missing: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "road-link-target-missing"


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
