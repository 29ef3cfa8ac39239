"""Rule marking-placement: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "marking-placement"


def test_markings_of_an_object_with_outline_outside_it():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.line == line_of(path, "<markings>") and f.rule_uid.endswith("markings_with_outline")


def test_side_marking_inside_an_outline():
    path = fixture(RULE, "fail_side.xodr")
    (f,) = findings(path, RULE)
    assert f.line == line_of(path, '<marking side="left"') and f.rule_uid.endswith("markings_without_outline")
    assert "runs along the left side" in f.message


def test_marking_naming_a_corner_its_outline_lacks():
    path = fixture(RULE, "fail_not_on.xodr")
    (f,) = findings(path, RULE)
    assert f.rule_uid.endswith("complete_or_partial_on_outline") and "references corner 7" in f.message
