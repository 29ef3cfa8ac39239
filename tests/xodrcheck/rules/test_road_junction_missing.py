"""Rule road-junction-missing: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "road-junction-missing"


def test_road_naming_a_missing_junction():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.road == "2" and f.line == line_of(path, 'junction="300"')
