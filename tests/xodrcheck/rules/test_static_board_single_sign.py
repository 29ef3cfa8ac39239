"""Rule static-board-single-sign (T004): the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "static-board-single-sign"


def test_a_board_with_one_stop_sign():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.line == line_of(path, 'id="10"') and "carries 1 sign" in f.message
