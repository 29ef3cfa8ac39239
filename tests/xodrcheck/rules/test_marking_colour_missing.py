"""Rule marking-colour-missing: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of
from xodrcheck.check import check

RULE = "marking-colour-missing"


def test_marking_without_colour_breaks_both_rules_from_1_8():
    path = fixture(RULE, "fail.xodr")
    found = findings(path, RULE)
    assert [f.rule_uid.rsplit(":", 1)[-1] for f in found] == [
        "road.object.marking.colour",
        "road.object.object_marking.colour",
    ]
    assert {f.line for f in found} == {line_of(path, '<marking side="left"')}


def test_a_1_7_file_gets_the_1_7_rule_only():
    text = fixture(RULE, "fail.xodr").read_text(encoding="utf-8").replace('revMinor="8"', 'revMinor="7"')
    found = [f for f in check(text.encode(), select=("B020",)).findings if f.code == "B020"]
    assert [f.rule_uid.rsplit(":", 1)[-1] for f in found] == ["road.object.marking.colour"]
