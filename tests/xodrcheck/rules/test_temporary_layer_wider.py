"""Rule temporary-layer-wider: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture

RULE = "temporary-layer-wider"


def test_temporary_right_lanes_wider_than_the_road():
    (f,) = findings(fixture(RULE, "fail.xodr"), RULE)
    assert (f.road, f.section_s) == ("1", 20.0)
    assert "right lanes" in f.message and "reach 1 m further out" in f.message
