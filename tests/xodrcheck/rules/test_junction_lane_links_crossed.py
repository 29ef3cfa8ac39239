"""Rule junction-lane-links-crossed: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture

RULE = "junction-lane-links-crossed"


def test_swapped_lane_links():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.road == "1"
    assert "lanes -1 and -2 of road 1" in f.message and "swapped order" in f.message
