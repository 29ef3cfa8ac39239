"""Rule lane-records-out-of-order: the finding each fail fixture gives."""

import pytest

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "lane-records-out-of-order"


@pytest.mark.parametrize(
    ("tag", "uid", "lane"),
    [
        ("access", "road.lane.access.elem_asc_order", -2),
        ("material", "road.lane.material.elem_asc_order", -2),
        ("rule", "road.lane.rule.elem_asc_order", -2),
        ("visibility", "road.lane.lane_properties.elem_asc_order", -1),
    ],
)
def test_the_record_that_goes_back(tag, uid, lane):
    path = fixture(RULE, f"fail_{tag}.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.lane) == ("1", lane)
    assert f.rule_uid.endswith(":" + uid)
    assert f.line == line_of(path, f'<{tag} sOffset="0"')
    assert "before the one at line" in f.message
