"""Rule border-folds: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture

RULE = "border-folds"


def test_border_past_the_centre_of_curvature():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.lane) == ("1", 1)
    assert "3.5 m to the left" in f.message and "radius 2 m" in f.message
