"""Rule vms-group-without-boards (T007): the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "vms-group-without-boards"


def test_a_group_naming_a_plain_sign():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.line == line_of(path, "<vmsGroup") and "no signal with a <vmsBoard> ('5')" in f.message
