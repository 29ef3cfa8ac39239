"""Rule outline-too-few-corners: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "outline-too-few-corners"


def test_single_corners_break_their_kind_and_the_outline_rule():
    path = fixture(RULE, "fail.xodr")
    found = [(f.line, f.rule_uid.rsplit(":", 1)[-1]) for f in findings(path, RULE)]
    crosswalk, island = line_of(path, '<outline id="0"', 1), line_of(path, '<outline id="0"', 2)
    assert found == [
        (crosswalk, "road.corner_road.element_min_amount"),
        (crosswalk, "road.object.outline.outline_followed_by_corner"),
        (island, "road.corner_local.element_min_amount"),
        (island, "road.object.outline.outline_followed_by_corner"),
    ]


def test_empty_outline():
    (f,) = findings(fixture(RULE, "fail_empty.xodr"), RULE)
    assert "has no corner or curve" in f.message
