"""Rule skeleton-outside-volume: the finding each fail fixture gives."""

import pytest

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "skeleton-outside-volume"


def test_vertex_above_the_volume_whose_section_stays_above_it():
    """The pole's top vertex at 5 m: 1 m above the 4 m volume; its section, level across the vertical pole, too."""
    path = fixture(RULE, "fail.xodr")
    inside, boundary = findings(path, RULE)
    assert inside.rule_uid.endswith("skeleton.points_inside_box") and "lies 1 m outside" in inside.message
    assert boundary.rule_uid.endswith("skeleton.points_boundary_inside_box")
    assert inside.line == boundary.line == line_of(path, 'dz="5"')
    assert (inside.x, inside.y) == pytest.approx((50.0, -6.8)), "the vertex, placed by the road's reference line"


def test_vertex_beside_the_volume_whose_section_reaches_into_it():
    path = fixture(RULE, "fail_inside_only.xodr")
    (f,) = findings(path, RULE)
    assert f.rule_uid.endswith("skeleton.points_inside_box") and "lies 0.1 m outside" in f.message
