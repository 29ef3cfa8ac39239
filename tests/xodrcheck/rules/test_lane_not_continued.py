"""Rule lane-not-continued: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of
from xodrcheck.findings import Severity

RULE = "lane-not-continued"


def test_full_width_lane_appearing_at_a_road_link():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.lane, f.s) == ("2", -2, 0.0)
    assert f.severity is Severity.WARNING and f.basis == "plausibility"  # 11.1 in words, no Annex F rule
    assert [g.severity for g in findings(path, RULE, "generator")] == [Severity.ERROR]
    assert f.line == line_of(path, '<lane id="-2"')
    assert "3.50 m wide" in f.message and "no predecessor in road 1" in f.message


def test_width_of_a_lane_given_by_borders_comes_from_the_geometry():
    path = fixture(RULE, "fail_border.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.lane) == ("2", -2)
    assert "3.00 m wide" in f.message


def test_connecting_lane_without_predecessor_is_not_excused_by_the_junction_lane_link():
    """Regression (found by fuzzing the generator with a dropped lane link): the junction's laneLink from road 1 does
    not stand in for the connecting lane's own predecessor."""
    path = fixture(RULE, "fail_junction.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.lane, f.s) == ("10", -1, 0.0)
    assert f.severity is Severity.WARNING
    assert [g.severity for g in findings(path, RULE, "generator")] == [Severity.ERROR]
    assert "no predecessor in road 1" in f.message
