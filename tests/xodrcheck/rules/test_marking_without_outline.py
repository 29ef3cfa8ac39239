"""Rule marking-without-outline: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "marking-without-outline"


def test_corner_references_and_no_side_without_outline():
    path = fixture(RULE, "fail.xodr")
    references, side = findings(path, RULE)
    assert (
        references.rule_uid.endswith("no_cornerreference_if_no_outline") and "2 <cornerReference>" in references.message
    )
    assert references.line == line_of(path, "<marking ")
    assert side.rule_uid.endswith("no_outline_side_attr") and "has no side" in side.message
