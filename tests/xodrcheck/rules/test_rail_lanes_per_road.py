"""Rule rail-lanes-per-road (W001): the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "rail-lanes-per-road"


def test_two_tram_lanes_in_one_section():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.road == "1" and f.section_s == 0 and f.line == line_of(path, "<laneSection")
    assert "2 rail-bound lanes (1 (tram), -1 (tram))" in f.message
