"""Rule outline-corners-mixed: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "outline-corners-mixed"


def test_road_and_local_corners_break_both_rules():
    path = fixture(RULE, "fail.xodr")
    found = findings(path, RULE)
    assert sorted(f.rule_uid.rsplit(":", 1)[-1] for f in found) == [
        "road.corner_local.no_mixing_road_local",
        "road.corner_road.corner_road_local_exclusivity",
    ]
    assert {f.line for f in found} == {line_of(path, "<cornerLocal")}, "at the first corner of the other kind"


def test_road_corners_and_a_curve_break_exclusivity_only():
    path = fixture(RULE, "fail_curve.xodr")
    (f,) = findings(path, RULE)
    assert f.rule_uid.endswith("corner_road_local_exclusivity") and "<cornerRoad>, <curveLocal>" in f.message
