"""Rule lane-width-undefined: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of
from xodrcheck.check import check

RULE = "lane-width-undefined"


def test_first_width_record_starts_late():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.lane, f.line) == ("1", -1, line_of(path, '<lane id="-1"'))
    assert "sOffset 10" in f.message


def test_lane_without_width():
    (f,) = findings(fixture(RULE, "fail_no_width.xodr"), RULE)
    assert f.lane == -1 and "no <width> record" in f.message


def test_files_before_17_are_not_held_to_it():
    """width_defined_whole_section is a 1.7.0 rule: a 1.6 file is not checked against it."""
    text = fixture(RULE, "fail.xodr").read_text(encoding="utf-8").replace('revMinor="7"', 'revMinor="6"')
    assert check(text.encode(), select=("L022",)).findings == ()
