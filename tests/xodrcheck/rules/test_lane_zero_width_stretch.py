"""Rule lane-zero-width-stretch: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of
from xodrcheck.check import check

RULE = "lane-zero-width-stretch"


def test_lane_runs_on_at_zero_width():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.lane, f.section_s, f.s) == ("1", -2, 0.0, 10.0)
    assert f.line == line_of(path, '<width sOffset="10"')
    assert abs(f.x - 10.0) < 1e-9 and abs(f.y + 3.5) < 1e-9  # where lane -2 has shrunk onto lane -1


def test_a_lane_that_closes_smoothly_at_the_section_end_is_no_stretch():
    """A cubic closing (3.5 (1 - u)^3) is under zero_width over its last metres but is not a zero record."""
    text = fixture(RULE, "pass.xodr").read_text(encoding="utf-8")
    text = text.replace('a="3.5" b="-0.07" c="0" d="0"', 'a="3.5" b="-0.21" c="0.0042" d="-0.000028"')
    assert check(text.encode(), select=("G015",)).findings == ()


def test_a_lane_of_zero_width_over_its_whole_section_is_no_count_change():
    text = fixture(RULE, "pass.xodr").read_text(encoding="utf-8").replace('a="3.5" b="-0.07"', 'a="0" b="0"')
    assert check(text.encode(), select=("G015",)).findings == ()
