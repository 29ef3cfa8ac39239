"""Rule junction-type-elements: the finding each fail fixture gives."""

import pytest

from tests.xodrcheck.rules.helpers import findings, fixture, line_of
from xodrcheck.rules.shared import junction_uids as U

RULE = "junction-type-elements"


@pytest.mark.parametrize(
    ("name", "uid", "text", "occurrence"),
    [
        ("fail_boundary_direct.xodr", U.BOUNDARY_ONLY_COMMON, "<boundary>", 1),
        ("fail_crossing_connection.xodr", U.CROSSING_ONLY_ROAD_SECTIONS, "<connection", 1),
        ("fail_two_grids.xodr", U.GRID_ONLY_ONE, "<elevationGrid", 2),
        (
            "fail_predecessor.xodr",
            U.COMMON_NO_PRED_SUCC,
            '<link><predecessor elementType="road" elementId="1" contactPoint',
            1,
        ),
    ],
)
def test_element_the_junction_type_does_not_allow(name, uid, text, occurrence):
    path = fixture(RULE, name)
    (f,) = findings(path, RULE)
    assert f.rule_uid == uid
    assert f.line == line_of(path, text, occurrence)
