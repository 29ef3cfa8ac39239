"""Rule marking-corner-references: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of
from xodrcheck.check import check

RULE = "marking-corner-references"


def test_one_corner_out_of_order_and_a_repeat_that_does_not_enclose():
    path = fixture(RULE, "fail.xodr")
    found = [(f.line, f.rule_uid.rsplit(":", 1)[-1]) for f in findings(path, RULE)]
    first = line_of(path, "<marking ", 1)
    assert found == [
        (first, "road.object.marking.outline_corner_reference_count"),
        (first, "road.object.object_marking.outline_corner_reference_count"),
        (first + 1, "road.object.object_marking.keep_id_ordered"),
        (first + 2, "road.object.object_marking.enclosed_outline_marking"),
    ]


def test_an_open_outline_is_not_enclosed():
    (f,) = findings(fixture(RULE, "fail_open.xodr"), RULE)
    assert "an open outline does not enclose the object" in f.message


def test_the_closing_edge_is_crossed_once_at_most():
    """3 -> 0 crosses the closing edge (passes); 3 -> 0 -> 2 -> 1 would run round the outline a second time."""
    text = fixture(RULE, "pass.xodr").read_text(encoding="utf-8")
    twice = text.replace(
        '<cornerReference id="3"/><cornerReference id="0"/>',
        '<cornerReference id="3"/><cornerReference id="0"/><cornerReference id="2"/><cornerReference id="1"/>',
        1,
    )
    found = [f for f in check(twice.encode(), select=("B023",)).findings if f.code == "B023"]
    assert [f.rule_uid.rsplit(".", 1)[-1] for f in found] == ["keep_id_ordered"]
