"""Rule junction-type-attribute: the finding each fail fixture gives."""

import pytest

from tests.xodrcheck.rules.helpers import findings, fixture, line_of
from xodrcheck.rules.shared import junction_uids as U

RULE = "junction-type-attribute"


@pytest.mark.parametrize(
    ("name", "uid", "text"),
    [
        ("fail_overlap_zone.xodr", U.COMMON_DIRECT_ATTRIBUTES, 'overlapZone="10"'),
        ("fail_main_road.xodr", U.COMMON_VIRTUAL_ATTRIBUTES, 'mainRoad="1"'),
        ("fail_virtual_connection.xodr", U.VIRTUAL_CONNECTIONS, 'type="virtual"'),
    ],
)
def test_attribute_of_another_junction_type(name, uid, text):
    path = fixture(RULE, name)
    (f,) = findings(path, RULE)
    assert f.rule_uid == uid
    assert f.line == line_of(path, text)


def test_main_road_message_names_the_attributes():
    (f,) = findings(fixture(RULE, "fail_main_road.xodr"), RULE)
    assert "mainRoad, sStart, sEnd" in f.message
