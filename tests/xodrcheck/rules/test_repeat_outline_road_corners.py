"""Rule repeat-outline-road-corners: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "repeat-outline-road-corners"


def test_repeated_object_outlined_in_road_corners():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.line == line_of(path, "<cornerRoad") and f"<repeat> at line {line_of(path, '<repeat')}" in f.message
