"""Rule signal-validity-direction (T010): the findings each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of
from xodrcheck.rules.shared import feature_uids as U

RULE = "signal-validity-direction"


def test_right_hand_traffic():
    path = fixture(RULE, "fail_rht.xodr")
    found = {f.rule_uid: f for f in findings(path, RULE)}
    assert set(found) == {U.VALIDITY_RHT, U.REFERENCE_RHT}
    assert found[U.VALIDITY_RHT].line == line_of(path, "<signal ")
    assert "spans positive ones" in found[U.VALIDITY_RHT].message
    assert 'orientation="none" shall be used' in found[U.REFERENCE_RHT].message


def test_left_hand_traffic_the_other_way_round():
    found = {f.rule_uid: f for f in findings(fixture(RULE, "fail_lht.xodr"), RULE)}
    assert set(found) == {U.VALIDITY_LHT, U.REFERENCE_LHT}
    assert "left-hand traffic" in found[U.VALIDITY_LHT].message and found[U.VALIDITY_LHT].road == "2"
