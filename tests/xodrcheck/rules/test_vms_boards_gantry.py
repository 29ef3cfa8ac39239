"""Rule vms-boards-gantry (T008): the findings each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of
from xodrcheck.rules.shared import feature_uids as U

RULE = "vms-boards-gantry"


def test_a_group_over_two_gantries_and_a_gantry_without_group():
    path = fixture(RULE, "fail.xodr")
    found = {f.rule_uid: f for f in findings(path, RULE)}
    assert set(found) == {U.GANTRY_SAME, U.GANTRY_VMS_GROUP}
    same = found[U.GANTRY_SAME]
    assert same.line == line_of(path, "<vmsGroup") and "board 30 on gantry g1, board 40 on gantry g2" in same.message
    alone = found[U.GANTRY_VMS_GROUP]
    assert alone.line == line_of(path, 'id="g3"') and "gantry g3 carries variable message boards 50" in alone.message
