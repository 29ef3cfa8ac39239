"""Rule plan-view-s-jump: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture

RULE = "plan-view-s-jump"


def test_s_jumps_by_two_metres():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.s) == ("1", 52.0)
    assert "should start at s=50" in f.message and "gap of 2 m" in f.message
