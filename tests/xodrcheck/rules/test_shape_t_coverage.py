"""Rule shape-t-coverage: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "shape-t-coverage"


def test_profile_starting_inside_the_road():
    """Lanes -1 (3.5 m) and -2 (1.5 m) reach t = -5; the profile at s=50 starts at t = -3.5."""
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.s, f.x, f.y) == ("1", 50.0, 50.0, 0.0)
    assert f.line == line_of(path, '<shape s="50" t="-3.5"')
    assert "start at t=-3.5, but the road reaches t=-5" in f.message and "1.5 m" in f.message
