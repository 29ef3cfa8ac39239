"""Rule surface-volumes-overlap: the finding each fail fixture gives."""

import pytest

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "surface-volumes-overlap"


def test_two_patches_half_a_metre_apart():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.line == line_of(path, 'id="p1"') and "road 1 object p2" in f.message and "by 0.24 m2" in f.message
    assert (f.x, f.y) == pytest.approx((50.25, -1.75)), "inside the shared area"


def test_instances_of_one_repeat():
    (f,) = findings(fixture(RULE, "fail_repeat.xodr"), RULE)
    assert "another instance of it (at s=20.5)" in f.message
