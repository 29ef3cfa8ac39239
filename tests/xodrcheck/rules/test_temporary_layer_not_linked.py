"""Rule temporary-layer-not-linked: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture

RULE = "temporary-layer-not-linked"


def test_temporary_lane_without_a_way_in():
    (f,) = findings(fixture(RULE, "fail.xodr"), RULE)
    assert (f.road, f.lane, f.s) == ("1", -1, 20.0)
    assert "no predecessor on the permanent layer" in f.message


def test_a_permanent_lane_naming_the_temporary_lane_links_it_too():
    """pass.xodr links both ways; a temporary lane is linked when either side names the other."""
    text = fixture(RULE, "pass.xodr").read_text(encoding="utf-8")
    one_way = text.replace('<predecessor id="-1" layer="permanent"/>', "")
    from xodrcheck.check import check

    assert check(one_way.encode(), select=("L031",)).findings == ()
