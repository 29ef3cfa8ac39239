"""Rule duplicate-junction-id: its pass fixtures give no finding, its fail fixtures one where the defect is."""

from tests.xodrcheck.rules.helpers import assert_passes, findings, fixture, line_of

RULE = "duplicate-junction-id"


def test_pass_fixtures_give_no_finding():
    assert_passes(RULE)


def test_second_junction_with_the_id_is_reported():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.line == line_of(path, '<junction id="100"', occurrence=2)
