"""Rule plan-view-kink: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture

RULE = "plan-view-kink"


def test_kink_without_gap():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.s) == ("1", 50.0)
    assert "5.73 deg" in f.message
