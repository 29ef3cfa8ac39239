"""Rule duplicate-connection-id: its pass fixtures give no finding, its fail fixtures one where the defect is."""

from tests.xodrcheck.rules.helpers import assert_passes, findings, fixture, line_of

RULE = "duplicate-connection-id"


def test_pass_fixtures_give_no_finding():
    assert_passes(RULE)


def test_second_connection_with_the_id_is_reported():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.line == line_of(path, '<connection id="0"', occurrence=2)
    assert "junction 100" in f.message
