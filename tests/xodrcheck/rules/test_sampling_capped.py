"""Rule sampling-capped: its pass fixtures give no finding, its fail fixture (a road of 1e9 m) one for its section."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of
from xodrcheck.findings import Severity

RULE = "sampling-capped"


def test_road_of_1e9_m_is_sampled_coarser_and_says_so():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.severity is Severity.WARNING and f.road == "1" and f.section_s == 0.0
    assert "200,000" in f.message and "5000 m step" in f.message
    assert f.line == line_of(path, '<laneSection s="0">')
