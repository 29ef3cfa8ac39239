"""Rule road-length-mismatch: its pass fixtures give no finding, its fail fixtures one where the defect is."""

from tests.xodrcheck.rules.helpers import assert_passes, findings, fixture, line_of

RULE = "road-length-mismatch"


def test_pass_fixtures_give_no_finding():
    assert_passes(RULE)


def test_declared_length_ten_metres_too_long():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.road == "1" and "-10 m" in f.message
    assert f.line == line_of(path, '<road id="1"')
