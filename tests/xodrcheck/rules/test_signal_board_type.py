"""Rule signal-board-type (T003): the findings each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture
from xodrcheck.rules.shared import feature_uids as U

RULE = "signal-board-type"


def test_static_and_vms_boards_make_a_dynamic_multi_board():
    found = findings(fixture(RULE, "fail_multi.xodr"), RULE)
    assert {f.rule_uid for f in found} == {U.MULTI_BOARD_TYPE, U.MULTI_BOARD_DYNAMIC}
    assert any("type='vmsBoard'" in f.message for f in found)


def test_static_board_with_a_sign_type():
    (f,) = findings(fixture(RULE, "fail_static.xodr"), RULE)
    assert f.rule_uid == U.STATIC_BOARD_TYPE and "type='274'" in f.message


def test_multi_board_without_static_part():
    (f,) = findings(fixture(RULE, "fail_parts.xodr"), RULE)
    assert f.rule_uid == U.MULTI_BOARD_SUB_BOARDS and "0 <staticBoard> and 1 <vmsBoard>" in f.message
