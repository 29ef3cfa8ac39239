"""Rule reference-radius-too-small: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture

RULE = "reference-radius-too-small"


def test_four_metre_arc_between_driving_lanes():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.road == "1" and f.lane is None
    assert "radius of 4 m" in f.message
