"""Rule temporary-lane-physical: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "temporary-lane-physical"


def test_material_on_a_temporary_lane():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.lane, f.section_s) == ("1", -1, 20.0)
    assert f.line == line_of(path, "<material ")
