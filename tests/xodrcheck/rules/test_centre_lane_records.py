"""Rule centre-lane-records: the finding each fail fixture gives."""

import pytest

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "centre-lane-records"


@pytest.mark.parametrize(
    ("tag", "uid"),
    [
        ("access", "road.lane.access.center_lane_no_acc_rule"),
        ("height", "road.lane.height.center_lane_no_height"),
        ("material", "road.lane.material.center_lane_no_material"),
        ("speed", "road.lane.speed.center_lane_no_spd_lmt"),
    ],
)
def test_each_record_of_the_centre_lane(tag, uid):
    path = fixture(RULE, f"fail_{tag}.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.lane) == ("1", 0)
    assert f.rule_uid.endswith(":" + uid)
    assert f.line == line_of(path, f"<{tag} ")
    assert f"<{tag}>" in f.message
