"""Rule switch-topology (W004): the findings each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of
from xodrcheck.rules.shared import feature_uids as U

RULE = "switch-topology"


def test_main_track_between_switches_and_a_partner_of_a_single_switch():
    path = fixture(RULE, "fail.xodr")
    found = {f.rule_uid: f for f in findings(path, RULE)}
    assert set(found) == {U.SWITCH_CONNECTION, U.SINGLE_SWITCH_NO_PARTNER}
    assert found[U.SWITCH_CONNECTION].road == "3" and "side track of switch '12'" in found[U.SWITCH_CONNECTION].message
    assert found[U.SINGLE_SWITCH_NO_PARTNER].line == line_of(path, "<partner")
