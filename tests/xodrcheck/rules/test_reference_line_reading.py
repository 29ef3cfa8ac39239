"""Reader rules that enforce the reference-line rules of Annex F (road.geometry.*, road.elevation/superelevation
order): the finding each of their fail fixtures gives, where, and with which UID."""

import pytest

from tests.xodrcheck.rules.helpers import findings, fixture, line_of
from xodrcheck.rules.shared import road_uids as U


@pytest.mark.parametrize(
    ("rule", "name", "uid", "line_text"),
    [
        ("records-out-of-order", "fail_geometry.xodr", U.GEOMETRY_ORDER, '<geometry s="0"'),
        ("records-out-of-order", "fail_elevation.xodr", U.ELEVATION_ORDER, '<elevation s="0"'),
        ("records-out-of-order", "fail_superelevation.xodr", U.SUPERELEVATION_ORDER, '<superelevation s="0"'),
        ("missing-element", "fail_no_plan_view.xodr", U.GEOMETRY_REFLINE_EXISTS, '<road id="1"'),
        ("missing-element", "fail_no_geometry.xodr", U.GEOMETRY_REFLINE_EXISTS, "    <planView>"),
        ("repeated-element", "fail_two_plan_views.xodr", U.GEOMETRY_ONLY_ONE_REFLINE, 'y="10"'),
        ("unknown-geometry", "fail_two_shapes.xodr", U.GEOMETRY_ONE_ELEMENT, "<geometry"),
        ("unknown-geometry", "fail_no_shape.xodr", U.GEOMETRY_ONE_ELEMENT, "<geometry"),
    ],
)
def test_reader_finding_names_the_rule_of_the_standard(rule, name, uid, line_text):
    path = fixture(rule, name)
    (f,) = findings(path, rule)
    assert f.road == "1" and f.rule_uid == uid
    expected = line_of(path, line_text) - (1 if line_text == 'y="10"' else 0)  # the second <planView> opens above
    assert f.line == expected


def test_a_second_plan_view_names_the_first():
    (f,) = findings(fixture("repeated-element", "fail_two_plan_views.xodr"), "repeated-element")
    assert "repeats the <planView> at line 7" in f.message
