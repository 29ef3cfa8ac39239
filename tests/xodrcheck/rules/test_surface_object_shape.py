"""Rule surface-object-shape: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "surface-object-shape"


def test_circular_object_with_a_surface():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.line == line_of(path, "<surface>") and "is circular (radius)" in f.message
