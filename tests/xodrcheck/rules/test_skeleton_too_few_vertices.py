"""Rule skeleton-too-few-vertices: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "skeleton-too-few-vertices"


def test_polylines_of_one_vertex():
    path = fixture(RULE, "fail.xodr")
    found = [(f.line, f.rule_uid.rsplit(".", 1)[-1]) for f in findings(path, RULE)]
    pole, trunk = line_of(path, '<polyline id="1"', 1), line_of(path, '<polyline id="1"', 2)
    assert found == [
        (pole, "element_min_amount"),
        (pole, "polyline_followed_by_vertex"),
        (trunk, "element_min_amount"),
        (trunk, "polyline_followed_by_vertex"),
    ]
