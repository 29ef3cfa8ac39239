"""Rule surface-repeated-continuously: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "surface-repeated-continuously"


def test_continuous_repeat_of_a_surface_object():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.line == line_of(path, "<repeat ") and "has distance 0" in f.message
