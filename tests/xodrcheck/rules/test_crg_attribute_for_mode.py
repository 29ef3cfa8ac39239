"""Rule crg-attribute-for-mode (U001): the findings each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of
from xodrcheck.rules.shared import feature_uids as U

RULE = "crg-attribute-for-mode"


def test_each_forbidden_combination_once():
    path = fixture(RULE, "fail.xodr")
    found = findings(path, RULE)
    assert sorted(f.rule_uid for f in found) == sorted(
        [U.CRG_ATTACH_FRICTION, U.CRG_FRICTION_Z, U.CRG_H_OFFSET, U.CRG_NO_OPPOSITE, U.CRG_ST_OFFSET_GLOBAL]
    )
    by_uid = {f.rule_uid: f for f in found}
    assert by_uid[U.CRG_ST_OFFSET_GLOBAL].line == line_of(path, 'file="w.crg"')
    assert "no sOffset or tOffset" in by_uid[U.CRG_ST_OFFSET_GLOBAL].message
    assert by_uid[U.CRG_FRICTION_Z].road == "1" and "no zOffset" in by_uid[U.CRG_FRICTION_Z].message
