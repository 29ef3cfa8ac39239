"""Rule connection-duplicate: its pass fixtures give no finding, its fail fixtures one where the defect is."""

from tests.xodrcheck.rules.helpers import assert_passes, findings, fixture, line_of

RULE = "connection-duplicate"


def test_pass_fixtures_give_no_finding():
    assert_passes(RULE)


def test_two_connections_for_one_incoming_and_connecting_road():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.road == "10"
    assert f.line == line_of(path, '<connection id="2"')
