"""Rule virtual-junction-range: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "virtual-junction-range"


def test_end_beyond_the_main_road():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.line) == ("1", line_of(path, '<junction id="555"'))
    assert "sEnd 250 is not on main road 1 (0 to 200)" in f.message
