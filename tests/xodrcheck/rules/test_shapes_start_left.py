"""Rule shapes-start-left: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "shapes-start-left"


def test_profile_starting_on_the_reference_line():
    path = fixture(RULE, "fail.xodr")
    found = findings(path, RULE)
    assert [(f.road, f.s, f.line) for f in found] == [("1", 0.0, line_of(path, '<shape s="0" t="0"'))]
    assert "start at t=0" in found[0].message
