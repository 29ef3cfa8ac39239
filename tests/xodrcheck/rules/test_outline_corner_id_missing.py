"""Rule outline-corner-id-missing: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "outline-corner-id-missing"


def test_corners_without_ids_in_outlines_with_markings():
    path = fixture(RULE, "fail.xodr")
    road, local = findings(path, RULE)
    assert road.rule_uid.endswith("corner_road.mandatory_id_with_markings")
    assert road.line == line_of(path, '<cornerRoad s="32"') and "2 <cornerRoad>" in road.message
    assert local.rule_uid.endswith("corner_local.mandatory_id_with_markings") and "4 <cornerLocal>" in local.message
