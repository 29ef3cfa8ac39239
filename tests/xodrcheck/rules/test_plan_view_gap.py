"""Rule plan-view-gap: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "plan-view-gap"


def test_five_centimetre_gap():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.s) == ("1", 50.0)
    assert "a gap of 0.05 m" in f.message
    assert f.line == line_of(path, 'x="50.05"')
