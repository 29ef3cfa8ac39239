"""Rule surface-object-not-referenced: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "surface-object-not-referenced"


def test_patch_over_a_road_without_reference():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.line) == ("1", line_of(path, 'id="p1"'))
    assert "covers 1 m2 of road 2's lanes" in f.message and '<objectReference id="p1">' in f.message
